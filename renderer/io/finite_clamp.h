#pragma once
// The one rule by which the EXR writer makes a value safe for its channel:
// NaN becomes 0 and magnitudes beyond the channel's largest finite value
// become that value (so ±Inf too). Used for HALF channels (65504,
// half_convert.cpp), FLOAT channels (FLT_MAX) and Cryptomatte coverages (1).

#include <cmath>

namespace raylab {

/// NaN -> 0, v > maxAbs -> maxAbs, v < -maxAbs -> -maxAbs, else v.
inline float finiteClamp(float v, float maxAbs) {
    if (std::isnan(v)) return 0.f;
    return v > maxAbs ? maxAbs : (v < -maxAbs ? -maxAbs : v);
}

}  // namespace raylab

#pragma once
// How shadow feelers treat surfaces that transmit light.

namespace raylab {

enum class ShadowMode {
    Opaque,    ///< every surface blocks the light (SPD's procedure, classic Whitted)
    Filtered,  ///< transmitters dim it by their kt (Hall & Greenberg): the default
};

/// "opaque" or "filtered": the spelling of --shadows and of render.shadows.
inline const char* shadowModeName(ShadowMode m) {
    return m == ShadowMode::Opaque ? "opaque" : "filtered";
}

}  // namespace raylab

#include "renderer/film.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>

namespace raylab {

Film::Film(int w, int h, int x0, int y0, int fullW, int fullH, int ranks)
    : width(w),
      height(h),
      originX(x0),
      originY(y0),
      fullWidth(fullW),
      fullHeight(fullH),
      matteRanks(std::clamp(ranks, 1, kMatteRanks)) {
    const size_t n = size_t(w) * size_t(h);
    tbb::parallel_invoke([&] { rgba.assign(n * 4, 0.f); },
                         [&] { z.assign(n, kNoHitDepth); },
                         [&] { distance.assign(n, kNoHitDepth); },
                         [&] { normal.assign(n * 3, 0.f); },
                         [&] { albedo.assign(n * 3, 0.f); },
                         [&] { objectId.assign(n, -1.f); },
                         [&] { mattes.assign(n * size_t(matteRanks), MatteEntry{}); });
}

}  // namespace raylab

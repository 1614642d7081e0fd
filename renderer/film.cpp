#include "renderer/film.h"

#include <tbb/parallel_invoke.h>

namespace raylab {

Film::Film(int w, int h, int x0, int y0, int fullW, int fullH)
    : width(w), height(h), originX(x0), originY(y0), fullWidth(fullW), fullHeight(fullH) {
    const size_t n = size_t(w) * size_t(h);
    tbb::parallel_invoke([&] { rgba.assign(n * 4, 0.f); },
                         [&] { z.assign(n, kNoHitDepth); },
                         [&] { distance.assign(n, kNoHitDepth); },
                         [&] { normal.assign(n * 3, 0.f); },
                         [&] { albedo.assign(n * 3, 0.f); },
                         [&] { objectId.assign(n, -1.f); },
                         [&] { mattes.assign(n * kMatteRanks, MatteEntry{}); });
}

}  // namespace raylab

#include "renderer/film.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <memory>
#include <utility>

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
    const size_t floats = n * sizeof(float), mattesBytes = n * size_t(matteRanks) * sizeof(MatteEntry);
    // Every plane's slot in one mapping (plane_arena.h), taken here in a
    // fixed order; the tasks below then fill them without reallocating.
    const auto arena = std::make_shared<PlaneArena>(PlaneArena::slot(4 * floats) +
                                                    3 * PlaneArena::slot(floats) +
                                                    2 * PlaneArena::slot(3 * floats) +
                                                    PlaneArena::slot(mattesBytes));
    const PlaneAllocator<float> fromArena(arena);
    for (auto [plane, size] : {std::pair{&rgba, n * 4}, {&z, n}, {&distance, n}, {&normal, n * 3},
                               {&albedo, n * 3}, {&objectId, n}}) {
        *plane = FilmPlane(fromArena);
        plane->reserve(size);
    }
    mattes = decltype(mattes)(PlaneAllocator<MatteEntry>(arena));
    mattes.reserve(n * size_t(matteRanks));
    tbb::parallel_invoke([&] { rgba.assign(n * 4, 0.f); },
                         [&] { z.assign(n, kNoHitDepth); },
                         [&] { distance.assign(n, kNoHitDepth); },
                         [&] { normal.assign(n * 3, 0.f); },
                         [&] { albedo.assign(n * 3, 0.f); },
                         [&] { objectId.assign(n, -1.f); },
                         [&] { mattes.assign(n * size_t(matteRanks), MatteEntry{}); });
}

}  // namespace raylab

#include "renderer/film.h"

#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <memory>
#include <utility>

namespace raylab {

Film::Film(int w, int h, int x0, int y0, int fullW, int fullH, int ranks, bool aovs)
    : width(w),
      height(h),
      originX(x0),
      originY(y0),
      fullWidth(fullW),
      fullHeight(fullH),
      matteRanks(std::clamp(ranks, 1, kMatteRanks)) {
    const size_t n = size_t(w) * size_t(h);
    // Every plane's slot in one mapping (plane_arena.h), sized for and taken
    // by these reservations in a fixed order; the tasks below then fill the
    // planes without reallocating. Without AOVs the other planes stay empty.
    const size_t a = aovs ? n : 0;
    const std::pair<FilmPlane*, size_t> planes[] = {{&rgba, n * 4},   {&z, a},
                                                    {&distance, a},   {&normal, a * 3},
                                                    {&albedo, a * 3}, {&objectId, a}};
    const size_t matteCount = a * size_t(matteRanks);
    size_t bytes = PlaneArena::slot(matteCount * sizeof(MatteEntry));
    for (const auto& [plane, size] : planes) bytes += PlaneArena::slot(size * sizeof(float));
    const auto arena = std::make_shared<PlaneArena>(bytes);
    for (const auto& [plane, size] : planes) {
        *plane = FilmPlane(PlaneAllocator<float>(arena));
        plane->reserve(size);
    }
    mattes = decltype(mattes)(PlaneAllocator<MatteEntry>(arena));
    mattes.reserve(matteCount);
    tbb::parallel_invoke([&] { rgba.assign(n * 4, 0.f); },
                         [&] { z.assign(a, kNoHitDepth); },
                         [&] { distance.assign(a, kNoHitDepth); },
                         [&] { normal.assign(a * 3, 0.f); },
                         [&] { albedo.assign(a * 3, 0.f); },
                         [&] { objectId.assign(a, -1.f); },
                         [&] { mattes.assign(matteCount, MatteEntry{}); });
}

}  // namespace raylab

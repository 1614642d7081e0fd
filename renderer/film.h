#pragma once
// The image being rendered: RGBA plus the AOV layers the EXR carries. Tiles
// are disjoint, so render threads write straight into it without locks.

#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/vec.h"
#include "renderer/huge_page_allocator.h"
#include "shading/color.h"

namespace raylab {

/// One layer of the film: megabytes per frame, so on huge pages (huge_page_allocator.h).
using FilmPlane = std::vector<float, HugePageAllocator<float>>;

struct Film {
    int width = 0, height = 0;
    FilmPlane rgba;      ///< 4 floats per pixel; A = coverage (fraction of samples that hit)
    FilmPlane depth;     ///< Z: eye distance to the first hit, +inf where nothing is hit
    FilmPlane normal;    ///< 3 floats per pixel: world shading normal of the first hit
    FilmPlane albedo;    ///< 3 floats per pixel: diffuse reflectance of the first hit
    FilmPlane objectId;  ///< index of the first object hit, -1 for background

    Film() = default;
    Film(int w, int h)
        : width(w), height(h),
          rgba(size_t(w) * h * 4, 0.f),
          depth(size_t(w) * h, std::numeric_limits<float>::infinity()),
          normal(size_t(w) * h * 3, 0.f),
          albedo(size_t(w) * h * 3, 0.f),
          objectId(size_t(w) * h, -1.f) {}

    size_t index(int x, int y) const { return size_t(y) * width + x; }
};

}  // namespace raylab

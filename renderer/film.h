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
    /// Where the film lies in the full image (a crop render, the EXR's data
    /// window inside its display window): its pixel (0, 0) is pixel
    /// (originX, originY) of a fullWidth × fullHeight image. A whole frame
    /// has origin 0 and full size = its size.
    int originX = 0, originY = 0;
    int fullWidth = 0, fullHeight = 0;
    FilmPlane rgba;      ///< 4 floats per pixel; A = coverage (fraction of samples that hit)
    FilmPlane depth;     ///< Z: eye distance to the first hit, +inf where nothing is hit
    FilmPlane normal;    ///< 3 floats per pixel: world shading normal of the first hit
    FilmPlane albedo;    ///< 3 floats per pixel: diffuse reflectance of the first hit
    FilmPlane objectId;  ///< index of the first object hit, -1 for background

    Film() = default;
    Film(int w, int h) : Film(w, h, 0, 0, w, h) {}
    /// The w × h window at (x0, y0) of a fullW × fullH image.
    Film(int w, int h, int x0, int y0, int fullW, int fullH)
        : width(w), height(h), originX(x0), originY(y0), fullWidth(fullW), fullHeight(fullH),
          rgba(size_t(w) * h * 4, 0.f),
          depth(size_t(w) * h, std::numeric_limits<float>::infinity()),
          normal(size_t(w) * h * 3, 0.f),
          albedo(size_t(w) * h * 3, 0.f),
          objectId(size_t(w) * h, -1.f) {}

    /// Full-image size (a film filled in by hand may leave it 0: then its own).
    int displayWidth() const { return fullWidth > 0 ? fullWidth : width; }
    int displayHeight() const { return fullHeight > 0 ? fullHeight : height; }
    bool isCrop() const {
        return originX != 0 || originY != 0 || displayWidth() != width || displayHeight() != height;
    }
    /// Index of pixel (x, y) in full-image coordinates.
    size_t index(int x, int y) const { return size_t(y - originY) * width + size_t(x - originX); }
};

}  // namespace raylab

#pragma once
// The image being rendered: RGBA plus the AOV layers the EXR carries. Tiles
// are disjoint, so render threads write straight into it without locks.

#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/vec.h"
#include "renderer/plane_arena.h"
#include "shading/color.h"

namespace raylab {

/// One layer of the film: megabytes per frame, so on huge pages
/// (huge_page_allocator.h), all of a film's layers in one mapping (plane_arena.h).
using FilmPlane = std::vector<float, PlaneAllocator<float>>;

/// Depth and distance of a pixel where nothing is hit: finite, the value
/// Blender's Cycles writes for the background (1e10), so that statistics and
/// depth-of-field tools never meet an Inf.
constexpr float kNoHitDepth = 1e10f;

/// Object ranks kept per pixel for the Cryptomatte layers: 6, the depth
/// Blender and Arnold write by default (CryptoObject00..02). Exact whenever a
/// pixel's samples see at most 6 objects; beyond that the 6 largest coverages
/// are kept.
constexpr int kMatteRanks = 6;

/// One rank of a pixel's object coverage: the fraction of the pixel's samples
/// whose camera ray hit `object` first. object = -1 marks an unused rank.
struct MatteEntry {
    int32_t object = -1;
    float coverage = 0.f;
};

struct Film {
    int width = 0, height = 0;
    /// Where the film lies in the full image (a crop render, the EXR's data
    /// window inside its display window): its pixel (0, 0) is pixel
    /// (originX, originY) of a fullWidth × fullHeight image. A whole frame
    /// has origin 0 and full size = its size.
    int originX = 0, originY = 0;
    int fullWidth = 0, fullHeight = 0;
    FilmPlane rgba;      ///< 4 floats per pixel; A per the alpha mode (alpha_mode.h)
    FilmPlane z;         ///< planar camera depth of the first hit, kNoHitDepth where nothing is hit
    FilmPlane distance;  ///< Euclidean eye distance of the first hit, kNoHitDepth where nothing is hit
    FilmPlane normal;    ///< 3 floats per pixel: world shading normal of the first hit
    FilmPlane albedo;    ///< 3 floats per pixel: diffuse reflectance of the first hit
    FilmPlane objectId;  ///< index of the first object hit, -1 for background
    /// `matteRanks` entries per pixel, by decreasing coverage (ties: lower
    /// object index first); from every sample of the pixel.
    std::vector<MatteEntry, PlaneAllocator<MatteEntry>> mattes;
    /// Entries per pixel in `mattes`, 1..kMatteRanks: the most objects one
    /// pixel's samples can see (matteRanksOfSampling), so a 1-sample render
    /// keeps 8 bytes per pixel and an SPD render 32 instead of 48 (fresh
    /// memory costs ~1.2-3 ms per MB on this project's VMs, docs/benchmarks.md).
    int matteRanks = kMatteRanks;

    Film() = default;
    Film(int w, int h) : Film(w, h, 0, 0, w, h) {}
    /// The w × h window at (x0, y0) of a fullW × fullH image, every plane at
    /// its blank value (above), all of them in one PlaneArena. The 60-100
    /// bytes per pixel are written by TBB tasks, a plane each (film.cpp): a
    /// frame's first touch of its film is not one core's serial pass before
    /// the render.
    /// `ranks`: matteRanks (clamped to 1..kMatteRanks).
    /// `aovs` false: RGBA alone, every other plane empty, for a render whose
    /// outputs carry no layer (RenderOptions::wantAovs): an SPD film is then
    /// 16 bytes per pixel instead of 84.
    Film(int w, int h, int x0, int y0, int fullW, int fullH, int ranks = kMatteRanks,
         bool aovs = true);

    /// Pixel i's first entry of `matteRanks`.
    MatteEntry* mattesOf(size_t i) { return mattes.data() + i * size_t(matteRanks); }
    const MatteEntry* mattesOf(size_t i) const { return mattes.data() + i * size_t(matteRanks); }

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

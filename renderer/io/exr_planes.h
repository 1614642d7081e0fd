#pragma once
// The pixel planes the EXR writer compresses, prepared from a Film one range
// of pixels at a time: RGBA and albedo converted to half, the FLOAT layers
// made safe, and the Cryptomatte plane (ids hashed from object names, ranks
// merged by name).
//
// Why ranges: the writer prepares each 16-line block's planes just before it
// compresses them, in the thread that compresses them, into buffers that
// thread reuses. Planes for the whole frame were 70 bytes per pixel (18 MB at
// 512x512) of fresh memory, and fresh memory is the dearest thing on this
// project's VMs (~1.2-3 ms per MB of first touch, docs/benchmarks.md, "Fresh
// memory"). Every output value is a function of one pixel's input values
// (and of the whole-film ExrMatteLayout), so the bytes do not depend on how
// the frame is split (tests/output/test_exr_planes.cpp checks every range
// against a one-pixel-at-a-time reference).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/film.h"

namespace raylab {

/// What the Cryptomatte layers need from the whole film before the header
/// can be written.
struct ExrMatteLayout {
    /// Ranks written (even, >= the wanted count and >= what any pixel holds).
    int ranks = 2;
    /// The highest object index any pixel's coverage names (-1: none).
    int maxObject = -1;
    /// Object index -> Cryptomatte id (as a float), 0..maxObject.
    std::vector<float> idOf;
};

/// Scans the film's mattes (TBB tasks on up to `threads` threads; 0: in the
/// calling thread's arena, within its limit): `wantedRanks` as
/// ExrOptions::matteRanks, object names as ExrOptions::objectNames.
ExrMatteLayout exrMatteLayout(const Film& film, const std::vector<std::string>& objectNames,
                              int wantedRanks, int threads);

/// The planes of pixels [begin, end) of a film (row-major pixel indices);
/// element 0 of each plane is pixel `begin`. The pointers are valid until the
/// next prepareExrPlanes on the same ExrPlanes or a change to the film.
struct ExrPlanes {
    /// RGBA as FLOAT (floatPixels; rgbaH is then null) or half bits (rgbaF null).
    const float* rgbaF = nullptr;
    const uint16_t* rgbaH = nullptr;
    /// The FLOAT layers: the film's own values when they are already safe
    /// (always, for a rendered film), else safe copies.
    const float* z = nullptr;
    const float* distance = nullptr;
    const float* normal = nullptr;
    const float* objectId = nullptr;
    const uint16_t* albedo = nullptr;  ///< half bits, 3 per pixel
    /// Per pixel ExrMatteLayout::ranks (id, coverage) float pairs, by
    /// decreasing coverage; unused ranks are (0, 0).
    const float* crypto = nullptr;

    // Storage, reused from call to call (grown, never shrunk); a whole
    // frame's planes on huge pages, as the film's own (huge_page_allocator.h).
    using HalfPlane = std::vector<uint16_t, HugePageAllocator<uint16_t>>;
    HalfPlane rgbaHalf, albedoHalf;
    FilmPlane cryptoValues, rgbaCopy, zCopy, distanceCopy, normalCopy, objectIdCopy;
};

/// Fills `out` with pixels [begin, end) of `film` (whose layer sizes writeExr
/// has checked), on the calling thread.
void prepareExrPlanes(const Film& film, size_t begin, size_t end, bool floatPixels,
                      const ExrMatteLayout& mattes, ExrPlanes& out);

/// Every pixel's planes at once (the compressions OpenEXR writes, which take
/// the whole frame): the same values as prepareExrPlanes over [0, W·H), its
/// independent planes prepared side by side on up to `threads` threads (0:
/// TBB's default).
void prepareExrFramePlanes(const Film& film, bool floatPixels, const ExrMatteLayout& mattes,
                           ExrPlanes& out, int threads);

}  // namespace raylab

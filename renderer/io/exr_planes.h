#pragma once
// The pixel planes the EXR writer hands to OpenEXR, prepared from a Film:
// RGBA and albedo converted to half, the FLOAT layers made safe, and the
// Cryptomatte plane (ids hashed from object names, ranks merged by name).
//
// Why a unit of its own: this preparation ran on the main thread alone
// (~20 ms for a 512x512 frame, a serial part of every render's wall time,
// docs/benchmarks.md bar 3). Every output value is a function of one pixel's
// input values, so it is split over pixel ranges with TBB and the planes are
// the same bytes for any thread count (tests/output/test_exr_planes.cpp
// checks them against a one-pixel-at-a-time reference).

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/film.h"
#include "renderer/huge_array.h"

namespace raylab {

struct ExrPlanes {
    /// RGBA as FLOAT (floatPixels) or half bits (otherwise; rgbaF is then null).
    const float* rgbaF = nullptr;
    HugeArray<uint16_t> rgbaH;
    /// The FLOAT layers: the film's own planes when they are already safe
    /// (always, for a rendered film), else the safe copies below.
    const float* z = nullptr;
    const float* distance = nullptr;
    const float* normal = nullptr;
    const float* objectId = nullptr;
    HugeArray<uint16_t> albedo;  ///< half bits, 3 per pixel
    /// Cryptomatte ranks written (even, >= the wanted count and >= what any
    /// pixel holds) and per pixel `matteRanks` (id, coverage) float pairs.
    int matteRanks = 0;
    HugeArray<float> crypto;
    /// The highest object index any pixel's coverage names (-1: none).
    int maxMatteObject = -1;

    // Storage for planes the film could not lend (empty AOV planes, values
    // that are NaN or infinite).
    FilmPlane rgbaCopy, zCopy, distanceCopy, normalCopy, objectIdCopy;
};

/// Prepares the planes of `film` (whose layer sizes writeExr has checked):
/// `wantedRanks` as ExrOptions::matteRanks, object names as
/// ExrOptions::objectNames. `threads`: at most this many threads (0: TBB's
/// default); the result does not depend on it.
ExrPlanes prepareExrPlanes(const Film& film, bool floatPixels,
                           const std::vector<std::string>& objectNames, int wantedRanks,
                           int threads);

}  // namespace raylab

#pragma once
// Everything that controls one render, after the scene file's settings and the
// command-line flags have been merged (flags win).

#include <cstdint>
#include <string>

#include "geometry/spawn.h"
#include "renderer/accel/accel_options.h"
#include "renderer/accelerator_kind.h"
#include "renderer/alpha_mode.h"
#include "renderer/crop_window.h"
#include "renderer/shadow_mode.h"
#include "renderer/texture_options.h"

namespace raylab {

// Limits shared by every way of setting these (flags, JSON, NFF), so a value
// one accepts the others accept too.
constexpr int kMaxImageSide = 65536;  ///< width and height (the memory guard still applies)
constexpr int kMaxSpp = 65536;
constexpr int kMaxDepth = 64;  ///< RenderStats counts rays per depth up to this
constexpr int kMaxAdaptiveLevels = 8;
constexpr long long kMaxSeed = 1LL << 53;  ///< JSON numbers are doubles: exact up to here
/// Rays (of every type) one camera sample may trace before its reflection and
/// refraction rays stop: a glass sphere inside a mirror doubles its ray tree
/// at every level, so without a cap depth 64 never ends. No shipped picture
/// and no SPD scene comes near it (docs/robustness.md, "Bounded work per
/// sample"); --max-rays changes it.
constexpr uint64_t kDefaultMaxRaysPerSample = 1u << 16;
constexpr long long kMaxRaysPerSampleLimit = 1LL << 40;  ///< the largest --max-rays

struct RenderOptions {
    int width = 640;
    int height = 480;
    int spp = 1;              ///< samples per pixel (stratified, jittered when > 1)
    int maxDepth = 5;         ///< ray-tree depth limit, the camera ray is depth 1
    double minWeight = 0;     ///< Hall & Greenberg pruning: skip rays whose weight < this (0 = off)
    double adaptiveThreshold = 0;  ///< Whitted adaptive supersampling threshold (0 = off)
    int adaptiveMaxLevel = 2;      ///< subdivision levels below the pixel corners
    uint64_t seed = 0;        ///< jitter seed; the image is a pure function of it
    uint64_t maxRaysPerSample = kDefaultMaxRaysPerSample;  ///< see kDefaultMaxRaysPerSample

    int threads = 0;          ///< 0 = all cores
    AcceleratorKind accel = AcceleratorKind::Embree;
    AccelOptions accelOptions;  ///< also the intersectors' accuracy knobs (precision, polygons)
    SpawnSettings spawn;      ///< self-intersection strategy
    /// Name the object a spawned ray leaves where the ray cannot meet it
    /// again (Shape::revisit; robust offset, double precision only), so that
    /// the accelerator skips its test: the same picture, faster. Off only to
    /// compare the two (tests).
    bool departures = true;
    ShadowMode shadows = ShadowMode::Filtered;  ///< SPD's procedure: opaque
    AlphaMode alpha = AlphaMode::Background;    ///< what A means where rays miss (--alpha)
    TextureOptions textures;  ///< filter and footprint of texture lookups

    bool spd = false;          ///< Haines' SPD testing procedure (corner rays, zero-weight rays traced)
    bool forceAllEffects = false;  ///< the general kernel: every ray type at every hit (--effects all)
    /// depth/normal/albedo/objectId/Cryptomatte layers are computed and the
    /// film has their planes (render: only when an output is an EXR)
    bool wantAovs = true;
    CropWindow crop;           ///< --crop: only these pixels are rendered (the film is the crop)
};

}  // namespace raylab

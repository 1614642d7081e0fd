#pragma once
// Shared by the distributed tests: a scene prepared exactly as `raylab
// render` prepares it, and bitwise comparisons of films and counters.

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/accelerator_kind.h"
#include "renderer/effects.h"
#include "renderer/film.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"

namespace raylab::test {

/// Scene, options, BVH and effects, in render_command.cpp's order. Held by
/// pointer: the accelerator refers to the scene.
struct PreparedScene {
    Scene scene;
    RenderOptions options;
    std::unique_ptr<Accelerator> accel;
    EffectSet effects;
};

inline std::unique_ptr<PreparedScene> prepare(const std::string& path,
                                              const RenderOverrides& overrides) {
    auto p = std::make_unique<PreparedScene>();
    p->scene = loadScene(path);
    p->options = resolveRenderOptions(p->scene, overrides);
    p->accel = makeAccelerator(p->options.accel, p->scene, p->options.accelOptions);
    p->effects = analyseEffects(p->scene, p->options);
    return p;
}

/// Bitwise equality of two float layers (NaN payloads and -0 included).
inline bool sameBits(const FilmPlane& a, const FilmPlane& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

/// "" when the films are bit-identical, else the first layer that differs.
inline std::string filmDifference(const Film& a, const Film& b) {
    if (a.width != b.width || a.height != b.height) return "size";
    if (!sameBits(a.rgba, b.rgba)) return "rgba";
    if (!sameBits(a.depth, b.depth)) return "depth";
    if (!sameBits(a.normal, b.normal)) return "normal";
    if (!sameBits(a.albedo, b.albedo)) return "albedo";
    if (!sameBits(a.objectId, b.objectId)) return "objectId";
    return "";
}

inline bool sameCounters(const RayCounters& a, const RayCounters& b) {
    return a.byDepth == b.byDepth && a.cameraHits == b.cameraHits;
}

}  // namespace raylab::test

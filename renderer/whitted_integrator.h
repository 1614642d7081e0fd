#pragma once
// The classic Whitted integrator: ambient + Lambert + Blinn-Phong from every
// light (with shadow feelers), plus recursive ideal reflection and refraction
// up to a depth limit. One readable kernel, compiled once per effect set
// (template over EffectBits) and dispatched once per render.

#include <limits>

#include "geometry/spawn.h"
#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/render_options.h"
#include "renderer/render_stats.h"
#include "renderer/scene.h"

namespace raylab {

/// What the camera ray saw first (the EXR's AOV layers).
struct FirstHit {
    bool hit = false;
    float distance = std::numeric_limits<float>::infinity();  ///< from the eye, along the ray
    /// Planar camera depth: along the view axis (set by the renderer, which knows the camera).
    float depth = std::numeric_limits<float>::infinity();
    Vec3 normal;       ///< world shading normal (outward)
    Color albedo;      ///< diffuse reflectance kd
    float objectId = -1;
};

class WhittedIntegrator {
public:
    WhittedIntegrator(const Scene& scene, const Accelerator& accel, const RenderOptions& options,
                      const EffectSet& effects);

    /// Radiance along a camera ray. Counts rays into `counters`; fills
    /// `first` (may be null) with the first hit's AOV data.
    Color Li(const Ray& cameraRay, RayCounters& counters, FirstHit* first) const;

private:
    template <unsigned E>
    Color trace(const Ray& ray, double tMin, int depth, RayType type, double weight,
                RayCounters& counters, FirstHit* first) const;
    template <unsigned E>
    Color shadeLocal(const SurfaceInteraction& si, const Material& m, const Vec3& n,
                     const RaySpawner& spawn, const Vec3& toViewer, int depth,
                     RayCounters& counters) const;

    using Kernel = Color (WhittedIntegrator::*)(const Ray&, double, int, RayType, double,
                                                RayCounters&, FirstHit*) const;

    const Scene& m_scene;
    const Accelerator& m_accel;
    RenderOptions m_options;
    EffectSet m_effects;
    bool m_prune = true;  ///< skip zero-weight rays (off for the general kernel and SPD)
    Kernel m_kernel = nullptr;
};

}  // namespace raylab

#pragma once
// The classic Whitted integrator: ambient + Lambert + Blinn-Phong from every
// light (with shadow feelers), plus recursive ideal reflection and refraction
// up to a depth limit. One readable kernel, compiled once per effect set
// (template over EffectBits) and dispatched once per render.

#include <limits>
#include <optional>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "geometry/spawn.h"
#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/prepared_hits.h"
#include "renderer/render_options.h"
#include "renderer/render_stats.h"
#include "renderer/scene.h"
#include "renderer/texture_shading.h"
#include "renderer/shadow_cache.h"
#include "shading/radiance_range.h"

namespace raylab {

/// What the camera ray saw first (the EXR's AOV layers).
struct FirstHit {
    bool hit = false;
    float distance = std::numeric_limits<float>::infinity();  ///< from the eye, along the ray
    /// Planar camera depth: along the view axis (set by the renderer, which knows the camera).
    float depth = std::numeric_limits<float>::infinity();
    Vec3 normal;       ///< world shading normal (outward)
    Color albedo;      ///< diffuse reflectance kd (textured where kd has a texture)
    float objectId = -1;
};

/// What an untextured kernel carries instead of a footprint: nothing.
struct NoFootprint {};

/// What one camera sample spent: the rays it traced (every type) and whether
/// the per-sample cap (RenderOptions::maxRaysPerSample) refused it a
/// reflection or refraction ray.
struct SampleRays {
    uint64_t traced = 0;
    bool capped = false;
};

class WhittedIntegrator {
public:
    WhittedIntegrator(const Scene& scene, const Accelerator& accel, const RenderOptions& options,
                      const EffectSet& effects);
    ~WhittedIntegrator();

    /// Radiance along a camera ray. Counts rays into `counters` and into
    /// `spent` (this sample alone); fills `first` (may be null) with the first
    /// hit's AOV data. After a stop request (renderer/cancel.h) no further
    /// reflection or refraction ray is traced: the result is then partial.
    /// `shadows` (may be null) is the calling thread's shadow cache: it
    /// changes no answer, only how fast shadow rays are answered (unused
    /// where the accelerator can use no hint: Accelerator::usesOcclusionHints).
    /// `cameraHit`, when given, is the camera ray's first hit as the
    /// accelerator answered it (cameraHits): it is not asked again; nor is
    /// `prepared` (when given: that hit prepared by prepareCameraHits) shaded
    /// again up to its feelers.
    Color Li(const Ray& cameraRay, RayCounters& counters, FirstHit* first, SampleRays& spent,
             ShadowCache* shadows = nullptr, const std::optional<Hit>* cameraHit = nullptr,
             const PreparedHit* prepared = nullptr) const;

    /// The first hits of `count` (1..Accelerator::kPacketRays) camera rays,
    /// asked of the accelerator together (a packet): out[i] is what Li would
    /// find for rays[i] itself.
    void cameraHits(const Ray* rays, int count, std::optional<Hit>* out) const;
    /// Whether cameraHits is worth calling (the accelerator traces packets).
    bool tracesPackets() const { return m_accel.tracesPackets(); }
    /// \brief Shades the camera hits of a packet (cameraHits' answers) up to
    ///   their shadow feelers, the feelers to each light asked of the
    ///   accelerator together (Accelerator::shadowPacket), and the terms of
    ///   the lights that arrive: Li then takes lane k's (out.lane(k)) and
    ///   brings back the same radiance, bit for bit.
    /// \details `shadows` is the calling thread's shadow cache, as for Li: a
    ///   feeler its guess answers is not asked in the packet. Prepares nothing
    ///   where packets of feelers do not apply or do not pay: no shadows,
    ///   textured kernels (their optics need the ray's footprint), an
    ///   accelerator without packets, and a scene whose feelers use the
    ///   shadow cache and whose analytic primitives outnumber its triangles
    ///   (there the cache's guesses one at a time are faster; the constructor
    ///   gives the measurements).
    void prepareCameraHits(const Ray* rays, const std::optional<Hit>* hits, int count,
                           PreparedHits& out, ShadowCache* shadows) const;

private:
    /// What one worker carries through a ray tree.
    struct TraceState {
        RayCounters& counters;
        ShadowCache* shadows;
        SampleRays& spent;  ///< this sample's rays, for the per-sample cap
    };

    static constexpr bool textured(unsigned E) { return (E & kTextures) != 0; }
    /// A ray's footprint in kernels with textures, nothing in the others.
    template <unsigned E>
    using Footprint = std::conditional_t<textured(E), RayFootprint, NoFootprint>;
    template <unsigned E>
    using HitFootprintOf = std::conditional_t<textured(E), HitFootprint, NoFootprint>;

    template <unsigned E>
    Color start(const Ray& cameraRay, double tNear, TraceState& state, FirstHit* first,
                const std::optional<Hit>* cameraHit, const PreparedHit* prepared) const;
    /// One more ray of `type` at `depth`, in the render's counters and this sample's.
    static void countRay(TraceState& state, RayType type, int depth) {
        state.counters.count(type, depth);
        ++state.spent.traced;
    }
    /// Counts the ray, asks the accelerator for its hit and shades it (traceHit).
    template <unsigned E>
    Color trace(const Ray& ray, double tMin, Departure from, int depth, RayType type,
                double weight, TraceState& state, FirstHit* first,
                const Footprint<E>* carried) const;
    /// The radiance a counted ray brings back from `hit` (the background for
    /// none); `prepared` (may be null) is that hit prepared by
    /// prepareCameraHits. Inlined into trace and start: the ray tree's hot
    /// path keeps one call per ray.
    template <unsigned E>
    [[gnu::always_inline]] inline Color traceHit(const Ray& ray, const std::optional<Hit>& hit,
                                                 int depth, RayType type, double weight,
                                                 TraceState& state, FirstHit* first,
                                                 const Footprint<E>* carried,
                                                 const PreparedHit* prepared) const;
    /// The camera ray's lower bound: the near plane (NFF's hither) is a
    /// distance along the view axis.
    double cameraTMin(const Ray& cameraRay) const;
    /// Ambient, and each light's diffuse and highlight where its feeler
    /// gets through; `answered` (may be null) holds the feelers by light as
    /// prepareCameraHits found them, with the terms of the lights that
    /// arrive (PreparedHit::feelers): the feelers are then counted, not
    /// traced, and the terms added.
    template <unsigned E>
    Color shadeLocal(const SurfaceInteraction& si, const SurfaceOptics& m, const Vec3& n,
                     const RaySpawner& spawn, const Vec3& toViewer, int depth,
                     TraceState& state, const PreparedFeeler* answered) const;
    /// Sets `t` to the terms light `arriving` along l adds at a surface of
    /// optics `m` and diffuse reflectance `diffuse` (n the shading normal on
    /// the ray's side): Lambert's, and the highlight (Phong or Blinn-Phong,
    /// as `m` asks) where `highlights` (the kernel has them) and `m` has one
    /// (the general kernel adds even a black ks's zero); t.highlight is left
    /// as it was where there is none.
    void lightTerms(LightTerms& t, bool highlights, const SurfaceOptics& m, const Color& diffuse,
                    const Color& arriving, const Vec3& n, const Vec3& l, double nDotL,
                    const Vec3& toViewer) const;
    /// Filtered shadows: the light that arrives through transmittance `through`.
    static Color arrivingThrough(const Light& light, const Color& through) {
        return saturated(light.intensity * saturated(through));
    }
    /// Whether shadeLocal traces feelers from a surface of optics `m` at all
    /// (SPD counts them even from surfaces without a local term).
    bool shadesLocally(const SurfaceOptics& m) const {
        return !m_prune || m_options.spd || m.hasLocalShading();
    }
    /// The direction from p to `light` (unnormalised: a point light's feeler
    /// ends at the light, t = 1) and the feeler's tMax.
    static std::pair<Vec3, double> towards(const Light& light, const Vec3& p) {
        if (light.type == Light::Type::Point) return {light.position - p, 1.0};
        return {-light.direction, std::numeric_limits<double>::infinity()};
    }
    /// What a ray leaving hit `si` in direction `dir` departs from: the hit's
    /// object where no such ray can meet it again (m_revisit), else nothing.
    Departure departure(const SurfaceInteraction& si, const Vec3& dir) const {
        const Revisit r = m_revisit[si.object];
        return r == Revisit::None || (r == Revisit::Inward && dot(dir, si.ng) > 0)
                   ? Departure{si.object}
                   : Departure{};
    }
    /// Whether the sample may trace one more reflection or refraction ray.
    bool mayBranch(SampleRays& spent) const;

    using Kernel = Color (WhittedIntegrator::*)(const Ray&, double, TraceState&, FirstHit*,
                                                const std::optional<Hit>*,
                                                const PreparedHit*) const;
    /// One kernel per effect combination: entry i is start<i>.
    template <unsigned... E>
    static constexpr auto kernelTable(std::integer_sequence<unsigned, E...>);

    const Scene& m_scene;
    const Accelerator& m_accel;
    RenderOptions m_options;
    EffectSet m_effects;
    bool m_prune = true;  ///< skip zero-weight rays (off for the general kernel and SPD)
    bool m_shadowHints = false;  ///< the accelerator can use a ShadowCache's hints
    bool m_prepareHits = false;  ///< prepareCameraHits prepares the hits (see there)
    /// Per object, which rays leaving it could meet it again (Shape::revisit;
    /// Any for every object where RenderOptions::departures does not apply).
    std::vector<Revisit> m_revisit;
    Kernel m_kernel = nullptr;
    std::unique_ptr<TextureShading> m_textures;  ///< only when the scene has textures
};

}  // namespace raylab

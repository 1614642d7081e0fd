#pragma once
// A recording decorator around any Accelerator (benchmarks: `raylab bench
// limit` replays a frame's exact rays through bare Embree). Every query is
// forwarded unchanged and its answer returned; the ray, its interval, the
// query kind and the answer are appended to a per-thread buffer.
//
// The Accelerator interface does not say which kind of ray is asked about, so
// the recorder derives it exactly from what the Whitted integrator does:
//  - camera ray: its origin is the eye (perspective) or it runs along the view
//    direction from the eye's plane (orthographic); it starts a new ray tree;
//  - shadow ray: every occluded() and transmittance() query;
//  - reflection / refraction: the parent is the hit whose spawnRay() origin
//    (recomputed with the render's SpawnSettings) equals the new ray's origin
//    bit for bit; the first child of a hit whose direction equals the
//    refract() direction of the parent ray is a refraction ray, any other
//    child a reflection ray. Depths follow from the parent (camera = 1).
// Per-thread buffers hold whole ray trees (a pixel sample is traced on one
// thread); takeRays() orders the trees by their camera ray's image position
// (row-major), so the recording is identical for any thread count.

#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/render_options.h"
#include "renderer/render_stats.h"
#include "renderer/scene.h"

namespace raylab {

/// One query as the integrator made it, with the wrapped accelerator's answer.
struct RecordedRay {
    Ray ray;
    double tMin = 0;
    double tMax = 0;
    RayType type = RayType::Camera;
    int depth = 1;           ///< camera ray = 1, as in RayCounters
    bool occlusion = false;  ///< occluded() (shadow feeler) rather than intersect()
    bool hit = false;        ///< intersect(): a hit was found; occluded(): occluded
    /// The object the query left out (Departure), which a replay leaves out
    /// too, so that it asks the same work of Embree's callbacks.
    uint32_t departed = Departure::kNone;
};

class RayRecorder final : public Accelerator {
public:
    /// \brief Records queries answered by `inner`. `scene` and `options` must
    ///   be the ones the render uses (camera, image size and spawn settings
    ///   identify camera rays and parents). All three must outlive the recorder.
    RayRecorder(const Accelerator& inner, const Scene& scene, const RenderOptions& options);

    using Accelerator::intersect;
    using Accelerator::occluded;
    using Accelerator::transmittance;
    /// Each query goes to the wrapped accelerator as asked; the record keeps
    /// its Departure for the replays.
    std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax,
                                 Departure from) const override;
    bool occluded(const Ray& ray, double tMin, double tMax, Departure from) const override;
    /// Recorded as an occlusion query answered "occluded" when nothing gets through.
    Color transmittance(const Ray& ray, double tMin, double tMax, Departure from) const override;
    /// The wrapped accelerator's name.
    std::string name() const override { return m_inner.name(); }
    double buildSeconds() const override { return m_inner.buildSeconds(); }
    FilterCounts filterCounts() const override { return m_inner.filterCounts(); }

    /// \brief Every ray recorded since the last call, ray trees in row-major
    ///   order of their camera ray, each tree in tracing order; clears the buffers.
    ///   Call only while no render is using the recorder.
    std::vector<RecordedRay> takeRays();

    /// Rays whose parent hit could not be identified since construction (0 for
    /// renders by the Whitted integrator; their type and depth are a guess).
    uint64_t unmatchedRays() const;

    /// Counts of `rays` by type and depth, plus camera rays that hit: the same
    /// numbers RenderResult::rays holds for the render that was recorded.
    static RayCounters countRays(const std::vector<RecordedRay>& rays);

private:
    /// A hit that may still spawn rays: what the integrator knew when it spawned them.
    struct PathEntry {
        Vec3 p;          ///< hit point (SurfaceInteraction::p)
        double span = 0; ///< SurfaceInteraction::span
        Vec3 ngSide;     ///< geometric normal on the side the ray arrived from
        Vec3 nSide;      ///< shading normal on that side
        Vec3 dirUnit;    ///< normalised direction of the ray that hit
        double etaI = 1, etaT = 1;
        int depth = 1;
        bool hadChild = false;
    };
    struct ThreadState {
        std::vector<RecordedRay> rays;
        std::vector<size_t> treeStarts;  ///< index of each camera ray in `rays`
        std::vector<PathEntry> path;     ///< open hits of the current tree, root first
        uint64_t unmatched = 0;
    };

    bool isCameraRay(const Ray& ray) const;
    /// Index in `path` of the hit that spawned a ray from `origin` with `tMin`, or -1.
    static long findParent(const std::vector<PathEntry>& path, const Ray& ray, double tMin,
                           const SpawnSettings& spawn);
    void pushHit(ThreadState& ts, const Ray& ray, const Hit& hit, int depth) const;
    void recordShadowRay(const Ray& ray, double tMin, double tMax, Departure from,
                         bool occluded) const;

    const Accelerator& m_inner;
    const Scene& m_scene;
    RenderOptions m_options;
    mutable tbb::enumerable_thread_specific<ThreadState> m_threads;
};

}  // namespace raylab

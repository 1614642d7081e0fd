#pragma once
// Embree 3 back end: one user geometry for every non-native primitive
// (embree_user_geometry.h) and one triangle geometry per shape that declares
// native triangles (embree_triangles.h); geometry and rays are handed to
// Embree in float relative to AccelOptions::origin (the eye), so far-away
// scenes keep their precision.
//
// Internal: include it only from renderer/accel/embree_*.cpp and white-box
// tests. Everyone else builds it through makeAccelerator (accelerator.h) and
// replays rays through EmbreeReplay (embree_replay.h).

#include <embree3/rtcore.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/accel/embree_device.h"
#include "renderer/accel/embree_edge_hits.h"
#include "renderer/accel/embree_triangles.h"
#include "renderer/accel/embree_user_geometry.h"
#include "renderer/scene.h"

namespace raylab {

class EmbreeAccelerator final : public Accelerator {
public:
    /// \brief Builds the Embree scene over `scene`, which must outlive this object.
    /// \param deviceConfig rtcNewDevice configuration, e.g. "isa=avx2" to pin
    ///   the ISA in golden tests ("threads=" is rejected, see EmbreeDevice).
    /// \throws std::invalid_argument for geometry Embree cannot represent (NaN
    ///   bounds, non-finite or out-of-range mesh data), std::runtime_error for
    ///   an error reported by Embree.
    EmbreeAccelerator(const Scene& scene, const AccelOptions& options = {},
                      const std::string& deviceConfig = "");
    EmbreeAccelerator(const EmbreeAccelerator&) = delete;
    EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

    using Accelerator::intersect;
    using Accelerator::occluded;
    using Accelerator::transmittance;
    /// The departed object's user-geometry entries answer "no hit" without
    /// their test (EmbreeQueryContext::departed); native triangles are
    /// tested as ever (Shape::revisit names no mesh).
    std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax,
                                 Departure from) const override;
    /// One rtcIntersect16 packet where the device traces 16 rays natively
    /// (AVX-512), else up to two rtcIntersect8 packets; each lane's analytic
    /// shapes tested with its exact double ray and each lane's triangle hit
    /// near an edge resolved as intersect() resolves it: the same answers as
    /// intersect(). (Embree 3.13's packet triangle test gives its single-ray
    /// test's t, u, v and Ng bit for bit: measured on 1.6 M rays aimed at
    /// vertices, edges and anywhere, SSE2 to AVX-512, robust or not;
    /// docs/benchmarks.md.)
    void intersectPacket(const Ray* rays, const double* tMin, const double* tMax, int count,
                         std::optional<Hit>* out) const override;
    bool tracesPackets() const override { return true; }
    bool occluded(const Ray& ray, double tMin, double tMax, Departure from) const override;
    /// The hint names user-geometry primitives (their entries in the table):
    /// the exact Shape::occluded test is exactly what the callback would run
    /// for one, so when it reports a hit, Embree would too (its padded box
    /// contains the primitive) and the traversal is skipped. The hint's
    /// primitive is asked first, then its fallback.
    bool occluded(const Ray& ray, double tMin, double tMax, Departure from,
                  OcclusionHint& hint) const override;
    /// Hints name user-geometry primitives (a scene of triangles alone has
    /// none); a transmittance query through a surface filter ignores them.
    bool usesOcclusionHints(bool filtered) const override {
        return !m_user.entries.empty() && !(filtered && m_filter.active());
    }
    Color transmittance(const Ray& ray, double tMin, double tMax, Departure from) const override;
    /// Without a surface filter, occluded() with the hint as black or white.
    Color transmittance(const Ray& ray, double tMin, double tMax, Departure from,
                        OcclusionHint& hint) const override;
    /// One rtcOccluded16 packet (two rtcOccluded8 without AVX-512), each
    /// lane with its own exact context and, for filtered shadows, its own
    /// crossings: each lane's answer is its single feeler's. A lane whose
    /// hint answers it (as in the hinted occluded()) is left out of the packet.
    void shadowPacket(const Ray* rays, const double* tMin, const double* tMax,
                      const Departure* from, int count, bool filtered, Color* out,
                      OcclusionHint* hints = nullptr) const override;
    std::string name() const override { return "embree"; }
    double buildSeconds() const override { return m_buildSeconds; }
    FilterCounts filterCounts() const override { return m_filter.counts(); }

    /// The committed scene, for bare rtcIntersect1/rtcOccluded1 replay.
    RTCScene rtcHandle() const { return m_scene.get(); }
    /// The point all Embree coordinates are relative to.
    Vec3 origin() const { return m_origin; }
    /// geomID of the user geometry (RTC_INVALID_GEOMETRY_ID when the scene has none).
    unsigned userGeometryId() const { return m_userGeomId; }

    /// \brief Fills an Embree ray for o + t·d, tMin < t < tMax: origin relative
    ///   to origin() in float, tnear = tMin rounded down (>= 0), tfar = tMax
    ///   rounded to nearest (+inf stays +inf), mask = all ones, flags = 0.
    /// \return false when the ray cannot be traced (non-finite, zero direction,
    ///   empty or NaN interval, out of float range): the query is a miss.
    ///   Embree is built with IGNORE_INVALID_RAYS=0, so this check is ours.
    bool toEmbreeRay(const Ray& ray, double tMin, double tMax, RTCRay& out) const;

    /// \brief Turns the result of rtcIntersect1(rtcHandle(), &ctx.rtc, &rayhit)
    ///   into a Hit: for a triangle {Embree's t, object, triangle, u, v}
    ///   (Scene::surfaceAt recomputes it in double); for a user-geometry hit the
    ///   double record kept in the context, or Embree's float record when the
    ///   context carried no double ray. Written into `out` (nothing where the
    ///   ray missed): a returned record, copied, was read back across its
    ///   stores, and the reads waited for them (a stall in the profile).
    void decode(const RTCRayHit& rayhit, const EmbreeQueryContext& ctx,
                std::optional<Hit>& out) const;
    /// decode() as a returned value, for callers off the hot path.
    std::optional<Hit> decode(const RTCRayHit& rayhit, const EmbreeQueryContext& ctx) const {
        std::optional<Hit> hit;
        decode(rayhit, ctx, hit);
        return hit;
    }

    /// \brief Prepares a context for one query of `ray` (may be null) over
    ///   (tMin, tMax), with this accelerator's surface filter.
    void initContext(EmbreeQueryContext& ctx, const Ray* ray, double tMin, double tMax,
                     Departure from = {}) const;

private:
    /// Whether a guess of the hint provably blocks the feeler, by its exact
    /// test (see the hinted occluded()); names it in hint.primitive.
    [[gnu::noinline]] bool answeredByHint(const Ray& ray, double tMin, double tMax, Departure from,
                                          OcclusionHint& hint) const;
    /// intersectPacket()'s work for one Embree packet type (RTCRayHit8 or
    /// RTCRayHit16), count <= its lanes.
    template <class Packet>
    void tracePacket(const Ray* rays, const double* tMin, const double* tMax, int count,
                     std::optional<Hit>* out) const;
    /// shadowPacket()'s work for one Embree packet type (RTCRay8 or RTCRay16).
    template <class Packet>
    void occludePacket(const Ray* rays, const double* tMin, const double* tMax,
                       const Departure* from, int count, bool filtered, Color* out,
                       OcclusionHint* hints) const;
    /// occludePacket()'s work: `crossings` (one per lane) collects the
    /// transmitters of filtered feelers, null for opaque ones (their
    /// accumulators are not even built); `hints` only for opaque ones.
    template <class Packet>
    void occludePacketLanes(const Ray* rays, const double* tMin, const double* tMax,
                            const Departure* from, int count,
                            TransmittanceAccumulator* crossings, Color* out,
                            OcclusionHint* hints) const;
    void addUserGeometry(const Scene& scene, RTCBuildQuality quality);
    void addTriangles(const Scene& scene, RTCBuildQuality quality);

    // Declaration order = reverse destruction order: the scene goes first,
    // then the tables its callbacks point into, then the device.
    EmbreeDevice m_device;
    Vec3 m_origin;
    SurfaceFilter m_filter;
    EmbreeUserTable m_user;
    /// geomID -> triangle geometry (null for the user geometry); the
    /// filter functions hold their addresses.
    std::vector<std::unique_ptr<EmbreeTriangleGeometry>> m_triangleGeoms;
    EmbreeScene m_scene;
    unsigned m_userGeomId = RTC_INVALID_GEOMETRY_ID;
    std::vector<const Shape*> m_shapes;  ///< Scene::objects' shapes, for edge hits
    EdgeHitContext m_edgeHits;
    double m_buildSeconds = 0;
    bool m_nativePackets16 = false;  ///< the device traces rtcIntersect16 natively
};

}  // namespace raylab

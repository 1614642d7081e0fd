#pragma once
// Embree 3 back end (Mitsuba's adaptor pattern, STYLE.md §2.3):
//  - every analytic shape goes into ONE user geometry whose generic bounds /
//    intersect / occluded callbacks forward to the pure Shape methods, so a new
//    primitive needs no Embree code; primID -> object index lives here;
//  - every mesh object becomes one native RTC_GEOMETRY_TYPE_TRIANGLE
//    (geomID -> object index lives here);
//  - geometry and rays are handed to Embree in float relative to
//    AccelOptions::origin (the eye), so far-away scenes keep their precision;
//  - analytic shapes are always intersected with the caller's double ray
//    (carried in an extended RTCIntersectContext), so their t, u, v are
//    bit-identical to the naive loop's.
// This header includes <embree3/rtcore.h>: include it only from
// renderer/accel/embree_*.cpp and from code that replays rays through
// rtcHandle() (benchmarks).

#include <embree3/rtcore.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/shape.h"
#include "renderer/accel/accelerator.h"
#include "renderer/accel/embree_device.h"
#include "renderer/scene.h"

namespace raylab {

/// \brief Per-query data reaching the user-geometry callbacks through Embree's
///   context pointer (the only pointer Embree guarantees to pass unchanged).
/// \details Every query on EmbreeAccelerator::rtcHandle() must pass one of
///   these, set up with EmbreeAccelerator::initContext: the callbacks read it.
struct EmbreeQueryContext {
    RTCIntersectContext rtc;  ///< Embree's context; must stay the first member
    /// The caller's exact double ray, or null: analytic shapes are then tested
    /// against Embree's float copy of the ray (made relative to origin()).
    /// Set it only for rtcIntersect1/rtcOccluded1; leave it null for packets and
    /// streams (one context cannot describe several rays, and incoherent
    /// streams call back with N = 1, so the callbacks could not tell).
    const Ray* ray = nullptr;
    double tMin = 0;   ///< exclusive lower bound, double (exact path only)
    double bestT = 0;  ///< closest analytic hit so far; starts at tMax
    double bestU = 0;  ///< its shape parameters
    double bestV = 0;
    uint32_t bestObject = 0;  ///< its object index
    bool exactHit = false;    ///< an analytic hit was recorded from `ray`
};

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

    std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax) const override;
    bool occluded(const Ray& ray, double tMin, double tMax) const override;
    std::string name() const override { return "embree"; }

    /// Wall-clock seconds spent converting the geometry and committing the
    /// scene (device creation excluded).
    double buildSeconds() const { return m_buildSeconds; }
    /// The committed scene, for bare rtcIntersect1/rtcOccluded1 replay.
    RTCScene rtcHandle() const { return m_scene.get(); }
    /// The point all Embree coordinates are relative to.
    Vec3 origin() const { return m_origin; }
    /// geomID of the user geometry holding all analytic shapes
    /// (RTC_INVALID_GEOMETRY_ID when the scene has none).
    unsigned userGeometryId() const { return m_userGeomId; }

    /// \brief Fills an Embree ray for o + t·d, tMin < t < tMax: origin relative
    ///   to origin() in float, tnear = tMin rounded down (>= 0), tfar = tMax
    ///   rounded to nearest (+inf stays +inf), mask = all ones, flags = 0.
    /// \return false when the ray cannot be traced (non-finite, zero direction,
    ///   empty or NaN interval, out of float range): the query is a miss.
    ///   Embree is built with IGNORE_INVALID_RAYS=0, so this check is ours.
    bool toEmbreeRay(const Ray& ray, double tMin, double tMax, RTCRay& out) const;

    /// \brief Prepares a context for one query of `ray` (may be null) over
    ///   (tMin, tMax). Use the same ray and interval as toEmbreeRay.
    static void initContext(EmbreeQueryContext& ctx, const Ray* ray, double tMin, double tMax);

    /// \brief Turns the result of rtcIntersect1(rtcHandle(), &ctx.rtc, &rayhit)
    ///   into a Hit: for a triangle {Embree's t, object, triangle, u, v}
    ///   (Scene::surfaceAt recomputes it in double); for an analytic shape the
    ///   double record kept in the context, or Embree's float record when the
    ///   context carried no double ray.
    std::optional<Hit> decode(const RTCRayHit& rayhit, const EmbreeQueryContext& ctx) const;

    /// User data of the analytic user geometry (read by the callbacks).
    struct AnalyticTable {
        std::vector<const Shape*> shapes;  ///< indexed by primID
        std::vector<uint32_t> objects;     ///< primID -> object index
        std::vector<RTCBounds> boxes;      ///< primID -> padded float box, relative to origin
        Vec3 origin;                       ///< to rebuild world rays from Embree's float lanes
    };

private:
    void addAnalyticShapes(const Scene& scene, RTCBuildQuality quality);
    void addMesh(const Object& object, uint32_t objectIndex, RTCBuildQuality quality);

    // Declaration order = reverse destruction order: the scene goes first,
    // then the table its callbacks point into, then the device.
    EmbreeDevice m_device;
    Vec3 m_origin;
    AnalyticTable m_analytic;
    EmbreeScene m_scene;
    unsigned m_userGeomId = RTC_INVALID_GEOMETRY_ID;
    std::vector<uint32_t> m_objectOfGeom;  ///< geomID -> object index
    /// geomID -> (Embree primID -> mesh triangle), empty where they coincide
    /// (zero-area triangles are left out of Embree's copy).
    std::vector<std::vector<uint32_t>> m_triangleOfPrim;
    double m_buildSeconds = 0;
};

}  // namespace raylab

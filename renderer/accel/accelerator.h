#pragma once
// One small interface over the ray-query back ends: Embree's BVH and the
// textbook loop over every object. Both answer from the same geometry/ math;
// the integrator cannot tell them apart except by speed.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "geometry/ray.h"
#include "renderer/accel/accel_options.h"
#include "renderer/accel/hit.h"
#include "renderer/scene.h"
#include "renderer/surface_filter.h"
#include "shading/color.h"

namespace raylab {

/// What an accelerator remembers about the occluders of earlier shadow rays,
/// for a similar one (the integrator's ShadowCache keeps them per receiver,
/// light and depth). Opaque: its meaning is the accelerator's own.
struct OcclusionHint {
    static constexpr uint32_t kNone = 0xffffffffu;
    /// Asked first; on return the occluder found, or kNone when none was
    /// (left as it was by an accelerator that takes no hint, and for
    /// filtered feelers through a surface filter).
    uint32_t primitive = kNone;
    /// Asked second, when it differs and `primitive` does not block.
    uint32_t fallback = kNone;
};

/// The object a spawned ray leaves, named when the ray cannot meet it again
/// (Shape::revisit): a query may then leave that object's test out, which
/// changes no answer; an accelerator may as well ignore it. kNone for camera
/// rays and for rays that could return.
struct Departure {
    static constexpr uint32_t kNone = 0xffffffffu;
    uint32_t object = kNone;
};

/// Each query has a short form without a Departure (camera rays, tests,
/// tools) that asks the virtual form with none; an implementation overrides
/// the virtual forms and keeps the short ones visible with
/// `using Accelerator::intersect;` (and occluded, transmittance).
class Accelerator {
public:
    virtual ~Accelerator() = default;
    /// Closest hit with tMin < t < tMax.
    std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, tMin, tMax, Departure{});
    }
    /// The same, for a ray that leaves `from`.
    virtual std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax,
                                         Departure from) const = 0;
    /// The most rays intersectPacket() takes at once.
    static constexpr int kPacketRays = 16;
    /// Whether intersectPacket() traces rays together, faster than one at a
    /// time: the integrator then asks rows of camera rays in packets. False
    /// by default (and for the ray recorder, which follows each ray tree in
    /// its depth-first order).
    virtual bool tracesPackets() const { return false; }
    /// intersect() of `count` (1..kPacketRays) rays at once: out[i] is
    /// exactly intersect(rays[i], tMin[i], tMax[i]). For coherent rays (a row
    /// of camera rays): Embree traces them as one packet; the default asks
    /// one at a time.
    virtual void intersectPacket(const Ray* rays, const double* tMin, const double* tMax,
                                 int count, std::optional<Hit>* out) const {
        for (int i = 0; i < count; ++i) out[i] = intersect(rays[i], tMin[i], tMax[i]);
    }
    /// Any hit with tMin < t < tMax (shadow feelers, opaque shadows).
    bool occluded(const Ray& ray, double tMin, double tMax) const {
        return occluded(ray, tMin, tMax, Departure{});
    }
    virtual bool occluded(const Ray& ray, double tMin, double tMax, Departure from) const = 0;
    /// occluded() with a hint: the accelerator may first ask the primitive the
    /// hint names, and names the occluder it finds in it. The answer is
    /// occluded()'s, whatever the hint holds. The default ignores the hint.
    bool occluded(const Ray& ray, double tMin, double tMax, OcclusionHint& hint) const {
        return occluded(ray, tMin, tMax, Departure{}, hint);
    }
    virtual bool occluded(const Ray& ray, double tMin, double tMax, Departure from,
                          OcclusionHint& hint) const {
        (void)hint;
        return occluded(ray, tMin, tMax, from);
    }
    /// Whether the hinted form of occluded() (`filtered` false) or of
    /// transmittance() (true) can use a hint on this scene: when not, the
    /// integrator keeps no shadow cache (its bookkeeping would be all cost).
    virtual bool usesOcclusionHints(bool filtered) const {
        (void)filtered;
        return false;
    }
    /// \brief What a shadow feeler carries from tMin to tMax (filtered shadows):
    ///   the product of the SurfaceFilter::transmission of every surface it
    ///   crosses, black at the first opaque one. Without transmitters in the
    ///   scene it is occluded() as black or white.
    Color transmittance(const Ray& ray, double tMin, double tMax) const {
        return transmittance(ray, tMin, tMax, Departure{});
    }
    virtual Color transmittance(const Ray& ray, double tMin, double tMax, Departure from) const = 0;
    /// transmittance() with a hint, as occluded() with one: the same answer
    /// whatever the hint holds. The default ignores the hint.
    Color transmittance(const Ray& ray, double tMin, double tMax, OcclusionHint& hint) const {
        return transmittance(ray, tMin, tMax, Departure{}, hint);
    }
    virtual Color transmittance(const Ray& ray, double tMin, double tMax, Departure from,
                                OcclusionHint& hint) const {
        (void)hint;
        return transmittance(ray, tMin, tMax, from);
    }
    /// \brief What `count` (1..kPacketRays) shadow feelers bring back, asked
    ///   together (the feelers of a packet's camera hits to one light): out[i]
    ///   is exactly transmittance(rays[i], tMin[i], tMax[i], from[i]) where
    ///   `filtered`, else occluded(...) as black (blocked) or white. `hints`
    ///   (may be null) are the feelers' hints, used as the hinted forms use
    ///   one: the answers are the same whatever they hold, and each comes back
    ///   naming an occluder of its feeler or none (a packet may find another
    ///   occluder than a single query would). For accelerators that trace
    ///   packets (tracesPackets); the default asks one feeler at a time.
    virtual void shadowPacket(const Ray* rays, const double* tMin, const double* tMax,
                              const Departure* from, int count, bool filtered, Color* out,
                              OcclusionHint* hints = nullptr) const {
        for (int i = 0; i < count; ++i) {
            if (filtered)
                out[i] = hints ? transmittance(rays[i], tMin[i], tMax[i], from[i], hints[i])
                               : transmittance(rays[i], tMin[i], tMax[i], from[i]);
            else
                out[i] = (hints ? occluded(rays[i], tMin[i], tMax[i], from[i], hints[i])
                                : occluded(rays[i], tMin[i], tMax[i], from[i]))
                             ? Color{}
                             : Color(1.0);
        }
    }
    /// "embree" or "naive".
    virtual std::string name() const = 0;
    /// Wall-clock seconds the constructor spent building the structure
    /// (Embree: geometry conversion and BVH, device creation excluded).
    virtual double buildSeconds() const = 0;
    /// Candidate hits the surface filter cut out or attenuated so far.
    virtual FilterCounts filterCounts() const = 0;
};

/// Builds the named accelerator ("embree" or "naive") over the scene, which
/// must outlive it; both honour the scene's SurfaceFilter (cut-outs,
/// transmitters). Throws std::invalid_argument for an unknown name and for
/// geometry the accelerator cannot take (validateShapes).
std::unique_ptr<Accelerator> makeAccelerator(const std::string& name, const Scene& scene,
                                             const AccelOptions& options = {});

/// \brief Every object's Shape::validate(), before an accelerator touches a
///   primitive. \throws std::invalid_argument "ACCEL: object 'NAME' (KIND): why".
void validateShapes(const Scene& scene, const char* accelName);

}  // namespace raylab

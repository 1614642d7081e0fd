#pragma once
// One small interface over the ray-query back ends: Embree's BVH and the
// textbook loop over every object. Both answer from the same geometry/ math;
// the integrator cannot tell them apart except by speed.

#include <memory>
#include <optional>
#include <string>

#include "geometry/ray.h"
#include "geometry/vec.h"
#include "renderer/scene.h"

namespace raylab {

/// Build options; only the Embree back end reads the BVH ones.
struct AccelOptions {
    enum class BvhQuality { Low, Medium, High };
    BvhQuality quality = BvhQuality::Medium;
    bool robust = false;   ///< RTC_SCENE_FLAG_ROBUST
    /// Geometry is handed to Embree in float relative to this point (normally
    /// the eye), so far-from-origin scenes keep their precision near the camera.
    Vec3 origin{0, 0, 0};
};

/// "low", "medium" or "high": the spelling of --bvh-quality and the JSON key.
inline const char* bvhQualityName(AccelOptions::BvhQuality q) {
    switch (q) {
        case AccelOptions::BvhQuality::Low:
            return "low";
        case AccelOptions::BvhQuality::High:
            return "high";
        default:
            return "medium";
    }
}

class Accelerator {
public:
    virtual ~Accelerator() = default;
    /// Closest hit with tMin < t < tMax.
    virtual std::optional<Hit> intersect(const Ray& ray, double tMin, double tMax) const = 0;
    /// Any hit with tMin < t < tMax (shadow feelers).
    virtual bool occluded(const Ray& ray, double tMin, double tMax) const = 0;
    /// "embree" or "naive".
    virtual std::string name() const = 0;
};

/// Builds the named accelerator ("embree" or "naive") over the scene, which
/// must outlive it. Throws std::invalid_argument for an unknown name.
std::unique_ptr<Accelerator> makeAccelerator(const std::string& name, const Scene& scene,
                                             const AccelOptions& options = {});

}  // namespace raylab

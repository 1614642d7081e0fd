#pragma once
// Shapes that declare native triangles (Shape::nativeTriangles()) become one
// Embree RTC_GEOMETRY_TYPE_TRIANGLE each: vertices in float relative to the
// accelerator's origin (the eye), zero-area float triangles left out, and
// one-sided meshes culled by filter functions. Internal to renderer/accel.

#include <embree3/rtcore.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "renderer/accel/embree_device.h"

namespace raylab {

struct EmbreeTriangleGeometry {
    unsigned geomId = RTC_INVALID_GEOMETRY_ID;
    /// Embree primID -> mesh triangle, empty where they coincide (zero-area
    /// triangles are left out of Embree's copy).
    std::vector<uint32_t> triangleOfPrim;
};

/// \brief Uploads `mesh` (validated) and attaches it to `scene`.
/// \return nothing when no triangle has area in float.
/// \throws std::invalid_argument "vertex I is not finite or too far from the
///   origin" (the caller names the object).
std::optional<EmbreeTriangleGeometry> attachTriangles(const EmbreeDevice& device, RTCScene scene,
                                                      const TriangleMesh& mesh, const Vec3& origin,
                                                      RTCBuildQuality quality);

}  // namespace raylab

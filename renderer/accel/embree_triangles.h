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
#include "renderer/accel/embree_user_geometry.h"

namespace raylab {

/// One uploaded mesh; also the user data of its filter functions, so it
/// must stay at one address while the Embree scene lives.
struct EmbreeTriangleGeometry {
    unsigned geomId = RTC_INVALID_GEOMETRY_ID;
    uint32_t object = 0;    ///< index into Scene::objects
    Sidedness sides = Sidedness::Both;
    bool filtered = false;  ///< the surface filter decides about its candidates
    bool cutsOut = false;   ///< ... in every query, not only in filtered shadows
    Vec3 origin;            ///< to rebuild world rays from Embree's float lanes
    /// Embree primID -> mesh triangle, empty where they coincide (zero-area
    /// triangles are left out of Embree's copy).
    std::vector<uint32_t> triangleOfPrim;

    uint32_t triangle(unsigned primID) const {
        return triangleOfPrim.empty() ? primID : triangleOfPrim[primID];
    }
};

/// \brief Uploads `mesh` (validated) and attaches it to `scene`, filling
///   `out` (geomId stays invalid when no triangle has area in float). One-sided
///   meshes get culling filter functions, filtered ones (out.filtered) the
///   surface filter's as well.
/// \throws std::invalid_argument "vertex I is not finite or too far from the
///   origin" (the caller names the object).
void attachTriangles(const EmbreeDevice& device, RTCScene scene, const TriangleMesh& mesh,
                     RTCBuildQuality quality, EmbreeTriangleGeometry& out);

}  // namespace raylab

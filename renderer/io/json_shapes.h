#pragma once
// The analytic shapes of the JSON scene format (sphere, plane, disk, cylinder,
// cone, quadric, polygon): their keys and how their fields become a Shape.
// Materials, names and sidedness are the scene reader's business.

#include <memory>
#include <string>
#include <vector>

#include "geometry/shape.h"
#include "renderer/io/json_fields.h"

namespace raylab {

/// The keys an object of analytic shape `type` takes besides "type", "name",
/// "material" and "sides"; null when `type` is not an analytic shape.
const std::vector<std::string>* analyticShapeKeys(const std::string& type);

/// Reads the analytic shape of `type` (one analyticShapeKeys knows) from its
/// object's fields. A polygon with "triangulate": true comes back as a
/// TriangleMesh of its ear-clipped triangles.
std::unique_ptr<Shape> readAnalyticShape(const JsonFieldReader& in, const JsonFields& f,
                                         const std::string& type);

}  // namespace raylab

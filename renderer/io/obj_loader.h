#pragma once
// Wavefront OBJ files (and the MTL libraries they name) as triangle meshes and
// Whitted materials. The MTL -> Material policy is in mtl_material.h.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/transform.h"
#include "geometry/triangle_mesh.h"
#include "geometry/vec.h"
#include "shading/material.h"

namespace raylab {

struct Scene;

/// One triangle mesh cut from an OBJ file. An OBJ file gives at most two
/// parts: faces with vertex normals on all corners (smooth shading) and faces
/// without (flat shading), because TriangleMesh normals are all-or-nothing.
struct ObjMeshPart {
    std::string name;
    std::shared_ptr<TriangleMesh> mesh;
    std::vector<uint32_t> faceMaterials;  ///< per triangle, index into ObjModel::materials
};

struct ObjModel {
    std::vector<ObjMeshPart> parts;
    /// MTL materials in file order, plus a grey "default" material at the end
    /// when some face has none (kd = ka = 0.8, no highlight).
    std::vector<Material> materials;
    std::vector<std::string> warnings;  ///< tinyobjloader's and ours, deduplicated
    size_t triangleCount() const;
};

struct ObjLoadOptions {
    Transform transform;        ///< applied to positions (and normals) on load
    bool printWarnings = true;  ///< print each warning as "raylab: warning: FILE: ..." to stderr
};

/// Reads an OBJ file (and the MTL libraries it names, relative to the OBJ's
/// folder). Polygons are triangulated by tinyobjloader; degenerate triangles
/// are dropped with a warning. Throws InputError(file, line, message) for a
/// missing OBJ, syntax errors tinyobjloader reports, face indices out of
/// range (with the face's line), non-finite vertices, and an OBJ without
/// triangles. A missing MTL or unknown material name is only a warning.
ObjModel loadObj(const std::string& path, const ObjLoadOptions& options = {});

/// Appends the model's materials and one Object per part to `scene`. With
/// `overrideMaterial` (an index into scene.materials) the OBJ materials are
/// not added and every face uses that material. Object names are
/// `baseName`, or `baseName` + " (flat)" for the flat part when both exist.
void appendObjModel(Scene& scene, const ObjModel& model, const std::string& baseName,
                    std::optional<uint32_t> overrideMaterial = std::nullopt);

}  // namespace raylab

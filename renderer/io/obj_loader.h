#pragma once
// Wavefront OBJ/MTL reading through tinyobjloader, into triangle meshes and
// Whitted materials.
//
// MTL -> Material mapping (MTL illumination models, Wavefront's MTL spec):
//   ka = Ka, kd = Kd, ks = Ks, shininess = Ns, ior = Ni (1 when Ni <= 0).
//   illum 0     colour only: ka = 0, ks = 0
//   illum 1     diffuse only: ks = 0
//   illum 2     diffuse + Blinn-Phong highlight
//   illum 3..7  "reflection: ray trace on": also mirror km = Ks
//   illum 4,6,7 transparency/refraction: kt = Tf when Tf is given and not
//               black, else kt = 1 - d (d = dissolve; "Tr t" means d = 1 - t)
//   other illum values are read as illum 2. Textures are ignored (warning).

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "geometry/vec.h"
#include "shading/material.h"

namespace raylab {

struct Scene;

/// Affine map p -> linear * p + translation, applied to mesh vertices on load.
struct MeshTransform {
    std::array<std::array<double, 3>, 3> linear{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    Vec3 translation{0, 0, 0};

    static MeshTransform translate(const Vec3& offset);
    static MeshTransform scale(const Vec3& factors);
    /// Right-handed rotation by `degrees` about `axis` (any non-zero length):
    /// counter-clockwise when the axis points at the viewer (Rodrigues' formula).
    static MeshTransform rotate(const Vec3& axis, double degrees);

    /// The composition "first this, then `next`" (next ∘ this).
    MeshTransform then(const MeshTransform& next) const;

    Vec3 applyPoint(const Vec3& p) const;
    /// Normals transform with the inverse transpose of `linear`; the result is unit length.
    Vec3 applyNormal(const Vec3& n) const;
    double determinant() const;
    bool isIdentity() const;
};

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
    MeshTransform transform;    ///< applied to positions (and normals) on load
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

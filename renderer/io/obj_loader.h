#pragma once
// Wavefront OBJ files (and the MTL libraries they name) as triangle meshes and
// Whitted materials. The stages, each in its own file: obj_parser (text into
// arrays), obj_materials + mtl_reader + mtl_material (libraries into
// materials), and obj_loader.cpp (faces into meshes: triangulation, smoothing
// groups, vertex colours, the transform).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/transform.h"
#include "geometry/triangle_mesh.h"
#include "renderer/io/mtl_reader.h"
#include "renderer/io/texture_library.h"
#include "shading/material.h"
#include "shading/texture.h"

namespace raylab {

struct Scene;

/// One triangle mesh cut from an OBJ file. An OBJ file gives at most two
/// parts: faces with vertex normals (the file's, or averaged within their
/// smoothing group) and faces without (flat shading), because TriangleMesh
/// normals are all-or-nothing.
struct ObjMeshPart {
    std::string name;
    std::shared_ptr<TriangleMesh> mesh;
    std::vector<uint32_t> faceMaterials;  ///< per triangle, index into ObjModel::materials
};

/// What one load read, for checks that it stays linear (each line once).
struct ObjLoadCounts {
    int objLines = 0;       ///< lines of the OBJ read
    int mtlLibraries = 0;   ///< MTL files read
    int mtlLines = 0;       ///< their lines read
};

struct ObjModel {
    std::vector<ObjMeshPart> parts;
    /// MTL materials in the order the libraries define them, plus a grey
    /// "default" material at the end when some face has none (kd = ka = 0.8).
    std::vector<Material> materials;
    /// What the MTL statements of materials[i] said (the default has none):
    /// texture maps and their files, for image textures.
    std::vector<MtlMaterial> mtlStatements;
    /// The textures of the MTL maps (map_Kd, bump, ...); materials' maps index this list.
    std::vector<Texture> textures;
    std::vector<std::string> warnings;  ///< each once, repeats counted
    ObjLoadCounts counts;
    size_t triangleCount() const;
};

/// Where a mesh's shading normals come from.
enum class ObjNormals {
    File,    ///< the file's vn where every corner of a face has one, else smoothing groups (s)
    Flat,    ///< none: every face flat
    Smooth,  ///< the file's vn, else averaged over all faces as one smoothing group
};

struct ObjLoadOptions {
    Transform transform;        ///< applied to positions (and normals) on load
    ObjNormals normals = ObjNormals::File;
    bool printWarnings = true;  ///< print each warning as "raylab: warning: FILE: ..." to stderr
    /// Where texture files are read and shared (a scene's); null: the load's own.
    TextureLibrary* textureFiles = nullptr;
};

/// Reads an OBJ file (and the MTL libraries it names, relative to the OBJ's
/// folder). Faces are triangulated by triangulateFace (convex quads along the
/// shorter diagonal, the rest by ear clipping); zero-area faces are dropped
/// with a warning at their line. Throws InputError(file, line, message) for a
/// missing or unreadable OBJ, a statement it cannot read (obj_parser.h), a
/// broken MTL (at the MTL's line), a transform that puts vertices beyond float
/// range, and an OBJ without faces or triangles. A missing MTL or an unknown
/// material name is only a warning.
ObjModel loadObj(const std::string& path, const ObjLoadOptions& options = {});

/// Appends the model's materials (their textures too, map indices offset
/// past the scene's) and one Object per part to `scene`. With
/// `overrideMaterial` (an index into scene.materials) the OBJ materials are
/// not added and every face uses that material. Object names are
/// `baseName`, or `baseName` + " (flat)" for the flat part when both exist.
void appendObjModel(Scene& scene, const ObjModel& model, const std::string& baseName,
                    std::optional<uint32_t> overrideMaterial = std::nullopt);

}  // namespace raylab

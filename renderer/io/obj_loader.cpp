// OBJ files into triangle meshes: tinyobjloader parses (after obj_scan's
// checks), mtl_reader and mtl_material turn the MTL libraries into materials,
// and this file builds the meshes, one smooth and one flat part.

#include "renderer/io/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <unordered_map>

#include "renderer/io/errors.h"
#include "renderer/io/load_warnings.h"
#include "renderer/io/loading_file.h"
#include "renderer/io/mtl_material.h"
#include "renderer/io/mtl_reader.h"
#include "renderer/io/obj_scan.h"
#include "renderer/io/text_file.h"
#include "renderer/io/tinyobj_messages.h"
#include "renderer/scene.h"

namespace raylab {

size_t ObjModel::triangleCount() const {
    size_t n = 0;
    for (const ObjMeshPart& p : parts) n += p.mesh->triangleCount();
    return n;
}

namespace {

/// Builds one mesh part, sharing vertices between triangles that use the same
/// (position, normal) index pair.
struct PartBuilder {
    ObjMeshPart part;
    std::unordered_map<uint64_t, uint32_t> vertexOf;
    bool smooth = false;

    uint32_t vertex(int v, int vn, const tinyobj::attrib_t& a, const Transform& xf) {
        const uint64_t key = (uint64_t(uint32_t(v)) << 32) | uint32_t(smooth ? vn + 1 : 0);
        const auto [it, inserted] = vertexOf.emplace(key, uint32_t(part.mesh->positions.size()));
        if (inserted) {
            const auto& p = a.vertices;
            part.mesh->positions.push_back(
                xf.point(Vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2])));
            if (smooth) {
                const auto& n = a.normals;
                part.mesh->normals.push_back(
                    xf.normal(Vec3(n[3 * vn], n[3 * vn + 1], n[3 * vn + 2])));
            }
        }
        return it->second;
    }
};

}  // namespace

ObjModel loadObj(const std::string& path, const ObjLoadOptions& options) {
    const LoadingFile loading(path);  // names this file if the parse runs out of memory
    const std::string text = readTextFile(path);
    // tinyobjloader reads a NUL as the end of a line and UTF-16 as no statements.
    if (const auto [line, message] = findNonText(text, "OBJ"); line > 0)
        throw InputError(path, line, message);
    // tinyobjloader only warns about bad indices (reporting the file's last
    // line) and may read out of bounds first; check them here with the real line.
    if (const auto [line, message] = findBadFaceIndex(text); line > 0)
        throw InputError(path, line, message);
    if (const auto [line, message] = findBadNumber(text, {{"v", 3}, {"vn", 3}, {"vt", 1}}, true);
        line > 0)
        throw InputError(path, line, message);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> mtls;
    std::string warnText, errText;
    std::istringstream stream(text);
    // MTL libraries are looked up beside the OBJ ("" = current directory).
    MtlLibraryReader mtlReader(path);
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &mtls, &warnText, &errText, &stream,
                                     &mtlReader, /*triangulate=*/true,
                                     /*default_vcols_fallback=*/false);
    LoadWarnings warn(path);
    const std::vector<std::string> errors = splitMessages(errText);
    if (!ok) {
        const std::string first = errors.empty() ? "cannot parse the OBJ file" : errors.front();
        const auto [line, message] = splitLineReference(first);
        throw InputError(path, line, message);
    }
    for (const std::string& e : errors) warn.add(e);

    const size_t vertexCount = attrib.vertices.size() / 3;
    const size_t normalCount = attrib.normals.size() / 3;

    // findBadFaceIndex checked the text already; this guards against our scan
    // and tinyobjloader's parser disagreeing, never against a crash.
    for (const auto& sh : shapes)
        for (const auto& idx : sh.mesh.indices)
            if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= vertexCount ||
                idx.normal_index < -1 ||
                (idx.normal_index >= 0 && size_t(idx.normal_index) >= normalCount))
                throw InputError(path, 0, "face index out of range");
    addTinyObjWarnings(splitMessages(warnText), text, warn);

    for (size_t i = 0; i < vertexCount; ++i)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(attrib.vertices[3 * i + k]))
                throw InputError(path, lineOfStatement(text, "v", i),
                                 "vertex " + std::to_string(i + 1) + " is not finite");

    ObjModel model;
    for (const MtlLibraryReader::Warning& w : mtlReader.warnings())
        warn.add(w.message, w.line, w.path);
    for (size_t i = 0; i < mtls.size(); ++i)
        model.materials.push_back(materialFromMtl(mtls[i], i, mtlReader, warn));
    const uint32_t mtlCount = uint32_t(model.materials.size());
    bool needDefault = false;

    PartBuilder smooth, flat;
    smooth.smooth = true;
    smooth.part.mesh = std::make_shared<TriangleMesh>();
    flat.part.mesh = std::make_shared<TriangleMesh>();
    const Transform& xf = options.transform;
    const bool mirrored = xf.flipsHandedness();
    size_t degenerate = 0;

    auto validNormal = [&](int vn) {
        if (vn < 0) return false;
        const Vec3 n(attrib.normals[3 * vn], attrib.normals[3 * vn + 1],
                     attrib.normals[3 * vn + 2]);
        return isFinite(n) && lengthSquared(n) > 0;
    };

    for (const tinyobj::shape_t& s : shapes) {
        size_t offset = 0;
        for (size_t f = 0; f < s.mesh.num_face_vertices.size(); ++f) {
            const size_t n = s.mesh.num_face_vertices[f];
            const int mid = f < s.mesh.material_ids.size() ? s.mesh.material_ids[f] : -1;
            uint32_t material = mtlCount;  // the default material, appended below
            if (mid >= 0 && uint32_t(mid) < mtlCount)
                material = uint32_t(mid);
            else
                needDefault = true;
            // tinyobjloader triangulates; fan anything it left as a polygon.
            for (size_t k = 1; k + 1 < n; ++k) {
                const tinyobj::index_t c[3] = {s.mesh.indices[offset], s.mesh.indices[offset + k],
                                               s.mesh.indices[offset + k + 1]};
                const bool hasNormals = validNormal(c[0].normal_index) &&
                                        validNormal(c[1].normal_index) &&
                                        validNormal(c[2].normal_index);
                PartBuilder& b = hasNormals ? smooth : flat;
                std::array<uint32_t, 3> tri;
                for (int j = 0; j < 3; ++j)
                    tri[j] = b.vertex(c[j].vertex_index, c[j].normal_index, attrib, xf);
                // A mirroring transform reverses the winding; swap to keep the front side.
                if (mirrored) std::swap(tri[1], tri[2]);
                const auto& P = b.part.mesh->positions;
                const Vec3 area = cross(P[tri[1]] - P[tri[0]], P[tri[2]] - P[tri[0]]);
                // Zero-area triangles have no normal; Embree would never report them.
                if (!(lengthSquared(area) > 0) || !isFinite(area)) {
                    ++degenerate;
                    continue;
                }
                b.part.mesh->triangles.push_back(tri);
                b.part.faceMaterials.push_back(material);
            }
            offset += n;
        }
    }
    if (degenerate > 0)
        warn.add("dropped " + std::to_string(degenerate) + " degenerate (zero-area) triangle" +
                 (degenerate > 1 ? "s" : ""));
    if (needDefault) {
        // Grey, lit by the ambient term too, so a bare OBJ is readable.
        Material def;
        def.name = "default";
        def.ka = def.kd;
        model.materials.push_back(def);
    }
    for (PartBuilder* b : {&smooth, &flat})
        if (b->part.mesh->triangleCount() > 0) model.parts.push_back(std::move(b->part));
    if (model.parts.empty()) {
        if (const int firstFace = lineOfStatement(text, "f", 0))
            throw InputError(path, firstFace,
                             xf.isIdentity()
                                 ? "the OBJ file has no triangles: every face has zero area or "
                                   "fewer than 3 corners"
                                 : "no triangles left: every face has zero area or fewer than 3 "
                                   "corners once the scene's transform (scale, rotate) is "
                                   "applied");
        throw InputError(path, 0, "the OBJ file has no faces");
    }

    model.warnings = warn.lines();
    if (options.printWarnings)
        for (const std::string& w : model.warnings)
            std::fprintf(stderr, "raylab: warning: %s\n", terminalSafe(w).c_str());
    return model;
}

void appendObjModel(Scene& scene, const ObjModel& model, const std::string& baseName,
                    std::optional<uint32_t> overrideMaterial) {
    const uint32_t firstMaterial = uint32_t(scene.materials.size());
    if (!overrideMaterial) {
        for (const Material& m : model.materials) {
            scene.materials.push_back(m);
            scene.materials.back().name = baseName + "/" + m.name;
        }
    }
    for (size_t i = 0; i < model.parts.size(); ++i) {
        const ObjMeshPart& part = model.parts[i];
        Object obj;
        obj.name = baseName;
        if (model.parts.size() > 1 && !part.mesh->hasNormals()) obj.name += " (flat)";
        obj.shape = part.mesh;
        if (overrideMaterial) {
            obj.material = *overrideMaterial;
        } else {
            // One material for the whole part needs no per-face table.
            bool uniform = true;
            for (uint32_t m : part.faceMaterials) uniform = uniform && m == part.faceMaterials[0];
            obj.material = firstMaterial + part.faceMaterials[0];
            if (!uniform)
                for (uint32_t m : part.faceMaterials)
                    obj.faceMaterials.push_back(firstMaterial + m);
        }
        scene.objects.push_back(std::move(obj));
    }
}

}  // namespace raylab

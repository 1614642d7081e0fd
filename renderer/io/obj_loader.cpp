// OBJ faces into triangle meshes: each face triangulated on its own plane,
// vertices shared between faces that agree on position, texture coordinate
// and normal, normals from the file or averaged within smoothing groups, the
// scene's transform applied, zero-area faces dropped with a warning.

#include "renderer/io/obj_loader.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "geometry/validate.h"
#include "renderer/io/errors.h"
#include "renderer/io/load_warnings.h"
#include "renderer/io/loading_file.h"
#include "renderer/io/obj_materials.h"
#include "renderer/io/mtl_textures.h"
#include "renderer/io/obj_parser.h"
#include "renderer/io/text_file.h"
#include "renderer/io/wavefront_text.h"
#include "renderer/scene.h"

namespace raylab {

size_t ObjModel::triangleCount() const {
    size_t n = 0;
    for (const ObjMeshPart& p : parts) n += p.mesh->triangleCount();
    return n;
}

namespace {

/// Where a corner's shading normal comes from: none (flat), the file's vn,
/// or the average over a smoothing group (computed once all faces are in).
struct NormalSource {
    enum Kind { Flat, File, Group } kind = Flat;
    uint64_t id = 0;  ///< vn index (File) or smoothing group (Group)
};

/// A mesh vertex: position, texture coordinate and normal source together.
struct VertexKey {
    uint32_t v;
    int32_t vt;
    NormalSource::Kind kind;
    uint64_t id;  ///< vn index for File, the group for Group, 0 for Flat
    bool operator==(const VertexKey& o) const {
        return v == o.v && vt == o.vt && kind == o.kind && id == o.id;
    }
};

struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        uint64_t h = (uint64_t(k.v) << 32) ^ uint64_t(uint32_t(k.vt));
        h ^= (k.id + uint64_t(k.kind) * 0x9E3779B97F4A7C15ull) * 0xBF58476D1CE4E5B9ull;
        return size_t(h ^ (h >> 31));
    }
};

/// The interior angle of triangle (a, b, c) at a.
double cornerAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e1 = normalize(b - a), e2 = normalize(c - a);
    return std::atan2(length(cross(e1, e2)), dot(e1, e2));
}

/// One mesh part: its vertices shared by VertexKey, and for smoothing groups
/// the angle-weighted sum of face normals per (position, group).
class PartBuilder {
public:
    PartBuilder() : m_part{"", std::make_shared<TriangleMesh>(), {}} {}

    uint32_t vertex(const ObjCorner& c, const NormalSource& n, const std::vector<Vec3>& world,
                    const ObjData& data, const Transform& xf) {
        const VertexKey key{c.v, c.vt, n.kind, n.id};
        const auto [it, added] = m_vertexOf.emplace(key, uint32_t(mesh().positions.size()));
        if (!added) return it->second;
        TriangleMesh& m = mesh();
        m.positions.push_back(world[c.v]);
        if (!data.colors.empty()) {
            const Vec3f& col = data.colors[c.v];
            m.colors.push_back(Vec3(col.x, col.y, col.z));
        }
        if (c.vt >= 0) {
            const Vec2f& t = data.texcoords[size_t(c.vt)];
            m.uvs.push_back(Vec2(t.x, t.y));
        } else {
            m.uvs.push_back(Vec2(0, 0));
            m_allUvs = false;
        }
        if (n.kind == NormalSource::File) {
            const Vec3f& f = data.normals[n.id];
            m.normals.push_back(xf.normal(Vec3(f.x, f.y, f.z)));
            m_sumOf.push_back(kNone);
        } else if (n.kind == NormalSource::Group) {
            // One sum per position and group, shared by vertices that differ
            // only in their texture coordinate (a UV seam is not a crease).
            const auto [s, fresh] =
                m_groupSum.emplace((uint64_t(c.v) << 32) ^ n.id * 0x9E3779B97F4A7C15ull,
                                   uint32_t(m_sums.size()));
            if (fresh) m_sums.emplace_back();
            m.normals.push_back(Vec3{});
            m_sumOf.push_back(s->second);
        } else {
            m_sumOf.push_back(kNone);
        }
        return it->second;
    }

    /// Adds a triangle (already checked for area) with its material; a
    /// smoothing-group triangle adds its normal, weighted by its angle at
    /// each corner, to the corners' sums.
    void triangle(const std::array<uint32_t, 3>& t, uint32_t material) {
        TriangleMesh& m = mesh();
        m.triangles.push_back(t);
        m_part.faceMaterials.push_back(material);
        if (m_sumOf[t[0]] == kNone) return;
        const Vec3& p0 = m.positions[t[0]];
        const Vec3& p1 = m.positions[t[1]];
        const Vec3& p2 = m.positions[t[2]];
        const Vec3 n = normalize(cross(p1 - p0, p2 - p0));
        const double angle[3] = {cornerAngle(p0, p1, p2), cornerAngle(p1, p2, p0),
                                 cornerAngle(p2, p0, p1)};
        for (int k = 0; k < 3; ++k) {
            Sum& s = m_sums[m_sumOf[t[size_t(k)]]];
            s.normal += n * angle[k];
            if (!s.first) s.first = n;
        }
    }

    /// The finished part: smoothing-group normals normalised (a sum that
    /// cancels takes its first face's normal), texture coordinates kept only
    /// when every corner had one.
    ObjMeshPart finish() {
        TriangleMesh& m = mesh();
        for (size_t i = 0; i < m_sumOf.size(); ++i) {
            if (m_sumOf[i] == kNone) continue;
            const Sum& s = m_sums[m_sumOf[i]];
            const Vec3 n = normalize(s.normal);
            m.normals[i] = isFinite(n) && lengthSquared(n) > 0 ? n : s.first.value_or(Vec3{});
        }
        if (!m_allUvs) m.uvs.clear();
        return std::move(m_part);
    }

    bool empty() const { return m_part.mesh->triangles.empty(); }
    const Vec3& position(uint32_t i) const { return m_part.mesh->positions[i]; }

private:
    static constexpr uint32_t kNone = UINT32_MAX;
    struct Sum {
        Vec3 normal{};
        std::optional<Vec3> first;
    };
    TriangleMesh& mesh() { return *m_part.mesh; }

    ObjMeshPart m_part;
    std::unordered_map<VertexKey, uint32_t, VertexKeyHash> m_vertexOf;
    bool m_allUvs = true;
    std::vector<uint32_t> m_sumOf;  ///< per vertex: its smoothing sum, or kNone
    std::vector<Sum> m_sums;
    std::unordered_map<uint64_t, uint32_t> m_groupSum;
};

/// Line of the `index`-th (0-based) `v` statement: error messages only.
int lineOfVertex(const std::string& text, size_t index) {
    StatementReader reader(text);
    size_t seen = 0;
    while (const auto s = reader.next())
        if (s->keyword == "v" && seen++ == index) return s->line;
    return 0;
}

/// The positions with the transform applied; beyond float they could not be
/// traced (and their areas would overflow into "zero-area" faces).
std::vector<Vec3> worldPositions(const ObjData& data, const Transform& xf,
                                 const std::string& path, const std::string& text) {
    std::vector<Vec3> world;
    world.reserve(data.positions.size());
    const double limit = double(std::numeric_limits<float>::max());
    for (size_t i = 0; i < data.positions.size(); ++i) {
        const Vec3f& p = data.positions[i];
        const Vec3 w = xf.point(Vec3(p.x, p.y, p.z));
        if (!isFinite(w) || maxComponent(abs(w)) > limit)
            throw InputError(path, lineOfVertex(text, i),
                             "the mesh's transform (scale, rotate, translate) moves vertex " +
                                 std::to_string(i + 1) + " to " + formatValue(w) +
                                 ", beyond float range (about 3.4e38)");
        world.push_back(w);
    }
    return world;
}

class MeshBuilder {
public:
    MeshBuilder(const ObjData& data, const ObjMaterials& mats, const ObjLoadOptions& options,
                std::vector<Vec3> world, LoadWarnings& warn)
        : m_data(data), m_mats(mats), m_options(options), m_world(std::move(world)),
          m_warn(warn) {}

    void build() {
        for (const ObjFace& f : m_data.faces) face(f);
    }

    bool usesDefaultMaterial() const { return m_needDefault; }
    std::vector<ObjMeshPart> parts() {
        std::vector<ObjMeshPart> out;
        for (PartBuilder* b : {&m_smooth, &m_flat})
            if (!b->empty()) out.push_back(b->finish());
        return out;
    }

private:
    const ObjCorner& corner(const ObjFace& f, size_t k) const {
        return m_data.corners[f.firstCorner + k];
    }

    bool validNormal(int32_t vn) const {
        if (vn < 0) return false;
        const Vec3f& n = m_data.normals[size_t(vn)];
        return std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z) &&
               (n.x != 0 || n.y != 0 || n.z != 0);
    }

    /// The file's normals when every corner has a usable one (`vn wins`),
    /// else the face's smoothing group, else flat. For File the id is set per corner.
    NormalSource normalSource(const ObjFace& f) const {
        if (m_options.normals == ObjNormals::Flat) return {};
        bool file = true;
        for (size_t i = 0; i < f.cornerCount && file; ++i) file = validNormal(corner(f, i).vn);
        if (file) return {NormalSource::File, 0};
        // Smooth: all faces one group, apart from every `s` group number.
        const uint64_t group =
            m_options.normals == ObjNormals::Smooth ? uint64_t(1) << 32 : f.smoothingGroup;
        if (group == 0) return {};
        return {NormalSource::Group, group};
    }

    uint32_t material(const ObjFace& f) {
        const uint32_t m =
            f.material == kNoObjMaterial ? kNoObjMaterial : m_mats.byName[f.material];
        if (m != kNoObjMaterial) return m;
        m_needDefault = true;
        return uint32_t(m_mats.materials.size());  // the default, appended after the MTL ones
    }

    void face(const ObjFace& f) {
        if (f.cornerCount < 3) {
            m_warn.add("face with fewer than 3 corners dropped", f.line, "", "dropped faces");
            return;
        }
        m_corners.clear();
        for (size_t k = 0; k < f.cornerCount; ++k) {
            const Vec3f& p = m_data.positions[corner(f, k).v];
            m_corners.push_back(Vec3(p.x, p.y, p.z));
        }
        std::vector<std::array<uint32_t, 3>> triangles;
        try {
            // On the file's coordinates: an affine transform changes no ear.
            triangles = triangulateFace(m_corners);
        } catch (const std::invalid_argument&) {
            // Collinear or repeated corners, or a crossing outline with no net area.
            m_warn.add("face encloses no area (collinear or repeated corners, or a crossing "
                       "outline whose parts cancel); dropped",
                       f.line, "", "dropped faces");
            return;
        }
        if (f.cornerCount > 3) checkCoverage(f, triangles);

        const NormalSource normals = normalSource(f);
        PartBuilder& part = normals.kind == NormalSource::Flat ? m_flat : m_smooth;
        const uint32_t mat = material(f);
        const bool mirrored = m_options.transform.flipsHandedness();
        size_t kept = 0;
        for (const auto& t : triangles) {
            std::array<uint32_t, 3> tri;
            for (size_t j = 0; j < 3; ++j) {
                const ObjCorner& c = corner(f, t[j]);
                NormalSource n = normals;
                if (n.kind == NormalSource::File) n.id = uint64_t(c.vn);
                tri[j] = part.vertex(c, n, m_world, m_data, m_options.transform);
            }
            // A mirroring transform reverses the winding; swap to keep the front side.
            if (mirrored) std::swap(tri[1], tri[2]);
            const Vec3 area = cross(part.position(tri[1]) - part.position(tri[0]),
                                    part.position(tri[2]) - part.position(tri[0]));
            // Zero-area triangles have no normal; Embree would never report them.
            if (!(lengthSquared(area) > 0) || !isFinite(area)) continue;
            part.triangle(tri, mat);
            ++kept;
        }
        if (kept == 0)
            m_warn.add("face has zero area; dropped", f.line, "", "dropped faces");
    }

    /// A face whose triangles cover more than its own area crosses itself (or
    /// is strongly warped): its triangulation can only approximate it.
    void checkCoverage(const ObjFace& f, const std::vector<std::array<uint32_t, 3>>& triangles) {
        const Vec3 n = newellNormal(m_corners);
        const Vec3 unit = normalize(n);
        double covered = 0;
        for (const auto& t : triangles)
            covered += std::abs(dot(unit, cross(m_corners[t[1]] - m_corners[t[0]],
                                                m_corners[t[2]] - m_corners[t[0]])));
        if (covered > length(n) * (1 + 1e-6))
            m_warn.add("face crosses itself: its triangles cover more than its area", f.line, "",
                       "self-intersecting faces");
    }

    const ObjData& m_data;
    const ObjMaterials& m_mats;
    const ObjLoadOptions& m_options;
    std::vector<Vec3> m_world;
    LoadWarnings& m_warn;
    PartBuilder m_smooth, m_flat;
    std::vector<Vec3> m_corners;  ///< the current face's corners (reused)
    bool m_needDefault = false;
};

}  // namespace

ObjModel loadObj(const std::string& path, const ObjLoadOptions& options) {
    const LoadingFile loading(path);  // names this file if the parse runs out of memory
    const std::string text = readTextFile(path);
    if (const auto [line, message] = findNonText(text, "OBJ"); line > 0)
        throw InputError(path, line, message);
    LoadWarnings warn(path);
    const ObjData data = parseObj(text, path, warn);
    if (data.faces.empty()) throw InputError(path, 0, "the OBJ file has no faces");
    ObjMaterials mats = loadObjMaterials(data, path, warn);

    MeshBuilder builder(data, mats, options, worldPositions(data, options.transform, path, text),
                        warn);
    builder.build();
    ObjModel model;
    model.parts = builder.parts();
    if (model.parts.empty())
        throw InputError(path, data.faces.front().line,
                         options.transform.isIdentity()
                             ? "the OBJ file has no triangles: every face has zero area or "
                               "fewer than 3 corners"
                             : "no triangles left: every face has zero area or fewer than 3 "
                               "corners once the scene's transform (scale, rotate) is applied");
    model.materials = std::move(mats.materials);
    model.mtlStatements = std::move(mats.statements);
    // Texture maps (issue 18): read after the materials, so a library's
    // warnings come in statement order per material.
    TextureLibrary ownTextureFiles;
    TextureLibrary& textureFiles = options.textureFiles ? *options.textureFiles : ownTextureFiles;
    for (size_t i = 0; i < model.mtlStatements.size(); ++i)
        applyMtlTextures(model.mtlStatements[i], model.materials[i], model.textures, textureFiles,
                         warn);
    if (builder.usesDefaultMaterial()) {
        // Grey, lit by the ambient term too, so a bare OBJ is readable.
        Material def;
        def.name = "default";
        def.ka = def.kd;
        model.materials.push_back(def);
    }
    model.counts = {data.linesRead, mats.librariesRead, mats.mtlLinesRead};
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
        const uint32_t firstTexture = uint32_t(scene.textures.size());
        scene.textures.insert(scene.textures.end(), model.textures.begin(), model.textures.end());
        for (const Material& m : model.materials) {
            scene.materials.push_back(m);
            Material& added = scene.materials.back();
            added.name = baseName + "/" + m.name;
            for (uint32_t* map : {&added.maps.ka, &added.maps.kd, &added.maps.ks, &added.maps.km,
                                  &added.maps.kt, &added.maps.shininess, &added.maps.bump,
                                  &added.maps.normal})
                if (*map != MaterialMaps::kNone) *map += firstTexture;
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

// OBJ faces into triangle meshes: each face triangulated on its own plane,
// vertices shared between faces that agree on position, texture coordinate
// and normal, normals from the file or averaged within smoothing groups, the
// scene's transform applied, zero-area faces dropped with a warning.

#include "renderer/io/obj_loader.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <atomic>
#include <memory>
#include <stdexcept>
#include <unordered_map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_pipeline.h>

#include "geometry/corner_angles.h"
#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "geometry/validate.h"
#include "renderer/huge_array.h"
#include "renderer/huge_pages.h"
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

/// A smoothing sum: one per position and group.
struct SumKey {
    uint32_t v;
    uint64_t group;
    bool operator==(const SumKey& o) const { return v == o.v && group == o.group; }
};

struct SumKeyHash {
    size_t operator()(const SumKey& k) const {
        const uint64_t h = (uint64_t(k.v) << 32) ^ (k.group * 0x9E3779B97F4A7C15ull);
        return size_t(h ^ (h >> 29));
    }
};

/// One mesh part: its vertices shared by VertexKey, and for smoothing groups
/// the angle-weighted sum of face normals per (position, group).
///
/// Lookups go first through a table indexed by position (the first vertex,
/// and the first sum, made from each position); only other keys of a
/// position (a UV seam, a second group, file normals) reach a hash map. A
/// mesh whose positions each make one vertex (a scan, a terrain) never
/// hashes. The result is the one a single hash map gives: same vertices in
/// the same order. Such a mesh is built by buildInParallel instead, with
/// the same result.
class PartBuilder {
public:
    PartBuilder() : m_part{"", std::make_shared<TriangleMesh>(), {}} {}

    void setPositionCount(size_t positions) { m_positionCount = positions; }

    /// Room for what the part can hold at most (untouched pages cost no memory).
    void reserve(size_t positions, size_t triangles) {
        m_positionCount = positions;
        TriangleMesh& m = mesh();
        // Per-vertex arrays: one vertex per position is the common case.
        reserveHugePages(m.positions, positions);
        reserveHugePages(m.normals, positions);
        reserveHugePages(m_keys, positions);
        reserveHugePages(m_sumOf, positions);
        reserveHugePages(m_sumGroup, positions);
        reserveHugePages(m.triangles, triangles);
        reserveHugePages(m_part.faceMaterials, triangles);
    }

    uint32_t vertex(const ObjCorner& c, const NormalSource& n, const HugeArray<Vec3>& world,
                    const ObjData& data, const Transform& xf) {
        const VertexKey key{c.v, c.vt, n.kind, n.id};
        if (m_firstVertex.empty()) resizeHugePages(m_firstVertex, m_positionCount, kNone);
        uint32_t& first = m_firstVertex[c.v];
        if (first != kNone && m_keys[first] == key) return first;
        if (first != kNone) {
            const auto [it, added] = m_otherVertices.emplace(key, uint32_t(mesh().positions.size()));
            if (!added) return it->second;
        } else {
            first = uint32_t(mesh().positions.size());
        }
        const uint32_t index = uint32_t(mesh().positions.size());
        m_keys.push_back(key);
        TriangleMesh& m = mesh();
        m.positions.push_back(world[c.v]);
        if (!data.colors.empty()) {
            const Vec3f& col = data.colors[c.v];
            m.colors.push_back(Vec3(col.x, col.y, col.z));
        }
        if (c.vt < 0) {
            // Texture coordinates are kept only when every corner has one.
            m_allUvs = false;
            std::vector<Vec2>().swap(m.uvs);
        } else if (m_allUvs) {
            const Vec2f& t = data.texcoords[size_t(c.vt)];
            m.uvs.push_back(Vec2(t.x, t.y));
        }
        if (n.kind == NormalSource::File) {
            const Vec3f& f = data.normals[n.id];
            m.normals.push_back(xf.normal(Vec3(f.x, f.y, f.z)));
            m_sumOf.push_back(kNone);
        } else if (n.kind == NormalSource::Group) {
            // One sum per position and group, shared by vertices that differ
            // only in their texture coordinate (a UV seam is not a crease).
            m.normals.push_back(Vec3{});
            m_sumOf.push_back(sum(c.v, n.id));
        } else {
            m_sumOf.push_back(kNone);
        }
        return index;
    }

    /// Builds the whole part at once, in parallel, when no position makes
    /// more than one vertex in it (one texture coordinate and one normal
    /// source per position: a terrain, a scan). Vertex i is then the
    /// position of the i-th first use, exactly what vertex() gives corner
    /// by corner, and every array comes out as the serial pass makes it, for
    /// any thread count. `corners(b, fn)` calls fn(ordinal, corner, normal
    /// source) for every corner of block b, in order (ordinals grow along
    /// the serial order); `triangles(b, fn)` calls fn(positions, material)
    /// for every kept triangle of block b, wound as it is added. Returns
    /// false, with nothing changed, when some position has two keys.
    template <class Corners, class Triangles>
    bool buildInParallel(size_t blockCount, const Corners& corners, const Triangles& triangles,
                         const HugeArray<Vec3>& world, const ObjData& data,
                         const Transform& xf) {
        const size_t positions = m_positionCount;
        const auto forBlocks = [&](const auto& body) {
            tbb::parallel_for(tbb::blocked_range<size_t>(0, blockCount, 1),
                              [&](const tbb::blocked_range<size_t>& r) {
                                  for (size_t b = r.begin(); b != r.end(); ++b) body(b);
                              });
        };
        // Pass 1: per position its first corner (the smallest ordinal: the
        // same whichever thread gets there first) and its one key.
        // Zero is "not seen yet": the arrays start as zero bytes.
        HugeArray<std::atomic<uint64_t>> first(positions);     // ordinal + 1
        HugeArray<std::atomic<uint64_t>> normalOf(positions);  // normal source, coded + 1
        HugeArray<std::atomic<uint32_t>> uvOf(positions);      // vt + 2
        // The first value a position gets; a second, different one: two keys.
        const auto claim = [](auto& slot, auto value) {
            auto had = slot.load(std::memory_order_relaxed);
            if (had == 0 && slot.compare_exchange_strong(had, value, std::memory_order_relaxed))
                return true;
            return had == value;
        };
        std::atomic<bool> twoKeys{false}, missingUv{false};
        forBlocks([&](size_t b) {
            bool localTwoKeys = false, localMissingUv = false;
            corners(b, [&](uint64_t ordinal, const ObjCorner& c, const NormalSource& n) {
                std::atomic<uint64_t>& f = first[c.v];
                uint64_t seen = f.load(std::memory_order_relaxed);
                while ((seen == 0 || ordinal + 1 < seen) &&
                       !f.compare_exchange_weak(seen, ordinal + 1, std::memory_order_relaxed)) {
                }
                // The rest of the key in two integers (vt + 2; the normal
                // source's kind and id, + 1): equal keys, equal numbers.
                const uint64_t normal = n.kind == NormalSource::File    ? (1ull << 40) + n.id + 1
                                        : n.kind == NormalSource::Group ? (2ull << 40) + n.id + 1
                                                                        : 1;
                localTwoKeys = localTwoKeys || !claim(normalOf[c.v], normal) ||
                               !claim(uvOf[c.v], uint32_t(c.vt + 2));
                localMissingUv = localMissingUv || c.vt < 0;
            });
            if (localTwoKeys) twoKeys.store(true, std::memory_order_relaxed);
            if (localMissingUv) missingUv.store(true, std::memory_order_relaxed);
        });
        if (twoKeys.load()) return false;
        normalOf.release();

        // Pass 2: what each block adds, then where its share goes.
        struct Share {
            size_t vertices = 0, sums = 0, normals = 0, triangles = 0;
        };
        std::vector<Share> share(blockCount + 1);
        forBlocks([&](size_t b) {
            Share n;
            corners(b, [&](uint64_t ordinal, const ObjCorner& c, const NormalSource& src) {
                if (first[c.v].load(std::memory_order_relaxed) != ordinal + 1) return;
                ++n.vertices;
                n.sums += src.kind == NormalSource::Group;
                n.normals += src.kind != NormalSource::Flat;
            });
            triangles(b, [&](const std::array<uint32_t, 3>&, uint32_t) { ++n.triangles; });
            share[b + 1] = n;
        });
        for (size_t b = 0; b < blockCount; ++b) {
            share[b + 1].vertices += share[b].vertices;
            share[b + 1].sums += share[b].sums;
            share[b + 1].normals += share[b].normals;
            share[b + 1].triangles += share[b].triangles;
        }
        const Share total = share[blockCount];
        // A part's vertices all have normals or none (Flat faces form a part of their own).
        if (total.normals != 0 && total.normals != total.vertices) return false;

        TriangleMesh& m = mesh();
        m_allUvs = !missingUv.load();
        // resize() fills each array (and faults its pages) in one thread: the
        // arrays are filled side by side (a terrain's are ~80 MB).
        tbb::parallel_invoke(
            [&] { resizeHugePages(m.positions, total.vertices); },
            [&] { if (total.normals > 0) resizeHugePages(m.normals, total.vertices); },
            [&] { if (!data.colors.empty()) resizeHugePages(m.colors, total.vertices); },
            [&] { if (m_allUvs) resizeHugePages(m.uvs, total.vertices); },
            [&] { resizeHugePages(m_sumOf, total.vertices, kNone); },
            [&] { resizeHugePages(m.triangles, total.triangles); },
            [&] { resizeHugePages(m_part.faceMaterials, total.triangles); });
        m_sumCount = uint32_t(total.sums);
        // Per position used: its vertex (in the memory of uvOf, done with).
        HugeArray<std::atomic<uint32_t>>& vertexOf = uvOf;

        // Pass 3: the vertices, each made at its first corner.
        forBlocks([&](size_t b) {
            size_t index = share[b].vertices, sumIndex = share[b].sums;
            corners(b, [&](uint64_t ordinal, const ObjCorner& c, const NormalSource& n) {
                if (first[c.v].load(std::memory_order_relaxed) != ordinal + 1) return;
                vertexOf[c.v].store(uint32_t(index), std::memory_order_relaxed);
                m.positions[index] = world[c.v];
                if (!data.colors.empty()) {
                    const Vec3f& col = data.colors[c.v];
                    m.colors[index] = Vec3(col.x, col.y, col.z);
                }
                if (m_allUvs) {
                    const Vec2f& t = data.texcoords[size_t(c.vt)];
                    m.uvs[index] = Vec2(t.x, t.y);
                }
                if (n.kind == NormalSource::File) {
                    const Vec3f& f = data.normals[n.id];
                    m.normals[index] = xf.normal(Vec3(f.x, f.y, f.z));
                } else if (n.kind == NormalSource::Group) {
                    m_sumOf[index] = uint32_t(sumIndex++);
                }
                ++index;
            });
        });
        first.release();

        // Pass 4: the triangles, in order.
        forBlocks([&](size_t b) {
            size_t index = share[b].triangles;
            triangles(b, [&](const std::array<uint32_t, 3>& p, uint32_t material) {
                m.triangles[index] = {vertexOf[p[0]].load(std::memory_order_relaxed),
                                      vertexOf[p[1]].load(std::memory_order_relaxed),
                                      vertexOf[p[2]].load(std::memory_order_relaxed)};
                m_part.faceMaterials[index] = material;
                ++index;
            });
        });
        return true;
    }

    /// Adds a triangle (already checked for area) with its material.
    void triangle(const std::array<uint32_t, 3>& t, uint32_t material) {
        mesh().triangles.push_back(t);
        m_part.faceMaterials.push_back(material);
    }

    /// The finished part: smoothing-group normals (below), texture
    /// coordinates kept only when every corner had one.
    ObjMeshPart finish() {
        // What only the vertex lookups needed.
        std::vector<VertexKey>().swap(m_keys);
        std::vector<uint32_t>().swap(m_firstVertex);
        std::vector<uint32_t>().swap(m_firstSum);
        std::vector<uint64_t>().swap(m_sumGroup);
        decltype(m_otherVertices)().swap(m_otherVertices);
        decltype(m_otherSums)().swap(m_otherSums);
        if (m_sumCount > 0) smoothNormals();
        if (!m_allUvs) mesh().uvs.clear();
        return std::move(m_part);
    }

    bool empty() const { return m_part.mesh->triangles.empty(); }
    const Vec3& position(uint32_t i) const { return m_part.mesh->positions[i]; }

private:
    static constexpr uint32_t kNone = UINT32_MAX;
    TriangleMesh& mesh() { return *m_part.mesh; }

    Vec3 faceNormal(const std::array<uint32_t, 3>& t) const {
        const TriangleMesh& m = *m_part.mesh;
        return normalize(cross(m.positions[t[1]] - m.positions[t[0]],
                               m.positions[t[2]] - m.positions[t[0]]));
    }

    /// Every smoothing sum is the angle-weighted sum of the normals of its
    /// triangles, added in triangle order (corner order within one), then
    /// normalised; a sum that cancels takes its first triangle's normal.
    /// What each corner adds (a face normal times the corner's angle: the
    /// atan2 calls are most of the work) is computed in parallel, block by
    /// block; the additions run in one serial stage that takes the blocks in
    /// triangle order, so every sum is added up exactly as a single pass
    /// adds it: the same bits for any thread count.
    void smoothNormals() {
        TriangleMesh& m = mesh();
        const auto& tris = m.triangles;
        HugeArray<Vec3> sum(m_sumCount);
        HugeArray<uint32_t> firstTriangle(m_sumCount);  // + 1; per sum: for a sum that cancels

        constexpr size_t kBlock = 1024;  // triangles: the cut depends only on the mesh
        const size_t blockCount = (tris.size() + kBlock - 1) / kBlock;
        // Buffers for the blocks in flight. The last stage is serial and in
        // order, so block b has left it before block b + kTokens can start.
        constexpr size_t kTokens = 4;
        std::vector<std::vector<std::array<Vec3, 3>>> added(kTokens);
        size_t nextBlock = 0;
        tbb::parallel_pipeline(
            kTokens,
            tbb::make_filter<void, size_t>(tbb::filter_mode::serial_in_order,
                                           [&](tbb::flow_control& fc) -> size_t {
                if (nextBlock == blockCount) {
                    fc.stop();
                    return 0;
                }
                return nextBlock++;
            }) &
            tbb::make_filter<size_t, size_t>(tbb::filter_mode::parallel, [&](size_t b) {
                std::vector<std::array<Vec3, 3>>& out = added[b % kTokens];
                out.resize(kBlock);
                const size_t end = std::min(tris.size(), (b + 1) * kBlock);
                for (size_t ti = b * kBlock; ti < end; ++ti) {
                    const auto& t = tris[ti];
                    if (m_sumOf[t[0]] == kNone) continue;
                    const Vec3& p0 = m.positions[t[0]];
                    const Vec3& p1 = m.positions[t[1]];
                    const Vec3& p2 = m.positions[t[2]];
                    const Vec3 n = normalize(cross(p1 - p0, p2 - p0));
                    const std::array<double, 3> angle = cornerAngles(p0, p1, p2);
                    auto& a = out[ti - b * kBlock];
                    for (size_t k = 0; k < 3; ++k) a[k] = n * angle[k];
                }
                return b;
            }) &
            tbb::make_filter<size_t, void>(tbb::filter_mode::serial_in_order, [&](size_t b) {
                const std::vector<std::array<Vec3, 3>>& in = added[b % kTokens];
                const size_t end = std::min(tris.size(), (b + 1) * kBlock);
                for (size_t ti = b * kBlock; ti < end; ++ti) {
                    const auto& t = tris[ti];
                    if (m_sumOf[t[0]] == kNone) continue;
                    for (size_t k = 0; k < 3; ++k) {
                        const uint32_t s = m_sumOf[t[k]];
                        if (firstTriangle[s] == 0) firstTriangle[s] = uint32_t(ti + 1);
                        sum[s] += in[ti - b * kBlock][k];
                    }
                }
            }));

        tbb::parallel_for(tbb::blocked_range<size_t>(0, sum.size(), 16384),
                          [&](const tbb::blocked_range<size_t>& r) {
            for (size_t s = r.begin(); s != r.end(); ++s) {
                const Vec3 n = normalize(sum[s]);
                sum[s] = isFinite(n) && lengthSquared(n) > 0 ? n
                         : firstTriangle[s] == 0             ? Vec3{}
                                                             : faceNormal(tris[firstTriangle[s] - 1]);
            }
        });
        tbb::parallel_for(tbb::blocked_range<size_t>(0, m_sumOf.size(), 16384),
                          [&](const tbb::blocked_range<size_t>& r) {
            for (size_t i = r.begin(); i != r.end(); ++i)
                if (m_sumOf[i] != kNone) m.normals[i] = sum[m_sumOf[i]];
        });
    }

    /// The sum of (position v, group): made on first use.
    uint32_t sum(uint32_t v, uint64_t group) {
        if (m_firstSum.empty()) resizeHugePages(m_firstSum, m_positionCount, kNone);
        uint32_t& first = m_firstSum[v];
        if (first != kNone && m_sumGroup[first] == group) return first;
        const uint32_t next = m_sumCount;
        if (first != kNone) {
            const auto [it, added] = m_otherSums.emplace(SumKey{v, group}, next);
            if (!added) return it->second;
        } else {
            first = next;
        }
        ++m_sumCount;
        m_sumGroup.push_back(group);
        return next;
    }

    ObjMeshPart m_part;
    size_t m_positionCount = 0;
    std::vector<uint32_t> m_firstVertex;  ///< per position: its first vertex here, or kNone
    std::vector<VertexKey> m_keys;        ///< per vertex
    std::unordered_map<VertexKey, uint32_t, VertexKeyHash> m_otherVertices;
    bool m_allUvs = true;
    std::vector<uint32_t> m_sumOf;  ///< per vertex: its smoothing sum, or kNone
    uint32_t m_sumCount = 0;
    std::vector<uint64_t> m_sumGroup;       ///< per sum: its group
    std::vector<uint32_t> m_firstSum;       ///< per position: its first sum, or kNone
    std::unordered_map<SumKey, uint32_t, SumKeyHash> m_otherSums;
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
HugeArray<Vec3> worldPositions(const ObjData& data, const Transform& xf,
                               const std::string& path) {
    HugeArray<Vec3> world(data.positions.size());
    const double limit = double(std::numeric_limits<float>::max());
    HugeArray<char> beyond(data.positions.size());
    tbb::parallel_for(tbb::blocked_range<size_t>(0, world.size(), 16384),
                      [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
            const Vec3f& p = data.positions[i];
            world[i] = xf.point(Vec3(p.x, p.y, p.z));
            beyond[i] = !isFinite(world[i]) || maxComponent(abs(world[i])) > limit;
        }
    });
    for (size_t i = 0; i < world.size(); ++i)  // the first one is reported
        if (beyond[i])
            // The text is gone by now (memory): read again for the message.
            throw InputError(path, lineOfVertex(readTextFile(path), i),
                             "the mesh's transform (scale, rotate, translate) moves vertex " +
                                 std::to_string(i + 1) + " to " + formatValue(world[i]) +
                                 ", beyond float range (about 3.4e38)");
    return world;
}

class MeshBuilder {
public:
    MeshBuilder(const ObjData& data, const ObjMaterials& mats, const ObjLoadOptions& options,
                HugeArray<Vec3> world, LoadWarnings& warn)
        : m_data(data), m_mats(mats), m_options(options), m_world(std::move(world)),
          m_warn(warn) {}

    /// Plans every face in parallel (triangulation, self-crossing check,
    /// which triangles have area, part and material), reports the faces'
    /// warnings in face order, then builds each part: in parallel when
    /// every position makes one vertex in it, else in one pass in face
    /// order (shared vertices through PartBuilder::vertex); the normals follow.
    void build() {
        // Each face's triangles go at a fixed place: a face of n corners has
        // at most n - 2 (fewer when collinear corners are skipped).
        m_slot = HugeArray<size_t>(m_data.faces.size() + 1);
        for (size_t i = 0; i < m_data.faces.size(); ++i) {
            const uint32_t n = m_data.faces[i].cornerCount;
            m_slot[i + 1] = m_slot[i] + (n > 2 ? n - 2 : 0);
        }
        const size_t slots = m_slot[m_data.faces.size()];
        m_plans = HugeArray<FacePlan>(m_data.faces.size());
        m_planned = HugeArray<PlannedTriangle>(slots);
        tbb::parallel_for(tbb::blocked_range<size_t>(0, m_data.faces.size(), 1024),
                          [&](const tbb::blocked_range<size_t>& r) {
            std::vector<Vec3> corners;
            std::vector<std::array<uint32_t, 3>> triangles;
            for (size_t i = r.begin(); i != r.end(); ++i)
                plan(m_data.faces[i], corners, triangles, m_plans[i], m_planned.data() + m_slot[i]);
        });
        for (size_t i = 0; i < m_data.faces.size(); ++i) report(m_data.faces[i], m_plans[i]);
        for (const bool flat : {false, true}) {
            PartBuilder& part = flat ? m_flat : m_smooth;
            if (!(flat ? m_flatFaces : m_smoothFaces)) continue;  // stays empty
            part.setPositionCount(m_data.positions.size());
            const size_t blocks = (m_data.faces.size() + kFaceBlock - 1) / kFaceBlock;
            const auto corners = [&](size_t b, const auto& fn) { forEachCorner(b, flat, fn); };
            const auto triangles = [&](size_t b, const auto& fn) { forEachTriangle(b, flat, fn); };
            if (part.buildInParallel(blocks, corners, triangles, m_world, m_data,
                                     m_options.transform))
                continue;
            part.reserve(m_data.positions.size(), slots);
            for (size_t i = 0; i < m_data.faces.size(); ++i)
                if (m_plans[i].kind == FacePlan::Triangles && m_plans[i].flat == flat)
                    face(m_data.faces[i], m_plans[i], m_planned.data() + m_slot[i], part);
        }
        m_plans.release();
        m_planned.release();
        m_slot.release();
    }

    bool usesDefaultMaterial() const { return m_needDefault; }
    std::vector<ObjMeshPart> parts() {
        std::vector<ObjMeshPart> out;
        for (PartBuilder* b : {&m_smooth, &m_flat})
            if (!b->empty()) out.push_back(b->finish());
        return out;
    }

private:
    ObjCorner corner(const ObjFace& f, size_t k) const { return m_data.corner(f.firstCorner + k); }

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

    uint32_t material(const ObjFace& f) const {
        const uint32_t m =
            f.material == kNoObjMaterial ? kNoObjMaterial : m_mats.byName[f.material];
        if (m != kNoObjMaterial) return m;
        return defaultMaterial();
    }
    /// The default material, appended after the MTL ones.
    uint32_t defaultMaterial() const { return uint32_t(m_mats.materials.size()); }

    /// What the parallel stage decides about a face.
    struct FacePlan {
        enum Kind : uint8_t { FewCorners, NoArea, Triangles } kind = FewCorners;
        bool crossesItself = false;
        bool flat = false;            ///< goes to the flat part (no normal source)
        uint32_t triangleCount = 0;
        uint32_t kept = 0;            ///< triangles with area
        uint32_t material = 0;
    };
    /// A triangle of a face's triangulation: corner numbers within the face,
    /// and whether it has area (wound as it will be, see face()).
    struct PlannedTriangle {
        std::array<uint32_t, 3> corner;
        bool hasArea;
    };

    /// Triangulates one face on the file's coordinates (an affine transform
    /// changes no ear) and checks each triangle's area on the world positions.
    void plan(const ObjFace& f, std::vector<Vec3>& corners,
              std::vector<std::array<uint32_t, 3>>& triangles, FacePlan& out,
              PlannedTriangle* planned) const {
        if (f.cornerCount < 3) {
            out.kind = FacePlan::FewCorners;
            return;
        }
        corners.clear();
        for (size_t k = 0; k < f.cornerCount; ++k) {
            const Vec3f& p = m_data.positions[m_data.cornerV[f.firstCorner + k]];
            corners.push_back(Vec3(p.x, p.y, p.z));
        }
        try {
            triangulateFace(corners, triangles);
        } catch (const std::invalid_argument&) {
            // Collinear or repeated corners, or a crossing outline with no net area.
            out.kind = FacePlan::NoArea;
            return;
        }
        out.kind = FacePlan::Triangles;
        out.crossesItself = f.cornerCount > 3 && crossesItself(corners, triangles);
        out.flat = normalSource(f).kind == NormalSource::Flat;
        out.material = material(f);
        out.triangleCount = uint32_t(triangles.size());
        const bool mirrored = m_options.transform.flipsHandedness();
        for (size_t j = 0; j < triangles.size(); ++j) {
            std::array<uint32_t, 3> t = triangles[j];
            // As face() will wind it (see there).
            if (mirrored) std::swap(t[1], t[2]);
            const Vec3& p0 = m_world[m_data.cornerV[f.firstCorner + t[0]]];
            const Vec3& p1 = m_world[m_data.cornerV[f.firstCorner + t[1]]];
            const Vec3& p2 = m_world[m_data.cornerV[f.firstCorner + t[2]]];
            const Vec3 area = cross(p1 - p0, p2 - p0);
            // Zero-area triangles have no normal; Embree would never report them.
            planned[j] = {triangles[j], lengthSquared(area) > 0 && isFinite(area)};
            out.kept += planned[j].hasArea;
        }
    }

    /// The warnings a face gives, and whether it needs the default material.
    void report(const ObjFace& f, const FacePlan& plan) {
        if (plan.kind == FacePlan::FewCorners) {
            m_warn.add("face with fewer than 3 corners dropped", f.line, "", "dropped faces");
            return;
        }
        if (plan.kind == FacePlan::NoArea) {
            m_warn.add("face encloses no area (collinear or repeated corners, or a crossing "
                       "outline whose parts cancel); dropped",
                       f.line, "", "dropped faces");
            return;
        }
        if (plan.crossesItself)
            m_warn.add("face crosses itself: its triangles cover more than its area", f.line, "",
                       "self-intersecting faces");
        if (plan.material == defaultMaterial()) m_needDefault = true;
        (plan.flat ? m_flatFaces : m_smoothFaces) = true;
        if (plan.kept == 0) m_warn.add("face has zero area; dropped", f.line, "", "dropped faces");
    }

    /// Faces per block of the parallel part build (the cut depends only on the file).
    static constexpr size_t kFaceBlock = 4096;

    /// fn(ordinal, corner, normal source) for every corner that makes a
    /// vertex in the part (`flat` or not), of the faces of block b, in the
    /// order face() visits them; the ordinal grows along that order.
    template <class Fn>
    void forEachCorner(size_t b, bool flat, const Fn& fn) const {
        const size_t end = std::min(m_data.faces.size(), (b + 1) * kFaceBlock);
        for (size_t i = b * kFaceBlock; i < end; ++i) {
            const FacePlan& plan = m_plans[i];
            if (plan.kind != FacePlan::Triangles || plan.flat != flat) continue;
            const ObjFace& f = m_data.faces[i];
            const NormalSource normals = normalSource(f);
            for (uint32_t j = 0; j < plan.triangleCount; ++j) {
                const PlannedTriangle& t = m_planned[m_slot[i] + j];
                for (size_t k = 0; k < 3; ++k) {
                    const ObjCorner c = corner(f, t.corner[k]);
                    NormalSource n = normals;
                    if (n.kind == NormalSource::File) n.id = uint64_t(c.vn);
                    fn(uint64_t(m_slot[i] + j) * 3 + k, c, n);
                }
            }
        }
    }

    /// fn(positions, material) for every triangle with area of the part's
    /// faces in block b, in order, wound as face() adds it.
    template <class Fn>
    void forEachTriangle(size_t b, bool flat, const Fn& fn) const {
        const bool mirrored = m_options.transform.flipsHandedness();
        const size_t end = std::min(m_data.faces.size(), (b + 1) * kFaceBlock);
        for (size_t i = b * kFaceBlock; i < end; ++i) {
            const FacePlan& plan = m_plans[i];
            if (plan.kind != FacePlan::Triangles || plan.flat != flat) continue;
            const uint32_t first = m_data.faces[i].firstCorner;
            for (uint32_t j = 0; j < plan.triangleCount; ++j) {
                const PlannedTriangle& t = m_planned[m_slot[i] + j];
                if (!t.hasArea) continue;
                std::array<uint32_t, 3> p;
                for (size_t k = 0; k < 3; ++k) p[k] = m_data.cornerV[first + t.corner[k]];
                if (mirrored) std::swap(p[1], p[2]);
                fn(p, plan.material);
            }
        }
    }

    /// Adds a planned face (of kind Triangles) to `part`, one corner at a time.
    void face(const ObjFace& f, const FacePlan& plan, const PlannedTriangle* planned,
              PartBuilder& part) {
        const NormalSource normals = normalSource(f);
        for (uint32_t j = 0; j < plan.triangleCount; ++j) {
            std::array<uint32_t, 3> tri;
            for (size_t k = 0; k < 3; ++k) {
                const ObjCorner c = corner(f, planned[j].corner[k]);
                NormalSource n = normals;
                if (n.kind == NormalSource::File) n.id = uint64_t(c.vn);
                // Every corner makes its vertex, also on a triangle without area.
                tri[k] = part.vertex(c, n, m_world, m_data, m_options.transform);
            }
            // A mirroring transform reverses the winding; swap to keep the front side.
            if (m_options.transform.flipsHandedness()) std::swap(tri[1], tri[2]);
            if (!planned[j].hasArea) continue;
            part.triangle(tri, plan.material);
        }
    }

    /// A face whose triangles cover more than its own area crosses itself (or
    /// is strongly warped): its triangulation can only approximate it.
    static bool crossesItself(const std::vector<Vec3>& corners,
                              const std::vector<std::array<uint32_t, 3>>& triangles) {
        const Vec3 n = newellNormal(corners);
        const Vec3 unit = normalize(n);
        double covered = 0;
        for (const auto& t : triangles)
            covered += std::abs(dot(unit, cross(corners[t[1]] - corners[t[0]],
                                                corners[t[2]] - corners[t[0]])));
        return covered > length(n) * (1 + 1e-6);
    }

    const ObjData& m_data;
    const ObjMaterials& m_mats;
    const ObjLoadOptions& m_options;
    HugeArray<Vec3> m_world;
    LoadWarnings& m_warn;
    PartBuilder m_smooth, m_flat;
    // While building (large: huge-page arrays, see huge_pages.h):
    HugeArray<FacePlan> m_plans;            ///< per face
    HugeArray<PlannedTriangle> m_planned;   ///< per face, at its slot
    HugeArray<size_t> m_slot;  ///< per face: where its planned triangles start
    bool m_needDefault = false;
    bool m_smoothFaces = false, m_flatFaces = false;  ///< some face goes to the part
};

}  // namespace

ObjModel loadObj(const std::string& path, const ObjLoadOptions& options) {
    const LoadingFile loading(path);  // names this file if the parse runs out of memory
    LoadWarnings warn(path);
    ObjData data;
    {
        // The text lives only while it is parsed: the mesh is built from the arrays.
        const std::string text = readTextFile(path);
        if (const auto [line, message] = findNonText(text, "OBJ"); line > 0)
            throw InputError(path, line, message);
        data = parseObj(text, path, warn);
    }
    if (data.faces.empty()) throw InputError(path, 0, "the OBJ file has no faces");
    ObjMaterials mats = loadObjMaterials(data, path, warn);

    MeshBuilder builder(data, mats, options, worldPositions(data, options.transform, path), warn);
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
            for (uint32_t* map : added.maps.slots())
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

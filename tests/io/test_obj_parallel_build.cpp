// The mesh builder's two ways to share vertices give one result: the
// parallel build (every position makes one vertex in its part) and the
// corner-by-corner pass (a UV seam, two smoothing groups meeting, file
// normals that differ at a position) are both checked against a naive
// serial reference written here (std::map of vertex keys, normals summed
// triangle by triangle), and each against itself with 1 thread and all cores.
#include <doctest/doctest.h>

#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "io/io_test_helpers.h"
#include "renderer/io/obj_loader.h"
#include "support/temp_dir.h"

using namespace raylab;
using raylab::test::quiet;
using raylab::test::TempDir;

namespace {

struct GridOptions {
    int n = 120;              ///< n x n cells, two triangles each
    bool twoGroups = false;   ///< rows alternate `s 1` / `s 2` in bands: groups meet
    bool uvs = false;         ///< a vt per position
    bool uvSeam = false;      ///< ... and one column of faces uses a second vt
    bool fileNormals = false; ///< a vn per position (`v//vn`)
    bool normalSeam = false;  ///< ... and one column of faces uses a second vn
};

/// A bumpy height field of triangles (`f a b c`), in a form the reference can read back.
struct Grid {
    std::string text;
    std::vector<Vec3f> v;
    std::vector<Vec2f> vt;
    std::vector<Vec3f> vn;
    struct Corner {
        int v, vt, vn;
    };
    std::vector<std::array<Corner, 3>> faces;
    std::vector<uint32_t> group;  ///< per face
};

Grid makeGrid(const GridOptions& o) {
    Grid g;
    const int n = o.n;
    char line[128];
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const Vec3f p(float(i) / n, float(j) / n,
                          float(0.1 * std::sin(0.37 * i) * std::cos(0.23 * j)));
            g.v.push_back(p);
            std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
            g.text += line;
            if (o.uvs) {
                g.vt.push_back(Vec2f(float(i) / n, float(j) / n));
                std::snprintf(line, sizeof line, "vt %.9g %.9g\n", g.vt.back().x, g.vt.back().y);
                g.text += line;
            }
            if (o.fileNormals) {
                g.vn.push_back(Vec3f(float(0.1 * std::cos(0.5 * i)), 0.25f, 1.0f));
                std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", g.vn.back().x,
                              g.vn.back().y, g.vn.back().z);
                g.text += line;
            }
        }
    const int extra = int(g.v.size());  // index of the seam's second vt / vn
    if (o.uvSeam) {
        g.vt.push_back(Vec2f(0.5f, 0.5f));
        g.text += "vt 0.5 0.5\n";
    }
    if (o.normalSeam) {
        g.vn.push_back(Vec3f(0, 0, 1));
        g.text += "vn 0 0 1\n";
    }
    uint32_t group = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const uint32_t want = o.twoGroups && (j / 7) % 2 ? 2 : 1;
            if (want != group) {
                group = want;
                g.text += "s " + std::to_string(group) + "\n";
            }
            const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
            const bool seam = i == n / 2;
            for (const auto& t : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, d}}) {
                std::array<Grid::Corner, 3> f;
                std::string s = "f";
                for (int k = 0; k < 3; ++k) {
                    const int vt = !o.uvs ? -1 : o.uvSeam && seam && k == 0 ? extra : t[k];
                    const int vn = !o.fileNormals ? -1 : o.normalSeam && seam && k == 1 ? extra : t[k];
                    f[k] = {t[k], vt, vn};
                    s += " " + std::to_string(t[k] + 1);
                    if (vt >= 0 || vn >= 0) s += "/" + (vt >= 0 ? std::to_string(vt + 1) : "");
                    if (vn >= 0) s += "/" + std::to_string(vn + 1);
                }
                g.text += s + "\n";
                g.faces.push_back(f);
                g.group.push_back(group);
            }
        }
    return g;
}

double cornerAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e1 = normalize(b - a), e2 = normalize(c - a);
    return std::atan2(length(cross(e1, e2)), dot(e1, e2));
}

/// The naive build: vertices by (v, vt, normal source) in order of first use,
/// normals the file's or the angle-weighted sum per (position, group) in triangle order.
TriangleMesh reference(const Grid& g) {
    TriangleMesh m;
    std::map<std::tuple<int, int, int, uint32_t>, uint32_t> vertexOf;  // v, vt, vn, group
    std::vector<std::pair<int, uint32_t>> sumKey;                     // per vertex: (v, group) or (-1, 0)
    for (size_t fi = 0; fi < g.faces.size(); ++fi) {
        std::array<uint32_t, 3> tri;
        for (int k = 0; k < 3; ++k) {
            const Grid::Corner& c = g.faces[fi][k];
            const uint32_t group = c.vn >= 0 ? 0 : g.group[fi];
            const auto key = std::make_tuple(c.v, c.vt, c.vn, group);
            auto it = vertexOf.find(key);
            if (it == vertexOf.end()) {
                it = vertexOf.emplace(key, uint32_t(m.positions.size())).first;
                const Vec3f& p = g.v[size_t(c.v)];
                m.positions.push_back(Vec3(p.x, p.y, p.z));
                if (c.vt >= 0) m.uvs.push_back(Vec2(g.vt[size_t(c.vt)].x, g.vt[size_t(c.vt)].y));
                if (c.vn >= 0) {
                    const Vec3f& f = g.vn[size_t(c.vn)];
                    m.normals.push_back(normalize(Vec3(f.x, f.y, f.z)));
                } else {
                    m.normals.push_back(Vec3{});
                }
                sumKey.push_back(c.vn >= 0 ? std::make_pair(-1, 0u) : std::make_pair(c.v, group));
            }
            tri[size_t(k)] = it->second;
        }
        m.triangles.push_back(tri);
    }
    std::map<std::pair<int, uint32_t>, Vec3> sums;
    std::map<std::pair<int, uint32_t>, bool> seen;
    for (const auto& t : m.triangles) {
        const Vec3 &p0 = m.positions[t[0]], &p1 = m.positions[t[1]], &p2 = m.positions[t[2]];
        const Vec3 n = normalize(cross(p1 - p0, p2 - p0));
        const double angle[3] = {cornerAngle(p0, p1, p2), cornerAngle(p1, p2, p0),
                                 cornerAngle(p2, p0, p1)};
        std::map<std::pair<int, uint32_t>, bool> doneHere;
        for (int k = 0; k < 3; ++k) {
            const auto key = sumKey[t[size_t(k)]];
            if (key.first < 0) continue;
            sums[key] += n * angle[k];
        }
    }
    for (size_t i = 0; i < m.positions.size(); ++i)
        if (sumKey[i].first >= 0) m.normals[i] = normalize(sums[sumKey[i]]);
    return m;
}

void checkSame(const TriangleMesh& got, const TriangleMesh& want) {
    REQUIRE(got.positions.size() == want.positions.size());
    REQUIRE(got.triangles.size() == want.triangles.size());
    REQUIRE(got.normals.size() == want.normals.size());
    REQUIRE(got.uvs.size() == want.uvs.size());
    size_t differ = 0;
    for (size_t i = 0; i < got.positions.size(); ++i)
        differ += !(got.positions[i] == want.positions[i]) || !(got.normals[i] == want.normals[i]) ||
                  (!got.uvs.empty() && !(got.uvs[i].x == want.uvs[i].x && got.uvs[i].y == want.uvs[i].y));
    for (size_t i = 0; i < got.triangles.size(); ++i) differ += got.triangles[i] != want.triangles[i];
    CHECK(differ == 0);
}

void checkLoad(const GridOptions& o) {
    const Grid g = makeGrid(o);
    const TempDir dir;
    const std::string path = dir.write("grid.obj", g.text);
    const ObjModel all = loadObj(path, quiet());
    ObjModel one;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = loadObj(path, quiet());
    }
    REQUIRE(all.parts.size() == 1);
    REQUIRE(one.parts.size() == 1);
    const TriangleMesh want = reference(g);
    checkSame(*all.parts[0].mesh, want);
    checkSame(*one.parts[0].mesh, want);
}

}  // namespace

TEST_CASE("obj build: one vertex per position (the parallel build) = the naive reference") {
    checkLoad({});
}

TEST_CASE("obj build: a vt per position (parallel) and a UV seam (corner by corner)") {
    GridOptions o;
    o.uvs = true;
    checkLoad(o);
    o.uvSeam = true;
    checkLoad(o);
}

TEST_CASE("obj build: two smoothing groups meeting at positions (corner by corner)") {
    GridOptions o;
    o.twoGroups = true;
    checkLoad(o);
}

TEST_CASE("obj build: file normals per position (parallel) and a normal seam (corner by corner)") {
    GridOptions o;
    o.fileNormals = true;
    checkLoad(o);
    o.normalSeam = true;
    checkLoad(o);
}

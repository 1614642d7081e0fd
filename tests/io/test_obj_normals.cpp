// Shading normals of OBJ meshes without vn: averaged, weighted by each face's
// angle at the vertex, within a smoothing group; flat across group borders
// and under `s off`; the file's vn win. And vertex colours multiplying kd.
#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "io/io_test_helpers.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/scene_loader.h"
#include "support/vec_checks.h"

using namespace raylab;
using raylab::test::quiet;
using raylab::test::checkVec;
using raylab::test::TempDir;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// A cube-sphere: the six faces of a cube split into n x n quads (shared
/// corners), every vertex pushed onto the unit sphere, quads wound outward.
/// `header` goes before the faces (an `s` statement, say).
std::string cubeSphere(int n, const std::string& header) {
    std::map<std::tuple<int, int, int>, int> index;
    std::string verts, faces;
    const auto vertex = [&](int i, int j, int k) {
        const auto key = std::make_tuple(i, j, k);
        const auto it = index.find(key);
        if (it != index.end()) return it->second;
        const Vec3 p = normalize(Vec3(2.0 * i / n - 1, 2.0 * j / n - 1, 2.0 * k / n - 1));
        char line[96];
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
        verts += line;
        const int id = int(index.size()) + 1;
        index[key] = id;
        return id;
    };
    // Each face: a fixed axis at 0 or n, the two others spanning it; corners
    // listed so that (b - a) x (c - a) points away from the cube's centre.
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side <= n; side += n)
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b) {
                    const auto at = [&](int s, int t) {
                        int c[3];
                        c[axis] = side;
                        c[(axis + 1) % 3] = s;
                        c[(axis + 2) % 3] = t;
                        return vertex(c[0], c[1], c[2]);
                    };
                    int q[4] = {at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)};
                    if (side == 0) std::swap(q[1], q[3]);
                    faces += "f " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " +
                             std::to_string(q[2]) + " " + std::to_string(q[3]) + "\n";
                }
    return verts + header + faces;
}

/// The largest angle, in degrees, between a vertex's shading normal (or, for
/// a flat mesh, the normal of each triangle at its corners) and the sphere's.
double worstAngle(const TriangleMesh& m) {
    double worst = 0;
    for (const auto& t : m.triangles)
        for (uint32_t i : t) {
            const Vec3 n = m.hasNormals()
                               ? m.normals[i]
                               : normalize(cross(m.positions[t[1]] - m.positions[t[0]],
                                                 m.positions[t[2]] - m.positions[t[0]]));
            const double c = std::min(1.0, dot(n, normalize(m.positions[i])));
            worst = std::max(worst, std::acos(c) * 180 / kPi);
        }
    return worst;
}

}  // namespace

TEST_CASE("smoothing groups: a cube-sphere's normals match the sphere's within 1.5 degrees") {
    TempDir dir;
    // 8 x 8 quads a face: facets span up to ~11 degrees of the sphere.
    const ObjModel smooth = loadObj(dir.write("s1.obj", cubeSphere(8, "s 1\n")), quiet());
    REQUIRE(smooth.parts.size() == 1);
    const TriangleMesh& m = *smooth.parts[0].mesh;
    REQUIRE(m.hasNormals());
    CHECK(m.positions.size() == 6 * 8 * 8 + 2);  // one vertex per position: one group, no seams
    const double smoothAngle = worstAngle(m);
    CAPTURE(smoothAngle);
    // The bound: the angle-weighted average errs most at the cube's corners,
    // where three faces meet at 120°-ish angles; measured 0.9°.
    CHECK(smoothAngle < 1.5);

    // The same mesh flat (s off, and without any s) is several times further off.
    for (const char* header : {"s off\n", "s 0\n", ""}) {
        CAPTURE(std::string(header));
        const ObjModel flat = loadObj(dir.write("s0.obj", cubeSphere(8, header)), quiet());
        REQUIRE(flat.parts.size() == 1);
        CHECK(!flat.parts[0].mesh->hasNormals());
        CHECK(worstAngle(*flat.parts[0].mesh) > 3 * smoothAngle);
    }
    // JSON "normals": "smooth" (or --normals smooth) averages a mesh without s statements.
    ObjLoadOptions o = quiet();
    o.normals = ObjNormals::Smooth;
    const ObjModel forced = loadObj(dir.file("s0.obj"), o);
    REQUIRE(forced.parts[0].mesh->hasNormals());
    CHECK(worstAngle(*forced.parts[0].mesh) == doctest::Approx(smoothAngle));
}

TEST_CASE("smoothing groups: weighted by angle, flat across group borders, vn wins") {
    TempDir dir;
    // Three triangles around the origin: one in z = 0 (normal +z, 90° at the
    // origin) and two in x = 0 (normal +x, 45° each). Weighted by angle the
    // origin's normal is (1, 0, 1)/√2; an unweighted average would lean to +x.
    const std::string fan =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 1 1\nv 0 0 1\n"
        "s 1\nf 1 2 3\nf 1 3 4\nf 1 4 5\n";
    const ObjModel m = loadObj(dir.write("fan.obj", fan), quiet());
    REQUIRE(m.parts.size() == 1);
    const TriangleMesh& mesh = *m.parts[0].mesh;
    checkVec(mesh.normals[mesh.triangles[0][0]], normalize(Vec3(1, 0, 1)));

    // Different groups: the shared corner gets one normal per group (the faces' own).
    const std::string crease =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 1 1\nv 0 0 1\n"
        "s 1\nf 1 2 3\ns 2\nf 1 3 4\nf 1 4 5\n";
    const ObjModel c = loadObj(dir.write("crease.obj", crease), quiet());
    const TriangleMesh& cm = *c.parts[0].mesh;
    CHECK(cm.positions.size() == 3 + 4);  // the origin and (0,1,0) twice
    checkVec(cm.normals[cm.triangles[0][0]], {0, 0, 1});
    checkVec(cm.normals[cm.triangles[1][0]], {1, 0, 0});

    // Faces that give vn use them, whatever their group says; the others in
    // the file still average: two parts only when some faces stay flat.
    const std::string mixed =
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 1 1\nvn 0 0.6 0.8\n"
        "s 1\nf 1//1 2//1 3//1\nf 1 3 4\ns off\nf 2 3 4\n";
    const ObjModel x = loadObj(dir.write("mixed.obj", mixed), quiet());
    REQUIRE(x.parts.size() == 2);
    const TriangleMesh& withNormals = *x.parts[0].mesh;
    CHECK(withNormals.triangleCount() == 2);
    checkVec(withNormals.normals[withNormals.triangles[0][1]], {0, 0.6, 0.8}, 1e-6);  // read as float
    checkVec(withNormals.normals[withNormals.triangles[1][2]], {1, 0, 0});  // its own face, alone
    CHECK(!x.parts[1].mesh->hasNormals());
    // JSON "normals": "flat" drops them all.
    ObjLoadOptions flat = quiet();
    flat.normals = ObjNormals::Flat;
    const ObjModel f = loadObj(dir.file("mixed.obj"), flat);
    REQUIRE(f.parts.size() == 1);
    CHECK(!f.parts[0].mesh->hasNormals());
}

TEST_CASE("vertex colours multiply kd, interpolated across the face") {
    TempDir dir;
    // Corners red, green, blue and a fourth without a colour (white).
    const ObjModel m = loadObj(
        dir.write("c.obj", "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0\nf 1 2 3\nf 2 4 3\n"),
        quiet());
    const TriangleMesh& mesh = *m.parts[0].mesh;
    REQUIRE(mesh.hasColors());
    CHECK(mesh.colors[mesh.triangles[0][0]] == Vec3(1, 0, 0));
    CHECK(mesh.colors[mesh.triangles[1][1]] == Vec3(1, 1, 1));
    // At the first triangle's centroid: the mean of red, green and blue.
    const Ray down{{1.0 / 3, 1.0 / 3, 1}, {0, 0, -1}};
    const auto hit = mesh.intersect(0, down, 0, 10, {});
    REQUIRE(hit);
    const SurfaceGeometry g = mesh.surfaceAt(0, down, *hit, {}, SurfaceDetail::Normals);
    checkVec(g.color, {1.0 / 3, 1.0 / 3, 1.0 / 3}, 1e-9);

    // Rendered: a square of one colour (0.5, 0.25, 1) under a light of 1 from
    // straight above, Kd 1 and no ambient: the pixel is the colour itself,
    // and the albedo layer carries kd times the colour.
    dir.write("w.mtl", "newmtl white\nKa 0 0 0\nKd 1 1 1\nillum 1\n");
    dir.write("sq.obj",
              "mtllib w.mtl\nusemtl white\n"
              "v 0 0 0 0.5 0.25 1\nv 1 0 0 0.5 0.25 1\nv 1 1 0 0.5 0.25 1\nv 0 1 0 0.5 0.25 1\n"
              "f 1 2 3 4\n");
    const Scene s = loadScene(dir.write(
        "s.json",
        "{\"camera\": {\"type\": \"orthographic\", \"eye\": [0.5, 0.5, 3], \"direction\": [0, 0, "
        "-1], \"width\": 2}, \"lights\": [{\"type\": \"directional\", \"direction\": [0, 0, -1]}],"
        " \"objects\": [{\"type\": \"mesh\", \"file\": \"sq.obj\"}]}"));
    for (const char* accel : {"embree", "naive"}) {
        const Film film = test::renderFilm(s, accel, 9, 9);
        const size_t i = film.index(4, 4);
        CHECK(film.rgba[4 * i] == 0.5f);
        CHECK(film.rgba[4 * i + 1] == 0.25f);
        CHECK(film.rgba[4 * i + 2] == 1.0f);
        CHECK(film.albedo[3 * i + 1] == 0.25f);
    }
}

TEST_CASE("without Ka, ambient light takes the vertex colours and map_Kd like the diffuse light") {
    // Gallery finding: Ka = Kd held for the constant only, so a green
    // vertex-coloured mesh without Ka was grey in shadow. No light, ambient
    // 0.5: the pixel is 0.5 x Kd x colour, exactly.
    TempDir dir;
    dir.write("m.mtl",
              "newmtl noka\nKd 1 1 1\n"                  // no Ka: follows the diffuse colour
              "newmtl ka\nKa 0.2 0.2 0.2\nKd 1 1 1\n"    // Ka given: as given
              "newmtl illum0\nKd 1 1 1\nillum 0\n");      // illum 0: no ambient at all
    const auto scene = [&](const std::string& material) {
        dir.write("sq.obj", "mtllib m.mtl\nusemtl " + material +
                                "\nv 0 0 0 0 1 0.5\nv 1 0 0 0 1 0.5\nv 1 1 0 0 1 0.5\nv 0 1 0 0 1 0.5\n"
                                "f 1 2 3 4\n");
        return loadScene(dir.write(
            "s.json",
            "{\"camera\": {\"type\": \"orthographic\", \"eye\": [0.5, 0.5, 3], \"direction\": [0, 0, "
            "-1], \"width\": 2}, \"ambient\": [0.5, 0.5, 0.5], \"lights\": [],"
            " \"objects\": [{\"type\": \"mesh\", \"file\": \"sq.obj\"}]}"));
    };
    const auto follows = [](const Scene& s, const std::string& name) {
        for (const Material& m : s.materials)
            if (m.name.size() > name.size() && m.name.compare(m.name.size() - name.size() - 1, std::string::npos, "/" + name) == 0)
                return m.ambientFollowsDiffuse;
        FAIL("no material " << name);
        return false;
    };
    const Scene noKa = scene("noka");
    CHECK(follows(noKa, "noka"));
    const Scene ka = scene("ka");
    CHECK_FALSE(follows(ka, "ka"));
    const Scene illum0 = scene("illum0");
    CHECK_FALSE(follows(illum0, "illum0"));
    for (const char* accel : {"embree", "naive"}) {
        CAPTURE(accel);
        const Film a = test::renderFilm(noKa, accel, 9, 9);
        const size_t i = a.index(4, 4);
        CHECK(a.rgba[4 * i] == 0.0f);
        CHECK(a.rgba[4 * i + 1] == 0.5f);
        CHECK(a.rgba[4 * i + 2] == 0.25f);
        const Film b = test::renderFilm(ka, accel, 9, 9);
        CHECK(b.rgba[4 * i] == 0.1f);  // 0.2 x 0.5, not coloured
        CHECK(b.rgba[4 * i + 1] == 0.1f);
        const Film c = test::renderFilm(illum0, accel, 9, 9);
        CHECK(c.rgba[4 * i + 1] == 0.0f);
    }
}

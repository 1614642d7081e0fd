// OBJ/MTL reading: triangulation, vertex sharing, smooth and flat parts, the
// MTL illum mapping, warnings that do not stop a render, and errors with lines.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "io/io_test_helpers.h"
#include "renderer/io/errors.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/scene_loader.h"
#include "renderer/scene.h"
#include "support/vec_checks.h"

using namespace raylab;
using raylab::test::quiet;
using raylab::test::checkVec;
using raylab::test::contains;
using raylab::test::failureOf;
using raylab::test::TempDir;

namespace {


bool anyWarning(const ObjModel& m, const std::string& needle) {
    for (const std::string& w : m.warnings)
        if (contains(w, needle)) return true;
    return false;
}

/// A unit cube: 8 corners, 6 quads counter-clockwise seen from outside,
/// one normal per face (so 24 distinct position/normal pairs).
const char* kCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n"
    "f 1//1 4//1 3//1 2//1\n"
    "f 5//2 6//2 7//2 8//2\n"
    "f 1//3 2//3 6//3 5//3\n"
    "f 4//4 8//4 7//4 3//4\n"
    "f 1//5 5//5 8//5 4//5\n"
    "f 2//6 3//6 7//6 6//6\n";

}  // namespace

TEST_CASE("obj: quads are triangulated, flat faces share positions") {
    TempDir dir;
    // The cube without normals: 8 shared vertices, 12 triangles.
    const std::string path =
        dir.write("cube.obj",
                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                  "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n");
    const ObjModel m = loadObj(path, quiet());
    REQUIRE(m.parts.size() == 1);
    const TriangleMesh& mesh = *m.parts[0].mesh;
    CHECK(mesh.positions.size() == 8);
    CHECK(mesh.triangleCount() == 12);
    CHECK(!mesh.hasNormals());
    CHECK(m.triangleCount() == 12);
    CHECK(m.warnings.empty());
    // Outward winding survives triangulation: each normal points away from the centre.
    for (const auto& t : mesh.triangles) {
        const auto& P = mesh.positions;
        const Vec3 n = cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]]);
        const Vec3 c = (P[t[0]] + P[t[1]] + P[t[2]]) / 3.0;
        CHECK(dot(n, c - Vec3(0.5, 0.5, 0.5)) > 0);
    }
    // No MTL: every face uses the appended grey default, which the ambient term also lights.
    REQUIRE(m.materials.size() == 1);
    CHECK(m.materials[0].name == "default");
    CHECK(m.materials[0].kd == Color(0.8, 0.8, 0.8));
    CHECK(m.materials[0].ka == Color(0.8, 0.8, 0.8));
    for (uint32_t f : m.parts[0].faceMaterials) CHECK(f == 0);
}

TEST_CASE("obj: vertex normals give a smooth part, one vertex per position/normal pair") {
    TempDir dir;
    const ObjModel m = loadObj(dir.write("cube.obj", kCube), quiet());
    REQUIRE(m.parts.size() == 1);
    const TriangleMesh& mesh = *m.parts[0].mesh;
    CHECK(mesh.positions.size() == 24);  // 6 faces × 4 corners, none shared
    CHECK(mesh.triangleCount() == 12);
    REQUIRE(mesh.hasNormals());
    REQUIRE(mesh.normals.size() == mesh.positions.size());
    // Each triangle's vertex normals equal its geometric normal here.
    for (const auto& t : mesh.triangles) {
        const auto& P = mesh.positions;
        const Vec3 n = normalize(cross(P[t[1]] - P[t[0]], P[t[2]] - P[t[0]]));
        for (int k = 0; k < 3; ++k) checkVec(mesh.normals[t[k]], n);
    }
}

TEST_CASE("obj: faces with and without normals become two parts") {
    TempDir dir;
    const std::string path =
        dir.write("mixed.obj",
                  "o mixed\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 2\n"
                  "f 1//1 2//1 3//2\n"
                  "f 2 4 3\n");
    const ObjModel m = loadObj(path, quiet());
    REQUIRE(m.parts.size() == 2);
    const TriangleMesh& smooth = *m.parts[0].mesh;
    const TriangleMesh& flat = *m.parts[1].mesh;
    CHECK(smooth.hasNormals());
    CHECK(smooth.triangleCount() == 1);
    checkVec(smooth.normals[2], {0, 0, 1});  // (0, 0, 2) normalised
    CHECK(!flat.hasNormals());
    CHECK(flat.triangleCount() == 1);
    checkVec(flat.positions[flat.triangles[0][1]], {1, 1, 0});

    Scene scene;
    appendObjModel(scene, m, "thing");
    REQUIRE(scene.objects.size() == 2);
    CHECK(scene.objects[0].name == "thing");
    CHECK(scene.objects[1].name == "thing (flat)");
    REQUIRE(scene.materials.size() == 1);
    CHECK(scene.materials[0].name == "thing/default");
    CHECK(scene.objects[0].faceMaterials.empty());  // one material: no per-face table
}

TEST_CASE("obj: one-value colours and 'd -halo' read as the MTL format defines them") {
    // tinyobjloader alone reads "Kd 0.5" as (0.5, 0, 0) and "d -halo 0.25" as d = 0.
    TempDir dir;
    dir.write("m.mtl", "newmtl a\nillum 4\nKd 0.5\nKs 0.25\nd -halo 0.25\nKa 0.125 # c\n");
    const ObjModel m = loadObj(
        dir.write("m.obj", "mtllib m.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
        quiet());
    REQUIRE(m.materials.size() == 1);
    // d = 0.25 (dissolve): the surface terms a quarter, kt = 1 - d.
    CHECK(m.materials[0].kd == Color(0.125, 0.125, 0.125));
    CHECK(m.materials[0].ks == Color(0.0625, 0.0625, 0.0625));
    CHECK(m.materials[0].kt == Color(0.75, 0.75, 0.75));
    CHECK(m.materials[0].ka == Color(0.03125, 0.03125, 0.03125));
}

TEST_CASE("obj: MTL illum models map to Whitted materials") {
    TempDir dir;
    // Values are exact in float, so the mapping can be checked with ==.
    dir.write(
        "m.mtl",
        "newmtl plain0\nKa 0.25 0.25 0.25\nKd 0.5 0.5 0.5\nKs 0.75 0.75 0.75\nillum 0\n"
        "newmtl matte1\nKa 0.25 0.25 0.25\nKd 0.5 0.25 0.125\nKs 0.75 0.75 0.75\nillum 1\n"
        "newmtl shiny2\nKd 0.5 0.5 0.5\nKs 0.75 0.5 0.25\nNs 50\nillum 2\nd 0.5\nmap_Kd t.png\n"
        "newmtl mirror3\nKd 0.125 0.125 0.125\nKs 0.75 0.5 0.25\nillum 3\n"
        "newmtl glass4\nKs 0.5 0.5 0.5\nd 0.25\nNi 1.25\nillum 4\n"
        "newmtl fresnel5\nKs 0.25 0.5 0.75\nillum 5\n"
        "newmtl glass6\nKs 0.5 0.5 0.5\nTf 0.5 0.625 0.75\nd 0.25\nNi 1.5\nillum 6\n"
        "newmtl glass7\nKs 0.5 0.5 0.5\nTr 0.375\nNi 1.5\nillum 7\n");
    std::string obj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (const char* name :
         {"glass7", "plain0", "matte1", "shiny2", "mirror3", "glass4", "fresnel5", "glass6"})
        obj += std::string("usemtl ") + name + "\nf 1 2 3\n";
    const ObjModel m = loadObj(dir.write("m.obj", obj), quiet());
    REQUIRE(m.materials.size() == 8);  // every face has a material: no default added
    const auto& M = m.materials;
    // MTL file order: plain0, matte1, shiny2, mirror3, glass4, fresnel5, glass6, glass7.
    CHECK(M[0].name == "plain0");
    // illum 0, colour only: no ambient, no highlight.
    CHECK(M[0].kd == Color(0.5, 0.5, 0.5));
    CHECK(M[0].ka.isBlack());
    CHECK(M[0].ks.isBlack());
    // illum 1, diffuse: ambient kept, no highlight.
    CHECK(M[1].ka == Color(0.25, 0.25, 0.25));
    CHECK(M[1].kd == Color(0.5, 0.25, 0.125));
    CHECK(M[1].ks.isBlack());
    // illum 2 with d 0.5: dissolve, half the surface and half see-through,
    // unbent (ior 1): kd 0.5 -> 0.25, ks (0.75, 0.5, 0.25) -> half of it.
    CHECK(M[2].ks == Color(0.375, 0.25, 0.125));
    CHECK(M[2].kd == Color(0.25, 0.25, 0.25));
    CHECK(M[2].shininess == 50);
    CHECK(M[2].km.isBlack());
    CHECK(M[2].kt == Color(0.5, 0.5, 0.5));
    CHECK(M[2].ior == 1.0);
    // illum 3 (and 5): mirror km = Ks.
    CHECK(M[3].km == Color(0.75, 0.5, 0.25));
    CHECK(M[3].kd == Color(0.125, 0.125, 0.125));
    CHECK(M[5].km == Color(0.25, 0.5, 0.75));
    CHECK(M[5].kt.isBlack());
    // illum 4 ("glass on", no refraction): dissolve d = 0.25: kt = 0.75, Ni
    // not used (ior 1), the ray-traced reflection km = Ks scaled by d.
    CHECK(M[4].kt == Color(0.75, 0.75, 0.75));
    CHECK(M[4].ior == 1.0);
    CHECK(M[4].km == Color(0.125, 0.125, 0.125));
    // illum 6: Tf wins over d.
    CHECK(M[6].kt == Color(0.5, 0.625, 0.75));
    CHECK(M[6].ior == 1.5);
    // illum 7: "Tr 0.375" means d = 0.625, so kt = 0.375.
    CHECK(M[7].kt == Color(0.375, 0.375, 0.375));
    CHECK(M[7].km == Color(0.5, 0.5, 0.5));
    // Non-transmissive materials keep ior 1 (tinyobjloader's default Ni).
    CHECK(M[0].ior == 1.0);

    // Per-face materials in face order.
    REQUIRE(m.parts.size() == 1);
    const std::vector<uint32_t> expected = {7, 0, 1, 2, 3, 4, 5, 6};
    CHECK(m.parts[0].faceMaterials == expected);
    // t.png does not exist: one warning, and the material is read untextured.
    CHECK(anyWarning(m, "shiny2': map_Kd: texture not read ("));

    // In a scene the indices are offset past the scene's own materials.
    Scene scene;
    scene.materials.resize(2);
    appendObjModel(scene, m, "m.obj");
    REQUIRE(scene.materials.size() == 10);
    CHECK(scene.materials[2].name == "m.obj/plain0");
    REQUIRE(scene.objects.size() == 1);
    const std::vector<uint32_t> offset = {9, 2, 3, 4, 5, 6, 7, 8};
    CHECK(scene.objects[0].faceMaterials == offset);
    // An override replaces them all and adds none.
    Scene scene2;
    scene2.materials.resize(1);
    appendObjModel(scene2, m, "m.obj", 0u);
    CHECK(scene2.materials.size() == 1);
    CHECK(scene2.objects[0].material == 0);
    CHECK(scene2.objects[0].faceMaterials.empty());
}

TEST_CASE("obj: a missing MTL is a warning and the mesh still loads") {
    TempDir dir;
    const std::string path = dir.write("nomtl.obj",
                                       "mtllib nothere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                       "usemtl a\nf 1 2 3\nusemtl b\nf 1 3 2\nusemtl a\nf 3 2 1\n");
    const ObjModel m = loadObj(path, quiet());
    CHECK(m.triangleCount() == 3);
    // One warning, at the mtllib line, not tinyobjloader's three messages.
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == path + ":1: material library 'nothere.mtl' not found beside the OBJ; "
                           "its materials get the default material");
    REQUIRE(m.materials.size() == 1);
    CHECK(m.materials[0].name == "default");
}

TEST_CASE("obj: a material the MTL does not define is one warning at its first usemtl") {
    TempDir dir;
    dir.write("lib.mtl", "newmtl red\nKd 1 0 0\n");
    const std::string path = dir.write("undef.obj",
                                       "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                       "usemtl red\nf 1 2 3\nusemtl blue\nf 1 3 2\n"
                                       "usemtl blue\nf 3 2 1\n");
    const ObjModel m = loadObj(path, quiet());
    CHECK(m.triangleCount() == 3);
    // Repeated warnings are reported once with a count.
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == path + ":7: material 'blue' is not defined in the MTL libraries; the "
                           "default material is used (2 times)");

    // Whole names: 'bl' is reported at its own usemtl, not at 'blue'. The
    // first of two libraries is missing, the second loads: both the missing
    // library and the undefined name are reported.
    const std::string two = dir.write("two.obj",
                                      "mtllib gone.mtl lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                      "usemtl blue\nf 1 2 3\nusemtl bl\nf 1 3 2\n");
    const ObjModel t = loadObj(two, quiet());
    REQUIRE(t.warnings.size() == 3);
    CHECK(t.warnings[0] == two + ":1: material library 'gone.mtl' not found beside the OBJ; its "
                               "materials get the default material");
    CHECK(t.warnings[1].rfind(two + ":5: material 'blue'", 0) == 0);
    CHECK(t.warnings[2].rfind(two + ":7: material 'bl'", 0) == 0);
}

TEST_CASE("obj: bad face indices are errors with the face's line") {
    TempDir dir;
    struct Case {
        const char* text;
        int line;
        const char* message;
    };
    const Case cases[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# comment\nf 1 2 9\n", 6,
         "face refers to vertex 9 but the file has 3 vertices"},
        // Relative index -4 with three vertices read so far.
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 -2 -1\n", 4, "face refers to vertex -4"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//5\n", 5,
         "face refers to normal 5 but the file has 1 normal"},
        // A quad: tinyobjloader alone would drop it silently.
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 7\n", 5, "face refers to vertex 7"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 0 1 2\n", 5, "face refers to vertex 0"},
        // A 6-gon goes through tinyobjloader's ear clipping, which reads vertices unchecked.
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 1 2 30\n", 4, "face refers to vertex 30"},
    };
    for (const Case& c : cases) {
        const std::string text = c.text;
        CAPTURE(text);
        const std::string path = dir.write("bad.obj", c.text);
        const test::Failure f = failureOf([&] { loadObj(path, quiet()); });
        CAPTURE(f.message);
        CHECK(f.file == path);
        CHECK(f.line == c.line);
        CHECK(contains(f.message, c.message));
    }
    // A positive index may refer to a vertex defined later in the file (as in tinyobjloader).
    CHECK(loadObj(dir.write("fwd.obj", "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n"), quiet())
              .triangleCount() == 1);
}

TEST_CASE("obj: degenerate triangles, empty files and missing files") {
    TempDir dir;
    const ObjModel m = loadObj(
        dir.write("degen.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\nf 1 2 4\n"),
        quiet());
    CHECK(m.triangleCount() == 1);
    // Reported at the first such face's line, with the count.
    CHECK(anyWarning(m, "degen.obj:6: face has zero area; dropped (2 times)"));

    test::Failure f = failureOf([&] { loadObj(dir.write("empty.obj", "v 0 0 0\n"), quiet()); });
    CHECK(f.message == "the OBJ file has no faces");
    CHECK(f.line == 0);
    f = failureOf([&] {
        loadObj(dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\n# collinear\nf 1 2 3\n"), quiet());
    });
    CHECK(f.message ==
          "the OBJ file has no triangles: every face has zero area or fewer than 3 corners");
    CHECK(f.line == 5);
    f = failureOf([&] { loadObj(dir.file("absent.obj"), quiet()); });
    CHECK(f.file == dir.file("absent.obj"));
    CHECK(f.message == "cannot open: No such file or directory");
}

TEST_CASE("obj scene: the silhouette framed to 80%, a key, fill and rim light, low ambient") {
    TempDir dir;
    const Scene s = loadObjScene(dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    CHECK(s.sourcePath == dir.file("tri.obj"));
    REQUIRE(s.objects.size() == 1);
    CHECK(test::meshOf(s.objects[0]) != nullptr);
    CHECK(s.camera.projection() == Camera::Projection::Perspective);
    CHECK(s.camera.vfovDegrees() == 40);
    // Seen from (1, 0.6, 1.5) with +y up (renderer/first_look.h; its own tests check the fit).
    checkVec(s.camera.frame().w, normalize(Vec3(1, 0.6, 1.5)));
    CHECK(s.camera.up() == Vec3(0, 1, 0));
    REQUIRE(s.lights.size() == 3);
    for (const Light& l : s.lights) CHECK(l.type == Light::Type::Directional);
    CHECK(s.ambient.maxComponent() < 0.1);
    CHECK(!s.ambient.isBlack());
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].kd == Color(0.8, 0.8, 0.8));
}

TEST_CASE("obj: the demo meshes in scenes/meshes") {
    const std::string dir = std::string(RAYLAB_SOURCE_DIR) + "/scenes/meshes/";
    // Torus: 36 x 18 quads with normals = 1296 triangles over 648 vertices.
    const ObjModel torus = loadObj(dir + "torus.obj", quiet());
    CHECK(torus.warnings.empty());
    REQUIRE(torus.parts.size() == 1);
    CHECK(torus.parts[0].mesh->hasNormals());
    CHECK(torus.parts[0].mesh->positions.size() == 648);
    CHECK(torus.triangleCount() == 1296);
    REQUIRE(torus.materials.size() == 1);
    CHECK(torus.materials[0].name == "coral");
    // Gem: an icosphere subdivided once, 42 vertices and 80 flat triangles,
    // gold (illum 3: km = Ks) on top and glass (illum 7: kt = 1 - d, ior Ni) below.
    const ObjModel gem = loadObj(dir + "gem.obj", quiet());
    CHECK(gem.warnings.empty());
    REQUIRE(gem.parts.size() == 1);
    CHECK(!gem.parts[0].mesh->hasNormals());
    CHECK(gem.parts[0].mesh->positions.size() == 42);
    CHECK(gem.triangleCount() == 80);
    REQUIRE(gem.materials.size() == 2);
    CHECK(gem.materials[0].km.r == doctest::Approx(0.8).epsilon(1e-6));
    CHECK(gem.materials[1].kt.g == doctest::Approx(0.9).epsilon(1e-6));
    CHECK(gem.materials[1].ior == doctest::Approx(1.5));
}

TEST_CASE("obj: the shared Stanford bunny (when ../shared is present)") {
    const std::string path = std::string(RAYLAB_SHARED_DIR) + "/models/bunny.obj";
    if (!std::filesystem::exists(path)) {
        MESSAGE("skipped: " << path << " not present");
        return;
    }
    const ObjModel m = loadObj(path, quiet());
    // README: 1839 vertices, 3674 triangles, no normals.
    REQUIRE(m.parts.size() == 1);
    CHECK(!m.parts[0].mesh->hasNormals());
    CHECK(m.parts[0].mesh->positions.size() == 1839);
    CHECK(m.triangleCount() == 3674);
}

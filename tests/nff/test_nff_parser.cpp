// NFF reader: every entity on small snippets, the SPD mapping (materials,
// light intensities, sidedness), the token-stream layout rules, and every
// error with the exact line it is reported on.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>

#include "geometry/triangle_mesh.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"
#include "shape_queries.h"

using namespace raylab;

namespace {

/// A complete viewpoint block (lines 1-7) that the snippets below append to.
const std::string kView =
    "v\n"                      // 1
    "from 0 0 5\n"             // 2
    "at 0 0 0\n"               // 3
    "up 0 1 0\n"               // 4
    "angle 40\n"               // 5
    "hither 0.5\n"             // 6
    "resolution 32 24\n";      // 7

Scene load(const std::string& text) { return loadNffScene(text, "t.nff"); }

struct Failure {
    int line = -1;  ///< -1: nothing was thrown
    std::string message;
    std::string located;
};

Failure failureOf(const std::string& text) {
    try {
        load(text);
    } catch (const InputError& e) {
        return {e.line(), e.what(), e.located()};
    }
    return {};
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

const Object* findObject(const Scene& s, const std::string& prefix) {
    for (const Object& o : s.objects)
        if (o.name.rfind(prefix, 0) == 0) return &o;
    return nullptr;
}

}  // namespace

TEST_CASE("nff: the viewpoint block sets camera, near distance and resolution") {
    const Scene s = load(kView + "s 0 0 0 1\n");
    const CameraFrame& f = s.camera.frame();
    CHECK(f.eye == Vec3(0, 0, 5));
    // w points from the look-at point back to the eye: +z; u = up x w = +x.
    CHECK(f.w.z == doctest::Approx(1.0));
    CHECK(f.u.x == doctest::Approx(1.0));
    CHECK(f.v.y == doctest::Approx(1.0));
    CHECK(s.camera.vfovDegrees() == 40.0);
    CHECK(s.cameraNear == 0.5);
    CHECK(s.image.width == 32);
    CHECK(s.image.height == 24);
    CHECK(s.image.maxDepth == 5);
    CHECK(s.background.isBlack());  // no 'b': black
}

TEST_CASE("nff: background, lights without colour get sqrt(L)/(2L), with colour keep it") {
    const Scene s = load(kView +
                         "b 0.1 0.2 0.3\n"
                         "l 1 2 3\n"
                         "l 4 5 6 0.5 0.25 1\n"
                         "s 0 0 0 1\n");
    CHECK(s.background.r == 0.1);
    CHECK(s.background.g == 0.2);
    CHECK(s.background.b == 0.3);
    REQUIRE(s.lights.size() == 2);
    // L = 2 lights: sqrt(2) / 4 = 0.353553...; the ambient term gets the same.
    const double i2 = std::sqrt(2.0) / 4.0;
    CHECK(s.lights[0].type == Light::Type::Point);
    CHECK(s.lights[0].position == Vec3(1, 2, 3));
    CHECK(s.lights[0].intensity.r == doctest::Approx(i2));
    CHECK(s.lights[0].intensity.b == doctest::Approx(i2));
    CHECK(s.lights[1].position == Vec3(4, 5, 6));
    CHECK(s.lights[1].intensity.r == 0.5);
    CHECK(s.lights[1].intensity.g == 0.25);
    CHECK(s.lights[1].intensity.b == 1.0);
    CHECK(s.ambient.g == doctest::Approx(i2));

    // L = 3 (balls, rings): sqrt(3) / 6 = 0.288675...
    const Scene t = load(kView + "l 1 0 0\nl 2 0 0\nl 3 0 0\n");
    CHECK(t.lights[2].intensity.r == doctest::Approx(0.2886751346));
    CHECK(t.ambient.r == doctest::Approx(0.2886751346));
}

TEST_CASE("nff: f maps colour, Kd, Ks, Shine, T and ior onto the Whitted material") {
    const Scene s = load(kView +
                         "f 1 0.5 0.25 0.8 0.3 20 0 0\n"  // 8: opaque, ior 0 as SPD writes it
                         "s 0 0 0 1\n"                    // 9
                         "f 1 1 1 0.2 0 100000 0.8 1.1\n" // 10: transmitter
                         "s 3 0 0 1\n");                  // 11
    REQUIRE(s.materials.size() == 2);
    const Material& m = s.materials[0];
    CHECK(m.kd.r == doctest::Approx(0.8));  // colour · Kd
    CHECK(m.kd.g == doctest::Approx(0.4));
    CHECK(m.kd.b == doctest::Approx(0.2));
    CHECK(m.ka.g == doctest::Approx(0.4));  // ambient uses the diffuse colour
    CHECK(m.ks.r == 0.3);                   // white highlight
    CHECK(m.ks.b == 0.3);
    CHECK(m.shininess == 20);
    CHECK(m.highlight == Highlight::Phong);  // SPD: Shine is a Phong cosine power
    CHECK(m.km.g == 0.3);  // mirror reflection weight Ks
    CHECK(m.kt.isBlack());
    CHECK(m.ior == 1.0);   // ignored ior 0 of an opaque surface
    const Material& g = s.materials[1];
    CHECK(g.kt.r == 0.8);
    CHECK(g.ior == 1.1);
    CHECK(g.km.isBlack());
    REQUIRE(s.objects.size() == 2);
    CHECK(s.objects[0].material == 0);
    CHECK(s.objects[1].material == 1);
    CHECK(s.objects[0].name == "sphere@9");
    CHECK(s.objects[1].name == "sphere@11");
}

TEST_CASE("nff: sidedness: one-sided objects, two-sided transmitters, negative radii inside") {
    const Scene s = load(kView +
                         "s 0 0 0 1\n"                          // 8
                         "s 0 0 0 -2\n"                         // 9
                         "c 0 0 0 -1 0 1 0 -1\n"                // 10
                         "c 0 0 0 0.5 0 1 0 0\n"                // 11: pointed cone
                         "p 4 0 0 0 1 0 0 1 1 0 0 1 0\n"        // 12
                         "f 1 1 1 0.1 0 1 0.9 1.5\n"            // 13
                         "s 5 0 0 1\n"                          // 14
                         "s 5 0 0 -0.5\n");                     // 15
    REQUIRE(s.objects.size() == 7);
    CHECK(findObject(s, "sphere@8")->shape->sidedness() == Sidedness::Outside);
    CHECK(findObject(s, "sphere@9")->shape->sidedness() == Sidedness::Inside);
    CHECK(findObject(s, "sphere@9")->shape->bounds().hi.x >= 2.0);  // |r| = 2
    CHECK(findObject(s, "cone@10")->shape->sidedness() == Sidedness::Inside);
    CHECK(findObject(s, "cone@11")->shape->sidedness() == Sidedness::Outside);
    CHECK(findObject(s, "polygon@12")->shape->sidedness() == Sidedness::Outside);
    CHECK(findObject(s, "sphere@14")->shape->sidedness() == Sidedness::Both);
    CHECK(findObject(s, "sphere@15")->shape->sidedness() == Sidedness::Both);
    // Objects before any 'f' get the white default material.
    CHECK(s.materials[0].name == "nff_default");
    CHECK(s.materials[0].kd.r == 1.0);
}

TEST_CASE("nff: cone end points on two lines (format document) or one line (SPD)") {
    const Scene two = load(kView + "c\n0 0 0 1\n0 2 0 0.5\n");
    const Scene one = load(kView + "c 0 0 0 1 0 2 0 0.5\n");
    REQUIRE(two.objects.size() == 1);
    REQUIRE(one.objects.size() == 1);
    CHECK(std::string(two.objects[0].shape->kind()) == std::string(one.objects[0].shape->kind()));
    const Bounds3 a = two.objects[0].shape->bounds(), b = one.objects[0].shape->bounds();
    CHECK(a.lo == b.lo);
    CHECK(a.hi == b.hi);
    // NFF cones have no caps: a ray up the axis enters through the open base
    // (a capped cone would be hit at y = 0), stays inside the lateral surface
    // and leaves through the open top (radius 0.5 at y = 2): no hit at all.
    const Ray axis{{0, -5, 0}, {0, 1, 0}};
    CHECK_FALSE(intersect1(*one.objects[0].shape, axis, 0, 100).has_value());
}

TEST_CASE("nff: polygons: triangles to a mesh, larger polygons analytic, pp smooth") {
    const Scene s = load(kView +
                         "f 1 0 0 1 0 1 0 1\n"                       // 8
                         "p 3\n0 0 0\n1 0 0\n0 1 0\n"                // 9-12
                         "f 0 1 0 1 0 1 0 1\n"                       // 13
                         "p 3 0 0 1 1 0 1 0 1 1\n"                   // 14: one line
                         "p 4\n0 0 2\n1 0 2\n1 1 2\n0 1 2\n"         // 15-19
                         "pp 3\n"                                    // 20
                         "0 0 3 -1 0 1\n"                            // 21
                         "1 0 3 1 0 1\n"                             // 22
                         "0 1 3 0 0 2\n"                             // 23
                         "pp 4\n0 0 4 0 0 1\n1 0 4 0 0 1\n1 1 4 0 0 1\n0 1 4 0 0 1\n");  // 24
    REQUIRE(s.objects.size() == 4);
    const Object* flat = findObject(s, "triangles");
    const Object* smooth = findObject(s, "patches");
    REQUIRE(flat);
    REQUIRE(smooth);
    CHECK(flat->shape->nativeTriangles()->triangleCount() == 2);
    CHECK_FALSE(flat->shape->nativeTriangles()->hasNormals());
    // Two materials in one mesh: a per-face table.
    REQUIRE(flat->faceMaterials.size() == 2);
    CHECK(flat->materialOf(0) == 0);
    CHECK(flat->materialOf(1) == 1);
    CHECK(smooth->shape->nativeTriangles()->triangleCount() == 1);
    REQUIRE(smooth->shape->nativeTriangles()->hasNormals());
    CHECK(findObject(s, "polygon@15"));
    CHECK(std::string(findObject(s, "polygon@15")->shape->kind()) == "polygon");
    CHECK(findObject(s, "patch@24"));

    // Smooth shading: a ray down -z onto the pp triangle at its centroid
    // (1/3, 1/3, 3) sees the mean of the unit vertex normals
    // (-1,0,1)/√2, (1,0,1)/√2 and (0,0,1): x cancels, so ns = +z; at the
    // point (0.1, 0.1, 3), barycentrics u = v = 0.1 (w0 = 0.8):
    // 0.8·(-0.7071, 0, 0.7071) + 0.1·(0.7071, 0, 0.7071) + 0.1·(0, 0, 1)
    // = (-0.49497, 0, 0.73640) -> normalised x = -0.55777.
    const uint32_t smoothIndex = uint32_t(smooth - s.objects.data());
    Hit h;
    h.object = smoothIndex;
    h.prim = 0;
    h.t = 7;
    const SurfaceInteraction si = s.surfaceAt(Ray{{0.1, 0.1, 10}, {0, 0, -1}}, h);
    CHECK(si.ns.x == doctest::Approx(-0.55777).epsilon(1e-4));
    CHECK(si.ng.z == doctest::Approx(1.0));  // counter-clockwise from +z
    CHECK(si.frontFace);
    const SurfaceInteraction c = s.surfaceAt(Ray{{1.0 / 3, 1.0 / 3, 10}, {0, 0, -1}}, h);
    CHECK(c.ns.x == doctest::Approx(0.0).epsilon(1e-9));
}

TEST_CASE("nff: zero-area polygons are dropped, ior 0 of opaque surfaces accepted") {
    const Scene s = load(kView +
                         "f 1 1 1 1 0 1 0 0\n"
                         "p 3 0 0 0 1 0 0 2 0 0\n"            // collinear triangle
                         "p 4 0 0 0 1 1 1 2 2 2 3 3 3\n"      // collinear quad
                         "p 3 1 1 1 1 1 1 1 1 1\n"            // a point
                         "s 0 0 0 1\n");
    REQUIRE(s.objects.size() == 1);
    CHECK(s.objects[0].name == "sphere@12");
}

TEST_CASE("nff: numbers: signs, exponents, underflow to zero") {
    // "+1" is accepted (from_chars alone would not), ".5" and "1." too; a
    // literal below the smallest denormal underflows to 0 rather than failing.
    const Scene s = load(kView + "s +1 .5 1. 1\ns 1e-400 -0.0 0." + std::string(400, '0') +
                         "1 2E0\n");
    REQUIRE(s.objects.size() == 2);
    const Bounds3 a = s.objects[0].shape->bounds();
    CHECK(a.lo.x == doctest::Approx(0.0).epsilon(1e-3));  // centre x 1, radius 1 (padded)
    CHECK(a.hi.y == doctest::Approx(1.5).epsilon(1e-3));
    const Bounds3 b = s.objects[1].shape->bounds();
    CHECK(b.hi.x == doctest::Approx(2.0).epsilon(1e-3));  // centre (0, 0, 0), radius 2
}

TEST_CASE("nff: comments, tabs, CRLF, a UTF-8 byte-order mark and one-line files") {
    const std::string crlf =
        "\xEF\xBB\xBF# header comment\r\nv\r\nfrom 0 0 5 # eye\r\nat 0 0 0\r\nup 0 1 0\r\n"
        "angle 40\r\nhither 1\r\nresolution 8 8\r\n\ts\t0 0 0#no space before the comment\r\n"
        "  1\r\n";
    const Scene a = load(crlf);
    REQUIRE(a.objects.size() == 1);
    CHECK(a.objects[0].name == "sphere@9");  // the line of 's', not of its radius
    // The whole scene on one line, as a token stream.
    const Scene b = load("v from 0 0 5 at 0 0 0 up 0 1 0 angle 40 hither 1 resolution 8 8 "
                         "l 1 1 1 f 1 1 1 1 0 1 0 0 s 0 0 0 1 p 3 0 0 0 1 0 0 0 1 0");
    CHECK(b.objects.size() == 2);
    CHECK(b.lights.size() == 1);
    CHECK(b.image.width == 8);
}

TEST_CASE("nff: every error names the exact line") {
    struct Case {
        const char* name;
        std::string text;
        int line;
        const char* says;
    };
    const Case cases[] = {
        {"unknown entity", kView + "s 0 0 0 1\nq 1 2 3\n", 9, "unknown entity 'q'"},
        {"too few numbers (sphere)", kView + "s 0 0 0\ns 1 1 1 1\n", 8,
         "s: expected 4 numbers (x y z radius), got 3 numbers before 's' on line 9"},
        {"too few numbers at EOF", kView + "\n\ns 0 0\n\n", 10,
         "s: unexpected end of file: expected 4 numbers (x y z radius), got 2 numbers"},
        {"too few numbers, entity over two lines", kView + "c 0 0 0 1\n0 1 0\n\ns 0 0 0 1\n", 9,
         "c: expected 8 numbers (base x y z radius, apex x y z radius), got 7 numbers before 's' "
         "on line 11 ('c' starts on line 8)"},
        {"too many numbers", kView + "s 0 0 0 1 2\n", 8, "too many numbers for 's'"},
        {"too many numbers, entity over two lines", kView + "s 0 0\n0 1\n2\n", 10,
         "too many numbers for 's' ('s' starts on line 8)"},
        {"number before any entity", "1 v\n", 1, "unexpected number '1' before any entity"},
        {"material missing ior", kView + "f 1 1 1 1 0 1 0\ns 0 0 0 1\n", 8,
         "f: expected 8 numbers (R G B Kd Ks Shine T ior), got 7 numbers before 's' on line 9"},
        {"light with 2 colour numbers", kView + "l 0 0 9 1 1\ns 0 0 0 1\n", 8,
         "expected 3 or 6 numbers"},
        {"truncated polygon (next entity)", kView + "p 4\n0 0 0\n1 0 0\n1 1 0\ns 0 0 0 1\n", 11,
         "p: truncated polygon: expected 4 vertices of 3 numbers (x y z), got 9 numbers before "
         "'s' on line 12 ('p' starts on line 8)"},
        {"truncated polygon (end of file)", kView + "p 3\n0 0 0\n1 0 0\n0 1\n", 11,
         "p: unexpected end of file: truncated polygon: expected 3 vertices of 3 numbers (x y z), "
         "got 8 numbers ('p' starts on line 8)"},
        {"polygon count beyond the file", kView + "p 3\n0 0 0\n1 0 0\n", 8,
         "p: truncated polygon: vertex count 3 exceeds what the file holds"},
        {"polygon vertex short of a number", kView + "p 3\n0 0 0\n1 0\n0 1 0\ns 0 0 0 1\n", 11,
         "got 8 numbers before 's' on line 12 ('p' starts on line 8) (vertex 2 starts on line 10 "
         "and continues on the next line: a number missing there?)"},
        {"patch without normals", kView + "pp 3\n0 0 0\n1 0 0\n0 1 0\n", 8, "truncated polygon"},
        {"not a number", kView + "s 0 0\nzero 1\n", 9,
         "s: expected a number for centre z, got 'zero'"},
        {"number with trailing junk", kView + "s 0 0 0 1.5x\n", 8, "got '1.5x'"},
        {"comma decimal", kView + "s 0 0 0 1,5\n", 8, "got '1,5'"},
        {"NaN", kView + "s 0 nan 0 1\n", 8, "centre y must be a finite number, got 'nan'"},
        {"Inf", kView + "l 0 0 0\ns 0 0 0 inf\n", 9, "radius must be a finite number"},
        {"overflow", kView + "\ns 1e999 0 0 1\n", 9, "out of range: '1e999'"},
        {"overflow with junk", kView + "s 0 0 0 1e999x\n", 8,
         "expected a number for radius, got '1e999x'"},
        {"long junk token", kView + "s 0 0 0 " + std::string(100, '7') + "x\n", 8,
         "got '7777777777777777777777777777777777777777...'"},
        {"absurd polygon count", kView + "p 2000000000\n0 0 0\n", 8,
         "p: vertex count 2000000000 exceeds the limit of 1048576"},
        {"absurd patch count", kView + "pp 1e15\n", 8, "exceeds the limit"},
        {"count the file cannot hold", kView + "p 1000\n0 0 0\n", 8,
         "p: truncated polygon: vertex count 1000 exceeds what the file holds (1000 vertices need "
         "at least 5999 more bytes, the file ends after 7)"},
        {"polygon count below 3", kView + "p 2\n0 0 0\n1 1 1\n", 8, "p: vertex count 2 is below 3"},
        {"negative polygon count", kView + "p -5\n", 8, "vertex count -5 is below 3"},
        {"fractional polygon count", kView + "\np 3.5\n", 9, "vertex count must be an integer"},
        {"polygon count not a number", kView + "p x\n", 8, "expected a number for vertex count"},
        {"zero patch normal", kView + "pp 3\n0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1\n", 10,
         "normal of vertex 2 is zero"},
        {"non-planar polygon", kView + "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 1\n", 8, "not coplanar"},
        {"zero sphere radius", kView + "l 0 0 0\n\ns 0 0 0 0\n", 10, "sphere"},
        {"cone radii of opposite signs", kView + "c 0 0 0 1 0 1 0 -1\n", 8, "opposite signs"},
        {"T > 0 with ior 0", kView + "f 1 1 1 1 0 1 0.5 0\n", 8,
         "index of refraction must be > 0 when T > 0"},
        {"negative Kd", kView + "f 1 1 1 -1 0 1 0 1\n", 8, "Kd, Ks and T must be >= 0"},
        {"angle out of range", "v\nfrom 0 0 1\nat 0 0 0\nup 0 1 0\nangle 180\n", 5,
         "field of view must be in (0, 180)"},
        {"negative hither", "v\nfrom 0 0 1\nat 0 0 0\nup 0 1 0\nangle 45\nhither -1\n", 6,
         "distance must be >= 0"},
        {"bad resolution", "v\nfrom 0 0 1\nat 0 0 0\nup 0 1 0\nangle 45\nresolution 0 10\n", 6,
         "resolution: expected two integers in [1, 65536]"},
        {"viewpoint incomplete", "v\nfrom 0 0 1\nat 0 0 0\nangle 45\ns 0 0 0 1\n", 0,
         "viewpoint incomplete: missing up"},
        {"eye at the look-at point", "\nv\nat 0 0 0\nfrom 0 0 0\nup 0 1 0\nangle 45\n", 4,
         "coincide"},
        {"zero up vector", "v\nfrom 0 0 1\nat 0 0 0\nup 0 0 0\nangle 45\n", 4, "zero length"},
        {"up along the view", "v\nfrom 0 0 1\nat 0 0 0\nangle 45\nup 0 0 -3\n", 5, "parallel"},
        {"UTF-16", std::string("\xFF\xFEv\0", 4), 1, "not a text file"},
        {"control bytes are escaped", kView + "s 0 0 0 1\n\x1b[2J\x89x\n", 9,
         "unknown entity '\\x1B[2J\\x89x'"},
    };
    for (const Case& c : cases) {
        const std::string caseName = c.name;
        CAPTURE(caseName);
        const Failure f = failureOf(c.text);
        CAPTURE(f.message);
        CHECK(f.line == c.line);
        CHECK(contains(f.message, c.says));
    }
    // The located form the app prints: "FILE:LINE: message".
    CHECK(failureOf(kView + "q\n").located == "t.nff:8: unknown entity 'q'");
    // No viewpoint at all: a file-level error (line 0, "FILE: message").
    const Failure none = failureOf("s 0 0 0 1\n");
    CHECK(none.line == 0);
    CHECK(contains(none.located, "t.nff: viewpoint incomplete: missing from, at, up, angle"));
}

TEST_CASE("nff: vertex counts are checked against the limit and the bytes left") {
    // 2e9 vertices would be 48 GB of Vec3: over the limit, refused before any
    // vertex is read or reserved.
    const Failure f = failureOf(kView + "p 2000000000\n" + std::string(100000, ' ') + "1 2 3\n");
    CHECK(f.line == 8);
    CHECK(contains(f.message, "exceeds the limit"));
    // Under the limit but more than the rest of the file can hold: each vertex
    // takes at least "0 0 0 " (6 bytes), so 1e6 vertices need 5999999 bytes and
    // the 100007 left after the count are not enough.
    const Failure g = failureOf(kView + "p 1000000\n" + std::string(100000, ' ') + "1 2 3\n");
    CHECK(g.line == 8);
    CHECK(contains(g.message, "(1000000 vertices need at least 5999999 more bytes, the file "
                              "ends after 100007)"));
    // A count the rest of the file can hold is read and then found short.
    const Failure h =
        failureOf(kView + "p 5\n0.0 0.0 0.0 1.0 0.0 0.0 1.0 1.0 0.0 0.0 1.0 0.0\n");
    CHECK(h.line == 9);
    CHECK(contains(h.message, "unexpected end of file: truncated polygon: expected 5 vertices of 3 "
                              "numbers (x y z), got 12 numbers ('p' starts on line 8)"));
}

TEST_CASE("nff: polygons are built while the text is read, and errors keep the file's order") {
    const std::string bad = "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 1\n";   // not coplanar
    const std::string good = "p 4\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";  // a unit square
    // The first of two bad polygons is reported, however many good ones
    // surround them (they are built several at a time).
    std::string many = kView;
    for (int i = 0; i < 500; ++i) many += good;  // lines 8 .. 2507
    many += bad;                                 // line 2508
    for (int i = 0; i < 500; ++i) many += good;
    many += bad;  // line 5013
    const Failure first = failureOf(many);
    CHECK(first.line == 2508);
    CHECK(contains(first.message, "not coplanar"));
    // A bad polygon before broken text: the polygon's error (its line comes
    // first), as when each polygon was built as soon as it was read.
    const Failure before = failureOf(kView + good + bad + "s 0 0 zero 1\n");
    CHECK(before.line == 13);
    CHECK(contains(before.message, "not coplanar"));
    // A bad polygon before a bad sphere (a factory error at its own line)
    // and before a missing viewpoint (a file-level error at the end): the
    // polygon's error, as when each was built in turn.
    const Failure beforeSphere = failureOf(kView + bad + "s 0 0 0 0\n");
    CHECK(beforeSphere.line == 8);
    CHECK(contains(beforeSphere.message, "not coplanar"));
    const Failure beforeEnd = failureOf("s 0 0 0 1\n" + bad);
    CHECK(beforeEnd.line == 2);
    CHECK(contains(beforeEnd.message, "not coplanar"));
    // A bad patch (pp, vertex normals) is reported alike.
    const Failure patch =
        failureOf(kView + "pp 4\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 1 0 0 1\n");
    CHECK(patch.line == 8);
    CHECK(contains(patch.message, "not coplanar"));
    // The same when the bad polygon's batch went to its builder while the
    // reader was still going (batches hand over every ~1,024 vertices): its
    // error, not the broken text's that follows, nor the later bad polygon's.
    std::string handedOver = kView;
    for (int i = 0; i < 300; ++i) handedOver += good;  // lines 8 .. 1507
    handedOver += bad;                                // line 1508
    for (int i = 0; i < 300; ++i) handedOver += good;
    handedOver += bad + "s 0 0 zero 1\n";  // lines 3013 and 3018
    const Failure early = failureOf(handedOver);
    CHECK(early.line == 1508);
    CHECK(contains(early.message, "not coplanar"));
    // Broken text before a bad polygon: the text's error.
    const Failure after = failureOf(kView + good + "s 0 0 zero 1\n" + bad);
    CHECK(after.line == 13);
    CHECK(contains(after.message, "expected a number for centre z"));
    // Every good polygon gets its shape, in order, with the entity's name.
    Scene s = loadNffScene(kView + good + "s 0 0 -5 1\n" + good +
                               "pp 4\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n",
                           "t.nff");
    REQUIRE(s.objects.size() == 4);
    CHECK(s.objects[0].name == "polygon@8");
    CHECK(s.objects[1].name == "sphere@13");
    CHECK(s.objects[2].name == "polygon@14");
    CHECK(s.objects[3].name == "patch@19");
    for (const Object& o : s.objects) CHECK(bool(o.shape));
    CHECK(std::string(s.objects[2].shape->kind()) == "polygon");
}

TEST_CASE("nff: loadScene dispatches .nff and reports the file name") {
    // A path that does not exist: the error names it (line 0).
    try {
        loadScene("/nonexistent/dir/scene.nff");
        FAIL("no error");
    } catch (const InputError& e) {
        CHECK(e.file() == "/nonexistent/dir/scene.nff");
        CHECK(e.line() == 0);
    }
}

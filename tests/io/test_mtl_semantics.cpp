// MTL files read as the format and the common exporters mean them: no illum is
// illumination model 2, no Ka is Ka = Kd (exact pixels under a known light),
// names keep their inner blanks and lose their outer ones, Windows paths and
// wrong letter case still find their files, statements raylab does not
// simulate are named once per file, and d, Tr and d -halo share one range.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "io/io_test_helpers.h"
#include "renderer/io/mtl_material.h"
#include "renderer/io/mtl_reader.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/scene_loader.h"

using namespace raylab;
using raylab::test::quiet;
using raylab::test::contains;
using raylab::test::failureOf;
using raylab::test::TempDir;

namespace {

/// A unit square at z = 0 facing +z, using material `name` from m.mtl.
std::string squareObj(const std::string& usemtl) {
    return "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl " + usemtl + "\nf 1 2 3 4\n";
}

/// The centre pixel of the square seen straight from above by an orthographic
/// camera, lit straight from above (N·L = 1, and H = N: the highlight is ks·I)
/// with intensity 1 and ambient 0.5.
Color centrePixel(const TempDir& dir, const std::string& mtl,
                  const std::string& background = "[0, 0, 0]") {
    dir.write("m.mtl", mtl);
    dir.write("sq.obj", squareObj("plastic"));
    const std::string json =
        "{\"background\": " + background + ", \"camera\": {\"type\": \"orthographic\", \"eye\": [0.5, 0.5, 3], \"direction\": "
        "[0, 0, -1], \"width\": 2}, \"ambient\": 0.5, \"lights\": [{\"type\": "
        "\"directional\", \"direction\": [0, 0, -1]}], \"objects\": [{\"type\": \"mesh\", "
        "\"file\": \"sq.obj\"}]}";
    const Film f = test::renderFilm(loadScene(dir.write("s.json", json)), "embree", 9, 9);
    const size_t i = f.index(4, 4);
    return Color(f.rgba[4 * i], f.rgba[4 * i + 1], f.rgba[4 * i + 2]);
}

}  // namespace

TEST_CASE("mtl: a material without illum or Ka, exact pixels under a known light") {
    TempDir dir;
    // Pixel = ka·Ia + kd·I·(N·L) + ks·I·(N·H)^Ns = ka·0.5 + kd + ks (all exact in float).
    // No illum -> illumination model 2 (highlight on); no Ka -> Ka = Kd:
    //   r = 0.5·0.5 + 0.5 + 0.25 = 1, g = 0.25·1.5 + 0.25 = 0.625, b = 0.125·1.5 + 0.25 = 0.4375.
    CHECK(centrePixel(dir, "newmtl plastic\nKd 0.5 0.25 0.125\nKs 0.25\nNs 8\n") ==
          Color(1, 0.625, 0.4375));
    // An explicit Ka 0 keeps shadows black: r = 0.5 + 0.25.
    CHECK(centrePixel(dir, "newmtl plastic\nKa 0 0 0\nKd 0.5 0.25 0.125\nKs 0.25\nNs 8\n") ==
          Color(0.75, 0.5, 0.375));
    // illum 0 (colour only) drops the ambient and the highlight: kd alone.
    CHECK(centrePixel(dir, "newmtl plastic\nKd 0.5 0.25 0.125\nKs 0.25\nNs 8\nillum 0\n") ==
          Color(0.5, 0.25, 0.125));
    // illum 1 (diffuse) drops the highlight only.
    CHECK(centrePixel(dir, "newmtl plastic\nKd 0.5 0.25 0.125\nKs 0.25\nNs 8\nillum 1\n") ==
          Color(0.75, 0.375, 0.1875));
    // Ns below 1 would paint the whole lit side with ks: read as no highlight.
    CHECK(centrePixel(dir, "newmtl plastic\nKd 0.5 0.25 0.125\nKs 0.9\nNs 0\n") ==
          Color(0.75, 0.375, 0.1875));
}

TEST_CASE("mtl: the mapping of absent statements") {
    LoadWarnings warn("m.mtl");
    const MtlLibrary lib = parseMtl("newmtl bare\n", "m.mtl", warn);
    REQUIRE(lib.materials.size() == 1);
    const Material m = materialFromMtl(lib.materials[0], warn);
    CHECK(m.kd == Color(0.8));  // no Kd: raylab's default grey, not black
    CHECK(m.ka == Color(0.8));  // no Ka: Ka = Kd
    CHECK(m.ks.isBlack());
    CHECK(m.shininess == 32);
    CHECK(m.ior == 1);
    CHECK(m.km.isBlack());
    CHECK(m.kt.isBlack());
    CHECK(warn.lines().empty());
}

TEST_CASE("mtl: names keep inner blanks and lose outer ones") {
    TempDir dir;
    dir.write("m.mtl",
              "newmtl   Hard Shiny Plastic White  \t\nKd 1 1 1\n"
              "newmtl Hard  Shiny\nKd 0 1 0\n"
              "newmtl Hard\nKd 1 0 0\n");
    const ObjModel m = loadObj(
        dir.write("n.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                           "usemtl Hard Shiny Plastic White \t \nf 1 2 3\n"
                           "usemtl Hard  Shiny\nf 1 3 2\n"
                           "usemtl   Hard\nf 3 2 1\n"),
        quiet());
    CHECK(m.warnings.empty());
    REQUIRE(m.materials.size() == 3);  // every name found: no default material
    CHECK(m.materials[0].name == "Hard Shiny Plastic White");
    CHECK(m.materials[1].name == "Hard  Shiny");
    REQUIRE(m.parts.size() == 1);
    const std::vector<uint32_t> expected = {0, 1, 2};
    CHECK(m.parts[0].faceMaterials == expected);
}

TEST_CASE("mtl: backslashes and letter case in library and texture paths") {
    TempDir dir;
    std::filesystem::create_directories(dir.file("mats/tex"));
    dir.write("mats/shapes.mtl", "newmtl red\nKd 1 0 0\nmap_Kd -s 2 2 1 tex\\Wood Grain.PNG\n");
    dir.write("mats/tex/wood grain.png", "not read yet");
    const std::string obj =
        dir.write("p.obj", "mtllib Mats\\Shapes.MTL\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const ObjModel m = loadObj(obj, quiet());
    REQUIRE(m.materials.size() == 1);
    CHECK(m.materials[0].kd == Color(1, 0, 0));
    // Both files were found ignoring case, each with one warning naming what was found.
    REQUIRE(m.mtlStatements.size() == 1);
    REQUIRE(m.mtlStatements[0].textures.size() == 1);
    const MtlTexture& t = m.mtlStatements[0].textures[0];
    CHECK(t.keyword == "map_Kd");
    CHECK(t.options == "-s 2 2 1");
    CHECK(t.file == dir.file("mats/tex/wood grain.png"));
    int caseWarnings = 0;
    for (const std::string& w : m.warnings) caseWarnings += contains(w, "the letter case differs");
    CHECK(caseWarnings == 2);
    CHECK(contains(m.warnings[0], "p.obj:1: material library 'Mats/Shapes.MTL' found as '"));
}

TEST_CASE("mtl: statements raylab does not simulate are named once per file") {
    TempDir dir;
    dir.write("m.mtl",
              "newmtl a\nKd 1 1 1\nKe 0 0 0\nPr 0.5\nPm 1\n"
              "newmtl b\nKd 1 1 1\nKe 1 0 0\nPr 0.2\nTf 1 1 1\nNs 0.5\nKs 1\nfrobnicate 3\n"
              "newmtl c\nKe 0 1 0\nPr 0.1\nfrobnicate 4\n");
    const ObjModel m = loadObj(
        dir.write("w.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n"),
        quiet());
    const std::string mtl = dir.file("m.mtl");
    const std::vector<std::string> expected = {
        mtl + ":4: 'Pr' (roughness (PBR)) is not simulated by raylab; ignored (3 times)",
        mtl + ":5: 'Pm' (metallic (PBR)) is not simulated by raylab; ignored",
        mtl + ":13: unknown MTL statement 'frobnicate' is ignored (2 times)",
        // Then the mapping's, material by material: a black Ke (what most
        // exporters write) is no emission and not worth a word.
        mtl + ":11: Ns below 1 makes the highlight cover the whole surface; read as no "
              "highlight (ks = 0)",
        mtl + ":10: 'Tf' (transmission filter) is only used with illum 6 or 7 (refraction); ignored",
        mtl + ":8: 'Ke' (emission) is not simulated by raylab; ignored (2 times)",
    };
    CHECK(m.warnings == expected);
}

TEST_CASE("mtl: d < 1 is dissolve: d of the surface plus 1 - d of what is behind, unbent") {
    TempDir dir;
    // The square of the first case (ka·0.5 + kd + ks = (1, 0.625, 0.4375)) at
    // d = 0.5 over a blue background (0, 0, 1): the surface's half plus half
    // the background, seen straight through: (0.5, 0.3125, 0.21875 + 0.5).
    const std::string plastic = "newmtl plastic\nKd 0.5 0.25 0.125\nKs 0.25\nNs 8\n";
    CHECK(centrePixel(dir, plastic + "d 0.5\n", "[0, 0, 1]") == Color(0.5, 0.3125, 0.71875));
    // Tr is 1 - d; illum 4 ("glass on") dissolves too and ignores Ni; its
    // ray-traced mirror km = d·Ks = 0.125 adds the blue background above.
    CHECK(centrePixel(dir, plastic + "Tr 0.5\nillum 4\nNi 1.5\n", "[0, 0, 1]") ==
          Color(0.5, 0.3125, 0.84375));
    // Fully dissolved: only the background.
    CHECK(centrePixel(dir, plastic + "d 0\n", "[0, 0, 1]") == Color(0, 0, 1));
    // illum 7 refracts instead: kt = 1 - d with Ni; the surface keeps its
    // terms (plus the mirror km = Ks, which sees the black sky above).
    CHECK(centrePixel(dir, plastic + "d 0.5\nillum 7\nNi 1.5\n", "[0, 0, 1]").r == 1);
}

TEST_CASE("mtl: d, Tr and d -halo share one range, [0, 1]") {
    // Each refused at its own line, naming the material and the spelling.
    struct Case {
        const char* statement;
        const char* message;
    };
    const Case refused[] = {
        {"d -1", "material 'glass': d (dissolve) must be in [0, 1] (got -1)"},
        {"d -0.5", "material 'glass': d (dissolve) must be in [0, 1] (got -0.5)"},
        {"d 1.5", "material 'glass': d (dissolve) must be in [0, 1] (got 1.5)"},
        {"Tr 2", "material 'glass': Tr (transparency, 1 - dissolve) must be in [0, 1] (got 2)"},
        {"Tr -0.25", "material 'glass': Tr (transparency, 1 - dissolve) must be in [0, 1] (got -0.25)"},
        {"d -halo -1", "material 'glass': d -halo (dissolve) must be in [0, 1] (got -1)"},
        {"d -halo 1.5", "material 'glass': d -halo (dissolve) must be in [0, 1] (got 1.5)"},
    };
    for (const Case& c : refused) {
        CAPTURE(c.statement);
        LoadWarnings warn("m.mtl");
        const test::Failure f = failureOf([&] {
            parseMtl(std::string("newmtl glass\nillum 4\n") + c.statement + "\n", "m.mtl", warn);
        });
        CHECK(f.line == 3);
        CHECK(f.message == c.message);
    }
    // The same values inside the range, in every spelling: kt = 1 - dissolve.
    for (const char* ok : {"d 0.25", "d -halo 0.25", "Tr 0.75"}) {
        CAPTURE(ok);
        LoadWarnings warn("m.mtl");
        const MtlLibrary lib = parseMtl(std::string("newmtl glass\nillum 4\n") + ok + "\n", "m.mtl", warn);
        CHECK(materialFromMtl(lib.materials[0], warn).kt == Color(0.75));
    }
}

TEST_CASE("mtl: a material defined twice keeps its first definition") {
    TempDir dir;
    dir.write("a.mtl", "newmtl m\nKd 1 0 0\n");
    dir.write("b.mtl", "newmtl m\nKd 0 1 0\n");
    const ObjModel m = loadObj(
        dir.write("t.obj", "mtllib a.mtl b.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
        quiet());
    REQUIRE(m.materials.size() == 1);
    CHECK(m.materials[0].kd == Color(1, 0, 0));
    REQUIRE(m.warnings.size() == 1);
    CHECK(m.warnings[0] == dir.file("b.mtl") + ":1: material 'm' is defined again; the first "
                                               "definition (" + dir.file("a.mtl") + ":1) is used");
}

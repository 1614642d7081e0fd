// MTL texture maps: map_Kd/map_Ka/map_Ks/map_Ns/bump/norm with their options
// honoured or warned about one by one, vt read as the mesh's uv, a missing
// file warned at the MTL statement's line, files shared with the JSON scene.
#include <doctest/doctest.h>

#include <algorithm>

#include "image_files.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/scene_loader.h"
#include "support/temp_dir.h"

using namespace raylab;
using namespace raylab::testing;

namespace {

const char* const kQuad =
    "mtllib m.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl tex\n"
    "f 1/1 2/2 3/3 4/4\n";

bool hasWarning(const ObjModel& m, const std::string& text) {
    return std::any_of(m.warnings.begin(), m.warnings.end(),
                       [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("mtl maps: colour, exponent, bump and normal maps with their options") {
    test::TempDir dir;
    writeImage(dir.file("a.png"), 2, 2, 3, std::vector<float>(12, 0.5f), OIIO::TypeDesc::UINT8);
    dir.write("q.obj", kQuad);
    dir.write("m.mtl",
              "newmtl tex\n"
              "Kd 0.5 0.5 0.5\n"
              "map_Kd -s 2 3 1 -o 0.5 0.25 0 -clamp on a.png\n"
              "map_Ka a.png\n"
              "map_Ks -blendu off -mm 0.1 2 a.png\n"
              "map_Ns -imfchan r a.png\n"
              "bump -bm 0.25 a.png\n"
              "norm a.png\n"
              "map_Tr a.png\n"
              "map_Ka -bm 2 a.png\n");
    ObjLoadOptions o;
    o.printWarnings = false;
    const ObjModel m = loadObj(dir.file("q.obj"), o);
    REQUIRE(m.materials.size() == 1);
    const Material& mat = m.materials[0];
    REQUIRE(mat.maps.kd != MaterialMaps::kNone);
    CHECK(mat.kd == Color(0.5));  // map_Kd multiplies Kd
    const Texture& kd = m.textures[mat.maps.kd];
    CHECK(kd.scale == Vec2(2, 3));
    CHECK(kd.offset == Vec2(0.5, 0.25));
    CHECK(kd.wrap == WrapMode::Clamp);
    CHECK(mat.maps.ka != MaterialMaps::kNone);
    CHECK(mat.maps.ks != MaterialMaps::kNone);
    REQUIRE(mat.maps.shininess != MaterialMaps::kNone);
    CHECK(m.textures[mat.maps.shininess].channel == TextureChannel::Red);
    REQUIRE(mat.maps.bump != MaterialMaps::kNone);
    CHECK(mat.maps.bumpScale == 0.25);
    CHECK(m.textures[mat.maps.bump].channel == TextureChannel::Luminance);
    CHECK(mat.maps.normal != MaterialMaps::kNone);
    // Colour maps are sRGB-decoded, data maps not: two pyramids of one file.
    CHECK(m.textures[mat.maps.kd].image() != m.textures[mat.maps.bump].image());
    CHECK(m.textures[mat.maps.bump].image() == m.textures[mat.maps.normal].image());
    // Ignored options, one warning each at the statement's line.
    CHECK(hasWarning(m, "m.mtl:5: material 'tex': map_Ks: option -blendu off is not supported"));
    CHECK(hasWarning(m, "m.mtl:5: material 'tex': map_Ks: option -mm is not supported"));
    CHECK(hasWarning(m, "map_Ka: option -bm applies to bump maps only; ignored"));
    CHECK(hasWarning(m, "m.mtl:9: material 'tex': texture maps other than"));
    // vt became the mesh's uv.
    REQUIRE(m.parts.size() == 1);
    const TriangleMesh& mesh = *m.parts[0].mesh;
    REQUIRE(mesh.hasUvs());
    for (size_t i = 0; i < mesh.positions.size(); ++i)
        CHECK(mesh.uvs[i] == Vec2(mesh.positions[i].x, mesh.positions[i].y));
}

TEST_CASE("mtl maps: a missing file is one warning at its MTL line, the material stays untextured") {
    test::TempDir dir;
    dir.write("q.obj", kQuad);
    dir.write("m.mtl", "newmtl tex\nKd 1 0 0\nmap_Kd nothere.png\nmap_Ka nothere.png\n");
    ObjLoadOptions o;
    o.printWarnings = false;
    const ObjModel m = loadObj(dir.file("q.obj"), o);
    CHECK(m.materials[0].maps.kd == MaterialMaps::kNone);
    CHECK(m.textures.empty());
    CHECK(hasWarning(m, "m.mtl:3: material 'tex': map_Kd: texture not read ("));
    CHECK_FALSE(hasWarning(m, "map_Ka: texture not read"));  // the same file: reported once
}

TEST_CASE("mtl maps in a JSON scene: files shared with the scene's materials, indices offset") {
    test::TempDir dir;
    writeImage(dir.file("a.png"), 2, 2, 3, std::vector<float>(12, 0.5f), OIIO::TypeDesc::UINT8);
    dir.write("q.obj", kQuad);
    dir.write("m.mtl", "newmtl tex\nmap_Kd a.png\n");
    dir.write("s.json",
              "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
              "\"materials\": {\"j\": {\"kd\": {\"checker\": [0, 1]}, \"ks\": {\"texture\": \"a.png\"}}},\n"
              "\"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, -3], \"radius\": 1, \"material\": \"j\"},\n"
              "{\"type\": \"mesh\", \"file\": \"q.obj\"}]}\n");
    const Scene s = loadScene(dir.file("s.json"));
    REQUIRE(s.textures.size() == 3);
    const Material& objMaterial = s.materials.back();
    REQUIRE(objMaterial.maps.kd == 2);  // after the JSON material's two
    CHECK(s.textures[2].image() == s.textures[1].image());  // one read of a.png
}

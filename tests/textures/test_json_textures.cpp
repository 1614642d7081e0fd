// JSON textured materials: image textures and checkers on any colour, their
// placement keys, the render keys, located errors for bad values, and a
// missing file: one warning, or an error with "required": true.
#include <doctest/doctest.h>

#include "image_files.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render_setup.h"
#include "support/temp_dir.h"

using namespace raylab;
using namespace raylab::testing;

namespace {

std::string scene(const std::string& material, const std::string& render = "") {
    return "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n" +
           (render.empty() ? std::string() : "\"render\": " + render + ",\n") +
           "\"materials\": {\"m\": " + material + "},\n"
           "\"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, "
           "\"material\": \"m\"}]}\n";
}

}  // namespace

TEST_CASE("json textures: image and checker colours, placement, bump and normal maps") {
    test::TempDir dir;
    writeImage(dir.file("a.png"), 2, 2, 3, std::vector<float>(12, 1.0f), OIIO::TypeDesc::UINT8);
    const std::string path = dir.file("s.json");
    const Scene s = loadJsonScene(
        scene("{\"kd\": {\"texture\": \"a.png\", \"scale\": [2, 3], \"offset\": [0.5, 0.25], "
              "\"wrap\": \"clamp\"},\n"
              " \"ka\": {\"checker\": [0.1, [1, 0.5, 0]], \"scale\": [8, 4]},\n"
              " \"ks\": {\"texture\": \"a.png\"}, \"km\": 0.5,\n"
              " \"bump\": {\"texture\": \"a.png\", \"height\": 0.02},\n"
              " \"normal_map\": {\"texture\": \"a.png\"}}",
              "{\"texture_filter\": \"anisotropic\", \"texture_footprint\": \"differentials\"}"),
        path);
    const Material& m = s.materials.at(0);
    REQUIRE(m.maps.kd != MaterialMaps::kNone);
    CHECK(m.kd == Color(1));  // the texture stands for the whole colour
    const Texture& kd = s.textures[m.maps.kd];
    CHECK(kd.scale == Vec2(2, 3));
    CHECK(kd.offset == Vec2(0.5, 0.25));
    CHECK(kd.wrap == WrapMode::Clamp);
    REQUIRE(m.maps.ka != MaterialMaps::kNone);
    CHECK(s.textures[m.maps.ka].kind() == Texture::Kind::Checker);
    CHECK(m.maps.km == MaterialMaps::kNone);
    CHECK(m.km == Color(0.5));
    CHECK(m.maps.bump != MaterialMaps::kNone);
    CHECK(m.maps.bumpScale == 0.02);
    CHECK(m.maps.normal != MaterialMaps::kNone);
    // One file, read as colour once and as data once, shared by every use.
    CHECK(s.textures[m.maps.kd].image() == s.textures[m.maps.ks].image());
    CHECK(s.textures[m.maps.kd].image() != s.textures[m.maps.bump].image());
    CHECK(s.textures[m.maps.bump].image() == s.textures[m.maps.normal].image());
    const RenderOptions o = resolveRenderOptions(s, {});
    CHECK(o.textures.filter == TextureFilter::Anisotropic);
    CHECK(o.textures.footprint == TextureFootprint::Differentials);
}

TEST_CASE("json textures: bad values are located errors") {
    test::TempDir dir;
    const std::string path = dir.file("s.json");
    const auto error = [&](const std::string& material, const std::string& render = "") {
        try {
            loadJsonScene(scene(material, render), path);
        } catch (const InputError& e) {
            return e.located();
        }
        return std::string("no error");
    };
    CHECK(error("{\"kd\": {\"texture\": \"a.png\", \"wrap\": \"mirror\"}}") ==
          path + ":2: materials.m.kd.wrap: must be one of 'repeat', 'clamp', 'black' (got 'mirror')");
    CHECK(error("{\"kd\": {\"texture\": \"a.png\", \"scale\": [1]}}") ==
          path + ":2: materials.m.kd.scale: expected [u, v], got an array of 1");
    CHECK(error("{\"kd\": {\"checker\": [1, 0], \"wrap\": \"clamp\"}}") ==
          path + ":2: materials.m.kd.wrap: unknown key for a checker texture (expected 'scale', "
                 "'offset', 'checker')");
    CHECK(error("{\"kd\": {\"textur\": \"a.png\"}}").find("did you mean 'texture'") != std::string::npos);
    CHECK(error("{\"kd\": {\"texture\": \"\"}}") == path + ":2: materials.m.kd.texture: must not be empty");
    CHECK(error("{\"kd\": 1}", "{\"texture_filter\": \"linear\"}") ==
          path + ":2: render.texture_filter: must be one of 'point', 'bilinear', 'trilinear', "
                 "'anisotropic' (got 'linear')");
    // A missing file is an error only when the texture is required.
    CHECK(error("{\"kd\": {\"texture\": \"missing.png\", \"required\": true}}")
              .rfind(path + ":2: materials.m.kd.texture: texture 'missing.png' not read (", 0) == 0);
    const Scene s = loadJsonScene(scene("{\"kd\": {\"texture\": \"missing.png\"}}"), path);
    CHECK(s.materials[0].maps.kd == MaterialMaps::kNone);
    CHECK(s.textures.empty());
}

TEST_CASE("json sphere pole: orients the sphere's (u, v)") {
    test::TempDir dir;
    const std::string text =
        "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]}, \"objects\": [\n"
        "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1},\n"
        "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"pole\": [0, 0, 2]}]}";
    const Scene s = loadJsonScene(text, dir.file("s.json"));
    // A ray down onto the top of the sphere: v = 1 at the +y pole of the
    // first, v = 1/2 on the equator of the second (pole +z).
    const Ray down{{0, 5, 0}, {0, -1, 0}};
    for (int i = 0; i < 2; ++i) {
        const auto h = s.objects[size_t(i)].shape->intersect(0, down, 0, 1e30, {});
        REQUIRE(h);
        const SurfaceGeometry g =
            s.objects[size_t(i)].shape->surfaceAt(0, down, *h, {}, SurfaceDetail::Complete);
        CHECK(g.uv.y == doctest::Approx(i == 0 ? 1.0 : 0.5));
    }
    CHECK_THROWS_WITH_AS(
        loadJsonScene("{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]}, \"objects\": [\n"
                      "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"pole\": [0, 0, 0]}]}",
                      dir.file("s.json")),
        "objects[0].pole: must not be the zero vector", InputError);
}

// Textured renders: uv at hits on every primitive through both accelerators,
// naive ≡ Embree on textured scenes under every filter and footprint, the
// image's top row at the top of an upright quad, the albedo layer as the
// textured kd, and the textures effect only where a material has a texture.
#include <doctest/doctest.h>

#include <cstring>

#include "geometry/primitives.h"
#include "geometry/triangle_mesh.h"
#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/render.h"
#include "texture_test_helpers.h"

using namespace raylab;
using namespace raylab::testing;

namespace {

/// One of each primitive, each with its own texture (images and checkers),
/// a mirror and a glass sphere reflecting and refracting them.
Scene texturedPrimitives() {
    Scene s;
    s.camera = Camera::perspective({0, 3, 9}, {0, 0.8, 0}, {0, 1, 0}, 45);
    s.ambient = Color(0.2);
    Light l;
    l.type = Light::Type::Point;
    l.position = {-4, 8, 6};
    l.intensity = Color(1);
    s.lights.push_back(l);
    const uint32_t img = addTexturedMaterial(s, Texture::fromImage(patternImage(64, 32), "pattern"));
    Texture checker = Texture::checker(Color(0.9), Color(0.1));
    checker.scale = {8, 4};
    const uint32_t chk = addTexturedMaterial(s, checker);
    Texture floorTex = Texture::fromImage(patternImage(16, 16), "floor");
    floorTex.scale = {0.25, 0.25};
    const uint32_t flr = addTexturedMaterial(s, floorTex);
    Material mirror;
    mirror.kd = Color(0.05);
    mirror.km = Color(0.9);
    s.materials.push_back(mirror);
    const uint32_t mir = uint32_t(s.materials.size() - 1);
    Material glass;
    glass.kd = Color(0);
    glass.kt = Color(0.9);
    glass.km = Color(0.1);
    glass.ior = 1.5;
    s.materials.push_back(glass);
    const uint32_t gls = uint32_t(s.materials.size() - 1);

    addObject(s, makePlane({0, 0, 0}, {0, 1, 0}, 100), flr, "floor");
    addObject(s, makeSphere({-2.2, 1, 0}, 1), img, "sphere");
    addObject(s, makeCone(ConeParams{{0, 0, -1}, 0.7, {0, 2, -1}, 0.7, true}), chk, "cylinder");
    addObject(s, makeCone(ConeParams{{2.2, 0, 0}, 0.8, {2.2, 2, 0}, 0.0, false}), img, "cone");
    addObject(s, makeDisk({3.5, 1.5, -2}, {-0.4, 0.3, 1}, 0.8), chk, "disk");
    PolygonParams quad;
    quad.vertices = {{-1, 2.2, -2}, {1, 2.2, -2}, {1, 3.4, -2}, {-1, 3.4, -2}};
    addObject(s, makePolygon(quad), img, "quad");
    QuadricParams ellipsoid;  // (x+3.5)²/0.36 + (y-2.8)²/0.25 + z²/0.36 = 1
    ellipsoid.A = 1 / 0.36;
    ellipsoid.B = 1 / 0.25;
    ellipsoid.C = 1 / 0.36;
    ellipsoid.G = 2 * 3.5 / 0.36;
    ellipsoid.H = -2 * 2.8 / 0.25;
    ellipsoid.J = 3.5 * 3.5 / 0.36 + 2.8 * 2.8 / 0.25 - 1;
    addObject(s, makeQuadric(ellipsoid), chk, "ellipsoid");
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions = {{1, 2.3, 1}, {2.5, 2.3, 1}, {2.5, 3.6, 0.5}, {1, 3.6, 0.5}};
    mesh->uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh->triangles = {{0, 1, 2}, {0, 2, 3}};
    Object m;
    m.name = "mesh";
    m.shape = mesh;
    m.material = img;
    s.objects.push_back(m);
    auto mirrorSphere = makeSphere({-0.5, 0.6, 1.5}, 0.6);
    addObject(s, std::move(mirrorSphere), mir, "mirror");
    std::unique_ptr<Shape> glassSphere = makeSphere({0.9, 0.5, 2.2}, 0.5);
    glassSphere->setSidedness(Sidedness::Both);
    addObject(s, std::move(glassSphere), gls, "glass");
    return s;
}

size_t differingPixels(const Film& a, const Film& b) {
    size_t n = 0;
    for (size_t i = 0; i < size_t(a.width) * a.height; ++i)
        n += std::memcmp(&a.rgba[4 * i], &b.rgba[4 * i], 4 * sizeof(float)) != 0 ||
             std::memcmp(&a.albedo[3 * i], &b.albedo[3 * i], 3 * sizeof(float)) != 0;
    return n;
}

}  // namespace

TEST_CASE("uv at hits: every primitive gives the same surface record through both accelerators") {
    const Scene s = texturedPrimitives();
    const RenderOptions opt = textureOptions(s, 80, 60, TextureFilter::Bilinear, TextureFootprint::Cones);
    auto embree = makeAccelerator("embree", s, opt.accelOptions);
    auto naive = makeAccelerator("naive", s, opt.accelOptions);
    std::vector<int> hitsPerObject(s.objects.size(), 0);
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 80; ++x) {
            const Ray r = s.camera.generateRay(x + 0.5, y + 0.5, 80, 60);
            const auto a = embree->intersect(r, 0, 1e30), b = naive->intersect(r, 0, 1e30);
            REQUIRE(a.has_value() == b.has_value());
            if (!a) continue;
            REQUIRE(a->object == b->object);
            const SurfaceInteraction sa = s.surfaceAt(r, *a, {}, SurfaceDetail::Complete);
            const SurfaceInteraction sb = s.surfaceAt(r, *b, {}, SurfaceDetail::Complete);
            CHECK(sa.uv == sb.uv);
            CHECK(sa.dpdu == sb.dpdu);
            CHECK(std::isfinite(sa.uv.x));
            ++hitsPerObject[a->object];
        }
    for (size_t i = 0; i < s.objects.size(); ++i) {
        CAPTURE(s.objects[i].name);
        CHECK(hitsPerObject[i] > 0);
    }
}

TEST_CASE("naive = embree on a textured scene, every filter and footprint, bit for bit") {
    const Scene s = texturedPrimitives();
    for (TextureFilter f : {TextureFilter::Point, TextureFilter::Bilinear, TextureFilter::Trilinear,
                            TextureFilter::Anisotropic})
        for (TextureFootprint fp : {TextureFootprint::Cones, TextureFootprint::Differentials}) {
            const std::string filterName = textureFilterName(f);
            CAPTURE(filterName);
            const std::string footprintName = textureFootprintName(fp);
            CAPTURE(footprintName);
            const RenderOptions opt = textureOptions(s, 64, 48, f, fp, 2);
            const EffectSet e = analyseEffects(s, opt);
            CHECK(e.textures());
            auto embree = makeAccelerator("embree", s, opt.accelOptions);
            auto naive = makeAccelerator("naive", s, opt.accelOptions);
            const RenderResult a = render(s, *embree, opt, e);
            const RenderResult b = render(s, *naive, opt, e);
            CHECK(differingPixels(a.film, b.film) == 0);
            CHECK(a.nonFiniteSamples == 0);
            CHECK(b.nonFiniteSamples == 0);
            // Thread count does not change a bit either.
            RenderOptions one = opt;
            one.threads = 1;
            CHECK(differingPixels(render(s, *embree, one, e).film, a.film) == 0);
        }
}

TEST_CASE("v orientation: a texture whose top row is red renders red at the top of an upright quad") {
    Scene s;
    s.camera = Camera::perspective({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40);
    s.ambient = Color(1);
    const auto redOverBlue = std::make_shared<const MipMap>(
        1, 2, 3, std::vector<float>{1, 0, 0, 0, 0, 1});
    const uint32_t mat = addTexturedMaterial(s, Texture::fromImage(redOverBlue, "rb"));
    s.materials[mat].ka = Color(1);
    s.materials[mat].maps.ka = s.materials[mat].maps.kd;
    PolygonParams quad;  // counter-clockwise from the lower left, facing the camera
    quad.vertices = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    addObject(s, makePolygon(quad), mat, "quad");
    const RenderOptions opt = textureOptions(s, 32, 32, TextureFilter::Point, TextureFootprint::Cones);
    auto accel = makeAccelerator("embree", s, opt.accelOptions);
    const RenderResult r = render(s, *accel, opt, analyseEffects(s, opt));
    const Film& f = r.film;
    const size_t top = f.index(16, 12), bottom = f.index(16, 20);
    CHECK(f.rgba[4 * top + 0] == 1.0f);
    CHECK(f.rgba[4 * top + 2] == 0.0f);
    CHECK(f.rgba[4 * bottom + 0] == 0.0f);
    CHECK(f.rgba[4 * bottom + 2] == 1.0f);
    // The albedo layer is the textured kd.
    CHECK(f.albedo[3 * top + 0] == 1.0f);
    CHECK(f.albedo[3 * bottom + 2] == 1.0f);
}

TEST_CASE("textures effect: on only where a material in use has a texture") {
    Scene s = texturedPrimitives();
    RenderOptions opt = textureOptions(s, 8, 8, TextureFilter::Bilinear, TextureFootprint::Cones);
    CHECK(analyseEffects(s, opt).textures());
    std::vector<std::string> names = analyseEffects(s, opt).names();
    CHECK(std::find(names.begin(), names.end(), "textures") != names.end());
    for (Material& m : s.materials) m.maps = MaterialMaps{};
    CHECK_FALSE(analyseEffects(s, opt).textures());
    opt.forceAllEffects = true;  // the general kernel does not force textures
    CHECK_FALSE(analyseEffects(s, opt).textures());
}

// Simulate only the effects a scene calls for: the effect set is derived from
// the scene, zero-weight work is never done, and the specialised kernel gives
// the same image as the fully general one (--effects all).
#include <doctest/doctest.h>

#include <cstring>

#include "geometry/primitives.h"
#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"

using namespace raylab;

namespace {

Scene emptyScene(int w = 32, int h = 24) {
    Scene s;
    s.camera = Camera::perspective({0, 1, 6}, {0, 0, 0}, {0, 1, 0}, 45);
    s.image.width = w;
    s.image.height = h;
    s.ambient = Color(0.1);
    s.background = Color(0.2, 0.3, 0.4);
    return s;
}

uint32_t add(Scene& s, const Material& m) {
    s.materials.push_back(m);
    return uint32_t(s.materials.size() - 1);
}

void addShape(Scene& s, std::unique_ptr<Shape> shape, uint32_t material, Sidedness sides = Sidedness::Outside) {
    Object o;
    shape->setSidedness(sides);
    o.shape = std::move(shape);
    o.material = material;
    s.objects.push_back(std::move(o));
}

Material matte(Color kd) {
    Material m;
    m.kd = kd;
    m.ka = kd;
    return m;
}

struct Run {
    RenderResult result;
    EffectSet effects;
};

Run renderWith(const Scene& s, bool general, int maxDepth = 5) {
    RenderOverrides o;
    o.maxDepth = maxDepth;
    if (general) o.effects = EffectsMode::All;
    const RenderOptions opt = resolveRenderOptions(s, o);
    auto accel = makeAccelerator("embree", s, opt.accelOptions);
    Run r;
    r.effects = analyseEffects(s, opt);
    r.result = render(s, *accel, opt, r.effects);
    return r;
}

bool sameImage(const Film& a, const Film& b) {
    return a.rgba.size() == b.rgba.size() &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

bool hasName(const EffectSet& e, const std::string& n) {
    for (const std::string& x : e.names())
        if (x == n) return true;
    return false;
}

}  // namespace

TEST_CASE("effects: a matte scene traces no reflection or refraction rays") {
    Scene s = emptyScene();
    s.lights.push_back({Light::Type::Point, {3, 5, 4}, {}, Color(1)});
    addShape(s, makeSphere({0, 0, 0}, 1), add(s, matte(Color(0.7, 0.2, 0.2))));
    addShape(s, makePlane({0, -1, 0}, {0, 1, 0}), add(s, matte(Color(0.5))));
    const Run r = renderWith(s, false);
    CHECK(r.effects.kernel == kShadows);
    CHECK(hasName(r.effects, "shadows"));
    CHECK_FALSE(hasName(r.effects, "reflection"));
    CHECK_FALSE(hasName(r.effects, "refraction"));
    CHECK_FALSE(hasName(r.effects, "highlights"));
    CHECK(r.result.rays.total(RayType::Reflection) == 0);
    CHECK(r.result.rays.total(RayType::Refraction) == 0);
    // One shadow ray per camera hit whose normal faces the single light.
    CHECK(r.result.rays.total(RayType::Shadow) > 0);
    CHECK(r.result.rays.total(RayType::Shadow) <= r.result.rays.cameraHits);
}

TEST_CASE("effects: a scene without lights traces no shadow rays") {
    Scene s = emptyScene();
    Material shiny = matte(Color(0.5));
    shiny.ks = Color(0.5);
    addShape(s, makeSphere({0, 0, 0}, 1), add(s, shiny));
    const Run r = renderWith(s, false);
    CHECK(r.effects.kernel == 0u);
    CHECK(r.result.rays.total(RayType::Shadow) == 0);
    CHECK(r.result.rays.cameraHits > 0);
}

TEST_CASE("effects: a lone mirror sphere spawns one reflection ray per camera hit") {
    // A convex mirror alone: every camera ray that hits it reflects once, and
    // no reflected ray can hit the sphere again, so the tree stops at depth 2.
    Scene s = emptyScene();
    Material mirror;
    mirror.kd = Color(0);
    mirror.km = Color(0.9);
    addShape(s, makeSphere({0, 0, 0}, 1.5), add(s, mirror));
    const Run r = renderWith(s, false);
    CHECK(r.effects.kernel == kReflection);
    CHECK(r.result.rays.cameraHits > 0);
    CHECK(r.result.rays.total(RayType::Reflection) == r.result.rays.cameraHits);
    CHECK(r.result.rays.byDepth[size_t(RayType::Reflection)][2] == r.result.rays.cameraHits);
    CHECK(r.result.rays.total(RayType::Shadow) == 0);
    // With --depth 1 the camera ray is the whole tree.
    const Run shallow = renderWith(s, false, 1);
    CHECK(shallow.effects.kernel == 0u);
    CHECK(shallow.result.rays.total(RayType::Reflection) == 0);
}

TEST_CASE("effects: a light behind every surface traces no shadow rays") {
    // The camera looks down -z at a quad facing +z; the light is far behind it.
    Scene s = emptyScene();
    s.camera = Camera::perspective({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30);
    s.lights.push_back({Light::Type::Point, {0, 0, -50}, {}, Color(1)});
    PolygonParams quad;
    quad.vertices = {{-10, -10, 0}, {10, -10, 0}, {10, 10, 0}, {-10, 10, 0}};
    addShape(s, makePolygon(quad), add(s, matte(Color(0.5))));
    const Run r = renderWith(s, false);
    CHECK(r.effects.has(kShadows));
    CHECK(r.result.rays.cameraHits == uint64_t(s.image.width) * s.image.height);
    CHECK(r.result.rays.total(RayType::Shadow) == 0);
}

TEST_CASE("effects: specialised and general kernels give bit-identical images") {
    SUBCASE("matte") {
        Scene s = emptyScene(48, 32);
        s.lights.push_back({Light::Type::Point, {3, 5, 4}, {}, Color(0.8)});
        s.lights.push_back({Light::Type::Point, {-3, 2, -4}, {}, Color(0.5)});
        addShape(s, makeSphere({0, 0, 0}, 1), add(s, matte(Color(0.7, 0.2, 0.2))));
        addShape(s, makePlane({0, -1, 0}, {0, 1, 0}), add(s, matte(Color(0.5))));
        const Run a = renderWith(s, false), b = renderWith(s, true);
        CHECK(sameImage(a.result.film, b.result.film));
        CHECK(b.result.rays.total() > a.result.rays.total());  // the general kernel wastes rays
        CHECK(b.effects.kernel == kAllKernelEffects);
    }
    SUBCASE("mirror, glass, highlights") {
        Scene s = emptyScene(48, 32);
        s.lights.push_back({Light::Type::Point, {3, 5, 4}, {}, Color(0.8)});
        Material mirror = matte(Color(0.1));
        mirror.km = Color(0.8);
        mirror.ks = Color(0.6);
        Material glass = matte(Color(0));
        glass.kt = Color(0.9);
        glass.ior = 1.5;
        addShape(s, makeSphere({-1.1, 0, 0}, 1), add(s, mirror));
        addShape(s, makeSphere({1.1, 0, 0.5}, 1), add(s, glass), Sidedness::Both);
        addShape(s, makePlane({0, -1, 0}, {0, 1, 0}), add(s, matte(Color(0.5))));
        const Run a = renderWith(s, false), b = renderWith(s, true);
        CHECK(a.effects.kernel == kAllKernelEffects);
        CHECK(sameImage(a.result.film, b.result.film));
    }
    SUBCASE("the demo and primitives scenes") {
        for (const char* name : {"/scenes/demo.json", "/scenes/primitives.json"}) {
            CAPTURE(name);
            Scene s = loadScene(std::string(RAYLAB_SOURCE_DIR) + name);
            s.image.width = 64;
            s.image.height = 48;
            s.image.spp = 1;
            const Run a = renderWith(s, false), b = renderWith(s, true);
            CHECK(sameImage(a.result.film, b.result.film));
            CHECK(a.result.rays.total() <= b.result.rays.total());
        }
    }
}

// The shadow cache (renderer/shadow_cache.h): per worker, the occluder last
// found for a receiver (its object, the light, the ray depth; and the same
// receiver at any depth as a fallback), asked first by the next feeler.
// Checked: the slots by hand; the tables' bounds for any scene; the
// accelerator's answer with any pair of guesses, and the fallback asked when
// the first guess does not block, and only then; and through the integrator,
// that most blocked feelers find an occluder their guesses named, some the
// fallback, without changing a pixel, and that no cache is kept where no
// hint can be used.

#include <doctest/doctest.h>

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/primitives.h"
#include "renderer/accel/embree_accelerator.h"
#include "renderer/accel/naive_accelerator.h"
#include "renderer/effects.h"
#include "renderer/render_setup.h"
#include "renderer/shadow_cache.h"
#include "renderer/shadow_cache_pixels.h"
#include "renderer/whitted_integrator.h"
#include "support/forwarding_accelerator.h"
#include "support/forwarding_shape.h"

using namespace raylab;

namespace {

constexpr uint32_t kNone = OcclusionHint::kNone;

bool same(const OcclusionHint& h, uint32_t primitive, uint32_t fallback) {
    return h.primitive == primitive && h.fallback == fallback;
}

OcclusionHint answered(uint32_t primitive) {
    OcclusionHint h;
    h.primitive = primitive;
    return h;
}

}  // namespace

TEST_CASE("shadow cache: a feeler's guesses are its receiver's last occluders, at its depth and at any") {
    ShadowCache cache;
    cache.prepare(10, 3, 5);  // objects, lights, depths 1..5
    const auto at = [&](uint32_t object, int depth) { return cache.receiver(object, depth); };
    CHECK(same(cache.slots(at(4, 2), 1).hint(), kNone, kNone));

    cache.slots(at(4, 2), 1).remember(answered(7));
    CHECK(same(cache.slots(at(4, 2), 1).hint(), 7, 7));
    CHECK(same(cache.slots(at(4, 3), 1).hint(), kNone, 7));      // another depth: the fallback only
    CHECK(same(cache.slots(at(4, 2), 0).hint(), kNone, kNone));  // another light
    CHECK(same(cache.slots(at(4, 2), 2).hint(), kNone, kNone));
    CHECK(same(cache.slots(at(5, 2), 1).hint(), kNone, kNone));  // another receiver
    CHECK(same(cache.slots(at(3, 2), 1).hint(), kNone, kNone));

    cache.slots(at(4, 3), 1).remember(answered(9));
    CHECK(same(cache.slots(at(4, 2), 1).hint(), 7, 9));  // its own depth's, then the latest at any
    CHECK(same(cache.slots(at(4, 3), 1).hint(), 9, 9));

    // A lit point forgets: its own slot and the receiver's.
    cache.slots(at(4, 2), 1).remember(answered(kNone));
    CHECK(same(cache.slots(at(4, 2), 1).hint(), kNone, kNone));
    CHECK(same(cache.slots(at(4, 3), 1).hint(), 9, kNone));

    // The same shape keeps the hints (prepare runs for every camera ray);
    // another one starts afresh.
    cache.prepare(10, 3, 5);
    CHECK(same(cache.slots(at(4, 3), 1).hint(), 9, kNone));
    cache.prepare(10, 2, 5);
    CHECK(same(cache.slots(at(4, 3), 1).hint(), kNone, kNone));
}

TEST_CASE("shadow cache: its tables fit small scenes and stop at their caps for large ones") {
    ShadowCache small;
    small.prepare(3, 2, 1);  // rows of 2 lights: 3 receivers at their one depth, 3 receivers
    CHECK(small.slotCount() == 3 * 2 + 3 * 2);
    ShadowCache one;
    one.prepare(1, 1, 0);
    CHECK(one.slotCount() == 1 + 1);

    ShadowCache large;
    large.prepare(1000000, 4, 5);  // 24 M and 4 M slots wanted
    CHECK(large.slotCount() == ShadowCache::kDepthSlots + ShadowCache::kReceiverSlots);
    ShadowCache odd;
    odd.prepare(1000000, 3, 5);  // rows of 3: 21,845 and 5,461 rows
    CHECK(odd.slotCount() == 21845 * 3 + 5461 * 3);
    ShadowCache many;
    many.prepare(10, 100000, 5);  // more lights than slots: one row each
    CHECK(many.slotCount() == 100000 + 100000);
    // Receivers beyond the cap share rows: a shared slot is only a wrong
    // guess (one test), never a wrong answer. With 3 lights the
    // receiver-and-depth table has 21,845 rows: receiver 4369 at depth 1 has
    // key 4369 x 5 + 0 = 21,845, which wraps to row 0, receiver 0's at depth 1.
    REQUIRE(ShadowCache::kDepthSlots == 65536);
    ShadowCache shared;
    shared.prepare(100000, 3, 5);
    shared.slots(shared.receiver(0, 1), 1).remember(answered(11));
    CHECK(shared.slots(shared.receiver(4369, 1), 1).hint().primitive == 11);
    CHECK(shared.slots(shared.receiver(4369, 1), 0).hint().primitive == kNone);
    CHECK(shared.slots(shared.receiver(4369, 2), 1).hint().primitive == kNone);
    shared.slots(shared.receiver(99999, 5), 2).remember(answered(12));  // the last key: in range
    CHECK(shared.slots(shared.receiver(99999, 5), 2).hint().primitive == 12);
}

TEST_CASE("embree: any pair of guesses gives occluded()'s answer, and the fallback answers when the first does not block") {
    // A row of five unit spheres along x at height 2 over a floor, light above.
    Scene s;
    s.materials.resize(1);
    for (int i = 0; i < 5; ++i) {
        Object o;
        o.name = "ball " + std::to_string(i);
        o.shape = makeSphere({3.0 * i, 2, 0}, 1);
        s.objects.push_back(std::move(o));
    }
    EmbreeAccelerator embree(s, {});
    CHECK(embree.usesOcclusionHints(false));
    CHECK(embree.usesOcclusionHints(true));  // no surface filter: transmittance is occluded()
    NaiveAccelerator naive(s, {});
    CHECK_FALSE(naive.usesOcclusionHints(false));
    const auto feeler = [](double x) {
        const Vec3 from{x, 0, 0};
        return Ray{from, Vec3{x, 10, 0} - from};
    };
    // Which entry blocks the feeler under ball k (learnt by a walk).
    std::vector<uint32_t> entryOf(5);
    for (int k = 0; k < 5; ++k) {
        OcclusionHint h;
        REQUIRE(embree.occluded(feeler(3.0 * k), 1e-9, 1.0, h));
        REQUIRE(h.primitive != kNone);
        entryOf[k] = h.primitive;
    }
    for (int k = 0; k < 5; ++k) {
        for (int other = 0; other < 5; ++other) {
            if (other == k) continue;
            CAPTURE(k);
            CAPTURE(other);
            // The first guess does not block, the fallback does.
            OcclusionHint h;
            h.primitive = entryOf[other];
            h.fallback = entryOf[k];
            CHECK(embree.occluded(feeler(3.0 * k), 1e-9, 1.0, h));
            CHECK(same(h, entryOf[k], entryOf[k]));
            // Neither blocks: the walk finds the occluder and names it.
            h.primitive = entryOf[other];
            h.fallback = kNone;
            CHECK(embree.occluded(feeler(3.0 * k), 1e-9, 1.0, h));
            CHECK(h.primitive == entryOf[k]);
        }
        // Between the balls nothing blocks, whatever the guesses name.
        for (uint32_t a : {kNone, entryOf[0], entryOf[4], 12345u}) {
            for (uint32_t b : {kNone, entryOf[1], entryOf[k], 777u}) {
                OcclusionHint h;
                h.primitive = a;
                h.fallback = b;
                CHECK_FALSE(embree.occluded(feeler(3.0 * k + 1.5), 1e-9, 1.0, h));
                CHECK(h.primitive == kNone);
                CHECK(embree.transmittance(feeler(3.0 * k + 1.5), 1e-9, 1.0, h) == Color(1.0));
            }
        }
    }
}

namespace {

/// A unit ball whose box Embree is told lies far away: no walk finds it, so
/// only a hint can name it (a broken Shape contract, on purpose: it shows
/// which guesses the accelerator asked).
class HiddenBall final : public test::ForwardingShape {
public:
    explicit HiddenBall(const Vec3& centre) : ForwardingShape(makeSphere(centre, 1)) {}
    Bounds3 bounds(uint32_t) const override { return bounds(); }
    Bounds3 bounds() const override { return {{1000, 1000, 1000}, {1001, 1001, 1001}}; }
    const char* kind() const override { return "hidden ball"; }
};

}  // namespace

TEST_CASE("embree: the fallback guess is asked when the first does not block, and only then") {
    Scene s;
    s.materials.resize(1);
    Object found, hidden, hiddenHigh;
    found.name = "ball";
    found.shape = makeSphere({0, 2, 0}, 1);
    hidden.name = "hidden ball";
    hidden.shape = std::make_unique<HiddenBall>(Vec3{6, 2, 0});
    hiddenHigh.name = "hidden ball above it";
    hiddenHigh.shape = std::make_unique<HiddenBall>(Vec3{6, 5, 0});
    s.objects.push_back(std::move(found));
    s.objects.push_back(std::move(hidden));
    s.objects.push_back(std::move(hiddenHigh));
    EmbreeAccelerator embree(s, {});
    const auto feeler = [](double x) {
        const Vec3 from{x, 0, 0};
        return Ray{from, Vec3{x, 10, 0} - from};
    };
    OcclusionHint learnt;
    REQUIRE(embree.occluded(feeler(0), 1e-9, 1.0, learnt));
    const uint32_t ball = learnt.primitive;
    REQUIRE(ball == 0);  // the user entries follow the objects' order
    const uint32_t hiddenBall = 1, hiddenAbove = 2;

    const Ray under = feeler(6);
    CHECK_FALSE(embree.occluded(under, 1e-9, 1.0));  // no walk finds the hidden balls
    const auto ask = [&](uint32_t primitive, uint32_t fallback) {
        OcclusionHint h;
        h.primitive = primitive;
        h.fallback = fallback;
        const bool blocked = embree.occluded(under, 1e-9, 1.0, h);
        CHECK(h.primitive == (blocked ? hiddenBall : kNone));  // guesses name the lower one
        return blocked;
    };
    CHECK(ask(hiddenBall, kNone));
    CHECK(ask(hiddenBall, ball));
    CHECK(ask(kNone, hiddenBall));  // the fallback, after no first guess
    CHECK(ask(ball, hiddenBall));   // the fallback, after a first guess that does not block
    CHECK_FALSE(ask(ball, kNone));
    CHECK_FALSE(ask(ball, ball));
    // Both guesses block (the feeler crosses both hidden balls): the first
    // answers, the fallback is not asked.
    for (const auto& [first, second] : {std::pair{hiddenBall, hiddenAbove}, {hiddenAbove, hiddenBall}}) {
        OcclusionHint h;
        h.primitive = first;
        h.fallback = second;
        CHECK(embree.occluded(under, 1e-9, 1.0, h));
        CHECK(h.primitive == first);
    }
}

namespace {

/// Records every hinted feeler (opaque or filtered): the guesses it came with
/// and what it found.
class HintRecorder final : public test::ForwardingAccelerator {
public:
    struct Feeler {
        OcclusionHint guesses;
        uint32_t found;
        bool blocked;
    };
    using ForwardingAccelerator::ForwardingAccelerator;
    using ForwardingAccelerator::occluded;
    bool occluded(const Ray& r, double tMin, double tMax, Departure from,
                  OcclusionHint& h) const override {
        const OcclusionHint guesses = h;
        const bool blocked = ForwardingAccelerator::occluded(r, tMin, tMax, from, h);
        CHECK(blocked == ForwardingAccelerator::occluded(r, tMin, tMax, from));
        feelers.push_back({guesses, h.primitive, blocked});
        return blocked;
    }
    using ForwardingAccelerator::transmittance;
    Color transmittance(const Ray& r, double tMin, double tMax, Departure from,
                        OcclusionHint& h) const override {
        const OcclusionHint guesses = h;
        const Color through = ForwardingAccelerator::transmittance(r, tMin, tMax, from, h);
        CHECK(through == ForwardingAccelerator::transmittance(r, tMin, tMax, from));
        feelers.push_back({guesses, h.primitive, through.isBlack()});
        return through;
    }
    mutable std::vector<Feeler> feelers;
};

Material matte(double kd, double km = 0) {
    Material m;
    m.kd = Color(kd);
    m.ka = Color(kd);
    m.km = Color(km);
    return m;
}

/// A floor (plane) under an opaque, reflective ball and a point light up on
/// the left, seen directly and in a mirror tilted down behind the shadow: the
/// ball's shadow on the floor is reached by camera rays (feelers at depth 1)
/// and by the ball's and the mirror's reflections (depth 2). A row that
/// crosses the ball and then the shadow meets the floor's shadow first at
/// depth 2, then at depth 1, where only the fallback knows the ball.
Scene shadowInMirror() {
    Scene s;
    s.camera = Camera::perspective({0, 6, 9}, {0, 0.5, 0}, {0, 1, 0}, 55);
    s.image.width = 64;
    s.image.height = 48;
    s.ambient = Color(0.2);
    Light light;
    light.position = {-6, 10, 0};
    s.lights.push_back(light);
    s.materials = {matte(0.5), matte(0.2, 0.7), matte(0.05, 0.9)};
    const auto add = [&](std::unique_ptr<Shape> shape, uint32_t material) {
        Object o;
        o.name = "object " + std::to_string(s.objects.size());
        o.shape = std::move(shape);
        o.material = material;
        s.objects.push_back(std::move(o));
    };
    add(makePlane({0, 0, 0}, {0, 1, 0}, 50), 0);
    add(makeSphere({0, 2, 0}, 1.5), 1);
    add(makeDisk({2.5, 1.8, -2.8}, normalize(Vec3{0, -0.3, 0.95}), 2.5), 2);
    return s;
}

}  // namespace

TEST_CASE("shadow cache: through the integrator most blocked feelers find an occluder a guess named, some the fallback, and no pixel changes") {
    const Scene s = shadowInMirror();
    RenderOverrides o;
    o.shadows = ShadowMode::Opaque;
    const RenderOptions options = resolveRenderOptions(s, o);
    const EffectSet effects = analyseEffects(s, options);
    EmbreeAccelerator embree(s, options.accelOptions);
    NaiveAccelerator naive(s, options.accelOptions);
    pixelsInBothAccelerators(s, naive, embree, options, effects, s.image.width, s.image.height);

    HintRecorder recorder(embree);
    const WhittedIntegrator integrator(s, recorder, options, effects);
    ShadowCache cache;
    for (int y = 0; y < s.image.height; ++y)
        for (int x = 0; x < s.image.width; ++x) {
            RayCounters counters;
            SampleRays spent;
            integrator.Li(s.camera.generateRay(x + 0.5, y + 0.5, s.image.width, s.image.height),
                          counters, nullptr, spent, &cache);
        }
    int blocked = 0, byFirst = 0, byFallback = 0;
    for (const auto& f : recorder.feelers) {
        if (!f.blocked) {
            CHECK(f.found == kNone);
            continue;
        }
        ++blocked;
        if (f.found == f.guesses.primitive) ++byFirst;
        else if (f.found == f.guesses.fallback) ++byFallback;
    }
    // (Whether a guess answered or a walk found the same ball cannot be told
    // here; the hidden-ball test above shows the guesses are asked.)
    MESSAGE("feelers ", recorder.feelers.size(), ", blocked ", blocked, ", by the first guess's occluder ",
            byFirst, ", by the fallback's ", byFallback);
    CHECK(blocked > 100);
    CHECK(byFirst + byFallback > blocked * 8 / 10);
    CHECK(byFallback > 0);
}

TEST_CASE("shadow cache: none is kept where the accelerator cannot use a hint") {
    // The feelers of one pixel, counted by whether they came with a cache.
    struct Traced {
        uint64_t feelers;
        size_t hinted;
        size_t slots;
    };
    const auto trace = [](const Scene& s, const Accelerator& accel, ShadowMode mode) {
        RenderOverrides o;
        o.shadows = mode;
        const RenderOptions options = resolveRenderOptions(s, o);
        HintRecorder recorder(accel);
        const WhittedIntegrator integrator(s, recorder, options, analyseEffects(s, options));
        ShadowCache cache;
        RayCounters counters;
        SampleRays spent;
        integrator.Li(s.camera.generateRay(40, 20, s.image.width, s.image.height), counters,
                      nullptr, spent, &cache);
        return Traced{counters.total(RayType::Shadow), recorder.feelers.size(), cache.slotCount()};
    };
    const Scene s = shadowInMirror();
    NaiveAccelerator naive(s, {});
    EmbreeAccelerator embree(s, {});
    for (ShadowMode mode : {ShadowMode::Opaque, ShadowMode::Filtered}) {
        const Traced byNaive = trace(s, naive, mode);  // the naive loop takes no hint
        CHECK(byNaive.feelers > 0);
        CHECK(byNaive.hinted == 0);
        CHECK(byNaive.slots == 0);
        const Traced byEmbree = trace(s, embree, mode);  // no transmitter: hints either way
        CHECK(byEmbree.hinted == byEmbree.feelers);
        CHECK(byEmbree.slots > 0);
    }
    // A glass ball: filtered feelers ask the surface filter, which no hint
    // can skip; opaque feelers still take hints.
    Scene glassy = shadowInMirror();
    glassy.materials[1].kt = Color(0.8);
    glassy.materials[1].ior = 1.5;
    EmbreeAccelerator throughGlass(glassy, {});
    const Traced filtered = trace(glassy, throughGlass, ShadowMode::Filtered);
    CHECK(filtered.feelers > 0);
    CHECK(filtered.slots == 0);
    const Traced opaque = trace(glassy, throughGlass, ShadowMode::Opaque);
    CHECK(opaque.hinted == opaque.feelers);
    CHECK(opaque.slots > 0);
}

// The words of the enum-valued render options (renderer/render_option_names.h)
// and how the parsed enums reach RenderOptions: the tables hold exactly the
// documented words, and resolveRenderOptions applies every value, file first,
// flags on top.
#include <doctest/doctest.h>

#include <string>
#include <utility>
#include <vector>

#include "geometry/primitives.h"
#include "renderer/accel/accelerator.h"
#include "renderer/render_option_names.h"
#include "renderer/render_setup.h"

using namespace raylab;

namespace {

template <class E>
std::vector<std::string> wordsOf(const OptionNames<E>& names) {
    std::vector<std::string> words;
    for (const auto& entry : names) words.push_back(entry.first);
    return words;
}

Scene oneSphere() {
    Scene s;
    s.materials.resize(1);
    Object o;
    o.name = "ball";
    o.shape = makeSphere({0, 0, -5}, 1);
    s.objects.push_back(std::move(o));
    return s;
}

}  // namespace

TEST_CASE("render option names: each table holds the documented words, in order") {
    // The words README.md, docs/scene-format.md and `raylab render --help` promise.
    CHECK(wordsOf(acceleratorNames()) == std::vector<std::string>{"embree", "naive"});
    CHECK(wordsOf(bvhQualityNames()) == std::vector<std::string>{"low", "medium", "high"});
    CHECK(wordsOf(precisionNames()) == std::vector<std::string>{"float", "double"});
    CHECK(wordsOf(effectsModeNames()) == std::vector<std::string>{"auto", "all"});
    CHECK(joinedNames(bvhQualityNames(), "|") == "low|medium|high");

    using Q = AccelOptions::BvhQuality;
    CHECK(acceleratorNames()[1].second == AcceleratorKind::Naive);
    CHECK(bvhQualityNames()[0].second == Q::Low);
    CHECK(bvhQualityNames()[2].second == Q::High);
    CHECK(precisionNames()[0].second == Precision::Float);
    CHECK(effectsModeNames()[1].second == EffectsMode::All);
    // A value's word reads back to the value.
    for (const auto& [word, q] : bvhQualityNames()) CHECK(word == bvhQualityName(q));
    for (const auto& [word, p] : precisionNames()) CHECK(word == precisionName(p));
    for (const auto& [word, k] : acceleratorNames()) CHECK(word == acceleratorName(k));
}

TEST_CASE("render option names: makeAccelerator builds the accelerator of each kind") {
    const Scene s = oneSphere();
    for (const auto& entry : acceleratorNames()) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& word = entry.first;
        const auto& kind = entry.second;
        CAPTURE(word);
        CHECK(makeAccelerator(kind, s)->name() == word);
    }
}

TEST_CASE("render option names: every parsed value reaches RenderOptions, flags over the file") {
    Scene s = oneSphere();
    const RenderOptions defaults = resolveRenderOptions(s, {});
    CHECK(defaults.accel == AcceleratorKind::Embree);
    CHECK(defaults.accelOptions.quality == AccelOptions::BvhQuality::Medium);
    CHECK(defaults.accelOptions.intersect.precision == Precision::Double);
    CHECK_FALSE(defaults.forceAllEffects);

    for (const auto& [word, kind] : acceleratorNames()) {
        RenderOverrides o;
        o.accel = kind;
        CHECK(resolveRenderOptions(s, o).accel == kind);
    }
    for (const auto& [word, q] : bvhQualityNames()) {
        RenderOverrides o;
        o.bvhQuality = q;
        CHECK(resolveRenderOptions(s, o).accelOptions.quality == q);
    }
    for (const auto& [word, p] : precisionNames()) {
        RenderOverrides o;
        o.precision = p;
        CHECK(resolveRenderOptions(s, o).accelOptions.intersect.precision == p);
    }
    for (const auto& [word, e] : effectsModeNames()) {
        RenderOverrides o;
        o.effects = e;
        CHECK(resolveRenderOptions(s, o).forceAllEffects == (e == EffectsMode::All));
    }

    // The scene file's "render" block, then the flags on top of it.
    s.settings.accel = AcceleratorKind::Naive;
    s.settings.bvhQuality = AccelOptions::BvhQuality::High;
    s.settings.precision = Precision::Float;
    const RenderOptions fromFile = resolveRenderOptions(s, {});
    CHECK(fromFile.accel == AcceleratorKind::Naive);
    CHECK(fromFile.accelOptions.quality == AccelOptions::BvhQuality::High);
    CHECK(fromFile.accelOptions.intersect.precision == Precision::Float);
    RenderOverrides flags;
    flags.accel = AcceleratorKind::Embree;
    flags.bvhQuality = AccelOptions::BvhQuality::Low;
    flags.precision = Precision::Double;
    const RenderOptions both = resolveRenderOptions(s, flags);
    CHECK(both.accel == AcceleratorKind::Embree);
    CHECK(both.accelOptions.quality == AccelOptions::BvhQuality::Low);
    CHECK(both.accelOptions.intersect.precision == Precision::Double);
}

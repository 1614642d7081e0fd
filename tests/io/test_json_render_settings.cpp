// The scene file's "render" block: every word of "accel", "bvh_quality" and
// "precision" reads into its enum, and any other value is an error at the
// value's own line that lists the words.
#include <doctest/doctest.h>

#include <string>

#include "io/io_test_helpers.h"
#include "renderer/io/scene_loader.h"

using namespace raylab;
using raylab::test::contains;
using raylab::test::failureOf;

namespace {

/// A scene whose "render" block is `members`; the block starts on line 2.
std::string withRender(const std::string& members) {
    return "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
           "\"render\": {\n" +
           members + "},\n\"objects\": []}\n";
}

RenderOverrides settingsOf(const std::string& members) {
    return loadJsonScene(withRender(members), "r.json").settings;
}

}  // namespace

TEST_CASE("json render settings: every word of accel, bvh_quality and precision") {
    using Q = AccelOptions::BvhQuality;
    CHECK(settingsOf("\"accel\": \"embree\"").accel == AcceleratorKind::Embree);
    CHECK(settingsOf("\"accel\": \"naive\"").accel == AcceleratorKind::Naive);
    CHECK(settingsOf("\"bvh_quality\": \"low\"").bvhQuality == Q::Low);
    CHECK(settingsOf("\"bvh_quality\": \"medium\"").bvhQuality == Q::Medium);
    CHECK(settingsOf("\"bvh_quality\": \"high\"").bvhQuality == Q::High);
    CHECK(settingsOf("\"precision\": \"float\"").precision == Precision::Float);
    CHECK(settingsOf("\"precision\": \"double\"").precision == Precision::Double);
    // Absent keys leave the defaults in place.
    const RenderOverrides none = settingsOf("");
    CHECK_FALSE(none.accel);
    CHECK_FALSE(none.bvhQuality);
    CHECK_FALSE(none.precision);
}

TEST_CASE("json render settings: an unknown word is an error at its line, listing the words") {
    struct Case {
        const char* members;
        const char* message;
    };
    const Case cases[] = {
        {"\"accel\": \"bvh4\"", "render.accel: must be one of 'embree', 'naive' (got 'bvh4')"},
        {"\"accel\": \"Embree\"", "render.accel: must be one of 'embree', 'naive' (got 'Embree')"},
        {"\"bvh_quality\": \"best\"",
         "render.bvh_quality: must be one of 'low', 'medium', 'high' (got 'best')"},
        {"\"precision\": \"half\"",
         "render.precision: must be one of 'float', 'double' (got 'half')"},
        {"\"precision\": 32", "render.precision: expected a string, got number"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.members);
        const test::Failure f =
            failureOf([&] { loadJsonScene(withRender(c.members), "r.json"); });
        CHECK(f.file == "r.json");
        CHECK(f.line == 3);  // the value's line, after the block's opening line
        CHECK(f.message == c.message);
    }
}

TEST_CASE("json render settings: a misspelt key is refused with a suggestion") {
    const test::Failure f =
        failureOf([&] { loadJsonScene(withRender("\"bvh_qualty\": \"low\""), "r.json"); });
    CHECK(f.line == 3);
    CHECK(contains(f.message, "did you mean 'bvh_quality'"));
}

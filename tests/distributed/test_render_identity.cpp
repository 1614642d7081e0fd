// What ranks compare before the first frame: identical renders agree, and a
// difference in the scene's bytes or in any setting that changes pixels is
// caught and named; settings that do not change pixels are left out.

#include <doctest/doctest.h>

#include <functional>
#include <string>
#include <vector>

#include "distributed/protocol.h"
#include "distributed/render_identity.h"
#include "renderer/content_hash.h"

using namespace raylab;

namespace {

/// A file read for the scene, as readTextFile records it.
InputFile digest(const std::string& bytes) {
    InputFile f;
    f.path = "f";
    f.bytes = bytes.size();
    f.contentHash = contentHash(bytes);
    return f;
}

const std::vector<InputFile> kFiles = {digest("{\"objects\": ...}"), digest("v 0 0 0\n")};

RenderIdentity identity(const RenderOptions& o, const std::vector<InputFile>& files = kFiles,
                        std::optional<FrameRange> frames = std::nullopt,
                        bool triangulated = false) {
    return renderIdentity("a.json", files, o, frames, triangulated);
}

const std::string kAdvice = "; every rank must render the same scene with the same options";

}  // namespace

TEST_CASE("renderIdentity: the same render agrees, whatever the thread count") {
    RenderOptions a, b;
    b.threads = 7;
    CHECK(disagreement(identity(a), identity(b), "rank 1 (n)") == "");
    // The scene's name only labels messages: the same bytes under another name agree.
    CHECK(disagreement(identity(a), renderIdentity("copy/a.json", kFiles, b, {}, false),
                       "rank 1") == "");
}

TEST_CASE("renderIdentity: other scene bytes are named with the files") {
    const RenderOptions o;
    const RenderIdentity root = identity(o);
    const RenderIdentity other = renderIdentity("b.json", {digest("{}")}, o, {}, false);
    CHECK(disagreement(root, other, "rank 1 (n)") ==
          "ranks disagree: rank 1 (n) read other scene bytes than rank 0: b.json (1 file, 2 "
          "bytes) against a.json (2 files, 24 bytes)" +
              kAdvice);
    // One byte of a mesh, and where one file ends and the next begins, count.
    CHECK(disagreement(root, identity(o, {digest("{\"objects\": ...}"), digest("v 0 0 1\n")}),
                       "rank 1") != "");
    CHECK(disagreement(identity(o, {digest("ab"), digest("c")}),
                       identity(o, {digest("a"), digest("bc")}), "rank 1") != "");
}

TEST_CASE("renderIdentity: a setting that differs is named") {
    RenderOptions a, b;
    a.width = 96;
    b.width = 64;
    CHECK(disagreement(identity(a), identity(b), "rank 2 (n)") ==
          "ranks disagree: rank 2 (n) renders with width=64, rank 0 with width=96" + kAdvice);
    CHECK(disagreement(identity(a, kFiles, FrameRange{1, 3}), identity(a, kFiles, FrameRange{1, 2}),
                       "rank 1") ==
          "ranks disagree: rank 1 renders with frames=1:2, rank 0 with frames=1:3" + kAdvice);
    CHECK(disagreement(identity(a, kFiles, {}, false), identity(a, kFiles, {}, true), "rank 1") ==
          "ranks disagree: rank 1 renders with triangulated=yes, rank 0 with triangulated=no" +
              kAdvice);
}

TEST_CASE("renderIdentity: every option that changes pixels is in the settings") {
    const std::vector<std::pair<const char*, std::function<void(RenderOptions&)>>> changes = {
        {"width", [](RenderOptions& o) { o.width = 33; }},
        {"height", [](RenderOptions& o) { o.height = 33; }},
        {"spp", [](RenderOptions& o) { o.spp = 4; }},
        {"depth", [](RenderOptions& o) { o.maxDepth = 9; }},
        {"min_weight", [](RenderOptions& o) { o.minWeight = 0.01; }},
        {"adaptive", [](RenderOptions& o) { o.adaptiveThreshold = 0.1; }},
        {"adaptive_levels", [](RenderOptions& o) { o.adaptiveMaxLevel = 3; }},
        {"seed", [](RenderOptions& o) { o.seed = 5; }},
        {"max_rays", [](RenderOptions& o) { o.maxRaysPerSample = 100; }},
        {"accel", [](RenderOptions& o) { o.accel = AcceleratorKind::Naive; }},
        {"shadows", [](RenderOptions& o) { o.shadows = ShadowMode::Opaque; }},
        {"texture_filter", [](RenderOptions& o) { o.textures.filter = TextureFilter::Point; }},
        {"texture_footprint",
         [](RenderOptions& o) { o.textures.footprint = TextureFootprint::Cones; }},
        {"bvh_quality",
         [](RenderOptions& o) { o.accelOptions.quality = AccelOptions::BvhQuality::High; }},
        {"robust", [](RenderOptions& o) { o.accelOptions.robust = !o.accelOptions.robust; }},
        {"accel_origin", [](RenderOptions& o) { o.accelOptions.origin.y = 1e-300; }},
        {"precision",
         [](RenderOptions& o) { o.accelOptions.intersect.precision = Precision::Float; }},
        {"polygons",
         [](RenderOptions& o) { o.accelOptions.intersect.polygonTest = PolygonTest::Projected; }},
        {"spawn", [](RenderOptions& o) { o.spawn.mode = OffsetMode::FixedEpsilon; }},
        {"epsilon", [](RenderOptions& o) { o.spawn.epsilon = 2e-4; }},
        {"spawn_reference", [](RenderOptions& o) { o.spawn.reference.z = 0.5; }},
        {"spd", [](RenderOptions& o) { o.spd = true; }},
        {"effects", [](RenderOptions& o) { o.forceAllEffects = true; }},
        {"aovs", [](RenderOptions& o) { o.wantAovs = false; }},
    };
    const RenderOptions base;
    for (const auto& entry : changes) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& name = entry.first;
        const auto& change = entry.second;
        RenderOptions o = base;
        change(o);
        const std::string why = disagreement(identity(base), identity(o), "rank 1");
        INFO(name << ": " << why);
        CHECK(why.find(std::string("renders with ") + name + "=") != std::string::npos);
    }
}

TEST_CASE("appendIdentity/readIdentity: an identity crosses the wire unchanged") {
    RenderOptions o;
    o.minWeight = 0.1;  // not exact in binary: text keeps it to the bit
    const RenderIdentity id = identity(o, kFiles, FrameRange{2, 5}, true);
    std::vector<unsigned char> bytes;
    appendIdentity(id, "node7", bytes);
    ByteReader in(bytes.data(), bytes.size());
    std::string host;
    const RenderIdentity back = readIdentity(in, host);
    CHECK(in.done());
    CHECK(host == "node7");
    CHECK(back.scene == id.scene);
    CHECK(back.files == 2);
    CHECK(back.bytes == id.bytes);
    CHECK(back.sceneHash == id.sceneHash);
    CHECK(back.settings == id.settings);
    CHECK(disagreement(id, back, "rank 1") == "");
    // A truncated message is refused, not read past its end.
    ByteReader cut(bytes.data(), bytes.size() - 1);
    CHECK_THROWS_AS(readIdentity(cut, host), std::runtime_error);
}

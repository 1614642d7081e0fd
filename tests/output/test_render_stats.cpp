#include <doctest/doctest.h>

#include <string>

#include "renderer/render_stats.h"

using namespace raylab;

namespace {

RenderStats makeStats() {
    RenderStats s;
    // Camera rays only at depth 1; shadow rays at depths 1 and 2 (depth 3 has a
    // zero that must not be printed); reflection only at depth 2, so its array
    // keeps the leading zero; no refraction at all.
    s.rays.byDepth[size_t(RayType::Camera)][1] = 100;
    s.rays.byDepth[size_t(RayType::Shadow)][1] = 50;
    s.rays.byDepth[size_t(RayType::Shadow)][2] = 20;
    s.rays.byDepth[size_t(RayType::Reflection)][2] = 5;
    s.rays.cameraHits = 60;
    s.parseSeconds = 0.001;
    s.buildSeconds = 0.25;
    s.renderSeconds = 0.5;
    s.writeSeconds = 12.3456789;
    s.primitives = 1234567;
    s.effects = {"shadows", "reflection"};
    s.threads = 8;
    s.accel = "embree";
    s.width = 640;
    s.height = 480;
    s.spp = 4;
    s.maxDepth = 5;
    s.nonFiniteSamples = 2;
    s.maxRaysPerSample = 65536;
    s.cappedSamples = 3;
    s.maxSampleRays = 65538;
    s.filter.cutOut = 11;
    s.filter.attenuated = 12;
    return s;
}

}  // namespace

TEST_CASE("render stats: the whole JSON document") {
    // total = 100 + 50 + 20 + 5 = 175 rays; mrays/s = 175 / 0.5 * 1e-6 = 0.00035.
    // Times use %.6g: 12.3456789 -> 12.3457.
    const std::string expected = R"({
  "rays": {
    "camera": 100,
    "shadow": 70,
    "reflection": 5,
    "refraction": 0,
    "total": 175,
    "by_depth": {
      "camera": [100],
      "shadow": [50, 20],
      "reflection": [0, 5],
      "refraction": []
    }
  },
  "camera_hits": 60,
  "time_s": {
    "parse": 0.001,
    "build": 0.25,
    "render": 0.5,
    "write": 12.3457
  },
  "mrays_per_s": 0.00035,
  "primitives": 1234567,
  "effects": ["shadows", "reflection"],
  "threads": 8,
  "accel": "embree",
  "image": {
    "width": 640,
    "height": 480,
    "spp": 4,
    "max_depth": 5
  },
  "non_finite_samples": 2,
  "ray_cap": {
    "rays_per_sample": 65536,
    "capped_samples": 3,
    "most_rays_in_a_sample": 65538
  },
  "surface_filter": {
    "cut_out_candidates": 11,
    "attenuating_crossings": 12
  }
}
)";
    CHECK(makeStats().toJson() == expected);
}

TEST_CASE("render stats: every key is present, also for an empty render") {
    const std::string json = RenderStats().toJson();
    for (const char* key :
         {"\"rays\"", "\"camera\"", "\"shadow\"", "\"reflection\"", "\"refraction\"", "\"total\"",
          "\"by_depth\"", "\"camera_hits\"", "\"time_s\"", "\"parse\"", "\"build\"", "\"render\"",
          "\"write\"", "\"mrays_per_s\"", "\"primitives\"", "\"effects\": []", "\"threads\"",
          "\"accel\": \"\"", "\"image\"", "\"width\"", "\"height\"", "\"spp\"",
          "\"max_depth\"", "\"non_finite_samples\"", "\"ray_cap\"", "\"rays_per_sample\"",
          "\"capped_samples\"", "\"most_rays_in_a_sample\"", "\"surface_filter\""}) {
        CAPTURE(key);
        CHECK(json.find(key) != std::string::npos);
    }
    CHECK(json.find("\"mrays_per_s\": 0,") != std::string::npos);  // no division by zero
}

TEST_CASE("render stats: large counters, the deepest bucket and string escaping") {
    RenderStats s;
    // uint64 counters print in full (no double rounding): 2^53 + 1.
    s.rays.byDepth[size_t(RayType::Camera)][1] = 9007199254740993ull;
    // The last slot collects every ray at depth >= kMaxTrackedDepth.
    s.rays.byDepth[size_t(RayType::Refraction)][RayCounters::kMaxTrackedDepth] = 3;
    s.accel = "a\"b\\c\n\t\x01";
    const std::string json = s.toJson();
    CHECK(json.find("\"camera\": 9007199254740993,") != std::string::npos);
    std::string refraction = "\"refraction\": [";
    for (int d = 1; d < RayCounters::kMaxTrackedDepth; ++d) refraction += "0, ";
    refraction += "3]";
    CHECK(json.find(refraction) != std::string::npos);
    CHECK(json.find(R"("accel": "a\"b\\c\n\t\u0001")") != std::string::npos);
}

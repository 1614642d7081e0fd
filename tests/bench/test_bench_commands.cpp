// The benchmark entry points: option checks happen before anything runs, the
// pixel sample covers every column, and a tiny limit benchmark runs end to end
// (no timing assertions: only structure and the recording/replay checks).

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <string>

#include "renderer/io/errors.h"
#include "support/temp_dir.h"
#include "tools/bench/accel_bench.h"
#include "tools/bench/limit_bench.h"

using namespace raylab;

TEST_CASE("pixel sample stride: smallest k >= requested that is coprime with the width") {
    CHECK(pixelSampleStride(1, 256) == 1);
    CHECK(pixelSampleStride(0, 256) == 1);
    // 256 = 2^8: 4 and 6 share a factor 2, 5 and 7 do not.
    CHECK(pixelSampleStride(4, 256) == 5);
    CHECK(pixelSampleStride(6, 256) == 7);
    // 255 = 3·5·17: 6 shares 3; 7 is coprime.
    CHECK(pixelSampleStride(6, 255) == 7);
    // Every column is visited: pixels k/2 + s·k (mod width) for a coprime k.
    const int width = 64;
    const size_t k = pixelSampleStride(10, width);
    CHECK(k == 11);
    std::vector<bool> seen(width, false);
    for (size_t s = 0; s < size_t(width); ++s) seen[(k / 2 + s * k) % width] = true;
    CHECK(std::accumulate(seen.begin(), seen.end(), 0) == width);
}

TEST_CASE("bench accel: invalid options are rejected before any measurement") {
    std::ostringstream out;
    AccelBenchOptions o;
    o.runs = 0;
    CHECK_THROWS_AS(runAccelBench(o, out), UsageError);
    o = {};
    o.width = 0;
    CHECK_THROWS_AS(runAccelBench(o, out), UsageError);
    o = {};
    o.naiveBudgetSeconds = 0;
    CHECK_THROWS_AS(runAccelBench(o, out), UsageError);
    o = {};
    o.outPath = "results.txt";
    CHECK_THROWS_AS(runAccelBench(o, out), UsageError);
    o = {};
    o.plotPath = "plot.png";
    CHECK_THROWS_AS(runAccelBench(o, out), UsageError);
    CHECK(out.str().empty());  // nothing ran
}

TEST_CASE("bench limit: invalid options are rejected") {
    std::ostringstream out;
    LimitBenchOptions o;
    CHECK_THROWS_AS(runLimitBench(o, out), UsageError);  // no scene
    o.scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json";
    o.runs = 0;
    CHECK_THROWS_AS(runLimitBench(o, out), UsageError);
    o.runs = 1;
    o.outPath = "limit.xml";
    CHECK_THROWS_AS(runLimitBench(o, out), UsageError);
}

TEST_CASE("bench limit: a tiny run records, replays and reports") {
    const test::TempDir dir;
    const std::string json = dir.file("limit.json");
    const std::string csv = dir.file("limit.csv");
    LimitBenchOptions o;
    o.scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json";
    o.width = 24;
    o.height = 18;
    o.runs = 1;
    o.threads = 1;
    o.outPath = json;
    std::ostringstream out;
    CHECK(runLimitBench(o, out) == 0);
    const std::string report = out.str();
    CHECK(report.find("recording: matches") != std::string::npos);
    CHECK(report.find("disagrees with the recorded hit/miss on 0 rays (interface replay: 0)") !=
          std::string::npos);
    CHECK(report.find("bare Embree replay") != std::string::npos);
    const std::string doc = test::readFile(json);
    CHECK(doc.find("\"recording_matches_counters\": true") != std::string::npos);
    CHECK(doc.find("\"replay_disagreements\": 0") != std::string::npos);
    // demo.json at spp 4: 24·18·4 camera rays.
    CHECK(doc.find("\"camera\": 1728") != std::string::npos);
    // Issue 20's bar without --spd (the demo's), named in the report.
    CHECK(doc.find("\"bar\": 0.7,") != std::string::npos);
    CHECK(report.find("of bare Embree (bar: >= 70%)") != std::string::npos);
    // One run: its own ratio is the run-by-run median, listed once.
    CHECK(report.find("run by run (each render against its own replays): median ") !=
          std::string::npos);
    CHECK(doc.find("\"renderer_fraction_per_run\": {\"median\": ") != std::string::npos);
    // One thread: the CPUs its timed phases ran on, named (sched_getcpu
    // answers on Linux), one or more of this machine's.
    const size_t cpusAt = doc.find("\"cpus\": [");
    REQUIRE(cpusAt != std::string::npos);
    int firstCpu = -1;
    REQUIRE(std::sscanf(doc.c_str() + cpusAt, "\"cpus\": [%d", &firstCpu) == 1);
    CHECK(firstCpu >= 0);
    CHECK(report.find("  timed on CPU " + std::to_string(firstCpu)) != std::string::npos);

    o.outPath = csv;
    o.threads = 2;
    std::ostringstream out2;
    CHECK(runLimitBench(o, out2) == 0);
    const std::string table = test::readFile(csv);
    CHECK(table.rfind("scene,width,height,spd,threads", 0) == 0);
    CHECK(std::count(table.begin(), table.end(), '\n') == 2);  // header + one row

    // With the SPD procedure the bar is issue 20's balls --spd one.
    o.spd = true;
    o.outPath = json;
    std::ostringstream out3;
    CHECK(runLimitBench(o, out3) == 0);
    CHECK(test::readFile(json).find("\"bar\": 0.8,") != std::string::npos);
    // Three runs: three ratios, their median among them.
    o.runs = 3;
    std::ostringstream out4;
    CHECK(runLimitBench(o, out4) == 0);
    const std::string doc3 = test::readFile(json);
    const size_t at = doc3.find("\"renderer_fraction_per_run\": {\"median\": ");
    REQUIRE(at != std::string::npos);
    double median = 0, a = 0, b = 0, c = 0;
    REQUIRE(std::sscanf(doc3.c_str() + at,
                        "\"renderer_fraction_per_run\": {\"median\": %lf, \"runs\": [%lf, %lf, %lf]}",
                        &median, &a, &b, &c) == 4);
    CHECK(a > 0);
    CHECK(b > 0);
    CHECK(c > 0);
    CHECK((median == a || median == b || median == c));
    CHECK(median >= std::min({a, b, c}));
    CHECK(median <= std::max({a, b, c}));
    CHECK(out3.str().find("of bare Embree (bar with --spd: >= 80%)") != std::string::npos);
}

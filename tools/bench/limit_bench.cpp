#include "tools/bench/limit_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/accel/embree_replay.h"
#include "renderer/accel/ray_recorder.h"
#include "renderer/effects.h"
#include "renderer/huge_page_allocator.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/json_string.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "tools/report/machine.h"
#include "tools/report/phase_clock.h"
#include "tools/report/table_format.h"

namespace raylab {

namespace {

using Clock = std::chrono::steady_clock;

/// The rays' answers through the Accelerator interface (what the integrator
/// calls: conversion, query, decoding), threaded as EmbreeReplay is.
class InterfaceReplay {
public:
    InterfaceReplay(const Accelerator& accel, const std::vector<RecordedRay>& rays)
        : m_accel(accel), m_rays(rays), m_results(rays.size(), 0) {}

    /// Traces the recorded rays [begin, end).
    void run(int threads, size_t begin, size_t end) {
        const auto one = [&](size_t i) {
            const RecordedRay& r = m_rays[i];
            const Departure from{r.departed};
            m_results[i] = r.occlusion
                               ? m_accel.occluded(r.ray, r.tMin, r.tMax, from)
                               : m_accel.intersect(r.ray, r.tMin, r.tMax, from).has_value();
        };
        forEachReplayedRay(threads, begin, end, one);
    }

    const std::vector<uint8_t>& results() const { return m_results; }

private:
    const Accelerator& m_accel;
    const std::vector<RecordedRay>& m_rays;
    std::vector<uint8_t> m_results;
};

/// Rays replayed per timed slice: 16384 recorded rays are 1.3 MB, which stay
/// in the cache between the untimed read below and the two replays.
constexpr size_t kSliceRays = 16384;

/// Reads every cache line of the slice's rays, untimed.
/// On this project's VMs the host takes memory back at any moment, and a page
/// it took costs ~6 us at the next touch: one byte per page of demo.json's
/// 466 MB recording took 0.005-0.8 s to read, varying from one pass to the
/// next. Replayed as one stream, the recording charged that to whichever
/// replay ran first after a render (the bare replay measured up to twice the
/// interface's time on the same rays). The renderer reads no recording:
/// neither replay may pay for reading it.
void touchSlice(const std::vector<RecordedRay>& rays, size_t begin, size_t end) {
    const auto* bytes = reinterpret_cast<const volatile unsigned char*>(rays.data() + begin);
    const size_t size = (end - begin) * sizeof(RecordedRay);
    for (size_t offset = 0; offset < size; offset += 64) (void)bytes[offset];
}

/// One timed pass of both replays over the recording, slice by slice: each
/// slice is read in untimed, then replayed bare and through the interface
/// (alternating which goes first). Adds each replay's time to its total.
void timeReplays(const PhaseClock& clock, const std::vector<RecordedRay>& rays, EmbreeReplay& bare,
                 InterfaceReplay& interface, int threads, double& bareSeconds, double& interfaceSeconds,
                 std::set<int>* cpus = nullptr) {
    bareSeconds = interfaceSeconds = 0;
    for (size_t begin = 0, slice = 0; begin < rays.size(); begin += kSliceRays, ++slice) {
        const size_t end = std::min(rays.size(), begin + kSliceRays);
        if (cpus) cpus->insert(currentCpu());
        touchSlice(rays, begin, end);
        const auto runBare = [&] { bareSeconds += clock.time([&] { bare.run(threads, begin, end); }); };
        const auto runInterface = [&] {
            interfaceSeconds += clock.time([&] { interface.run(threads, begin, end); });
        };
        if (slice % 2 == 0) {
            runBare();
            runInterface();
        } else {
            runInterface();
            runBare();
        }
    }
}

uint64_t disagreementsOf(const std::vector<uint8_t>& results, const std::vector<RecordedRay>& rays) {
    uint64_t n = 0;
    for (size_t i = 0; i < rays.size(); ++i) n += results[i] != uint8_t(rays[i].hit);
    return n;
}

bool sameCounters(const RayCounters& a, const RayCounters& b) {
    return a.byDepth == b.byDepth && a.cameraHits == b.cameraHits;
}

/// "0, 1": the report's and the JSON's list of CPUs.
std::string commaList(const std::set<int>& values) {
    std::string list;
    for (const int v : values) list += (list.empty() ? "" : ", ") + std::to_string(v);
    return list;
}

std::string fixed(double v, int decimals) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

struct LimitResult {
    std::string scene;
    int width = 0, height = 0, threads = 1, runs = 1;
    bool spd = false;
    uint64_t primitives = 0;
    double buildSeconds = 0;
    RayCounters counters;
    uint64_t rays = 0;
    double renderSeconds = 0, interfaceSeconds = 0, bareSeconds = 0;
    /// bare ÷ renderer of each run: a render and the replays timed right
    /// after it, so a drift of the machine's speed between runs cancels.
    std::vector<double> runFractions;
    uint64_t bareDisagreements = 0, interfaceDisagreements = 0;
    bool countersMatch = false;
    bool cpuClock = false;  ///< times are the working thread's CPU time (one thread)
    /// CPUs the calling thread was on around the timed renders and at each
    /// replay slice (-1: unknown); with one thread, where the phases ran.
    std::set<int> cpus;
    double loadAverage = -1;  ///< 1-minute load average when the run started

    double rate(double seconds) const { return seconds > 0 ? double(rays) / seconds : 0; }
    double fraction() const { return bareSeconds > 0 ? bareSeconds / renderSeconds : 0; }
    double pairedFraction() const { return runFractions.empty() ? 0 : median(runFractions); }
    double bar() const { return limitBenchBar(spd); }
    bool barMet() const { return fraction() >= bar(); }
};

std::string csvDocument(const LimitResult& r, const std::string& cpu) {
    std::string t =
        "scene,width,height,spd,threads,runs,primitives,build_s,rays,camera_rays,shadow_rays,"
        "reflection_rays,refraction_rays,render_s,render_mrays_per_s,interface_replay_s,"
        "interface_mrays_per_s,bare_replay_s,bare_mrays_per_s,renderer_fraction_of_bare,"
        "renderer_fraction_per_run_median,bar_met,clock,cpu,cores\n";
    t += csvField(r.scene) + "," + std::to_string(r.width) + "," + std::to_string(r.height) + "," +
         (r.spd ? "true" : "false") + "," + std::to_string(r.threads) + "," +
         std::to_string(r.runs) + "," + std::to_string(r.primitives) + "," +
         jsonNumber(r.buildSeconds) + "," + std::to_string(r.rays) + "," +
         std::to_string(r.counters.total(RayType::Camera)) + "," +
         std::to_string(r.counters.total(RayType::Shadow)) + "," +
         std::to_string(r.counters.total(RayType::Reflection)) + "," +
         std::to_string(r.counters.total(RayType::Refraction)) + "," +
         jsonNumber(r.renderSeconds) + "," + jsonNumber(r.rate(r.renderSeconds) * 1e-6) + "," +
         jsonNumber(r.interfaceSeconds) + "," + jsonNumber(r.rate(r.interfaceSeconds) * 1e-6) +
         "," + jsonNumber(r.bareSeconds) + "," + jsonNumber(r.rate(r.bareSeconds) * 1e-6) + "," +
         jsonNumber(r.fraction()) + "," + jsonNumber(r.pairedFraction()) + "," +
         (r.barMet() ? "true" : "false") +
         "," + (r.cpuClock ? "thread_cpu" : "wall") + "," + csvField(cpu) + "," +
         std::to_string(logicalCores()) + "\n";
    return t;
}

std::string jsonDocument(const LimitResult& r, const std::string& cpu) {
    const auto phase = [&](double s) {
        return "{\"seconds\": " + jsonNumber(s) +
               ", \"mrays_per_second\": " + jsonNumber(r.rate(s) * 1e-6) + "}";
    };
    std::string runs = "[";
    for (size_t i = 0; i < r.runFractions.size(); ++i)
        runs += (i ? ", " : "") + jsonNumber(r.runFractions[i]);
    runs += "]";
    std::string j = "{\n  \"scene\": " + jsonString(r.scene) +
                    ",\n  \"machine\": {\"cpu\": " + jsonString(cpu) +
                    ", \"cores\": " + std::to_string(logicalCores()) +
                    ", \"load_average\": " + jsonNumber(r.loadAverage) + "}" +
                    ",\n  \"width\": " + std::to_string(r.width) +
                    ",\n  \"height\": " + std::to_string(r.height) +
                    ",\n  \"spd\": " + (r.spd ? "true" : "false") +
                    ",\n  \"threads\": " + std::to_string(r.threads) +
                    ",\n  \"runs\": " + std::to_string(r.runs) +
                    ",\n  \"clock\": " + (r.cpuClock ? "\"thread_cpu\"" : "\"wall\"") +
                    ",\n  \"cpus\": [" + commaList(r.cpus) + "]" +
                    ",\n  \"primitives\": " + std::to_string(r.primitives) +
                    ",\n  \"build_seconds\": " + jsonNumber(r.buildSeconds) +
                    ",\n  \"rays\": {\"total\": " + std::to_string(r.rays) +
                    ", \"camera\": " + std::to_string(r.counters.total(RayType::Camera)) +
                    ", \"camera_hits\": " + std::to_string(r.counters.cameraHits) +
                    ", \"shadow\": " + std::to_string(r.counters.total(RayType::Shadow)) +
                    ", \"reflection\": " + std::to_string(r.counters.total(RayType::Reflection)) +
                    ", \"refraction\": " + std::to_string(r.counters.total(RayType::Refraction)) +
                    "},\n  \"renderer\": " + phase(r.renderSeconds) +
                    ",\n  \"interface_replay\": " + phase(r.interfaceSeconds) +
                    ",\n  \"bare_replay\": " + phase(r.bareSeconds) +
                    ",\n  \"renderer_fraction_of_bare\": " + jsonNumber(r.fraction()) +
                    ",\n  \"renderer_fraction_per_run\": {\"median\": " +
                    jsonNumber(r.pairedFraction()) + ", \"runs\": " + runs + "}" +
                    ",\n  \"bar\": " + jsonNumber(r.bar()) +
                    ",\n  \"bar_met\": " + (r.barMet() ? "true" : "false") +
                    ",\n  \"recording_matches_counters\": " +
                    (r.countersMatch ? "true" : "false") +
                    ",\n  \"replay_disagreements\": " + std::to_string(r.bareDisagreements) +
                    "\n}\n";
    return j;
}

}  // namespace

int runLimitBench(const LimitBenchOptions& options, std::ostream& out) {
    if (options.scene.empty()) throw UsageError("bench limit: missing SCENE");
    if (options.width < 0 || options.height < 0)
        throw UsageError("bench limit: width and height must be >= 1");
    if (options.runs < 1) throw UsageError("bench limit: runs must be >= 1");
    if (options.threads < 0) throw UsageError("bench limit: threads must be >= 0");
    std::optional<TableFormat> format;
    if (!options.outPath.empty()) format = tableFormatOf(options.outPath, "bench limit: output");

    Scene scene = loadScene(options.scene);
    RenderOverrides o;
    o.spd = options.spd;
    if (options.width > 0) o.width = options.width;
    if (options.height > 0) o.height = options.height;
    if (options.threads > 0) o.threads = options.threads;
    // Bare Embree replays opaque shadow feelers; filtered ones run the
    // surface filter's callbacks, which are work beyond traversal.
    o.shadows = ShadowMode::Opaque;
    const RenderOptions renderOptions = resolveRenderOptions(scene, o);
    checkMemoryBudget(scene, renderOptions);
    const EffectSet effects = analyseEffects(scene, renderOptions);

    LimitResult r;
    r.scene = options.scene;
    r.width = renderOptions.width;
    r.height = renderOptions.height;
    r.spd = options.spd;
    r.threads = effectiveThreads(options.threads);
    r.runs = options.runs;
    r.primitives = scene.primitiveCount();
    r.loadAverage = loadAverage();
    const std::string cpu = cpuModelName();

    // Device creation included: the BVH alone is in `bench accel`.
    const auto t0 = Clock::now();
    const std::unique_ptr<Accelerator> accel =
        makeAccelerator("embree", scene, renderOptions.accelOptions);
    r.buildSeconds = secondsSince(t0);

    out << "raylab bench limit: " << options.scene << "\n"
        << "  " << r.width << "x" << r.height
        << (options.spd ? " SPD procedure (rays through pixel corners)" : "") << ", spp "
        << renderOptions.spp << ", depth " << renderOptions.maxDepth << ", " << r.primitives
        << " primitives, Embree device + build " << fixed(r.buildSeconds * 1e3, 1) << " ms\n"
        << "  machine: " << cpu << ", " << logicalCores() << " logical cores, load average "
        << r.loadAverage << "; threads: "
        << r.threads << "; median of " << r.runs << " interleaved runs, "
        << PhaseClock(r.threads == 1).name() << "\n"
        << std::flush;

    // The renders reuse their buffers' mappings, as the frames of a sequence
    // do (render --frames): a fresh mapping's faults are no part of tracing.
    const huge_pages::ReuseScope reuseFrameBuffers;

    // 1. One recorded render: the exact rays of a frame, in deterministic order.
    RayRecorder recorder(*accel, scene, renderOptions);
    const RenderResult recorded = render(scene, recorder, renderOptions, effects);
    const std::vector<RecordedRay> rays = recorder.takeRays();
    r.rays = rays.size();
    EmbreeReplay replay(*accel, rays);

    // 2. Warm-up of every phase, then the timed runs interleaved (render,
    //    then both replays slice by slice), so that a machine whose speed
    //    drifts (shared cores, turbo) affects the three medians alike.
    //    The renders are the renderer as users run it: no recording.
    const RenderResult warm = render(scene, *accel, renderOptions, effects);
    r.counters = warm.rays;
    InterfaceReplay interface(*accel, rays);
    const int replayThreads = options.threads;
    r.cpuClock = r.threads == 1;
    const PhaseClock clock(r.cpuClock);
    double bareSeconds = 0, interfaceSeconds = 0;
    timeReplays(clock, rays, replay, interface, replayThreads, bareSeconds, interfaceSeconds);
    std::vector<double> renderTimes, bareTimes, interfaceTimes;
    for (int i = 0; i < options.runs; ++i) {
        r.cpus.insert(currentCpu());
        renderTimes.push_back(clock.time([&] { render(scene, *accel, renderOptions, effects); }));
        r.cpus.insert(currentCpu());
        timeReplays(clock, rays, replay, interface, replayThreads, bareSeconds, interfaceSeconds,
                    &r.cpus);
        bareTimes.push_back(bareSeconds);
        interfaceTimes.push_back(interfaceSeconds);
        r.runFractions.push_back(bareSeconds / renderTimes.back());
    }
    r.renderSeconds = median(renderTimes);
    r.bareSeconds = median(bareTimes);
    r.interfaceSeconds = median(interfaceTimes);
    r.interfaceDisagreements = disagreementsOf(interface.results(), rays);
    r.bareDisagreements = disagreementsOf(replay.results(), rays);
    r.countersMatch = sameCounters(RayRecorder::countRays(rays), recorded.rays) &&
                      sameCounters(recorded.rays, r.counters) && recorder.unmatchedRays() == 0;

    const RayCounters& c = r.counters;
    out << "  rays per frame: " << r.rays << " (camera " << c.total(RayType::Camera) << ", hits "
        << c.cameraHits << "; shadow " << c.total(RayType::Shadow) << "; reflection "
        << c.total(RayType::Reflection) << "; refraction " << c.total(RayType::Refraction)
        << ")\n";
    out << "  recording: " << (r.countersMatch ? "matches" : "DOES NOT MATCH")
        << " the render's ray counters by type and depth; replay disagrees with the recorded "
           "hit/miss on "
        << r.bareDisagreements << " rays (interface replay: " << r.interfaceDisagreements
        << ")\n\n";
    char line[200];
    std::snprintf(line, sizeof line, "  %-44s %10s %10s %10s\n", "", "seconds", "Mrays/s",
                  "of bare");
    out << line;
    const auto row = [&](const char* name, double seconds) {
        std::snprintf(line, sizeof line, "  %-44s %10.4f %10.3f %9.1f%%\n", name, seconds,
                      r.rate(seconds) * 1e-6,
                      seconds > 0 ? 100.0 * r.bareSeconds / seconds : 0.0);
        out << line;
    };
    row("bare Embree replay (rtcIntersect1/rtcOccluded1)", r.bareSeconds);
    row("replay through Accelerator::intersect/occluded", r.interfaceSeconds);
    row("renderer (full render, shading included)", r.renderSeconds);
    out << "\n  renderer reaches " << fixed(100.0 * r.fraction(), 1)
        << "% of bare Embree (bar" << (r.spd ? " with --spd" : "") << ": >= "
        << fixed(100.0 * r.bar(), 0) << "%): " << (r.barMet() ? "met" : "NOT met") << "\n";
    // The same ratio taken run by run: each render against the replays timed
    // right after it. Less exposed to the machine's drift than the ratio of
    // the two medians above, which may come from different minutes.
    out << "  run by run (each render against its own replays): median "
        << fixed(100.0 * r.pairedFraction(), 1) << "% (";
    for (size_t i = 0; i < r.runFractions.size(); ++i)
        out << (i ? ", " : "") << fixed(100.0 * r.runFractions[i], 1) << "%";
    out << ")\n";
    // Where the time goes: the two gaps as shares of the renderer's frame time.
    if (r.renderSeconds > 0) {
        const double traversal = r.bareSeconds / r.renderSeconds;
        const double query = std::max(0.0, r.interfaceSeconds - r.bareSeconds) / r.renderSeconds;
        const double rest = std::max(0.0, r.renderSeconds - r.interfaceSeconds) / r.renderSeconds;
        out << "  frame time split: Embree traversal " << fixed(100 * traversal, 1)
            << "%, query conversion/decoding " << fixed(100 * query, 1)
            << "%, shading, ray generation and bookkeeping " << fixed(100 * rest, 1) << "%\n";
    }
    if (r.threads == 1 && !r.cpus.empty() && *r.cpus.begin() >= 0) {
        out << "  timed on CPU " << commaList(r.cpus)
            << (r.cpus.size() > 1
                    ? " (the process moved: where the CPUs differ in speed, the phases were timed "
                      "at different speeds; `taskset -c N` keeps it on one)\n"
                    : "\n");
    }

    if (format) {
        writeFileAtomically(options.outPath, *format == TableFormat::Csv
                                                 ? csvDocument(r, cpu)
                                                 : jsonDocument(r, cpu));
        out << "  results: " << options.outPath << "\n";
    }
    return 0;
}

}  // namespace raylab

// raylab bench: accel (BVH vs naive loop), limit (renderer vs bare Embree),
// effects (specialised vs general kernel), primitives (ns per intersection).
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "apps/arg_parser.h"
#include "apps/commands.h"
#include "renderer/io/did_you_mean.h"
#include "renderer/io/errors.h"
#include "tools/bench/accel_bench.h"
#include "tools/bench/effects_bench.h"
#include "tools/bench/ingest_bench.h"
#include "tools/bench/limit_bench.h"
#include "tools/bench/primitive_bench.h"
#include "tools/bench/texture_bench.h"

namespace raylab {

namespace {

const char* const kBenchHelp =
    "usage: raylab bench <benchmark> [options]\n"
    "\n"
    "benchmarks:\n"
    "  accel [SCENE...]      Embree BVH vs the naive all-objects loop on growing procedural scenes\n"
    "                        (and the given scene files): build time, rays/s, speedup, crossover\n"
    "  limit SCENE           the renderer's rays/s as a fraction of bare rtcIntersect1/rtcOccluded1\n"
    "                        replaying the same rays\n"
    "  effects SCENE...      specialised kernel vs general kernel (every ray type at every hit)\n"
    "  primitives            ns per intersect() call of every analytic primitive\n"
    "  textures              ns per texture lookup: raylab's MIP pyramid vs OpenImageIO's\n"
    "                        TextureSystem, every filter\n"
    "  ingest                OBJ ingest: MB/s and peak memory per triangle loading a generated\n"
    "                        2-million-triangle height-field OBJ\n"
    "\n"
    "Run 'raylab bench <benchmark> --help' for its options. Benchmarks print medians of repeated\n"
    "runs; they assert nothing (the tests do).\n";

const char* const kBenchAccelHelp =
    "usage: raylab bench accel [SCENE...] [options]\n"
    "\n"
    "Compares the Embree BVH with the naive loop over every primitive on the same rays (same\n"
    "scene, same render options, one ray per pixel centre), for growing sizes of four procedural\n"
    "scenes (sphereflake levels 0-5, random spheres, a height-field mesh, a polygon field) and\n"
    "then for every SCENE given (.json, .obj, .nff). Reports the primitive count, build time,\n"
    "frame time and rays/s of both back ends, the speedup (ratio of rays/s), and per scene family\n"
    "the size below which the naive loop is faster. Times are medians of --runs runs. Embree\n"
    "always renders the full frame; where a naive frame would take longer than --naive-budget,\n"
    "the naive loop traces every k-th pixel only (row-major, k coprime with the width) and the\n"
    "table says \"1/k\". Frame times are wall-clock, or with --threads 1 the working thread's\n"
    "CPU time (robust on a shared machine). The default run takes about 3 minutes on 2 cores.\n"
    "\n"
    "options:\n"
    "  --width W, --height H   image size (default 256x256)\n"
    "  --runs N                timed runs per measurement, median reported (default 5)\n"
    "  --threads N             worker threads (default: all cores)\n"
    "  --naive-budget S        longest naive frame in seconds before pixel sampling (default 2)\n"
    "  --out FILE              also write the results as CSV (.csv) or JSON (.json)\n"
    "  --plot FILE.svg         log-log plot: time per ray against primitive count, both back ends\n"
    "  --html DIR              DIR/index.html: a self-contained page with the plot, the table and\n"
    "                          each scene's image (Embree and naive side by side, with a zoom)\n"
    "  --quick                 smoke run of about 20 s: small sizes, at most 128x128, 3 runs,\n"
    "                          0.5 s naive budget\n"
    "Flags take their value as '--flag value' or '--flag=value'.\n";

const char* const kBenchLimitHelp =
    "usage: raylab bench limit SCENE [options]\n"
    "\n"
    "How close the renderer comes to Embree's own speed on SCENE. Records every ray one render\n"
    "traces (camera, shadow, reflection, refraction), replays exactly those rays through bare\n"
    "rtcIntersect1/rtcOccluded1 on the same Embree scene (same float conversion, mask and\n"
    "context, which carries the exact ray and the object a query leaves out; no shading), and\n"
    "reports the renderer's rays/s (separate, un-recorded renders) as a fraction of the\n"
    "replay's. A replay through the Accelerator interface splits the gap into query overhead\n"
    "and shading. Shadows are opaque here (bare Embree cannot replay filtered shadow\n"
    "feelers). Performance bars (issue 20): renderer >= 80% of bare Embree with --spd,\n"
    ">= 70% without (scenes like the demo: supersampled, glass). Times are medians of\n"
    "--runs runs; the ratio is also given run by run (each render against the replays timed\n"
    "right after it) with its median, which a drift of the machine's speed moves less (the\n"
    "bar is judged on the ratio of the medians). The replays are timed slice by slice (16384\n"
    "rays), each slice read into the cache untimed first, so that neither pays for reading\n"
    "the recording. The renders reuse their buffers' memory from one run to the next, as\n"
    "the frames of render --frames do. With one thread it names the CPU the timed phases\n"
    "ran on, and says so when the process moved between CPUs (which, on a VM, may differ\n"
    "in speed: taskset -c N keeps it on one).\n"
    "\n"
    "options:\n"
    "  --width W, --height H   image size (default: the scene's; 512x512 with --spd)\n"
    "  --spd                   Haines' SPD procedure: 513x513 corner rays, depth 5\n"
    "  --runs N                timed runs of each measurement, median reported (default 5)\n"
    "  --threads N             threads of the render and of the replays (default 1;\n"
    "                          0 = all cores)\n"
    "  --out FILE              also write the results as CSV (.csv) or JSON (.json)\n";

const char* const kBenchEffectsHelp =
    "usage: raylab bench effects SCENE... [--width W --height H --runs N --threads N --spd]\n"
    "\n"
    "Renders each scene with the specialised kernel (only the effects the scene calls for) and with\n"
    "the general kernel (every ray type at every hit, zero weights included: --effects all), runs\n"
    "interleaved, and prints the median render times, the rays traced and the speedup. The two\n"
    "images are checked to be bit-identical.\n";

const char* const kBenchPrimitivesHelp =
    "usage: raylab bench primitives [--iterations N]\n"
    "\n"
    "ns per intersect() call of every analytic primitive, for rays that hit and rays\n"
    "that miss, in double and float precision, and both polygon inside tests.\n";

const char* const kBenchTexturesHelp =
    "usage: raylab bench textures [--size N] [--lookups N] [--runs N]\n"
    "\n"
    "ns per texture lookup of raylab's own MIP pyramid and of OpenImageIO's TextureSystem on\n"
    "the same N x N linear float image (default 1024), for point, bilinear, trilinear and\n"
    "anisotropic filtering, on the same random points and footprints (0.5 to 16 texels,\n"
    "anisotropy up to 8); one thread, fastest of --runs (default 5) runs of --lookups\n"
    "(default 200000) lookups; the mean absolute difference of the two answers.\n";
const char* const kBenchIngestHelp =
    "usage: raylab bench ingest [--triangles N] [--runs N] [--threads N] [--dir DIR]\n"
    "\n"
    "Writes a height-field OBJ (quads, `s 1`, no vn, four materials in an MTL) of about N\n"
    "triangles (default 2000000) and loads it as `raylab render terrain.obj` does (parse,\n"
    "triangulation, smoothing-group normals, material assignment), --runs times (default 5),\n"
    "with 1 thread and with all cores (or only --threads N). Prints the median wall time, MB/s\n"
    "of OBJ text and the median peak RSS above the baseline measured just before each load,\n"
    "per triangle; also the parse stage alone (read + parseObj). Performance bar (issue 20):\n"
    ">= 100 MB/s on all cores, <= 150 bytes/triangle. --dir keeps the files there.\n";

void help(const char* text) {
    std::fputs(text, stdout);
    std::exit(0);
}

bool isHelp(const std::string& a) { return a == "-h" || a == "--help"; }

}  // namespace

const CommandFlags kBenchAccelFlags{"bench accel", kBenchAccelHelp,
                                    {{"--width", "", true},
                                     {"--height", "", true},
                                     {"--runs", "", true},
                                     {"--threads", "", true},
                                     {"--naive-budget", "", true},
                                     {"--out", "", true},
                                     {"--plot", "", true},
                                     {"--html", "", true},
                                     {"--quick", "", false}}};
const CommandFlags kBenchLimitFlags{"bench limit", kBenchLimitHelp,
                                    {{"--width", "", true},
                                     {"--height", "", true},
                                     {"--runs", "", true},
                                     {"--threads", "", true},
                                     {"--spd", "", false},
                                     {"--out", "", true}}};
const CommandFlags kBenchEffectsFlags{"bench effects", kBenchEffectsHelp,
                                      {{"--width", "", true},
                                       {"--height", "", true},
                                       {"--runs", "", true},
                                       {"--threads", "", true},
                                       {"--spd", "", false}}};
const CommandFlags kBenchPrimitivesFlags{"bench primitives", kBenchPrimitivesHelp,
                                         {{"--iterations", "", true}}};
const CommandFlags kBenchTexturesFlags{"bench textures", kBenchTexturesHelp,
                                       {{"--size", "", true},
                                        {"--lookups", "", true},
                                        {"--runs", "", true}}};
const CommandFlags kBenchIngestFlags{"bench ingest", kBenchIngestHelp,
                                     {{"--triangles", "", true},
                                      {"--runs", "", true},
                                      {"--threads", "", true},
                                      {"--dir", "", true}}};

namespace {

int benchAccel(const std::vector<std::string>& args) {
    AccelBenchOptions o;
    ArgParser p(args, kBenchAccelFlags);
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "--width") o.width = int(p.integer(a, 1, 8192));
        else if (a == "--height") o.height = int(p.integer(a, 1, 8192));
        else if (a == "--runs") o.runs = int(p.integer(a, 1, 1000));
        else if (a == "--threads") o.threads = int(p.integer(a, 1, 4096));
        else if (a == "--naive-budget") o.naiveBudgetSeconds = p.number(a, 0.001, 1e6);
        else if (a == "--out") o.outPath = p.value(a);
        else if (a == "--plot") o.plotPath = p.value(a);
        else if (a == "--html") o.htmlDir = p.value(a);
        else if (a == "--quick") o.quick = true;
        else o.sceneFiles.push_back(a);
    }
    return runAccelBench(o, std::cout);
}

int benchLimit(const std::vector<std::string>& args) {
    LimitBenchOptions o;
    ArgParser p(args, kBenchLimitFlags);
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "--width") o.width = int(p.integer(a, 1, 8192));
        else if (a == "--height") o.height = int(p.integer(a, 1, 8192));
        else if (a == "--runs") o.runs = int(p.integer(a, 1, 1000));
        else if (a == "--threads") o.threads = int(p.integer(a, 0, 4096));
        else if (a == "--spd") o.spd = true;
        else if (a == "--out") o.outPath = p.value(a);
        else if (o.scene.empty()) o.scene = a;
        else throw UsageError("bench limit: one scene at a time");
    }
    if (o.scene.empty()) throw UsageError("bench limit: missing SCENE");
    return runLimitBench(o, std::cout);
}

int benchEffects(const std::vector<std::string>& args) {
    EffectsBenchOptions o;
    ArgParser p(args, kBenchEffectsFlags);
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "--width") o.width = int(p.integer(a, 1, 8192));
        else if (a == "--height") o.height = int(p.integer(a, 1, 8192));
        else if (a == "--runs") o.runs = int(p.integer(a, 1, 1000));
        else if (a == "--threads") o.threads = int(p.integer(a, 1, 4096));
        else if (a == "--spd") o.spd = true;
        else o.scenes.push_back(a);
    }
    if (o.scenes.empty()) throw UsageError("bench effects: missing SCENE");
    return runEffectsBench(o, std::cout);
}

int benchPrimitives(const std::vector<std::string>& args) {
    int iterations = 50;
    ArgParser p(args, kBenchPrimitivesFlags);
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "--iterations") iterations = int(p.integer(a, 1, 100000));
        else throw UsageError("bench primitives: unexpected argument '" + a + "'");
    }
    runPrimitiveBench(std::cout, iterations);
    return 0;
}

int benchTextures(const std::vector<std::string>& args) {
    TextureBenchOptions o;
    ArgParser p(args, kBenchTexturesFlags);
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "--size") o.size = int(p.integer(a, 2, 8192));
        else if (a == "--lookups") o.lookups = int(p.integer(a, 1, 100000000));
        else if (a == "--runs") o.runs = int(p.integer(a, 1, 1000));
        else throw UsageError("bench textures: unknown argument '" + a + "'");
    }
    runTextureBench(o, std::cout);
    return 0;
}

int benchIngest(const std::vector<std::string>& args) {
    IngestBenchOptions o;
    ArgParser p(args, kBenchIngestFlags);
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "--triangles") o.triangles = size_t(p.integer(a, 2, 200000000));
        else if (a == "--runs") o.runs = int(p.integer(a, 1, 1000));
        else if (a == "--threads") o.threads = {int(p.integer(a, 0, 4096))};
        else if (a == "--dir") {
            o.dir = p.value(a);
            o.keep = true;
        } else throw UsageError("bench ingest: unknown argument '" + a + "'");
    }
    return runIngestBench(o, std::cout);
}

}  // namespace

int benchCommand(const std::vector<std::string>& args) {
    if (args.empty())
        throw UsageError(
            "bench: expected a benchmark: accel, limit, effects, primitives, textures or ingest");
    const std::vector<std::string> benchmarks{"accel", "limit", "effects", "primitives", "textures",
                                              "ingest"};
    const std::string which = args.front();
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (isHelp(which)) help(kBenchHelp);
    if (which == "accel") return benchAccel(rest);
    if (which == "limit") return benchLimit(rest);
    if (which == "effects") return benchEffects(rest);
    if (which == "primitives") return benchPrimitives(rest);
    if (which == "textures") return benchTextures(rest);
    if (which == "ingest") return benchIngest(rest);
    const std::string hint = didYouMean(which, benchmarks);
    throw UsageError("bench: unknown benchmark '" + which + "'" +
                     (hint.empty() ? " (expected accel, limit, effects, primitives, textures or ingest)"
                                   : hint));
}

}  // namespace raylab

// raylab bench: accel (BVH vs naive loop), limit (renderer vs bare Embree),
// effects (specialised vs general kernel), primitives (ns per intersection).
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "apps/arg_parser.h"
#include "apps/commands.h"
#include "renderer/io/errors.h"
#include "tools/bench/accel_bench.h"
#include "tools/bench/effects_bench.h"
#include "tools/bench/limit_bench.h"
#include "tools/bench/primitive_bench.h"

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
    "\n"
    "Run 'raylab bench <benchmark> --help' for its options. Benchmarks print medians of repeated\n"
    "runs; they assert nothing (the tests do).\n";

void help(const char* text) {
    std::fputs(text, stdout);
    std::exit(0);
}

bool isHelp(const std::string& a) { return a == "-h" || a == "--help"; }

int benchAccel(const std::vector<std::string>& args) {
    AccelBenchOptions o;
    ArgParser p(args);
    while (!p.done()) {
        const std::string a = p.next();
        if (isHelp(a)) help(kBenchAccelHelp);
        else if (a == "--width") o.width = int(p.integer(a, 1, 8192));
        else if (a == "--height") o.height = int(p.integer(a, 1, 8192));
        else if (a == "--runs") o.runs = int(p.integer(a, 1, 1000));
        else if (a == "--threads") o.threads = int(p.integer(a, 1, 4096));
        else if (a == "--naive-budget") o.naiveBudgetSeconds = p.number(a, 0.001, 1e6);
        else if (a == "--out") o.outPath = p.value(a);
        else if (a == "--plot") o.plotPath = p.value(a);
        else if (a == "--quick") o.quick = true;
        else if (!a.empty() && a[0] == '-') throw UsageError("bench accel: unknown option '" + a + "'");
        else o.sceneFiles.push_back(a);
    }
    return runAccelBench(o, std::cout);
}

int benchLimit(const std::vector<std::string>& args) {
    LimitBenchOptions o;
    ArgParser p(args);
    while (!p.done()) {
        const std::string a = p.next();
        if (isHelp(a)) help(kBenchLimitHelp);
        else if (a == "--width") o.width = int(p.integer(a, 1, 8192));
        else if (a == "--height") o.height = int(p.integer(a, 1, 8192));
        else if (a == "--runs") o.runs = int(p.integer(a, 1, 1000));
        else if (a == "--threads") o.threads = int(p.integer(a, 0, 4096));
        else if (a == "--spd") o.spd = true;
        else if (a == "--out") o.outPath = p.value(a);
        else if (!a.empty() && a[0] == '-') throw UsageError("bench limit: unknown option '" + a + "'");
        else if (o.scene.empty()) o.scene = a;
        else throw UsageError("bench limit: one scene at a time");
    }
    if (o.scene.empty()) throw UsageError("bench limit: missing SCENE");
    return runLimitBench(o, std::cout);
}

int benchEffects(const std::vector<std::string>& args) {
    EffectsBenchOptions o;
    ArgParser p(args);
    while (!p.done()) {
        const std::string a = p.next();
        if (isHelp(a)) help(kBenchEffectsHelp);
        else if (a == "--width") o.width = int(p.integer(a, 1, 8192));
        else if (a == "--height") o.height = int(p.integer(a, 1, 8192));
        else if (a == "--runs") o.runs = int(p.integer(a, 1, 1000));
        else if (a == "--threads") o.threads = int(p.integer(a, 1, 4096));
        else if (a == "--spd") o.spd = true;
        else if (!a.empty() && a[0] == '-') throw UsageError("bench effects: unknown option '" + a + "'");
        else o.scenes.push_back(a);
    }
    if (o.scenes.empty()) throw UsageError("bench effects: missing SCENE");
    return runEffectsBench(o, std::cout);
}

int benchPrimitives(const std::vector<std::string>& args) {
    int iterations = 50;
    ArgParser p(args);
    while (!p.done()) {
        const std::string a = p.next();
        if (isHelp(a)) {
            help("usage: raylab bench primitives [--iterations N]\n\n"
                 "ns per intersect() call of every analytic primitive, for rays that hit and rays\n"
                 "that miss, in double and float precision, and both polygon inside tests.\n");
        } else if (a == "--iterations") {
            iterations = int(p.integer(a, 1, 100000));
        } else {
            throw UsageError("bench primitives: unknown argument '" + a + "'");
        }
    }
    runPrimitiveBench(std::cout, iterations);
    return 0;
}

}  // namespace

int benchCommand(const std::vector<std::string>& args) {
    if (args.empty()) throw UsageError("bench: expected a benchmark: accel, limit, effects or primitives");
    const std::string which = args.front();
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (isHelp(which)) help(kBenchHelp);
    if (which == "accel") return benchAccel(rest);
    if (which == "limit") return benchLimit(rest);
    if (which == "effects") return benchEffects(rest);
    if (which == "primitives") return benchPrimitives(rest);
    throw UsageError("bench: unknown benchmark '" + which + "' (expected accel, limit, effects or primitives)");
}

}  // namespace raylab

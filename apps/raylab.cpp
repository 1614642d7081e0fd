// raylab: the command-line front end. Parses the sub-command and hands over;
// all rendering lives in the libraries.

#include <pmmintrin.h>
#include <unistd.h>
#include <xmmintrin.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"

namespace raylab {

std::atomic<bool> g_interrupted{false};

namespace {

const char* const kMainHelp =
    "raylab: a Whitted ray tracer on Embree\n"
    "\n"
    "usage: raylab <command> [options]\n"
    "\n"
    "commands:\n"
    "  render SCENE -o OUT.exr [options]   render a scene (.json, .obj or .nff) to OpenEXR\n"
    "  bench accel|limit|effects|primitives ...\n"
    "                                      benchmarks (BVH vs naive loop, overhead, kernels, primitives)\n"
    "  accuracy SCENE [options]            what accuracy costs in time: error vs time sweep\n"
    "  compare A.exr B.exr                 how far apart two renders are (RMSE, PSNR, identical pixels)\n"
    "\n"
    "Run 'raylab <command> --help' for the options of a command.\n"
    "Exit codes: 0 success, 1 bad input (scene, mesh, file), 2 bad usage, 130 interrupted.\n";

extern "C" void onInterrupt(int) {
    // First Ctrl-C: ask the render to stop between tiles. Second: leave now,
    // removing any half-written output first (async-signal-safe calls only).
    if (g_interrupted.exchange(true)) {
        removeInFlightTempFiles();
        _exit(130);
    }
}

}  // namespace
}  // namespace raylab

int main(int argc, char** argv) {
    using namespace raylab;
    // Embree wants flush-to-zero and denormals-are-zero on every thread; set
    // before TBB starts its workers, which inherit the MXCSR.
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    std::signal(SIGINT, onInterrupt);

    std::vector<std::string> args(argv + 1, argv + argc);
    std::string commandLine = "raylab";
    for (const std::string& a : args) commandLine += " " + a;

    try {
        if (args.empty()) {
            std::fputs(kMainHelp, stderr);
            return 2;
        }
        const std::string command = args.front();
        const std::vector<std::string> rest(args.begin() + 1, args.end());
        if (command == "--help" || command == "-h" || command == "help") {
            std::fputs(kMainHelp, stdout);
            return 0;
        }
        if (command == "--version") {
            std::puts("raylab 0.1.0");
            return 0;
        }
        if (command == "render") return renderCommand(rest, commandLine);
        if (command == "bench") return benchCommand(rest);
        if (command == "accuracy") return accuracyCommand(rest);
        if (command == "compare") return compareCommand(rest);
        throw UsageError("unknown command '" + command +
                         "' (expected render, bench, accuracy or compare)");
    } catch (const UsageError& e) {
        std::fprintf(stderr, "raylab: error: %s\n", terminalSafe(e.what()).c_str());
        return 2;
    } catch (const InputError& e) {
        std::fprintf(stderr, "raylab: error: %s\n", terminalSafe(e.located()).c_str());
        return 1;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "raylab: error: out of memory\n");
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "raylab: error: %s\n", terminalSafe(e.what()).c_str());
        return 1;
    }
}

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
#include "apps/exit_keep.h"
#include "apps/heap_pages.h"
#include "apps/signals.h"
#include "renderer/cancel.h"
#include "renderer/io/did_you_mean.h"
#include "renderer/io/errors.h"

namespace raylab {

namespace {

const char* const kMainHelp =
    "raylab: a Whitted ray tracer on Embree\n"
    "\n"
    "usage: raylab <command> [options]\n"
    "       raylab help <command>      the options of a command (= raylab <command> --help)\n"
    "       raylab --version, -V       the version\n"
    "\n"
    "commands:\n"
    "  render SCENE -o OUT.exr [options]   render a scene (.json, .obj or .nff) to OpenEXR\n"
    "  bench accel|limit|effects|primitives|ingest ...\n"
    "                                      benchmarks (BVH vs naive loop, overhead, kernels, primitives,\n"
    "                                      OBJ ingest)\n"
    "  accuracy SCENE [options]            what accuracy costs in time: error vs time sweep\n"
    "  compare A.exr B.exr                 how far apart two renders are (RMSE, PSNR, identical pixels)\n"
    "\n"
    "Run 'raylab <command> --help' or 'raylab help <command>' for the options of a command.\n"
    "Flags take their value as '--flag value' or '--flag=value'; -o and -q are short for\n"
    "--output and --quiet.\n"
    "Exit codes: 0 success, 1 bad input (scene, mesh, file), 2 bad usage,\n"
    "128+N stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP).\n";

/// Runs the command; every way out of it but a forced exit goes through here.
int run(const std::vector<std::string>& args) {
    try {
        if (args.empty()) {
            std::fputs(kMainHelp, stderr);
            return 2;
        }
        std::string command = args.front();
        std::vector<std::string> rest(args.begin() + 1, args.end());
        if (command == "help" && !rest.empty()) {
            // "raylab help bench accel" is "raylab bench accel --help".
            command = rest.front();
            rest.erase(rest.begin());
            rest.push_back("--help");
        }
        if (command == "--help" || command == "-h" || command == "help") {
            std::fputs(kMainHelp, stdout);
            return 0;
        }
        if (command == "--version" || command == "-V") {
            std::puts("raylab 0.1.0");
            return 0;
        }
        int code = 0;
        if (command == "render") code = renderCommand(rest);
        else if (command == "bench") code = benchCommand(rest);
        else if (command == "accuracy") code = accuracyCommand(rest);
        else if (command == "compare") code = compareCommand(rest);
        else {
            const std::string hint =
                didYouMean(command, {"render", "bench", "accuracy", "compare", "help", "--help",
                                     "--version"});
            throw UsageError("unknown command '" + command + "'" +
                             (hint.empty() ? " (expected render, bench, accuracy or compare)" : hint));
        }
        // Commands that stop on the flag themselves return 130 whatever the signal.
        if (code == 130 && cancelSignal() != 0) code = 128 + cancelSignal();
        return code;
    } catch (const Cancelled&) {
        return reportInterrupted();
    } catch (const UsageError& e) {
        std::fprintf(stderr, "raylab: error: %s\n", terminalSafe(e.message()).c_str());
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

}  // namespace
}  // namespace raylab

int main(int argc, char** argv) {
    using namespace raylab;
    // Embree wants flush-to-zero and denormals-are-zero on every thread; set
    // before TBB starts its workers, which inherit the MXCSR.
    _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
    _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
    useHugePageHeap();  // before any thread: see heap_pages.h
    installSignalHandling();
    setProcessEndsAfterCommand();  // a command's leftovers go with the process (exit_keep.h)
    const int code = run(std::vector<std::string>(argv + 1, argv + argc));
    claimExit();  // from here on the watchdog neither prints nor exits
    return code;
}

#include "apps/run_phase.h"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <string>
#include <thread>

#include "renderer/cancel.h"

namespace raylab {

const char* phaseName(Phase phase) {
    switch (phase) {
        case Phase::Parse: return "parse";
        case Phase::Build: return "build";
        case Phase::Render: return "render";
        case Phase::Write: return "write";
        case Phase::Commit: return "commit";
    }
    return "?";
}

void enterPhase(Phase phase) {
    static int entered[5] = {};
    const int count = ++entered[int(phase)];
    const char* stopAt = std::getenv("RAYLAB_TEST_STOP_AT");
    if (!stopAt) return;
    // "render" stops at the first render, "render:2" at the second (a sequence's frame 2).
    const std::string wanted = stopAt;
    const size_t colon = wanted.find(':');
    const int nth = colon == std::string::npos ? 1 : std::atoi(wanted.c_str() + colon + 1);
    if (wanted.substr(0, colon) != phaseName(phase) || count != nth) return;
    std::raise(SIGSTOP);
    // A test that signals the process while it is stopped says so
    // (RAYLAB_TEST_SIGNALED_WHILE_STOPPED=1) and expects this phase to see
    // the signal. A signal sent to the process is handled by whichever of
    // its threads the kernel picks (a TBB worker, the watchdog), which may
    // run only after this thread has gone on past the phase's last check
    // point (a commit is a few renames): wait until the handler has run.
    const char* signaled = std::getenv("RAYLAB_TEST_SIGNALED_WHILE_STOPPED");
    if (signaled && *signaled == '1')
        for (int ms = 0; ms < 60000 && !cancelRequested(); ++ms)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

}  // namespace raylab

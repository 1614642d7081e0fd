#include "apps/run_phase.h"

#include <csignal>
#include <cstdlib>
#include <string>

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
    if (wanted.substr(0, colon) == phaseName(phase) && count == nth) std::raise(SIGSTOP);
}

}  // namespace raylab

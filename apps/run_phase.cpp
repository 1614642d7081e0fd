#include "apps/run_phase.h"

#include <csignal>
#include <cstdlib>
#include <cstring>

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
    static bool stopped = false;
    const char* stopAt = std::getenv("RAYLAB_TEST_STOP_AT");
    if (!stopped && stopAt && std::strcmp(stopAt, phaseName(phase)) == 0) {
        stopped = true;
        std::raise(SIGSTOP);
    }
}

}  // namespace raylab

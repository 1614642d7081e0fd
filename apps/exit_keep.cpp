#include "apps/exit_keep.h"

#include <vector>

namespace raylab {

namespace {

bool g_processEndsAfterCommand = false;

/// Never destroyed: a static object's destructor would free at exit what the
/// keeping is meant to leave to the kernel.
std::vector<std::shared_ptr<void>>& keptObjects() {
    static auto* kept = new std::vector<std::shared_ptr<void>>();
    return *kept;
}

}  // namespace

void setProcessEndsAfterCommand() { g_processEndsAfterCommand = true; }

bool processEndsAfterCommand() { return g_processEndsAfterCommand; }

void detail::keepUntilExit(std::shared_ptr<void> object) { keptObjects().push_back(std::move(object)); }

}  // namespace raylab

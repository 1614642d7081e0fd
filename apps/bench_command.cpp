// raylab bench: placeholder dispatch filled in by the benchmark issue.
#include <cstdio>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "renderer/io/errors.h"

namespace raylab {

int benchCommand(const std::vector<std::string>& args) {
    if (args.empty()) throw UsageError("bench: expected a benchmark name (accel, limit, primitives)");
    throw UsageError("bench: unknown benchmark '" + args[0] + "'");
}

int accuracyCommand(const std::vector<std::string>&) {
    throw UsageError("accuracy: not available in this build");
}

}  // namespace raylab

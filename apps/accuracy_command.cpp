// raylab accuracy: the error-versus-time sweep (issue 6 builds it here).
#include <string>
#include <vector>

#include "apps/commands.h"
#include "renderer/io/errors.h"

namespace raylab {

int accuracyCommand(const std::vector<std::string>&) {
    throw UsageError("accuracy: not available in this build");
}

}  // namespace raylab

#include "distributed/config.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace raylab {

double timeoutSeconds() {
    const char* v = std::getenv("RAYLAB_MPI_TIMEOUT");
    if (!v || !*v) return 120;
    char* end = nullptr;
    const double t = std::strtod(v, &end);
    if (end == v || *end != '\0' || !(t > 0))
        throw std::runtime_error(std::string("RAYLAB_MPI_TIMEOUT must be a number of seconds > 0 "
                                             "(got '") + v + "')");
    return t;
}

bool rootRenders(int ranks) {
    const char* v = std::getenv("RAYLAB_MPI_ROOT_RENDERS");
    return ranks == 1 || !v || std::string(v) != "0";
}

}  // namespace raylab

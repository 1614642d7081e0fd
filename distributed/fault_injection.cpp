#include "distributed/fault_injection.h"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <string>
#include <thread>

namespace raylab {

Fault Fault::forRank(int rank) {
    Fault f;
    const char* v = std::getenv("RAYLAB_MPI_FAULT");
    if (!v) return f;
    const std::string s = v;
    const size_t colon = s.find(':');
    if (colon == std::string::npos || std::atoi(s.c_str() + colon + 1) != rank) return f;
    f.stall = s.compare(0, colon, "stall") == 0;
    f.kill = s.compare(0, colon, "kill") == 0;
    return f;
}

void Fault::strike() const {
    if (kill) std::raise(SIGKILL);
    if (stall)
        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
}

}  // namespace raylab

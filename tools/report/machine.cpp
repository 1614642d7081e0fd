#include "tools/report/machine.h"

#include <sched.h>
#include <tbb/info.h>

#include <algorithm>
#include <fstream>
#include <thread>

namespace raylab {

std::string cpuModelName() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) != 0) continue;
        const size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string name = line.substr(colon + 1);
        const size_t first = name.find_first_not_of(" \t");
        return first == std::string::npos ? "unknown CPU" : name.substr(first);
    }
    return "unknown CPU";
}

double loadAverage() {
    std::ifstream in("/proc/loadavg");
    double load = -1;
    if (!(in >> load)) return -1;
    return load;
}

int logicalCores() { return std::max(1u, std::thread::hardware_concurrency()); }

int effectiveThreads(int threads) {
    return threads > 0 ? threads : std::max(1, tbb::info::default_concurrency());
}

int currentCpu() { return sched_getcpu(); }

}  // namespace raylab

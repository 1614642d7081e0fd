#include "renderer/memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace raylab {

namespace {

std::optional<std::string> readSmallFile(const char* path) {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

std::optional<double> parseMemAvailable(const std::string& meminfo) {
    std::istringstream in(meminfo);
    std::string key, unit;
    double value = 0;
    for (std::string line; std::getline(in, line);) {
        std::istringstream fields(line);
        if (fields >> key >> value && key == "MemAvailable:") {
            fields >> unit;
            return unit == "kB" ? value * 1024.0 : value;
        }
    }
    return std::nullopt;
}

std::optional<double> parseCgroupLimit(const std::string& text) {
    std::istringstream in(text);
    std::string word;
    if (!(in >> word) || word == "max") return std::nullopt;
    char* end = nullptr;
    const double bytes = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0' || !(bytes > 0)) return std::nullopt;
    // cgroup v1 writes "no limit" as the largest page-aligned 63-bit number.
    if (bytes >= 4611686018427387904.0) return std::nullopt;
    return bytes;
}

MemoryFacts readMemoryFacts() {
    MemoryFacts f;
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && pageSize > 0) f.physicalBytes = double(pages) * double(pageSize);
    if (const auto meminfo = readSmallFile("/proc/meminfo"))
        f.availableBytes = parseMemAvailable(*meminfo);
    // cgroup v2 as a container sees it; else the v1 memory controller.
    if (const auto v2 = readSmallFile("/sys/fs/cgroup/memory.max"))
        f.cgroupLimitBytes = parseCgroupLimit(*v2);
    else if (const auto v1 = readSmallFile("/sys/fs/cgroup/memory/memory.limit_in_bytes"))
        f.cgroupLimitBytes = parseCgroupLimit(*v1);
    struct rlimit as {};
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY)
        f.addressSpaceBytes = double(as.rlim_cur);
    if (const auto statm = readSmallFile("/proc/self/statm")) {
        std::istringstream in(*statm);
        double sizePages = 0;
        if (in >> sizePages && pageSize > 0) f.virtualSizeBytes = sizePages * double(pageSize);
    }
    return f;
}

std::optional<MemoryLimit> tightestMemoryLimit(const MemoryFacts& f) {
    std::optional<MemoryLimit> best;
    const auto consider = [&](double bytes, const char* source) {
        if (bytes < 0) bytes = 0;
        if (!best || bytes < best->bytes) best = MemoryLimit{bytes, source};
    };
    // 80%: the rest of the system (and this process's own scene) needs room too.
    if (f.physicalBytes) consider(0.8 * *f.physicalBytes, "this machine's memory");
    if (f.availableBytes) consider(*f.availableBytes, "the memory available now (MemAvailable)");
    if (f.cgroupLimitBytes) consider(0.8 * *f.cgroupLimitBytes, "the cgroup memory limit");
    if (f.addressSpaceBytes)
        consider(*f.addressSpaceBytes - f.virtualSizeBytes - kAddressSpaceReserve,
                 "the address-space limit (ulimit -v)");
    return best;
}

}  // namespace raylab

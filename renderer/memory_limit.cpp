#include "renderer/memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

std::optional<std::string> parseCgroupPath(const std::string& procSelfCgroup,
                                           const std::string& controller) {
    std::istringstream in(procSelfCgroup);
    for (std::string line; std::getline(in, line);) {
        // "ID:CONTROLLERS:PATH"; v2 has ID 0 and no controllers.
        const size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1);
        if (b == std::string::npos) continue;
        const std::string controllers = line.substr(a + 1, b - a - 1);
        bool match = controller.empty() ? line.compare(0, a, "0") == 0 && controllers.empty()
                                        : false;
        for (size_t p = 0; !controller.empty() && p <= controllers.size();) {
            const size_t comma = std::min(controllers.find(',', p), controllers.size());
            match = match || controllers.compare(p, comma - p, controller) == 0;
            p = comma + 1;
        }
        if (!match) continue;
        std::string path = line.substr(b + 1);
        // Outside the namespace the kernel shows "/../x"; nothing to read there.
        if (path.empty() || path[0] != '/' || path.find("..") != std::string::npos)
            return std::nullopt;
        while (path.size() > 1 && path.back() == '/') path.pop_back();
        return path;
    }
    return std::nullopt;
}

MemoryFacts readMemoryFacts() {
    MemoryFacts f;
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && pageSize > 0) f.physicalBytes = double(pages) * double(pageSize);
    if (const auto meminfo = readSmallFile("/proc/meminfo"))
        f.availableBytes = parseMemAvailable(*meminfo);
    // The process's own cgroup and every group above it up to the mount root
    // (often all a container sees); the smallest limit applies. cgroup v2
    // first, else the v1 memory controller.
    const auto smallestOnTheWayUp = [&](const std::string& root, const std::string& group,
                                        const char* file) {
        bool found = false;
        std::string dir = root + (group == "/" ? std::string() : group);
        while (true) {
            if (const auto text = readSmallFile((dir + "/" + file).c_str())) {
                found = true;
                if (const auto bytes = parseCgroupLimit(*text))
                    if (!f.cgroupLimitBytes || *bytes < *f.cgroupLimitBytes)
                        f.cgroupLimitBytes = bytes;
            }
            if (dir.size() <= root.size()) break;
            dir = dir.substr(0, dir.find_last_of('/'));
        }
        return found;
    };
    const std::string self = readSmallFile("/proc/self/cgroup").value_or("");
    const auto v2 = parseCgroupPath(self, "");
    if (!(v2 && smallestOnTheWayUp("/sys/fs/cgroup", *v2, "memory.max")))
        smallestOnTheWayUp("/sys/fs/cgroup/memory",
                           parseCgroupPath(self, "memory").value_or("/"),
                           "memory.limit_in_bytes");
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

std::string describeBytes(double bytes) {
    const double kib = 1024.0, mib = kib * kib;
    char text[48];
    if (bytes < mib)
        std::snprintf(text, sizeof text, "%.0f KiB", std::ceil(bytes / kib));
    else if (bytes < 10 * mib)
        std::snprintf(text, sizeof text, "%.1f MiB", bytes / mib);
    else
        std::snprintf(text, sizeof text, "%.0f MiB", std::floor(bytes / mib));
    return text;
}

std::optional<MemoryLimit> tightestMemoryLimit(const MemoryFacts& f) {
    std::optional<MemoryLimit> best;
    const auto consider = [&](double bytes, const std::string& source) {
        if (bytes < 0) bytes = 0;
        if (!best || bytes < best->bytes) best = MemoryLimit{bytes, source};
    };
    // 80%: the rest of the system (and this process's own scene) needs room too.
    if (f.physicalBytes) consider(0.8 * *f.physicalBytes, "this machine's memory allows");
    if (f.availableBytes) consider(*f.availableBytes, "the memory available now (MemAvailable) allows");
    if (f.cgroupLimitBytes) consider(0.8 * *f.cgroupLimitBytes, "the cgroup memory limit allows");
    if (f.addressSpaceBytes) {
        // Say what the limit leaves: under a small `ulimit -v` the mapped
        // libraries and the reserve take it all, and "0 MiB" alone puzzles.
        consider(*f.addressSpaceBytes - f.virtualSizeBytes - kAddressSpaceReserve,
                 "the address-space limit (ulimit -v) allows (" +
                     describeBytes(*f.addressSpaceBytes) + ", less " +
                     describeBytes(f.virtualSizeBytes) + " mapped already and " +
                     describeBytes(kAddressSpaceReserve) + " kept in reserve)");
    }
    return best;
}

}  // namespace raylab

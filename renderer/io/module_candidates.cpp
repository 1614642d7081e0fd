#include "renderer/io/module_candidates.h"

#include <unistd.h>

#include <climits>

namespace raylab {

namespace {

/// The executable's folder, with its trailing slash ("" if unknown).
std::string executableFolder() {
    char buffer[PATH_MAX];
    const ssize_t n = ::readlink("/proc/self/exe", buffer, sizeof buffer - 1);
    if (n <= 0) return {};
    std::string path(buffer, size_t(n));
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

}  // namespace

std::vector<std::string> moduleCandidates(const std::string& fileName, const char* buildPath) {
    std::vector<std::string> candidates;
    if (std::string folder = executableFolder(); !folder.empty())
        candidates.push_back(folder + fileName);
    if (buildPath && *buildPath && (candidates.empty() || candidates.front() != buildPath))
        candidates.push_back(buildPath);
    return candidates;
}

}  // namespace raylab

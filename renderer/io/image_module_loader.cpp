#include "renderer/io/image_module_loader.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "renderer/io/module_candidates.h"
#include "renderer/memory_limit.h"

namespace raylab {

namespace {

constexpr const char* kModuleName = "raylab-openimageio.so";
constexpr const char* kProbeName = "raylab-openimageio-probe";
/// Address space kept free beyond what the probe measured.
constexpr double kProbeMargin = 64.0 * (1 << 20);

extern "C" char** environ;

/// Runs the probe (image_module_probe.cpp) on `module` and `image`; the
/// address space the module took there, or nullopt if the probe failed or
/// crashed (its stderr is discarded: a crash there is the expected case
/// under a tight limit).
std::optional<double> probeModuleCost(const std::string& probe, const std::string& module,
                                      const std::string& image) {
    int out[2];
    if (::pipe2(out, O_CLOEXEC) != 0) return std::nullopt;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    std::vector<std::string> args{probe, module, image};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = ::posix_spawn(&pid, probe.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    std::string text;
    if (spawned == 0) {
        char buffer[64];
        ssize_t n;
        while ((n = ::read(out[0], buffer, sizeof buffer)) > 0 ||
               (n < 0 && errno == EINTR))
            if (n > 0) text.append(buffer, size_t(n));
    }
    ::close(out[0]);
    if (spawned != 0) return std::nullopt;
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
    char* end = nullptr;
    const double bytes = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || !(bytes >= 0)) return std::nullopt;
    return bytes;
}

/// Under a finite `ulimit -v`, OpenImageIO's library constructors crash
/// (they do not fail) when the address space runs out inside dlopen. So
/// the cost is measured first, in a probe process that may crash, and the
/// module is loaded only if it fits beside what this process maps already.
/// Why not, or nullopt when it may be loaded.
std::optional<std::string> addressSpaceRefusal(const std::string& module,
                                               const std::string& image) {
    struct rlimit as {};
    if (::getrlimit(RLIMIT_AS, &as) != 0 || as.rlim_cur == RLIM_INFINITY) return std::nullopt;
    const double limit = double(as.rlim_cur);
    const std::string where = "the address-space limit (ulimit -v) of " + describeBytes(limit);
    const std::string probe = module.substr(0, module.rfind('/') + 1) + kProbeName;
    const std::optional<double> cost = probeModuleCost(probe, module, image);
    if (!cost) return "it does not load within " + where;
    const double inUse = readMemoryFacts().virtualSizeBytes;
    if (inUse + *cost + kProbeMargin > limit)
        return "it needs about " + describeBytes(*cost) + " of address space, and " + where +
               " leaves " + describeBytes(std::max(0.0, limit - inUse));
    return std::nullopt;
}

using Loaded = OpenedModule<image_module::Api>;

std::atomic<bool> g_loaded{false};

Loaded load(const std::string& image) {
#ifdef RAYLAB_IMAGE_MODULE_BUILD_PATH
    const char* buildPath = RAYLAB_IMAGE_MODULE_BUILD_PATH;
#else
    const char* buildPath = nullptr;
#endif
    // Under a finite ulimit -v the module is probed before it is opened
    // (addressSpaceRefusal); a broken one beside the executable is reported,
    // not replaced by the build tree's (openFirstModule).
    const auto opened = openFirstModule<image_module::Api>(
        kModuleName, buildPath, RTLD_NOW | RTLD_LOCAL, image_module::kEntryPoint,
        image_module::kVersion, "image",
        [&](const std::string& path) { return addressSpaceRefusal(path, image); });
    if (!opened.api) return {nullptr, "OpenImageIO is not available (" + opened.failure + ")"};
    g_loaded = true;
    return {opened.api, {}};
}

}  // namespace

const image_module::Api& imageModule(const std::string& image) {
    static const Loaded loaded = load(image);
    if (!loaded.api) throw ImageModuleUnavailable(loaded.failure);
    return *loaded.api;
}

bool imageModuleLoaded() { return g_loaded; }

}  // namespace raylab

#include "renderer/io/exr_module_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <atomic>

#include "renderer/io/module_candidates.h"

namespace raylab {

namespace {

constexpr const char* kModuleName = "raylab-openexr.so";

struct Loaded {
    const exr_module::Api* api = nullptr;
    std::string failure;
};

std::atomic<bool> g_loaded{false};

Loaded load() {
#ifdef RAYLAB_EXR_MODULE_BUILD_PATH
    const char* buildPath = RAYLAB_EXR_MODULE_BUILD_PATH;
#else
    const char* buildPath = nullptr;
#endif
    // The first module found is the one meant: a broken one beside the
    // executable (or one of another build, whose interface may differ) is
    // reported, not replaced by the build tree's.
    std::string reasons;
    for (const std::string& path : moduleCandidates(kModuleName, buildPath)) {
        if (::access(path.c_str(), F_OK) != 0) continue;
        const auto opened = openModule<exr_module::Api>(path, RTLD_NOW | RTLD_LOCAL,
                                                        exr_module::kEntryPoint,
                                                        exr_module::kVersion, "OpenEXR");
        if (!opened.api) {
            reasons = opened.failure;
            break;
        }
        g_loaded = true;
        return {opened.api, {}};
    }
    if (reasons.empty())
        reasons = std::string(kModuleName) + " not found beside the executable" +
                  (buildPath ? " nor in the build tree" : "");
    return {nullptr, "OpenEXR is not available (" + reasons + ")"};
}

}  // namespace

const exr_module::Api& exrModule() {
    static const Loaded loaded = load();
    if (!loaded.api) throw ExrModuleUnavailable(loaded.failure);
    return *loaded.api;
}

bool exrModuleLoaded() { return g_loaded; }

}  // namespace raylab

#include "renderer/io/exr_module_loader.h"

#include <dlfcn.h>

#include <atomic>

#include "renderer/io/module_candidates.h"

namespace raylab {

namespace {

constexpr const char* kModuleName = "raylab-openexr.so";

using Loaded = OpenedModule<exr_module::Api>;

std::atomic<bool> g_loaded{false};

Loaded load() {
#ifdef RAYLAB_EXR_MODULE_BUILD_PATH
    const char* buildPath = RAYLAB_EXR_MODULE_BUILD_PATH;
#else
    const char* buildPath = nullptr;
#endif
    const auto opened = openFirstModule<exr_module::Api>(
        kModuleName, buildPath, RTLD_NOW | RTLD_LOCAL, exr_module::kEntryPoint,
        exr_module::kVersion, "OpenEXR");
    if (!opened.api) return {nullptr, "OpenEXR is not available (" + opened.failure + ")"};
    g_loaded = true;
    return {opened.api, {}};
}

}  // namespace

const exr_module::Api& exrModule() {
    static const Loaded loaded = load();
    if (!loaded.api) throw ExrModuleUnavailable(loaded.failure);
    return *loaded.api;
}

bool exrModuleLoaded() { return g_loaded; }

}  // namespace raylab

#include "distributed/mpi_module_loader.h"

#include <dlfcn.h>

#include <atomic>
#include <string>

#include "renderer/io/module_candidates.h"

namespace raylab {

namespace {

constexpr const char* kModuleName = "raylab-mpi.so";

using Loaded = OpenedModule<mpi_module::Api>;

std::atomic<bool> g_loaded{false};

Loaded load() {
#ifdef RAYLAB_MPI_MODULE_BUILD_PATH
    const char* buildPath = RAYLAB_MPI_MODULE_BUILD_PATH;
#else
    const char* buildPath = nullptr;
#endif
    // RTLD_GLOBAL (as mpi4py does): Open MPI dlopens plug-ins of its own
    // (mca_*.so), and 14 of Debian 12's 120 (btl tcp among them) do not
    // name libmpi or libopen-pal as dependencies: they find them in the
    // global scope. A broken module beside the executable is reported, not
    // replaced by the build tree's (openFirstModule).
    const auto opened = openFirstModule<mpi_module::Api>(
        kModuleName, buildPath, RTLD_NOW | RTLD_GLOBAL, mpi_module::kEntryPoint,
        mpi_module::kVersion, "MPI");
    if (!opened.api) return {nullptr, "MPI is not available (" + opened.failure + ")"};
    g_loaded = true;
    return {opened.api, {}};
}

}  // namespace

const mpi_module::Api& mpiModule() {
    static const Loaded loaded = load();
    if (!loaded.api) throw MpiModuleUnavailable(loaded.failure);
    return *loaded.api;
}

bool mpiModuleLoaded() { return g_loaded; }

}  // namespace raylab

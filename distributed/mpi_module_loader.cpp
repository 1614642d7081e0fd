#include "distributed/mpi_module_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <string>

#include "renderer/io/module_candidates.h"

namespace raylab {

namespace {

constexpr const char* kModuleName = "raylab-mpi.so";

struct Loaded {
    const mpi_module::Api* api = nullptr;
    std::string failure;
};

std::atomic<bool> g_loaded{false};

Loaded load() {
#ifdef RAYLAB_MPI_MODULE_BUILD_PATH
    const char* buildPath = RAYLAB_MPI_MODULE_BUILD_PATH;
#else
    const char* buildPath = nullptr;
#endif
    // The first module found is the one meant: a broken one beside the
    // executable is reported, not replaced by the build tree's.
    std::string reasons;
    for (const std::string& path : moduleCandidates(kModuleName, buildPath)) {
        if (::access(path.c_str(), F_OK) != 0) continue;
        // RTLD_GLOBAL (as mpi4py does): Open MPI dlopens plug-ins of its own
        // (mca_*.so), and 14 of Debian 12's 120 (btl tcp among them) do not
        // name libmpi or libopen-pal as dependencies: they find them in the
        // global scope.
        // Never closed: MPI keeps threads and state until exit.
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
        if (!handle) {
            const char* e = ::dlerror();
            reasons = e ? e : ("cannot load " + path);
            break;
        }
        using Entry = const mpi_module::Api* (*)();
        auto entry = reinterpret_cast<Entry>(::dlsym(handle, mpi_module::kEntryPoint));
        const mpi_module::Api* api = entry ? entry() : nullptr;
        if (!api || api->version != mpi_module::kVersion) {
            reasons = path + " is not raylab's MPI module of interface version " +
                      std::to_string(mpi_module::kVersion);
            break;
        }
        g_loaded = true;
        return {api, {}};
    }
    if (reasons.empty()) reasons = std::string(kModuleName) + " not found beside the executable";
    return {nullptr, "MPI is not available (" + reasons + ")"};
}

}  // namespace

const mpi_module::Api& mpiModule() {
    static const Loaded loaded = load();
    if (!loaded.api) throw MpiModuleUnavailable(loaded.failure);
    return *loaded.api;
}

bool mpiModuleLoaded() { return g_loaded; }

}  // namespace raylab

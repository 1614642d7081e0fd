#pragma once
// Where raylab looks for the shared objects it loads with dlopen only when a
// run needs them (the OpenImageIO module, the MPI module): beside the running
// executable first, where an installed or copied raylab keeps them, then
// where the build put them (compiled in), for executables elsewhere in the tree.

#include <dlfcn.h>

#include <string>
#include <vector>

namespace raylab {

/// The paths to try for the module file `fileName`, in order; `buildPath`
/// (may be null) is the module's path in the build tree.
std::vector<std::string> moduleCandidates(const std::string& fileName, const char* buildPath);

/// What opening one module file gave: its interface, or why not.
template <class Api>
struct OpenedModule {
    const Api* api = nullptr;
    std::string failure;  ///< when api is null: dlerror()'s text or the version mismatch
};

/// \brief dlopen(path, dlopenFlags), then the module's entry point
///   `entryPoint`, whose Api must carry `int version` equal to `version`.
///   `what` names the module in the failure ("image", "MPI"). The handle is
///   never closed: the libraries behind a module keep threads and state until exit.
template <class Api>
OpenedModule<Api> openModule(const std::string& path, int dlopenFlags, const char* entryPoint,
                             int version, const char* what) {
    void* handle = ::dlopen(path.c_str(), dlopenFlags);
    if (!handle) {
        const char* e = ::dlerror();
        return {nullptr, e ? std::string(e) : "cannot load " + path};
    }
    using Entry = const Api* (*)();
    auto entry = reinterpret_cast<Entry>(::dlsym(handle, entryPoint));
    const Api* api = entry ? entry() : nullptr;
    if (!api || api->version != version)
        return {nullptr, path + " is not raylab's " + what + " module of interface version " +
                             std::to_string(version)};
    return {api, {}};
}

}  // namespace raylab

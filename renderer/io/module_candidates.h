#pragma once
// Where raylab looks for the shared objects it loads with dlopen only when a
// run needs them (the OpenImageIO module, the MPI module): beside the running
// executable first, where an installed or copied raylab keeps them, then
// where the build put them (compiled in), for executables elsewhere in the tree.

#include <dlfcn.h>
#include <unistd.h>

#include <functional>
#include <optional>
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

/// \brief The first of moduleCandidates(fileName, buildPath) that exists,
///   opened with openModule. The first module found is the one meant: one
///   that does not load (broken, or of another build, whose interface may
///   differ) is reported, not replaced by a later candidate. `refusal`, when
///   set, may refuse a found file before it is opened: its text is then the
///   failure.
template <class Api>
OpenedModule<Api> openFirstModule(
    const std::string& fileName, const char* buildPath, int dlopenFlags, const char* entryPoint,
    int version, const char* what,
    const std::function<std::optional<std::string>(const std::string& path)>& refusal = {}) {
    for (const std::string& path : moduleCandidates(fileName, buildPath)) {
        if (::access(path.c_str(), F_OK) != 0) continue;
        if (refusal)
            if (std::optional<std::string> refused = refusal(path)) return {nullptr, *refused};
        return openModule<Api>(path, dlopenFlags, entryPoint, version, what);
    }
    return {nullptr, fileName + " not found beside the executable"};
}

}  // namespace raylab

#pragma once
// Loads the OpenEXR module (exr_module.h) on first use, once per process,
// from beside the running executable or, failing that, from where the build
// put it.

#include <stdexcept>
#include <string>

#include "renderer/io/exr_module.h"

namespace raylab {

/// Why the module could not be used (not found, not loadable, e.g. under a
/// memory limit, or built for another interface version).
class ExrModuleUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The module's entry points; throws ExrModuleUnavailable (every call again,
/// with the same reason) when it cannot be loaded.
const exr_module::Api& exrModule();

/// True once the module has been loaded by this process.
bool exrModuleLoaded();

}  // namespace raylab

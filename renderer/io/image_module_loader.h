#pragma once
// Loads the OpenImageIO module (image_module.h) on first use, once per
// process, from beside the running executable or, failing that, from where
// the build put it.

#include <stdexcept>
#include <string>

#include "renderer/io/image_module.h"

namespace raylab {

/// Why the module could not be used (not found, not loadable, e.g. under a
/// memory limit, or built for another interface version).
class ImageModuleUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The module's entry points; throws ImageModuleUnavailable (every call
/// again, with the same reason) when it cannot be loaded. `image`: the file
/// the caller is about to read, which the address-space probe reads too
/// under a finite `ulimit -v` (image_module_loader.cpp).
const image_module::Api& imageModule(const std::string& image = {});

/// True once the module has been loaded by this process.
bool imageModuleLoaded();

}  // namespace raylab

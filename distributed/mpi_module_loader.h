#pragma once
// Loads the MPI module (mpi_module.h) once per process, on first use, from
// beside the running executable or, failing that, from where the build put
// it. Only MpiSession asks for it, and only under an MPI launcher.

#include <stdexcept>

#include "distributed/mpi_module.h"

namespace raylab {

/// Why the module could not be used (built without MPI, not found, not
/// loadable, or built for another interface version).
class MpiModuleUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The module's entry points; throws MpiModuleUnavailable (every call again,
/// with the same reason) when it cannot be loaded.
const mpi_module::Api& mpiModule();

/// True once the module has been loaded by this process.
bool mpiModuleLoaded();

}  // namespace raylab

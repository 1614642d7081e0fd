#include "distributed/mpi_session.h"

#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <stdexcept>

#include "distributed/mpi_module_loader.h"

namespace raylab {

namespace {

std::string hostName() {
    char buf[256] = {};
    if (gethostname(buf, sizeof buf - 1) != 0) return "?";
    return buf;
}

}  // namespace

bool mpiAvailable() {
#if RAYLAB_HAVE_MPI
    return true;
#else
    return false;
#endif
}

bool launchedUnderMpirun() {
    for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
        if (const char* v = std::getenv(var); v && *v) return true;
    return false;
}

MpiSession::MpiSession() : m_host(hostName()) {
    if (!launchedUnderMpirun()) return;
    if (!mpiAvailable())
        throw std::runtime_error(
            "this raylab was built without MPI (RAYLAB_MPI=OFF or MPI not found): it cannot "
            "render across processes; install libopenmpi-dev and openmpi-bin and rebuild, or run "
            "it without mpirun");
    // Open MPI is loaded here, under a launcher only: a plain run never maps it.
    const mpi_module::Api& api = mpiModule();
    mpi_module::World world;
    std::string error;
    if (!api.start(world, error)) throw std::runtime_error(error);
    m_active = true;
    m_rank = world.rank;
    m_size = world.size;
    m_nodeRanks = world.nodeRanks;
}

MpiSession::~MpiSession() {
    if (!m_active) return;
    if (std::uncaught_exceptions() > 0) return;
    mpiModule().finish();
}

}  // namespace raylab

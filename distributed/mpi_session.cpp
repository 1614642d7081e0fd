#include "distributed/mpi_session.h"

#include <unistd.h>

#include <cstdlib>
#include <exception>
#include <stdexcept>

#if RAYLAB_HAVE_MPI
#include "distributed/mpi_c_api.h"
#endif

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

#if RAYLAB_HAVE_MPI

MpiSession::MpiSession() : m_host(hostName()) {
    if (!launchedUnderMpirun()) return;
    int initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (initialised || finalised)
        throw std::runtime_error("MPI: only one MpiSession per process");
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
        throw std::runtime_error("MPI: MPI_Init_thread failed");
    m_active = true;
    if (provided < MPI_THREAD_FUNNELED) {
        // Render threads coexist with MPI calls on the main thread; an MPI
        // that cannot promise that is unusable here.
        MPI_Finalize();
        m_active = false;
        throw std::runtime_error("MPI: the library does not provide MPI_THREAD_FUNNELED");
    }
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &m_size);
    // Ranks on this machine share its cores: the default thread count divides them.
    MPI_Comm node;
    if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, m_rank, MPI_INFO_NULL, &node) ==
        MPI_SUCCESS) {
        MPI_Comm_size(node, &m_nodeRanks);
        MPI_Comm_free(&node);
    }
}

MpiSession::~MpiSession() {
    if (!m_active) return;
    if (std::uncaught_exceptions() > 0) return;
    MPI_Finalize();
}

#else  // built without MPI

MpiSession::MpiSession() : m_host(hostName()) {
    if (launchedUnderMpirun())
        throw std::runtime_error(
            "this raylab was built without MPI (RAYLAB_MPI=OFF or MPI not found): it cannot "
            "render across processes; install libopenmpi-dev and openmpi-bin and rebuild, or run "
            "it without mpirun");
}

MpiSession::~MpiSession() = default;

#endif

}  // namespace raylab

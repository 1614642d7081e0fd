#pragma once
// The MPI lifetime of one raylab process. MPI is loaded (the module
// raylab-mpi.so, mpi_module.h) and initialised only when the process was
// started by an MPI launcher (mpirun, mpiexec, srun), so a plain
// `raylab render` never maps or touches MPI. Built without MPI
// (RAYLAB_MPI=OFF or no MPI found), or with the module missing, a launch
// under mpirun is refused with a clear message instead of N processes
// silently rendering the same image.

#include <string>

namespace raylab {

/// True when this build can render across processes (its MPI module was
/// built; whether it loads is found out under mpirun).
bool mpiAvailable();

/// True when the environment says an MPI launcher started this process
/// (OMPI_COMM_WORLD_SIZE for Open MPI, PMI_SIZE for MPICH/Hydra and Slurm,
/// PMIX_RANK for PMIx launchers). Reads the environment only.
bool launchedUnderMpirun();

/// RAII: MPI_Init_thread(MPI_THREAD_FUNNELED) in the constructor when launched
/// under mpirun, MPI_Finalize in the destructor. FUNNELED suffices because
/// only the thread that created the session calls MPI; TBB's render threads
/// never do. At most one session per process (MPI cannot be initialised
/// twice). Errors of MPI calls are returned, not fatal (MPI_ERRORS_RETURN),
/// so the distributed renderer can name the rank that failed.
class MpiSession {
public:
    /// Initialises MPI when launchedUnderMpirun(); otherwise an inactive
    /// session (rank 0 of 1). Throws std::runtime_error when launched under
    /// mpirun by a build without MPI, when the MPI module cannot be loaded
    /// (MpiModuleUnavailable), or when MPI cannot be initialised.
    MpiSession();
    /// Finalises MPI. While an exception is unwinding it does not: a rank that
    /// failed alone must not block in MPI_Finalize waiting for peers that wait
    /// for it; exiting without finalising makes mpirun end the whole job.
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;

    /// True when MPI was initialised (even with one rank).
    bool active() const { return m_active; }
    /// This process's rank in MPI_COMM_WORLD (0 without MPI).
    int rank() const { return m_rank; }
    /// Number of ranks (1 without MPI).
    int size() const { return m_size; }
    /// Rank 0: the one that assembles frames and writes the files.
    bool isRoot() const { return m_rank == 0; }
    /// Ranks sharing this rank's machine (for the default thread count).
    int ranksOnThisNode() const { return m_nodeRanks; }
    /// Host name of this rank (for messages and the load report).
    const std::string& host() const { return m_host; }

private:
    bool m_active = false;
    int m_rank = 0, m_size = 1, m_nodeRanks = 1;
    std::string m_host;
};

}  // namespace raylab

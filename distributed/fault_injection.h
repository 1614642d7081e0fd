#pragma once
// A testing hook for the failure paths (docs/distributed.md, used by
// tests/distributed/test_mpirun_cli.cpp): when its first chunk arrives, rank
// R >= 1 stops answering (RAYLAB_MPI_FAULT=stall:R) or dies by SIGKILL (kill:R).

namespace raylab {

struct Fault {
    bool stall = false;
    bool kill = false;

    /// What RAYLAB_MPI_FAULT asks of `rank`: nothing when it is unset or
    /// names another rank.
    static Fault forRank(int rank);

    /// Called when a chunk arrives: dies or hangs as asked, else returns.
    void strike() const;
};

}  // namespace raylab

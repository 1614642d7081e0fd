#pragma once
// What each rank did in a distributed render, and the per-rank table of the
// end-of-render summary (docs/distributed.md shows one).

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

/// What one rank did in a distributed render.
struct RankLoad {
    int rank = 0;
    std::string host;
    int threads = 0;
    uint64_t items = 0;      ///< work items it rendered
    uint64_t chunks = 0;     ///< chunks it was handed
    double busySeconds = 0;  ///< thread-seconds (wall) spent rendering items
    double cpuSeconds = 0;   ///< CPU seconds of those threads (busy minus time preempted)
    /// When its last item was done (rank 0) or arrived at rank 0 (the
    /// others), in seconds on rank 0's clock since rank 0 started the frame.
    double finishSeconds = 0;
    uint64_t rays = 0;       ///< rays of every type it traced
    uint64_t bytesSent = 0;  ///< item data it sent to rank 0 (0 for rank 0)
};

/// The load balance of a distributed render; complete on rank 0 only.
struct DistributedReport {
    int ranks = 1;
    int items = 0;                ///< work items in the frame
    bool spd = false;             ///< items were SPD corner rows, not 16x16 tiles
    double seconds = 0;           ///< wall time of the render on rank 0
    std::vector<RankLoad> loads;  ///< one per rank, in rank order
};

/// The per-rank table for the end-of-render summary ("" without ranks), e.g.
///   "  ranks:    2 ranks, 1200 tiles, 13.2 MiB gathered in 2.105 s\n"
///   "    rank 0 (vm, 1 thread): 590 items (49.2%) in 31 chunks, busy 2.010 s (cpu 1.980 s),
///    done at 2.101 s, 4.61 Mrays\n" (one line per rank).
std::string formatLoadReport(const DistributedReport& report);

}  // namespace raylab

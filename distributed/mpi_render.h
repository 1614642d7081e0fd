#pragma once
// One frame rendered by every rank of an MPI job (docs/distributed.md).
//
// Every rank loads the scene and builds its own BVH; rank 0 keeps the work
// queue (guided chunks over a scattered item order, work_schedule.h) and
// answers requests from its main thread while its TBB threads render too.
// Every rank renders the items it holds with TBB and sends the finished
// pixels (SPD mode: corner rows) to rank 0 byte for byte; rank 0 assembles
// the frame and merges the ray counters. Items are deterministic, so the
// image and the counters equal those of a single-process render bit for bit.

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "distributed/mpi_session.h"
#include "renderer/render.h"

namespace raylab {

/// What one rank did in a distributed render.
struct RankLoad {
    int rank = 0;
    std::string host;
    int threads = 0;
    uint64_t items = 0;        ///< work items it rendered
    uint64_t chunks = 0;       ///< chunks it was handed
    double busySeconds = 0;    ///< thread-seconds (wall) spent rendering items
    double cpuSeconds = 0;     ///< CPU seconds of those threads (busy minus time preempted)
    /// When its last item was done (rank 0) or arrived at rank 0 (the
    /// others), in seconds on rank 0's clock since rank 0 started the frame.
    double finishSeconds = 0;
    uint64_t rays = 0;         ///< rays of every type it traced
    uint64_t bytesSent = 0;    ///< item data it sent to rank 0 (0 for rank 0)
};

/// The load balance of a distributed render; complete on rank 0 only.
struct DistributedReport {
    int ranks = 1;
    int items = 0;            ///< work items in the frame
    bool spd = false;         ///< items were SPD corner rows, not 16x16 tiles
    double seconds = 0;       ///< wall time of the render on rank 0
    std::vector<RankLoad> loads;  ///< one per rank, in rank order
};

/// Render threads of this rank: options.threads when set, else the cores of
/// this machine divided among the ranks running on it (at least 1).
int threadsPerRank(const MpiSession& mpi, const RenderOptions& options);

/// Renders one frame across the ranks of `mpi`; every rank must call it with
/// the same scene, options and effects. On rank 0 the result holds the whole
/// film and the counters of all ranks; on other ranks an empty film and that
/// rank's own counters. With an inactive session (no mpirun) it is exactly
/// render(): the single-process path does not change.
///
/// `progress` is called on rank 0's calling thread; `cancel` (may be null)
/// stops every rank between items (result.cancelled on all ranks). A rank
/// that stops answering for RAYLAB_MPI_TIMEOUT seconds (default 120) makes
/// the surviving side throw std::runtime_error naming the rank and the
/// items it held; a frame with missing items is never returned. With
/// RAYLAB_MPI_ROOT_RENDERS=0 rank 0 only serves the queue and assembles.
RenderResult renderDistributed(const MpiSession& mpi, const Scene& scene, const Accelerator& accel,
                               const RenderOptions& options, const EffectSet& effects,
                               const ProgressCallback& progress = {},
                               const std::atomic<bool>* cancel = nullptr,
                               DistributedReport* report = nullptr);

/// The per-rank table for the end-of-render summary ("" without ranks), e.g.
///   "  ranks:    2 ranks, 1200 tiles, 13.2 MiB gathered in 2.105 s\n"
///   "    rank 0 (vm, 1 thread): 590 items (49.2%) in 31 chunks, busy 2.010 s (cpu 1.980 s),
///    done at 2.101 s, 4.61 Mrays\n" (one line per rank).
std::string formatLoadReport(const DistributedReport& report);

}  // namespace raylab

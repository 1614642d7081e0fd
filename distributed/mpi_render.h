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

#include "distributed/load_report.h"
#include "distributed/mpi_session.h"
#include "renderer/render.h"

namespace raylab {

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

}  // namespace raylab

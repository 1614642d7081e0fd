#include "distributed/mpi_render.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "distributed/config.h"
#include "distributed/fault_injection.h"
#include "distributed/frame_job.h"
#include "distributed/work_schedule.h"

namespace raylab {

int threadsPerRank(const MpiSession& mpi, const RenderOptions& options) {
    if (options.threads > 0) return options.threads;
    const int cores = std::max(1, int(std::thread::hardware_concurrency()));
    return std::max(1, cores / std::max(1, mpi.ranksOnThisNode()));
}

RenderResult renderDistributed(const MpiSession& mpi, const Scene& scene, const Accelerator& accel,
                               const RenderOptions& options, const EffectSet& effects,
                               const ProgressCallback& progress, const std::atomic<bool>* cancel,
                               DistributedReport* report) {
    if (!mpi.active()) {
        if (report) *report = DistributedReport{};
        return render(scene, accel, options, effects, progress, cancel);
    }
    // Every rank counts its calls the same way: the count names the frame in
    // each message (only the thread that owns the session calls this).
    static int32_t s_epoch = 0;
    const int32_t epoch = ++s_epoch;

    const FrameRenderer frame(scene, accel, options, effects);
    FrameJob job{mpi,
                 frame,
                 options,
                 threadsPerRank(mpi, options),
                 epoch,
                 timeoutSeconds(),
                 Fault::forRank(mpi.rank()),
                 scatteredOrder(frame.workItemCount()),
                 std::chrono::steady_clock::now()};
    // The render threads plus this (mostly sleeping) MPI thread.
    const tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism,
                                          size_t(job.threads) + 1);
    return mpi.isRoot() ? runRoot(job, progress, cancel, report) : runWorker(job, cancel);
}

}  // namespace raylab

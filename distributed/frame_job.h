#pragma once
// One frame as the ranks share it: what rank 0's loop (root.cpp) and the
// workers' loop (worker.cpp) both need. Built by renderDistributed.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "distributed/fault_injection.h"
#include "distributed/load_report.h"
#include "distributed/mpi_session.h"
#include "renderer/render.h"

namespace raylab {

struct FrameJob {
    const MpiSession& mpi;
    const FrameRenderer& frame;
    const RenderOptions& options;
    int threads;
    int32_t epoch;
    double timeout;
    Fault fault;
    std::vector<int> order;  ///< scattered hand-out order of the items
    std::chrono::steady_clock::time_point start;

    /// The items at positions [begin, begin + count) of the hand-out order.
    std::vector<int> chunkItems(int begin, int count) const {
        if (begin < 0 || count < 0 || begin > int(order.size()) - count)
            throw std::runtime_error("chunk [" + std::to_string(begin) + ", +" +
                                     std::to_string(count) + ") is outside the frame");
        return std::vector<int>(order.begin() + begin, order.begin() + begin + count);
    }
};

/// Rank 0: serves the queue, renders its share, assembles the frame.
RenderResult runRoot(const FrameJob& job, const ProgressCallback& progress,
                     const std::atomic<bool>* cancel, DistributedReport* report);

/// Ranks 1..N-1: ask for chunks, render them, send the items back.
RenderResult runWorker(const FrameJob& job, const std::atomic<bool>* cancel);

}  // namespace raylab

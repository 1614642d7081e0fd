#pragma once
// Renders the work items handed to one rank on a TBB arena of its own. The
// thread that owns it (the one that talks MPI) only submits chunks and
// collects finished items, so it can answer messages while rendering goes on.
// On rank 0 the render threads also refill it straight from the queue (a
// `source`), so they never wait for the MPI thread to wake up.

#include <tbb/enumerable_thread_specific.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "renderer/render.h"

namespace raylab {

class LocalWorker {
public:
    /// Takes the next chunk's items from the queue; empty when there are none.
    using Source = std::function<std::vector<int>()>;

    /// `reserve`: how many items it wants in hand (rendering or queued)
    /// before it asks for more; see wantsMore().
    LocalWorker(const FrameRenderer& frame, FrameBuffers& buffers, int threads, int reserve,
                Source source = {});
    ~LocalWorker() { stopAndWait(); }
    LocalWorker(const LocalWorker&) = delete;
    LocalWorker& operator=(const LocalWorker&) = delete;

    /// Queues the items of one chunk (any thread).
    void submit(const std::vector<int>& items);

    /// More work is wanted when fewer than `reserve` items are in hand. A
    /// rank asks early enough that its threads keep busy while the request
    /// travels, but no earlier: whatever it holds when the others run dry
    /// is the imbalance at the end of the frame.
    bool wantsMore() const { return m_inFlight.load() < m_reserve; }
    bool idle() const { return m_inFlight.load() == 0; }

    /// Pulls chunks from the source while wantsMore(); false when it is empty.
    bool refill();

    /// Items finished since the last call.
    std::vector<int> takeDone();

    /// Items not started yet are dropped; running ones finish.
    void stop() { m_stop = true; }
    void stopAndWait();

    /// Rethrows (as std::runtime_error) the first exception of a render task.
    void rethrowIfFailed();

    /// Sum of the per-thread counters; call when idle.
    WorkCounters counters() const;
    double busySeconds() const { return double(m_busyNs.load()) * 1e-9; }
    double cpuSeconds() const { return double(m_cpuNs.load()) * 1e-9; }
    uint64_t chunks() const { return m_chunks.load(); }
    int threads() const { return m_threads; }

private:
    void run(int item);
    void fail(const std::string& message);

    const FrameRenderer& m_frame;
    FrameBuffers& m_buffers;
    const int m_threads;
    const int m_reserve;
    const Source m_source;
    tbb::task_arena m_arena;
    tbb::enumerable_thread_specific<WorkCounters> m_counters;
    std::atomic<int> m_inFlight{0};
    std::atomic<bool> m_stop{false};
    std::atomic<int64_t> m_busyNs{0};
    std::atomic<int64_t> m_cpuNs{0};
    std::atomic<uint64_t> m_chunks{0};
    std::mutex m_mutex;
    std::vector<int> m_done;
    std::string m_error;
};

}  // namespace raylab

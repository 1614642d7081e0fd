#include "distributed/local_worker.h"

#include <chrono>
#include <stdexcept>
#include <thread>
#include <utility>

#include "distributed/config.h"
#include "renderer/timing.h"

namespace raylab {

LocalWorker::LocalWorker(const FrameRenderer& frame, FrameBuffers& buffers, int threads,
                         int reserve, Source source)
    : m_frame(frame), m_buffers(buffers), m_threads(threads), m_reserve(reserve),
      m_source(std::move(source)),
      m_arena(threads, 0) {}  // no slot reserved: the MPI thread never joins

void LocalWorker::submit(const std::vector<int>& items) {
    if (items.empty()) return;
    m_inFlight += int(items.size());
    ++m_chunks;
    for (int item : items) m_arena.enqueue([this, item] { run(item); });
}

bool LocalWorker::refill() {
    while (m_source && !m_stop.load() && wantsMore()) {
        const std::vector<int> items = m_source();
        if (items.empty()) return false;
        submit(items);
    }
    return true;
}

std::vector<int> LocalWorker::takeDone() {
    std::lock_guard<std::mutex> lock(m_mutex);
    std::vector<int> done;
    done.swap(m_done);
    return done;
}

void LocalWorker::stopAndWait() {
    stop();
    while (!idle()) std::this_thread::sleep_for(kPollInterval);
}

void LocalWorker::rethrowIfFailed() {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (!m_error.empty()) throw std::runtime_error(m_error);
}

WorkCounters LocalWorker::counters() const {
    WorkCounters sum;
    for (const WorkCounters& c : m_counters) sum += c;
    return sum;
}

void LocalWorker::run(int item) {
    if (!m_stop.load(std::memory_order_relaxed)) {
        try {
            const auto t0 = std::chrono::steady_clock::now();
            const int64_t cpu0 = threadCpuNanoseconds();
            m_frame.renderWorkItem(item, m_buffers, m_counters.local());
            m_cpuNs += threadCpuNanoseconds() - cpu0;
            m_busyNs += std::chrono::duration_cast<std::chrono::nanoseconds>(
                            std::chrono::steady_clock::now() - t0)
                            .count();
            {
                std::lock_guard<std::mutex> lock(m_mutex);
                m_done.push_back(item);
            }
            // Still counted in flight here, so the worker never looks idle
            // between this item and the chunk it pulls.
            refill();
        } catch (const std::exception& e) {
            fail(e.what());
        } catch (...) {
            fail("unknown exception in a render thread");
        }
    }
    // Last: once nothing is in flight the owner may destroy the worker.
    --m_inFlight;
}

void LocalWorker::fail(const std::string& message) {
    std::lock_guard<std::mutex> lock(m_mutex);
    if (m_error.empty()) m_error = message;
    m_stop = true;
}

}  // namespace raylab

#include "distributed/mpi_render.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>

#if RAYLAB_HAVE_MPI
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <time.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <functional>
#include <list>
#include <mutex>

#include "distributed/item_codec.h"
#include "distributed/work_schedule.h"
#include "renderer/timing.h"

// The C API only (no deprecated C++ bindings and their warnings).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

namespace raylab {

int threadsPerRank(const MpiSession& mpi, const RenderOptions& options) {
    if (options.threads > 0) return options.threads;
    const int cores = std::max(1, int(std::thread::hardware_concurrency()));
    return std::max(1, cores / std::max(1, mpi.ranksOnThisNode()));
}

std::string formatLoadReport(const DistributedReport& report) {
    if (report.loads.empty()) return "";
    uint64_t bytes = 0, items = 0;
    for (const RankLoad& l : report.loads) {
        bytes += l.bytesSent;
        items += l.items;
    }
    char line[512];
    std::snprintf(line, sizeof line, "  ranks:    %d ranks, %d %s, %.1f MiB gathered in %.3f s\n",
                  report.ranks, report.items, report.spd ? "corner rows" : "tiles",
                  double(bytes) / (1024.0 * 1024.0), report.seconds);
    std::string s = line;
    for (const RankLoad& l : report.loads) {
        std::snprintf(line, sizeof line,
                      "    rank %d (%s, %d thread%s): %llu items (%.1f%%) in %llu chunks, busy "
                      "%.3f s (cpu %.3f s), done at %.3f s, %.2f Mrays\n",
                      l.rank, l.host.c_str(), l.threads, l.threads == 1 ? "" : "s",
                      (unsigned long long)l.items,
                      items ? 100.0 * double(l.items) / double(items) : 0.0,
                      (unsigned long long)l.chunks, l.busySeconds, l.cpuSeconds, l.finishSeconds,
                      double(l.rays) * 1e-6);
        s += line;
    }
    return s;
}

#if !RAYLAB_HAVE_MPI

RenderResult renderDistributed(const MpiSession& mpi, const Scene& scene, const Accelerator& accel,
                               const RenderOptions& options, const EffectSet& effects,
                               const ProgressCallback& progress, const std::atomic<bool>* cancel,
                               DistributedReport* report) {
    // MpiSession refuses to start under mpirun in this build, so a session
    // here is always inactive: the single-process render.
    if (mpi.active()) throw std::runtime_error("this raylab was built without MPI");
    if (report) *report = DistributedReport{};
    return render(scene, accel, options, effects, progress, cancel);
}

#else  // RAYLAB_HAVE_MPI

namespace {

using Clock = std::chrono::steady_clock;

// Message tags. Every message starts with the frame's epoch (the number of
// renderDistributed calls so far), so a message from another frame is caught.
enum Tag : int {
    kTagRequest = 0x5241,  ///< worker -> 0: more work, please
    kTagAssign,            ///< 0 -> worker: chunk {begin, count}; count 0 = no more work
    kTagResult,            ///< worker -> 0: finished items (item_codec.h)
    kTagDone,              ///< worker -> 0: all its items sent; its load and counters
    kTagHeartbeat,         ///< worker -> 0: still alive, rendering a long chunk
    kTagAbort,             ///< 0 -> worker: the render was cancelled, stop
};

/// Idle wait of the MPI threads between polls: short against a tile's render
/// time, long enough that polling costs no noticeable CPU.
constexpr auto kPollInterval = std::chrono::microseconds(500);

/// Seconds of silence after which a peer counts as failed (RAYLAB_MPI_TIMEOUT).
double timeoutSeconds() {
    const char* v = std::getenv("RAYLAB_MPI_TIMEOUT");
    if (!v || !*v) return 120;
    char* end = nullptr;
    const double t = std::strtod(v, &end);
    if (end == v || *end != '\0' || !(t > 0))
        throw std::runtime_error(std::string("RAYLAB_MPI_TIMEOUT must be a number of seconds > 0 "
                                             "(got '") + v + "')");
    return t;
}

/// RAYLAB_MPI_ROOT_RENDERS=0: rank 0 only serves the queue and assembles the
/// frame (when it runs on a login node, or to measure the workers alone).
bool rootRenders(int ranks) {
    const char* v = std::getenv("RAYLAB_MPI_ROOT_RENDERS");
    return ranks == 1 || !v || std::string(v) != "0";
}

/// Testing hook for the failure paths (docs/distributed.md): when its first
/// chunk arrives, rank R >= 1 stops answering (RAYLAB_MPI_FAULT=stall:R) or
/// dies by SIGKILL (kill:R).
struct Fault {
    bool stall = false;
    bool kill = false;
};

Fault faultFor(int rank) {
    Fault f;
    const char* v = std::getenv("RAYLAB_MPI_FAULT");
    if (!v) return f;
    const std::string s = v;
    const size_t colon = s.find(':');
    if (colon == std::string::npos || std::atoi(s.c_str() + colon + 1) != rank) return f;
    f.stall = s.compare(0, colon, "stall") == 0;
    f.kill = s.compare(0, colon, "kill") == 0;
    return f;
}

/// Renders the items handed to this rank on a TBB arena of its own. The
/// thread that owns it (the one that talks MPI) only submits chunks and
/// collects finished items, so it can answer messages while rendering goes on.
/// On rank 0 the render threads also refill it straight from the queue (a
/// `source`), so they never wait for the MPI thread to wake up.
class LocalWorker {
public:
    /// Takes the next chunk's items from the queue; empty when there are none.
    using Source = std::function<std::vector<int>()>;

    /// `reserve`: how many items it wants in hand (rendering or queued)
    /// before it asks for more; see wantsMore().
    LocalWorker(const FrameRenderer& frame, FrameBuffers& buffers, int threads, int reserve,
                Source source = {})
        : m_frame(frame), m_buffers(buffers), m_threads(threads), m_reserve(reserve),
          m_source(std::move(source)),
          m_arena(threads, 0) {}  // no slot reserved: the MPI thread never joins

    ~LocalWorker() { stopAndWait(); }

    /// Queues the items of one chunk (any thread).
    void submit(const std::vector<int>& items) {
        if (items.empty()) return;
        m_inFlight += int(items.size());
        ++m_chunks;
        for (int item : items) m_arena.enqueue([this, item] { run(item); });
    }

    /// More work is wanted when fewer than `reserve` items are in hand. A
    /// rank asks early enough that its threads keep busy while the request
    /// travels, but no earlier: whatever it holds when the others run dry
    /// is the imbalance at the end of the frame.
    bool wantsMore() const { return m_inFlight.load() < m_reserve; }
    bool idle() const { return m_inFlight.load() == 0; }

    /// Pulls chunks from the source while wantsMore(); false when it is empty.
    bool refill() {
        while (m_source && !m_stop.load() && wantsMore()) {
            const std::vector<int> items = m_source();
            if (items.empty()) return false;
            submit(items);
        }
        return true;
    }

    /// Items finished since the last call.
    std::vector<int> takeDone() {
        std::lock_guard<std::mutex> lock(m_mutex);
        std::vector<int> done;
        done.swap(m_done);
        return done;
    }

    /// Items not started yet are dropped; running ones finish.
    void stop() { m_stop = true; }
    void stopAndWait() {
        stop();
        while (!idle()) std::this_thread::sleep_for(kPollInterval);
    }

    /// Rethrows (as std::runtime_error) the first exception of a render task.
    void rethrowIfFailed() {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (!m_error.empty()) throw std::runtime_error(m_error);
    }

    /// Sum of the per-thread counters; call when idle.
    WorkCounters counters() const {
        WorkCounters sum;
        for (const WorkCounters& c : m_counters) {
            sum.rays += c.rays;
            sum.nonFinite += c.nonFinite;
        }
        return sum;
    }
    double busySeconds() const { return double(m_busyNs.load()) * 1e-9; }
    double cpuSeconds() const { return double(m_cpuNs.load()) * 1e-9; }
    uint64_t chunks() const { return m_chunks.load(); }
    int threads() const { return m_threads; }

private:
    void run(int item) {
        if (!m_stop.load(std::memory_order_relaxed)) {
            try {
                const auto t0 = Clock::now();
                const int64_t cpu0 = threadCpuNanoseconds();
                m_frame.renderWorkItem(item, m_buffers, m_counters.local());
                m_cpuNs += threadCpuNanoseconds() - cpu0;
                m_busyNs += std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - t0)
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

    void fail(const std::string& message) {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_error.empty()) m_error = message;
        m_stop = true;
    }

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

/// Point-to-point MPI on MPI_COMM_WORLD with every call checked: errors
/// return (MPI_ERRORS_RETURN) and become exceptions naming the call. Sends are
/// non-blocking and kept until delivered, so neither side ever blocks on the other.
class Transport {
public:
    ~Transport() {
        // Undelivered sends (only on an error path, just before the process
        // ends): their buffers must outlive MPI's use of them.
        for (Outgoing& o : m_out) new std::vector<unsigned char>(std::move(o.bytes));
    }

    void post(int dest, int tag, std::vector<unsigned char> bytes) {
        m_out.push_back({MPI_REQUEST_NULL, std::move(bytes)});
        Outgoing& o = m_out.back();
        check(MPI_Isend(o.bytes.data(), int(o.bytes.size()), MPI_BYTE, dest, tag, MPI_COMM_WORLD,
                        &o.request),
              "send to rank " + std::to_string(dest));
    }

    /// Lets MPI advance the pending sends; forgets the delivered ones.
    void progress() {
        for (auto it = m_out.begin(); it != m_out.end();) {
            int flag = 0;
            check(MPI_Test(&it->request, &flag, MPI_STATUS_IGNORE), "send");
            it = flag ? m_out.erase(it) : std::next(it);
        }
    }

    /// Waits up to `timeout` seconds for every pending send; false if some remain.
    bool flush(double timeout) {
        const auto t0 = Clock::now();
        for (;;) {
            progress();
            if (m_out.empty()) return true;
            if (secondsSince(t0) > timeout) return false;
            std::this_thread::sleep_for(kPollInterval);
        }
    }

    /// A message from `source` waiting to be received: its tag and size.
    bool probe(int source, int& tag, int& bytes) {
        int flag = 0;
        MPI_Status st;
        check(MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st),
              "probe rank " + std::to_string(source));
        if (!flag) return false;
        tag = st.MPI_TAG;
        check(MPI_Get_count(&st, MPI_BYTE, &bytes), "message size");
        return true;
    }

    std::vector<unsigned char> receive(int source, int tag, int bytes) {
        std::vector<unsigned char> data(size_t(std::max(0, bytes)));
        check(MPI_Recv(data.data(), bytes, MPI_BYTE, source, tag, MPI_COMM_WORLD,
                       MPI_STATUS_IGNORE),
              "receive from rank " + std::to_string(source));
        return data;
    }

private:
    static void check(int rc, const std::string& what) {
        if (rc == MPI_SUCCESS) return;
        char text[MPI_MAX_ERROR_STRING] = {};
        int len = 0;
        MPI_Error_string(rc, text, &len);
        throw std::runtime_error("MPI: " + what + ": " + std::string(text, size_t(len)));
    }

    struct Outgoing {
        MPI_Request request;
        std::vector<unsigned char> bytes;
    };
    std::list<Outgoing> m_out;  ///< std::list: buffers never move while MPI holds them
};

std::vector<unsigned char> header(int32_t epoch) {
    std::vector<unsigned char> bytes;
    ByteWriter(bytes).put(epoch);
    return bytes;
}

/// The part of a DONE message that describes the rank's work.
void appendLoad(const RankLoad& l, bool cancelled, std::vector<unsigned char>& out) {
    ByteWriter w(out);
    w.put(int32_t(cancelled));
    w.put(int32_t(l.threads));
    w.put(l.items);
    w.put(l.chunks);
    w.put(l.busySeconds);
    w.put(l.cpuSeconds);
    w.put(l.bytesSent);
    w.putString(l.host);
}

RankLoad readLoad(ByteReader& in, bool& cancelled) {
    RankLoad l;
    cancelled = in.get<int32_t>() != 0;
    l.threads = in.get<int32_t>();
    l.items = in.get<uint64_t>();
    l.chunks = in.get<uint64_t>();
    l.busySeconds = in.get<double>();
    l.cpuSeconds = in.get<double>();
    l.bytesSent = in.get<uint64_t>();
    l.host = in.getString();
    return l;
}

std::string rankName(int rank, const std::string& host) {
    return "rank " + std::to_string(rank) + (host.empty() ? "" : " (" + host + ")");
}

/// The state shared by rank 0's and the workers' loops.
struct FrameJob {
    const MpiSession& mpi;
    const FrameRenderer& frame;
    const RenderOptions& options;
    int threads;
    int32_t epoch;
    double timeout;
    Fault fault;
    std::vector<int> order;  ///< scattered hand-out order of the items
    Clock::time_point start;

    std::vector<int> chunkItems(int begin, int count) const {
        if (begin < 0 || count < 0 || begin > int(order.size()) - count)
            throw std::runtime_error("chunk [" + std::to_string(begin) + ", +" +
                                     std::to_string(count) + ") is outside the frame");
        return std::vector<int>(order.begin() + begin, order.begin() + begin + count);
    }
};

/// Rank 0: serves the queue, renders its share, assembles the frame.
RenderResult runRoot(const FrameJob& job, const ProgressCallback& progress,
                     const std::atomic<bool>* cancel, DistributedReport* report) {
    struct Peer {
        uint64_t assigned = 0, received = 0;
        bool finished = false, cancelled = false;
        Clock::time_point lastHeard;
        double lastResult = 0;  ///< when its last items arrived, s since the start
        RankLoad load;
        WorkCounters counters;
    };
    const int ranks = job.mpi.size();
    const int items = job.frame.workItemCount();
    const bool renders = rootRenders(ranks);
    // The queue, shared by this thread (remote requests) and the render threads.
    GuidedSchedule schedule(items, renders ? ranks : ranks - 1);
    std::mutex scheduleMutex;
    std::atomic<bool> stopping{false};
    const auto nextChunk = [&] {
        std::lock_guard<std::mutex> lock(scheduleMutex);
        return stopping.load() ? WorkChunk{0, 0} : schedule.next();
    };
    const auto remaining = [&] {
        std::lock_guard<std::mutex> lock(scheduleMutex);
        return schedule.remaining();
    };
    FrameBuffers buffers = job.frame.makeBuffers();
    const ItemCodec codec(job.frame, job.options);
    Transport net;
    // Declared after what its render threads use: destroyed (and waited for) first.
    // Rank 0 pulls from the queue without a message: one item per thread in
    // reserve (+1) is enough.
    LocalWorker local(job.frame, buffers, job.threads, job.threads + 1,
                      renders ? LocalWorker::Source([&] {
                          const WorkChunk c = nextChunk();
                          return job.chunkItems(c.begin, c.count);
                      })
                              : LocalWorker::Source());
    std::vector<Peer> peers(static_cast<size_t>(ranks));
    for (Peer& p : peers) p.lastHeard = job.start;

    std::vector<uint8_t> have(static_cast<size_t>(items), 0);
    int haveCount = 0, reported = -1;
    uint64_t localItems = 0;
    double localFinish = 0;
    const auto accept = [&](int item, int from) {
        if (have[size_t(item)])
            throw std::runtime_error("work item " + std::to_string(item) + " arrived twice (from " +
                                     rankName(from, "") + ")");
        have[size_t(item)] = 1;
        ++haveCount;
    };

    for (;;) {
        bool active = false;
        for (int item : local.takeDone()) {
            accept(item, 0);
            ++localItems;
            localFinish = secondsSince(job.start);
            active = true;
        }
        try {
            local.rethrowIfFailed();
        } catch (const std::exception& e) {
            throw std::runtime_error(rankName(0, job.mpi.host()) + ": " + e.what());
        }
        local.refill();  // the first chunks; later the render threads pull their own

        for (int r = 1; r < ranks; ++r) {
            Peer& p = peers[size_t(r)];
            int tag = 0, size = 0;
            while (!p.finished && net.probe(r, tag, size)) {
                active = true;
                const std::vector<unsigned char> msg = net.receive(r, tag, size);
                p.lastHeard = Clock::now();
                ByteReader in(msg.data(), msg.size());
                const int32_t epoch = in.get<int32_t>();
                if (epoch != job.epoch)
                    throw std::runtime_error(rankName(r, "") + " is on frame " +
                                             std::to_string(epoch) + ", rank 0 on frame " +
                                             std::to_string(job.epoch));
                if (tag == kTagRequest) {
                    const WorkChunk c = nextChunk();
                    p.assigned += uint64_t(c.count);
                    std::vector<unsigned char> reply = header(job.epoch);
                    ByteWriter w(reply);
                    w.put(int32_t(c.begin));
                    w.put(int32_t(c.count));
                    net.post(r, kTagAssign, std::move(reply));
                } else if (tag == kTagResult) {
                    std::vector<int> got;
                    codec.extract(in, buffers, got);
                    for (int item : got) accept(item, r);
                    p.received += got.size();
                    // On rank 0's clock, so every rank's "done at" compares.
                    p.lastResult = secondsSince(job.start);
                } else if (tag == kTagDone) {
                    p.load = readLoad(in, p.cancelled);
                    p.counters = readCounters(in);
                    p.load.rank = r;
                    p.load.finishSeconds = p.lastResult;
                    p.load.rays = p.counters.rays.total();
                    p.finished = true;
                    if (!p.cancelled && p.received != p.assigned)
                        throw std::runtime_error(
                            rankName(r, p.load.host) + " finished, but " +
                            std::to_string(p.assigned - p.received) + " of its " +
                            std::to_string(p.assigned) + " items never arrived");
                } else if (tag != kTagHeartbeat) {
                    throw std::runtime_error("unexpected message (tag " + std::to_string(tag) +
                                             ") from " + rankName(r, ""));
                }
            }
        }

        if (progress && haveCount != reported) {
            reported = haveCount;
            progress(double(haveCount) / double(items));
        }

        bool peerCancelled = false, allFinished = true;
        for (int r = 1; r < ranks; ++r) {
            peerCancelled |= peers[size_t(r)].cancelled;
            allFinished &= peers[size_t(r)].finished;
        }
        if (!stopping && ((cancel && cancel->load()) || peerCancelled)) {
            // Cancelled here or on a worker: stop every rank between items.
            stopping = true;
            local.stop();
            for (int r = 1; r < ranks; ++r)
                if (!peers[size_t(r)].finished) net.post(r, kTagAbort, header(job.epoch));
        }
        if (allFinished && local.idle()) {
            if (stopping || haveCount == items) break;
            if (remaining() == 0)
                throw std::runtime_error(std::to_string(items - haveCount) +
                                         " work items were handed out but never arrived");
        }
        for (int r = 1; r < ranks; ++r) {
            const Peer& p = peers[size_t(r)];
            if (p.finished || secondsSince(p.lastHeard) <= job.timeout) continue;
            char held[96] = "since the frame started";
            if (p.assigned > 0)
                std::snprintf(held, sizeof held, "while holding %llu unfinished work items",
                              (unsigned long long)(p.assigned - p.received));
            char msg[320];
            std::snprintf(msg, sizeof msg,
                          "%s sent nothing for %g s %s (limit: RAYLAB_MPI_TIMEOUT); the frame is "
                          "incomplete and is not written",
                          rankName(r, "").c_str(), job.timeout, held);
            throw std::runtime_error(msg);
        }
        net.progress();
        if (!active) std::this_thread::sleep_for(kPollInterval);
    }
    local.stopAndWait();
    if (!net.flush(job.timeout))
        throw std::runtime_error("messages to the workers were not delivered within " +
                                 std::to_string(int(job.timeout)) + " s");

    RenderResult result;
    result.cancelled = stopping.load();
    if (!result.cancelled) job.frame.finish(buffers);
    result.renderSeconds = secondsSince(job.start);
    // Integer sums: the same totals as one process, whatever the split.
    const WorkCounters own = local.counters();
    result.rays = own.rays;
    result.nonFiniteSamples = own.nonFinite;
    for (int r = 1; r < ranks; ++r) {
        result.rays += peers[size_t(r)].counters.rays;
        result.nonFiniteSamples += peers[size_t(r)].counters.nonFinite;
    }
    result.film = std::move(buffers.film);

    if (report) {
        report->ranks = ranks;
        report->items = items;
        report->spd = job.options.spd;
        report->seconds = result.renderSeconds;
        report->loads.assign(size_t(ranks), RankLoad{});
        RankLoad& mine = report->loads[0];
        mine.rank = 0;
        mine.host = job.mpi.host();
        mine.threads = renders ? local.threads() : 0;
        mine.items = localItems;
        mine.chunks = local.chunks();
        mine.busySeconds = local.busySeconds();
        mine.cpuSeconds = local.cpuSeconds();
        mine.finishSeconds = localFinish;
        mine.rays = own.rays.total();
        for (int r = 1; r < ranks; ++r) report->loads[size_t(r)] = peers[size_t(r)].load;
    }
    return result;
}

/// Ranks 1..N-1: ask for chunks, render them, send the items back.
RenderResult runWorker(const FrameJob& job, const std::atomic<bool>* cancel) {
    FrameBuffers buffers = job.frame.makeBuffers();
    const ItemCodec codec(job.frame, job.options);
    Transport net;
    // A request takes a round trip and a wake-up of rank 0's MPI thread (on a
    // loaded machine, milliseconds): two items per thread (+2) in reserve.
    LocalWorker local(job.frame, buffers, job.threads, 2 * job.threads + 2);
    const double heartbeat = std::min(1.0, job.timeout / 4);
    bool requested = false, noMore = false, aborted = false;
    auto lastSent = job.start, lastHeard = job.start;
    RankLoad load;
    load.rank = job.mpi.rank();
    load.host = job.mpi.host();
    load.threads = local.threads();

    const auto finish = [&](bool cancelled) {
        local.stopAndWait();
        const WorkCounters counters = local.counters();
        load.chunks = local.chunks();
        load.busySeconds = local.busySeconds();
        load.cpuSeconds = local.cpuSeconds();
        std::vector<unsigned char> msg = header(job.epoch);
        appendLoad(load, cancelled, msg);
        appendCounters(counters, msg);
        net.post(0, kTagDone, std::move(msg));
        if (!net.flush(job.timeout))
            throw std::runtime_error(rankName(job.mpi.rank(), job.mpi.host()) +
                                     ": rank 0 did not take the final message within " +
                                     std::to_string(int(job.timeout)) + " s");
        RenderResult result;
        result.cancelled = cancelled;
        result.rays = counters.rays;
        result.nonFiniteSamples = counters.nonFinite;
        result.renderSeconds = secondsSince(job.start);
        return result;
    };

    for (;;) {
        bool active = false;
        int tag = 0, size = 0;
        while (net.probe(0, tag, size)) {
            active = true;
            const std::vector<unsigned char> msg = net.receive(0, tag, size);
            lastHeard = Clock::now();
            ByteReader in(msg.data(), msg.size());
            const int32_t epoch = in.get<int32_t>();
            if (epoch < job.epoch) continue;  // an abort that crossed our last DONE
            if (epoch > job.epoch)
                throw std::runtime_error("rank 0 is on frame " + std::to_string(epoch) + ", " +
                                         rankName(job.mpi.rank(), "") + " on frame " +
                                         std::to_string(job.epoch));
            if (tag == kTagAssign) {
                const int begin = in.get<int32_t>(), count = in.get<int32_t>();
                requested = false;
                if (count == 0) {
                    noMore = true;
                } else {
                    local.submit(job.chunkItems(begin, count));
                    if (job.fault.kill) std::raise(SIGKILL);
                    if (job.fault.stall)
                        for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
                }
            } else if (tag == kTagAbort) {
                aborted = true;
            } else {
                throw std::runtime_error("unexpected message (tag " + std::to_string(tag) +
                                         ") from rank 0");
            }
        }

        // Idle is read before collecting: every item finished by then is collected now.
        const bool wasIdle = local.idle();
        const std::vector<int> done = local.takeDone();
        if (!done.empty()) {
            std::vector<unsigned char> msg = header(job.epoch);
            for (int item : done) codec.append(item, buffers, msg);
            load.items += done.size();
            load.bytesSent += msg.size();
            net.post(0, kTagResult, std::move(msg));
            lastSent = Clock::now();
            active = true;
        }
        try {
            local.rethrowIfFailed();
        } catch (const std::exception& e) {
            throw std::runtime_error(rankName(job.mpi.rank(), job.mpi.host()) + ": " + e.what());
        }
        if (aborted || (cancel && cancel->load())) return finish(true);
        if (noMore && wasIdle && done.empty()) return finish(false);
        if (!noMore && !requested && local.wantsMore()) {
            net.post(0, kTagRequest, header(job.epoch));
            requested = true;
            lastSent = Clock::now();
        }
        if (secondsSince(lastSent) > heartbeat) {
            net.post(0, kTagHeartbeat, header(job.epoch));
            lastSent = Clock::now();
        }
        if (requested && secondsSince(lastHeard) > job.timeout) {
            char msg[256];
            std::snprintf(msg, sizeof msg,
                          "%s: rank 0 has not answered for %g s (limit: RAYLAB_MPI_TIMEOUT)",
                          rankName(job.mpi.rank(), job.mpi.host()).c_str(), job.timeout);
            throw std::runtime_error(msg);
        }
        net.progress();
        if (!active) std::this_thread::sleep_for(kPollInterval);
    }
}

}  // namespace

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
                 faultFor(mpi.rank()),
                 scatteredOrder(frame.workItemCount()),
                 Clock::now()};
    // The render threads plus this (mostly sleeping) MPI thread.
    const tbb::global_control threadLimit(tbb::global_control::max_allowed_parallelism,
                                          size_t(job.threads) + 1);
    return mpi.isRoot() ? runRoot(job, progress, cancel, report) : runWorker(job, cancel);
}

#endif  // RAYLAB_HAVE_MPI

}  // namespace raylab

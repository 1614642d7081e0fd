// Rank 0 of a distributed frame (docs/distributed.md): it keeps the work
// queue, answers the workers from this thread while its own render threads
// pull chunks straight from the queue, and assembles the frame from the items
// that come back, each exactly once.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "distributed/config.h"
#include "distributed/frame_job.h"
#include "distributed/item_codec.h"
#include "distributed/local_worker.h"
#include "distributed/protocol.h"
#include "distributed/transport.h"
#include "distributed/work_schedule.h"
#include "renderer/timing.h"

namespace raylab {

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

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

    // Rank 0's finished items, and its render threads' first error.
    const auto collectLocal = [&] {
        bool any = false;
        for (int item : local.takeDone()) {
            accept(item, 0);
            ++localItems;
            localFinish = secondsSince(job.start);
            any = true;
        }
        try {
            local.rethrowIfFailed();
        } catch (const std::exception& e) {
            throw std::runtime_error(rankName(0, job.mpi.host()) + ": " + e.what());
        }
        return any;
    };

    for (;;) {
        bool active = collectLocal();
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
                    std::vector<unsigned char> reply = messageHeader(job.epoch);
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
                if (!peers[size_t(r)].finished) net.post(r, kTagAbort, messageHeader(job.epoch));
        }
        if (allFinished && local.idle()) {
            // Collected again after idle() was read: an item rank 0 finished
            // since the top of this pass is in the done list now (it is
            // listed before it stops counting as in flight), and would
            // otherwise look lost.
            collectLocal();
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
    WorkCounters sum = own;
    for (int r = 1; r < ranks; ++r) sum += peers[size_t(r)].counters;
    result.setCounters(sum);
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

}  // namespace raylab

// Ranks 1..N-1 of a distributed frame (docs/distributed.md): ask rank 0 for
// chunks before running dry, render them on the local TBB arena, send the
// finished items back byte for byte, and keep rank 0 informed (heartbeats)
// while a long chunk renders.

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
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
#include "renderer/timing.h"

namespace raylab {

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

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
        std::vector<unsigned char> msg = messageHeader(job.epoch);
        appendLoad(load, cancelled, msg);
        appendCounters(counters, msg);
        net.post(0, kTagDone, std::move(msg));
        if (!net.flush(job.timeout))
            throw std::runtime_error(rankName(job.mpi.rank(), job.mpi.host()) +
                                     ": rank 0 did not take the final message within " +
                                     std::to_string(int(job.timeout)) + " s");
        RenderResult result;
        result.cancelled = cancelled;
        result.setCounters(counters);
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
                    job.fault.strike();
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
            std::vector<unsigned char> msg = messageHeader(job.epoch);
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
            net.post(0, kTagRequest, messageHeader(job.epoch));
            requested = true;
            lastSent = Clock::now();
        }
        if (secondsSince(lastSent) > heartbeat) {
            net.post(0, kTagHeartbeat, messageHeader(job.epoch));
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

}  // namespace raylab

#include "distributed/rank_agreement.h"

#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "distributed/config.h"
#include "distributed/protocol.h"
#include "distributed/transport.h"
#include "renderer/timing.h"

namespace raylab {

namespace {

/// Waits for the next message from `source`, which must have tag `tag`;
/// `silence` names the waiting side's complaint when `timeout` passes first.
std::vector<unsigned char> await(Transport& net, int source, int tag, double timeout,
                                 const std::string& silence) {
    const auto t0 = std::chrono::steady_clock::now();
    for (;;) {
        int got = 0, size = 0;
        if (net.probe(source, got, size)) {
            if (got != tag)
                throw std::runtime_error("unexpected message (tag " + std::to_string(got) +
                                         ") from " + rankName(source, "") +
                                         " before the first frame");
            std::vector<unsigned char> msg = net.receive(source, got, size);
            ByteReader in(msg.data(), msg.size());
            if (in.get<int32_t>() != 0)
                throw std::runtime_error(rankName(source, "") +
                                         " is rendering a frame before the ranks agreed");
            return msg;
        }
        net.progress();
        if (secondsSince(t0) > timeout)
            throw std::runtime_error(silence + " for " + std::to_string(int(timeout)) +
                                     " s before the first frame (limit: RAYLAB_MPI_TIMEOUT)");
        std::this_thread::sleep_for(kPollInterval);
    }
}

}  // namespace

std::string compareRanks(const MpiSession& mpi, const RenderIdentity& mine) {
    if (!mpi.active() || mpi.size() == 1) return "";
    const double timeout = timeoutSeconds();
    Transport net;
    if (!mpi.isRoot()) {
        std::vector<unsigned char> msg = messageHeader(0);
        appendIdentity(mine, mpi.host(), msg);
        net.post(0, kTagIdentity, std::move(msg));
        const std::vector<unsigned char> answer =
            await(net, 0, kTagVerdict, timeout,
                  rankName(mpi.rank(), mpi.host()) + ": rank 0 has not answered");
        net.flush(timeout);  // rank 0 has our identity: already delivered
        ByteReader in(answer.data(), answer.size());
        (void)in.get<int32_t>();  // the epoch, checked by await
        return in.getString();
    }
    // Every rank is heard before the verdict, so none is left waiting.
    std::string verdict;
    for (int r = 1; r < mpi.size(); ++r) {
        const std::vector<unsigned char> msg =
            await(net, r, kTagIdentity, timeout, rankName(r, "") + " sent nothing");
        ByteReader in(msg.data(), msg.size());
        (void)in.get<int32_t>();  // the epoch, checked by await
        std::string host;
        const RenderIdentity theirs = readIdentity(in, host);
        if (verdict.empty()) verdict = disagreement(mine, theirs, rankName(r, host));
    }
    for (int r = 1; r < mpi.size(); ++r) {
        std::vector<unsigned char> msg = messageHeader(0);
        ByteWriter(msg).putString(verdict);
        net.post(r, kTagVerdict, std::move(msg));
    }
    if (!net.flush(timeout))
        throw std::runtime_error("the ranks' verdict was not delivered within " +
                                 std::to_string(int(timeout)) + " s");
    return verdict;
}

}  // namespace raylab

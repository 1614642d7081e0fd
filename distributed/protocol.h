#pragma once
// The messages between rank 0 and the other ranks (docs/distributed.md, "How
// a frame is shared"). Every message starts with the frame's epoch (the
// number of renderDistributed calls so far), so a message from another frame
// is caught (the rank agreement before the first frame uses epoch 0); the
// item data itself is encoded by item_codec.h.

#include <cstdint>
#include <string>
#include <vector>

#include "distributed/byte_buffer.h"
#include "distributed/load_report.h"
#include "distributed/render_identity.h"

namespace raylab {

/// MPI tags of the messages.
enum MessageTag : int {
    kTagRequest = 0x5241,  ///< worker -> 0: more work, please
    kTagAssign,            ///< 0 -> worker: chunk {begin, count}; count 0 = no more work
    kTagResult,            ///< worker -> 0: finished items (item_codec.h)
    kTagDone,              ///< worker -> 0: all its items sent; its load and counters
    kTagHeartbeat,         ///< worker -> 0: still alive, rendering a long chunk
    kTagAbort,             ///< 0 -> worker: the render was cancelled, stop
    kTagIdentity,          ///< worker -> 0, before the first frame: what it renders
    kTagVerdict,           ///< 0 -> worker: "" when every rank agrees, else what differs
};

/// A new message: its epoch, to which the body is appended.
std::vector<unsigned char> messageHeader(int32_t epoch);

/// Appends the part of a DONE message that describes the rank's work.
void appendLoad(const RankLoad& load, bool cancelled, std::vector<unsigned char>& out);

/// Reads what appendLoad wrote (rank, finish time and rays are not sent).
RankLoad readLoad(ByteReader& in, bool& cancelled);

/// Appends what a rank renders (render_identity.h) and its host name.
void appendIdentity(const RenderIdentity& identity, const std::string& host,
                    std::vector<unsigned char>& out);

/// Reads what appendIdentity wrote.
RenderIdentity readIdentity(ByteReader& in, std::string& host);

/// "rank 3" or "rank 3 (host)", for messages.
std::string rankName(int rank, const std::string& host);

}  // namespace raylab

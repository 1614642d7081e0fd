#include "distributed/protocol.h"

namespace raylab {

std::vector<unsigned char> messageHeader(int32_t epoch) {
    std::vector<unsigned char> bytes;
    ByteWriter(bytes).put(epoch);
    return bytes;
}

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

void appendIdentity(const RenderIdentity& id, const std::string& host,
                    std::vector<unsigned char>& out) {
    ByteWriter w(out);
    w.putString(id.scene);
    w.put(id.files);
    w.put(id.bytes);
    w.put(id.sceneHash);
    w.putString(id.settings);
    w.putString(host);
}

RenderIdentity readIdentity(ByteReader& in, std::string& host) {
    RenderIdentity id;
    id.scene = in.getString();
    id.files = in.get<uint32_t>();
    id.bytes = in.get<uint64_t>();
    id.sceneHash = in.get<uint64_t>();
    id.settings = in.getString();
    host = in.getString();
    return id;
}

std::string rankName(int rank, const std::string& host) {
    return "rank " + std::to_string(rank) + (host.empty() ? "" : " (" + host + ")");
}

}  // namespace raylab

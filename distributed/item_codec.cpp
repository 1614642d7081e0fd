#include "distributed/item_codec.h"

#include <cassert>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "renderer/matte_coverage.h"

namespace raylab {

namespace {

// Per pixel: the first-hit AOV layers: z (1) + distance (1) + normal (3) +
// albedo (3) + objectId (1) floats.
constexpr size_t kAovBytes = 9 * sizeof(float);
// A tile's pixel: rgba (4 floats), the AOV layers and the film's Cryptomatte
// ranks (matteRanksOfSampling, as every rank's film has them).
size_t pixelBytes(int matteRanks) {
    return 4 * sizeof(float) + kAovBytes + size_t(matteRanks) * sizeof(MatteEntry);
}
// Per corner: colour (3 doubles), hit (1 byte), object id (int32: the root
// derives the pixels' Cryptomatte coverage from the corners, as it does their
// colour). An SPD item (corner row y) also carries the AOV layers of pixel
// row y, which its corners wrote.
constexpr size_t kCornerBytes = 3 * 8 + 1 + 4;

/// Writes into bytes already allocated: one resize per item instead of one
/// per value (the codec runs on the MPI thread, between messages).
class SpanWriter {
public:
    explicit SpanWriter(unsigned char* p) : m_p(p) {}
    template <class T>
    void put(const T& v) {
        std::memcpy(m_p, &v, sizeof(T));
        m_p += sizeof(T);
    }
    void putBytes(const void* src, size_t n) {
        std::memcpy(m_p, src, n);
        m_p += n;
    }
    const unsigned char* position() const { return m_p; }

private:
    unsigned char* m_p;
};

}  // namespace

ItemCodec::ItemCodec(const FrameRenderer& frame, const RenderOptions& options)
    : m_frame(frame), m_spd(options.spd), m_matteRanks(matteRanksOfSampling(options)),
      m_window(cropPixels(options.crop, options.width, options.height)) {
    // Every message carries the AOV layers: a film without them has none to
    // send or to receive into (render keeps them under mpirun).
    if (!options.wantAovs)
        throw std::logic_error("distributed rendering needs the AOV layers (RenderOptions::wantAovs)");
}

size_t ItemCodec::payloadBytes(int item) const {
    const WorkRegion r = m_frame.region(item);
    const size_t n = size_t(r.x1 - r.x0) * size_t(r.y1 - r.y0);
    if (!m_spd) return n * pixelBytes(m_matteRanks);
    return n * kCornerBytes + size_t(aovPixels(r)) * kAovBytes;
}

int ItemCodec::aovPixels(const WorkRegion& r) const {
    // Corner row y < y1 is the top edge of pixel row y, whose AOVs it wrote.
    return r.y0 < m_window.y1 ? m_window.width() : 0;
}

size_t ItemCodec::itemBytes(int item) const { return sizeof(int32_t) + payloadBytes(item); }

void ItemCodec::append(int item, const FrameBuffers& from, std::vector<unsigned char>& out) const {
    const WorkRegion r = m_frame.region(item);
    const size_t at = out.size();
    out.resize(at + itemBytes(item));
    SpanWriter w(out.data() + at);
    w.put(int32_t(item));
    const Film& f = from.film;
    const auto putAovs = [&](size_t i) {
        w.putBytes(&f.z[i], sizeof(float));
        w.putBytes(&f.distance[i], sizeof(float));
        w.putBytes(&f.normal[3 * i], 3 * sizeof(float));
        w.putBytes(&f.albedo[3 * i], 3 * sizeof(float));
        w.putBytes(&f.objectId[i], sizeof(float));
    };
    if (m_spd) {
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1; ++x) {
                const CornerSample& s = from.corner(x, y);
                w.put(s.c.r);
                w.put(s.c.g);
                w.put(s.c.b);
                w.put(uint8_t(s.hit ? 1 : 0));
                w.put(s.objectId);
            }
        }
        for (int x = 0; x < aovPixels(r); ++x) putAovs(f.index(m_window.x0 + x, r.y0));
        assert(w.position() == out.data() + out.size());
        return;
    }
    for (int y = r.y0; y < r.y1; ++y) {
        for (int x = r.x0; x < r.x1; ++x) {
            const size_t i = f.index(x, y);
            w.putBytes(&f.rgba[4 * i], 4 * sizeof(float));
            putAovs(i);
            w.putBytes(f.mattesOf(i), size_t(m_matteRanks) * sizeof(MatteEntry));
        }
    }
    assert(w.position() == out.data() + out.size());
}

void ItemCodec::extract(ByteReader& in, FrameBuffers& to, std::vector<int>& items) const {
    while (!in.done()) {
        const int item = in.get<int32_t>();
        if (item < 0 || item >= m_frame.workItemCount())
            throw std::runtime_error("message names work item " + std::to_string(item) +
                                     " of a frame with " +
                                     std::to_string(m_frame.workItemCount()));
        // Check the whole item first: a truncated message changes nothing.
        if (in.left() < payloadBytes(item)) throw std::runtime_error("message is truncated");
        const WorkRegion r = m_frame.region(item);
        Film& f = to.film;
        const auto getAovs = [&](size_t i) {
            in.getBytes(&f.z[i], sizeof(float));
            in.getBytes(&f.distance[i], sizeof(float));
            in.getBytes(&f.normal[3 * i], 3 * sizeof(float));
            in.getBytes(&f.albedo[3 * i], 3 * sizeof(float));
            in.getBytes(&f.objectId[i], sizeof(float));
        };
        if (m_spd) {
            for (int y = r.y0; y < r.y1; ++y) {
                for (int x = r.x0; x < r.x1; ++x) {
                    CornerSample& s = to.corner(x, y);
                    s.c.r = in.get<double>();
                    s.c.g = in.get<double>();
                    s.c.b = in.get<double>();
                    s.hit = in.get<uint8_t>() != 0;
                    s.objectId = in.get<int32_t>();
                }
            }
            for (int x = 0; x < aovPixels(r); ++x) getAovs(f.index(m_window.x0 + x, r.y0));
        } else {
            for (int y = r.y0; y < r.y1; ++y) {
                for (int x = r.x0; x < r.x1; ++x) {
                    const size_t i = f.index(x, y);
                    in.getBytes(&f.rgba[4 * i], 4 * sizeof(float));
                    getAovs(i);
                    in.getBytes(f.mattesOf(i), size_t(m_matteRanks) * sizeof(MatteEntry));
                }
            }
        }
        items.push_back(item);
    }
}

void appendCounters(const WorkCounters& c, std::vector<unsigned char>& out) {
    ByteWriter w(out);
    for (const auto& perType : c.rays.byDepth)
        for (uint64_t n : perType) w.put(n);
    w.put(c.rays.cameraHits);
    w.put(c.nonFinite);
    w.put(c.cappedSamples);
    w.put(c.maxSampleRays);
}

WorkCounters readCounters(ByteReader& in) {
    WorkCounters c;
    for (auto& perType : c.rays.byDepth)
        for (uint64_t& n : perType) n = in.get<uint64_t>();
    c.rays.cameraHits = in.get<uint64_t>();
    c.nonFinite = in.get<uint64_t>();
    c.cappedSamples = in.get<uint64_t>();
    c.maxSampleRays = in.get<uint64_t>();
    return c;
}

}  // namespace raylab

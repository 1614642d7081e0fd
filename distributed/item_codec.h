#pragma once
// The bytes a rank sends rank 0 for finished work items: the pixels of a
// tile, or in SPD mode a row of corner samples with the AOV layers of the
// pixel row below it, and the rank's ray counters.
// Every float and double is copied bit for bit, so the gathered frame is
// bit-identical to one rendered in a single process (no text, no rounding).

#include <cstddef>
#include <vector>

#include "distributed/byte_buffer.h"
#include "renderer/render.h"

namespace raylab {

class ItemCodec {
public:
    /// Items of `frame`, rendered with `options` (SPD mode decides the layout).
    ItemCodec(const FrameRenderer& frame, const RenderOptions& options);

    /// Bytes of item `item` in a message, its number included (edge tiles are smaller).
    size_t itemBytes(int item) const;

    /// Appends item `item` of `from` (a rendered item) to `out`.
    void append(int item, const FrameBuffers& from, std::vector<unsigned char>& out) const;

    /// Copies every item encoded in the rest of `in` into `to` and appends
    /// their numbers to `items`. Throws std::runtime_error on malformed data
    /// (an item number out of range, a truncated message).
    void extract(ByteReader& in, FrameBuffers& to, std::vector<int>& items) const;

private:
    size_t payloadBytes(int item) const;
    /// SPD items: pixels of the film row whose AOV layers travel with region r
    /// (from m_window.x0 on).
    int aovPixels(const WorkRegion& r) const;

    const FrameRenderer& m_frame;
    bool m_spd;
    int m_matteRanks;  ///< Film::matteRanks of every rank's film
    PixelWindow m_window;  ///< the pixels of the frame (the crop window, or the whole image)
};

/// Appends every counter of `c` (ray counts per type and depth, camera hits,
/// non-finite samples) to `out`.
void appendCounters(const WorkCounters& c, std::vector<unsigned char>& out);

/// Reads counters written by appendCounters.
WorkCounters readCounters(ByteReader& in);

}  // namespace raylab

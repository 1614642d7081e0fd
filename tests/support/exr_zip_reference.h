#pragma once
// Tests' bridge from OpenEXR's types to raylab's own EXR writer: an
// Imf::Header as an ExrHeader (each attribute with the bytes its own
// writeValueTo writes) and encodeExrZipFile for an Imf::FrameBuffer, so a
// test can build one image with OpenEXR and compare raylab's file with
// OpenEXR's. Tests link OpenEXR; raylab itself loads it only for what it
// does not write itself (renderer/io/exr_module.h).

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStdIO.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/io/exr_header.h"
#include "renderer/io/exr_zip_file.h"

namespace raylab::test {

/// \throws std::logic_error for a tiled or multi-part header, a subsampled
///         or perceptually linear channel; Iex errors when OpenEXR's own
///         sanityCheck refuses it.
inline ExrHeader exrHeaderOf(const Imf::Header& header) {
    if (header.hasTileDescription() || header.hasType())
        throw std::logic_error("exrHeaderOf: only single-part scan-line images");
    header.sanityCheck();
    const auto box = [](const Imath::Box2i& b) { return ExrBox{b.min.x, b.min.y, b.max.x, b.max.y}; };
    ExrHeader out(box(header.displayWindow()), box(header.dataWindow()));
    out.setCompression(ExrCompressionId(header.compression()));
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        const Imf::Channel& channel = it.channel();
        if (channel.xSampling != 1 || channel.ySampling != 1 || channel.pLinear)
            throw std::logic_error(std::string("exrHeaderOf: channel ") + it.name() +
                                   " is subsampled or perceptually linear");
        out.addChannel(it.name(), ExrPixelType(channel.type));
    }
    for (auto it = header.begin(); it != header.end(); ++it) {
        if (std::strcmp(it.name(), "channels") == 0) continue;
        Imf::StdOSStream os;
        it.attribute().writeValueTo(os, 2);
        out.setAttribute(it.name(), it.attribute().typeName(), os.str());
    }
    return out;
}

/// The bytes raylab's ZIP writer writes for `header` with the pixels of
/// `frameBuffer`: every channel needs a slice of its own type and sampling
/// 1x1, or none (zeros, as Imf::OutputFile writes).
inline std::string encodeExrZipFile(const Imf::Header& header, const Imf::FrameBuffer& frameBuffer,
                                    int threads) {
    const ExrHeader own = exrHeaderOf(header);
    const ExrBox& dw = own.dataWindow();
    std::vector<ExrChannelSource> sources;
    for (const ExrHeader::Channel& channel : own.channels()) {
        ExrChannelSource source;
        source.size = exrPixelTypeSize(channel.type);
        if (const Imf::Slice* slice = frameBuffer.findSlice(channel.name)) {
            if (ExrPixelType(slice->type) != channel.type || slice->xSampling != 1 ||
                slice->ySampling != 1)
                throw std::logic_error("encodeExrZipFile: the slice of channel " + channel.name +
                                       " has another type or sampling");
            source.base = slice->base + ptrdiff_t(dw.xMin) * ptrdiff_t(slice->xStride) +
                          ptrdiff_t(dw.yMin) * ptrdiff_t(slice->yStride);
            source.xStride = ptrdiff_t(slice->xStride);
            source.yStride = ptrdiff_t(slice->yStride);
        }
        sources.push_back(source);
    }
    return raylab::encodeExrZipFile(own, sources, threads);
}

}  // namespace raylab::test

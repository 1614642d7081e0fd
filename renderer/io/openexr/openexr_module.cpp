// raylab's OpenEXR module (see renderer/io/exr_module.h): the only source of
// raylab that includes OpenEXR, built as raylab-openexr.so and loaded on
// first use. Every entry point catches everything: nothing may be thrown
// across the dlopen boundary.

#include <OpenEXR/ImfAttribute.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <climits>
#include <exception>
#include <memory>
#include <new>
#include <string>

#include "renderer/io/exr_module.h"
#include "renderer/io/module_failure.h"

namespace {

using namespace raylab::exr_module;

/// An EXR string attribute that OpenEXR writes in one piece. Imf::StringAttribute
/// reads and writes its value one character at a time (about 130
/// instructions a character): 25-28 M for balls.nff's 185 kB Cryptomatte
/// manifest at every write (docs/benchmarks.md, bar 3). The same bytes: the
/// type is "string", the value its characters with no terminator.
class OnePieceString final : public Imf::StringAttribute {
public:
    explicit OnePieceString(const std::string& value) : Imf::StringAttribute(value) {}
    Imf::Attribute* copy() const override { return new OnePieceString(value()); }
    void writeValueTo(Imf::OStream& os, int /*version*/) const override {
        const std::string& s = value();
        for (size_t at = 0; at < s.size();) {  // OStream::write takes an int count
            const size_t n = std::min(s.size() - at, size_t(INT_MAX));
            os.write(s.data() + at, int(n));
            at += n;
        }
    }
};

/// raylab's header as OpenEXR's: each attribute's value read by OpenEXR's
/// own readValueFrom, but a string taken whole (Imf::StringAttribute would
/// read the manifest a character at a time, and write it so); the channels
/// are the slices'.
Imf::Header headerOf(const WriteRequest& request) {
    Imf::Header header;
    for (const raylab::ExrAttribute& a : request.attributes) {
        if (a.typeName == "string") {
            header.insert(a.name, OnePieceString(a.value));
            continue;
        }
        std::unique_ptr<Imf::Attribute> value(Imf::Attribute::newAttribute(a.typeName.c_str()));
        Imf::StdISStream is;
        is.str(a.value);
        value->readValueFrom(is, int(a.value.size()), 2);
        header.insert(a.name, *value);
    }
    for (const Slice& s : request.slices)
        header.channels().insert(s.name, Imf::Channel(Imf::PixelType(s.type)));
    return header;
}

void insert(Imf::FrameBuffer& fb, const Slice& s, const Imath::Box2i& dataWindow) {
    fb.insert(s.name, Imf::Slice::Make(Imf::PixelType(s.type), s.origin, dataWindow,
                                       size_t(s.xStride), size_t(s.yStride), 1, 1, s.fill));
}

bool write(const WriteRequest& request, std::string& error) {
    try {
        // raylab's header, each value read by OpenEXR itself: the file carries
        // exactly the attributes raylab's own ZIP writer would write.
        const Imf::Header header = headerOf(request);
        const Imath::Box2i& dw = header.dataWindow();
        Imf::FrameBuffer fb;
        for (const Slice& s : request.slices) insert(fb, s, dw);
        // OpenEXR runs compression tasks on its global pool (empty by
        // default: everything on the calling thread); the per-file count alone
        // adds no workers.
        if (Imf::globalThreadCount() < request.threads) Imf::setGlobalThreadCount(request.threads);
        // Closed (offset table written) when it goes out of scope.
        Imf::OutputFile file(request.path.c_str(), header, request.blocksInFlight);
        file.setFrameBuffer(fb);
        file.writePixels(dw.max.y - dw.min.y + 1);
        return true;
    } catch (...) {
        error = raylab::describeFailure(std::current_exception());
        return false;
    }
}

bool read(const std::string& path, const SlicesFor& slicesFor, std::string& error) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        ReadInfo info;
        const Imath::Box2i& dw = header.dataWindow();
        const Imath::Box2i& display = header.displayWindow();
        const int32_t d[4] = {dw.min.x, dw.min.y, dw.max.x, dw.max.y};
        const int32_t s[4] = {display.min.x, display.min.y, display.max.x, display.max.y};
        std::copy(d, d + 4, info.dataWindow);
        std::copy(s, s + 4, info.displayWindow);
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
            info.channels.push_back(it.name());
        const std::vector<Slice> slices = slicesFor(info);
        if (slices.empty()) return true;
        Imf::FrameBuffer fb;
        for (const Slice& slice : slices) insert(fb, slice, dw);
        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return true;
    } catch (...) {
        error = raylab::describeFailure(std::current_exception());
        return false;
    }
}

const Api kApi{kVersion, &write, &read};

}  // namespace

extern "C" __attribute__((visibility("default"))) const Api* raylab_exr_module_v1() { return &kApi; }

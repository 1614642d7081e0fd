// raylab's OpenEXR module (see renderer/io/exr_module.h): the only source of
// raylab that includes OpenEXR, built as raylab-openexr.so and loaded on
// first use. Every entry point catches everything: nothing may be thrown
// across the dlopen boundary.

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <exception>
#include <new>
#include <string>

#include "renderer/io/exr_module.h"

namespace {

using namespace raylab::exr_module;

std::string describe(const std::exception_ptr& p) {
    try {
        std::rethrow_exception(p);
    } catch (const std::bad_alloc&) {
        return "out of memory";
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown failure";
    }
}

void insert(Imf::FrameBuffer& fb, const Slice& s, const Imath::Box2i& dataWindow) {
    fb.insert(s.name, Imf::Slice::Make(Imf::PixelType(s.type), s.origin, dataWindow,
                                       size_t(s.xStride), size_t(s.yStride), 1, 1, s.fill));
}

bool write(const WriteRequest& request, std::string& error) {
    try {
        // raylab's header bytes, read by OpenEXR itself: the file carries
        // exactly the attributes raylab's own ZIP writer would write.
        Imf::StdISStream is;
        is.str(request.header);
        Imf::Header header;
        int version = request.versionField;
        header.readFrom(is, version);
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
        error = describe(std::current_exception());
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
        error = describe(std::current_exception());
        return false;
    }
}

const Api kApi{kVersion, &write, &read};

}  // namespace

extern "C" __attribute__((visibility("default"))) const Api* raylab_exr_module_v1() { return &kApi; }

// raylab's ZIP/ZIPS writer (igzip) against OpenEXR's own Imf::OutputFile:
// the same header bytes, the same decoded values in every channel, blocks
// that do not shrink stored raw, bytes independent of the thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/exr_zip_file.h"
#include "support/exr_zip_reference.h"
#include "support/temp_dir.h"

using namespace raylab;
using raylab::test::encodeExrZipFile;
using raylab::test::exrHeaderOf;
using raylab::test::TempDir;

namespace {

/// OpenEXR's ZIP pre-pass as ImfZip.cpp writes it: reorder, then predictor.
std::vector<unsigned char> referencePrepass(const std::vector<unsigned char>& raw) {
    const size_t n = raw.size();
    std::vector<unsigned char> t(n);
    if (n == 0) return t;
    unsigned char* t1 = t.data();
    unsigned char* t2 = t.data() + (n + 1) / 2;
    const unsigned char* in = raw.data();
    const unsigned char* stop = raw.data() + n;
    while (true) {
        if (in < stop) *(t1++) = *(in++); else break;
        if (in < stop) *(t2++) = *(in++); else break;
    }
    unsigned char* p = t.data() + 1;
    int prev = p[-1];
    for (; p < t.data() + n; ++p) {
        const int d = int(p[0]) - prev + (128 + 256);
        prev = p[0];
        p[0] = static_cast<unsigned char>(d);
    }
    return t;
}

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

/// Pixels of a 37x35 crop (data window offset in a 41x45 display window):
/// HALF colour interleaved in fours, a FLOAT depth with a constant region and
/// a varied region, a UINT id, a FLOAT channel interleaved in threes, and a
/// channel with a long name; `noise` makes every byte random (blocks that
/// deflate cannot shrink).
struct TestImage {
    static constexpr int kMinX = 3, kMinY = 5, kW = 37, kH = 35;
    std::vector<Imath::half> rgba = std::vector<Imath::half>(size_t(kW * kH * 4));
    std::vector<float> depth = std::vector<float>(size_t(kW * kH));
    std::vector<uint32_t> ids = std::vector<uint32_t>(size_t(kW * kH));
    std::vector<float> normal = std::vector<float>(size_t(kW * kH * 3));
    std::vector<float> longNamed = std::vector<float>(size_t(kW * kH));
    Imf::Header header;
    Imf::FrameBuffer fb;

    TestImage(Imf::Compression compression, bool noise)
        : header(Imath::Box2i({0, 0}, {40, 44}),
                 Imath::Box2i({kMinX, kMinY}, {kMinX + kW - 1, kMinY + kH - 1})) {
        std::mt19937 rng(noise ? 7u : 11u);
        std::uniform_real_distribution<float> u(-2.0f, 2.0f);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const size_t i = size_t(y * kW + x);
                for (int c = 0; c < 4; ++c)
                    rgba[4 * i + size_t(c)] = noise ? Imath::half(u(rng)) : Imath::half(0.01f * float(x + c));
                depth[i] = noise || x > 20 ? 10.0f + u(rng) : 1e10f;
                ids[i] = noise ? uint32_t(rng()) : uint32_t(y / 7);
                for (int c = 0; c < 3; ++c) normal[3 * i + size_t(c)] = noise ? u(rng) : 0.5f * float(c);
                longNamed[i] = noise ? u(rng) : float(x * y);
            }
        if (noise) {  // random bits in every byte: nothing for deflate to find
            auto randomBytes = [&](auto& v) {
                auto* p = reinterpret_cast<unsigned char*>(v.data());
                for (size_t k = 0; k < v.size() * sizeof(v[0]); ++k) p[k] = (unsigned char)rng();
            };
            randomBytes(rgba), randomBytes(depth), randomBytes(ids), randomBytes(normal),
                randomBytes(longNamed);
        }
        header.compression() = compression;
        header.insert("a/very/long/attribute/name/of/forty/characters", Imf::IntAttribute(42));
        header.insert("software", Imf::StringAttribute("raylab test"));
        // One channel without a slice: written as zeros by both writers (not
        // beside the noise, whose blocks it would make compressible).
        if (!noise) header.channels().insert("unsliced", Imf::Channel(Imf::HALF));
        const char* rgbaNames[4] = {"R", "G", "B", "A"};
        const Imath::Box2i dw = header.dataWindow();
        for (int c = 0; c < 4; ++c) {
            header.channels().insert(rgbaNames[c], Imf::Channel(Imf::HALF));
            fb.insert(rgbaNames[c], Imf::Slice::Make(Imf::HALF, &rgba[size_t(c)], dw,
                                                     4 * sizeof(Imath::half),
                                                     4 * sizeof(Imath::half) * kW));
        }
        header.channels().insert("Z", Imf::Channel(Imf::FLOAT));
        fb.insert("Z", Imf::Slice::Make(Imf::FLOAT, depth.data(), dw, sizeof(float),
                                        sizeof(float) * kW));
        header.channels().insert("id", Imf::Channel(Imf::UINT));
        fb.insert("id", Imf::Slice::Make(Imf::UINT, ids.data(), dw, sizeof(uint32_t),
                                         sizeof(uint32_t) * kW));
        const char* normalNames[3] = {"N.X", "N.Y", "N.Z"};
        for (int c = 0; c < 3; ++c) {
            header.channels().insert(normalNames[c], Imf::Channel(Imf::FLOAT));
            fb.insert(normalNames[c], Imf::Slice::Make(Imf::FLOAT, &normal[size_t(c)], dw,
                                                       3 * sizeof(float), 3 * sizeof(float) * kW));
        }
        const char* longName = "a.channel.name.of.more.than.31.characters";
        header.channels().insert(longName, Imf::Channel(Imf::FLOAT));
        fb.insert(longName, Imf::Slice::Make(Imf::FLOAT, longNamed.data(), dw, sizeof(float),
                                             sizeof(float) * kW));
    }
};

/// Every channel of `path` as raw bytes per channel, decoded by OpenEXR.
std::vector<std::vector<char>> decodeAll(const std::string& path, int& version) {
    Imf::InputFile in(path.c_str());
    version = in.version();
    const Imath::Box2i dw = in.header().dataWindow();
    const size_t w = size_t(dw.max.x - dw.min.x + 1), h = size_t(dw.max.y - dw.min.y + 1);
    std::vector<std::vector<char>> planes;
    Imf::FrameBuffer fb;
    for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
        const size_t size = it.channel().type == Imf::HALF ? 2 : 4;
        planes.emplace_back(w * h * size);
        fb.insert(it.name(), Imf::Slice::Make(it.channel().type, planes.back().data(), dw, size,
                                              size * w));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return planes;
}

std::string headerBytes(const Imf::Header& header) {
    Imf::StdOSStream os;
    header.writeTo(os);
    return os.str();
}

}  // namespace

TEST_CASE("exr zip: the pre-pass by hand and against OpenEXR's reorder and predictor") {
    // 1 2 3 4 5 -> even bytes 1 3 5, odd 2 4 -> 1, 3-1+128, 5-3+128, 2-5+128, 4-2+128
    const std::vector<unsigned char> raw = {1, 2, 3, 4, 5};
    std::vector<unsigned char> out(5);
    exrZipPrepass(raw.data(), raw.size(), out.data());
    CHECK(out == std::vector<unsigned char>{1, 130, 130, 125, 130});

    std::mt19937 rng(3);
    std::vector<size_t> sizes;
    for (size_t n = 0; n <= 100; ++n) sizes.push_back(n);
    for (size_t n : {127u, 128u, 129u, 4095u, 4097u, 600001u}) sizes.push_back(n);
    for (size_t n : sizes) {
        std::vector<unsigned char> in(n);
        for (auto& b : in) b = (unsigned char)(rng() % 7 == 0 ? rng() : 200 + rng() % 3);
        std::vector<unsigned char> got(n);
        exrZipPrepass(in.data(), n, got.data());
        CAPTURE(n);
        CHECK(got == referencePrepass(in));
    }
}

TEST_CASE("exr zip: same header bytes and decoded values as Imf::OutputFile, any thread count") {
    TempDir dir;
    for (Imf::Compression compression : {Imf::ZIP_COMPRESSION, Imf::ZIPS_COMPRESSION})
        for (bool noise : {false, true}) {
            CAPTURE(int(compression));
            CAPTURE(noise);
            TestImage image(compression, noise);
            const std::string reference = (dir.path() / "openexr.exr").string();
            {
                Imf::OutputFile out(reference.c_str(), image.header);
                out.setFrameBuffer(image.fb);
                out.writePixels(TestImage::kH);
            }
            const std::string ours = (dir.path() / "raylab.exr").string();
            const std::string b = encodeExrZipFile(image.header, image.fb, 1);
            writeFileAtomically(ours, b);
            const std::string a = readAll(reference);
            CHECK(readAll(ours) == b);

            // Magic, version (with the long-names flag) and header: the same bytes.
            const size_t headerEnd = 8 + headerBytes(image.header).size();
            REQUIRE(a.size() > headerEnd);
            REQUIRE(b.size() > headerEnd);
            CHECK(a.compare(0, headerEnd, b, 0, headerEnd) == 0);
            int versionA = 0, versionB = 0;
            const auto planesA = decodeAll(reference, versionA);
            const auto planesB = decodeAll(ours, versionB);
            CHECK(versionB == versionA);
            CHECK((versionB & 0x400) != 0);  // the long names need the flag
            CHECK(planesB == planesA);

            // The chunks: one per 16 lines (ZIP) or line (ZIPS), in order,
            // each raw exactly when deflate would not have made it smaller.
            const int lines = compression == Imf::ZIP_COMPRESSION ? 16 : 1;
            const int blocks = (TestImage::kH + lines - 1) / lines;
            const size_t bytesPerLine = size_t(TestImage::kW) * (2 * (noise ? 4 : 5) + 4 * 6);
            int rawBlocks = 0;
            for (int k = 0; k < blocks; ++k) {
                uint64_t offset = 0;
                std::memcpy(&offset, b.data() + headerEnd + 8 * size_t(k), 8);
                REQUIRE(offset + 8 <= b.size());
                int32_t y = 0, size = 0;
                std::memcpy(&y, b.data() + offset, 4);
                std::memcpy(&size, b.data() + offset + 4, 4);
                CHECK(y == TestImage::kMinY + k * lines);
                const int blockLines = std::min(lines, TestImage::kH - k * lines);
                const size_t rawSize = bytesPerLine * size_t(blockLines);
                CHECK(size_t(size) <= rawSize);
                rawBlocks += size_t(size) == rawSize;
            }
            // Smooth pixels shrink; random bytes do not.
            CHECK(rawBlocks == (noise ? blocks : 0));

            for (int threads : {0, 2, 3}) CHECK(encodeExrZipFile(image.header, image.fb, threads) == b);
        }
}

TEST_CASE("exr zip: other compressions and unwritable paths are refused") {
    TestImage image(Imf::PIZ_COMPRESSION, false);
    TempDir dir;
    CHECK_THROWS(encodeExrZipFile(image.header, image.fb, 1));
    image.header.compression() = Imf::ZIP_COMPRESSION;
    CHECK_THROWS_AS(writeFileAtomically((dir.path() / "missing/folder/x.exr").string(),
                                        encodeExrZipFile(image.header, image.fb, 1)),
                    InputError);
}

TEST_CASE("exr zip: gatherExrLines lays out each line channel after channel, by hand") {
    // Two lines of width 2: a HALF channel interleaved with another (stride 4
    // bytes), a FLOAT channel packed, and a channel without values (zeros).
    const uint16_t halves[8] = {0x1111, 0xaaaa, 0x2222, 0xbbbb, 0x3333, 0xcccc, 0x4444, 0xdddd};
    const float floats[4] = {1.f, 2.f, 3.f, 4.f};
    std::vector<ExrChannelSource> sources(3);
    sources[0] = {reinterpret_cast<const char*>(halves), 2, 4, 8};
    sources[1] = {reinterpret_cast<const char*>(floats), 4, 4, 8};
    sources[2] = {nullptr, 2, 0, 0};
    std::vector<unsigned char> raw(2 * (2 * 2 + 2 * 4 + 2 * 2), 0xee);
    gatherExrLines(sources, 2, 2, raw.data());
    std::vector<unsigned char> expected;
    const auto append = [&](const void* p, size_t n) {
        const auto* b = static_cast<const unsigned char*>(p);
        expected.insert(expected.end(), b, b + n);
    };
    for (int y = 0; y < 2; ++y) {
        append(&halves[4 * y + 0], 2);
        append(&halves[4 * y + 2], 2);
        append(&floats[2 * y], 8);
        const uint16_t zeros[2] = {0, 0};
        append(zeros, 4);
    }
    CHECK(raw == expected);
}

TEST_CASE("exr zip: the streamed file is the bytes encodeExrZipFile returns, and errors are thrown") {
    TempDir dir;
    for (Imf::Compression compression : {Imf::ZIP_COMPRESSION, Imf::ZIPS_COMPRESSION}) {
        CAPTURE(int(compression));
        TestImage image(compression, false);
        const std::string expected = encodeExrZipFile(image.header, image.fb, 2);
        // The same pixels through writeExrZipFile's block callback.
        std::vector<ExrChannelSource> sources;
        const Imath::Box2i& dw = image.header.dataWindow();
        for (auto it = image.header.channels().begin(); it != image.header.channels().end(); ++it) {
            ExrChannelSource s;
            s.size = it.channel().type == Imf::HALF ? 2 : 4;
            if (const Imf::Slice* slice = image.fb.findSlice(it.name())) {
                s.base = slice->base + ptrdiff_t(dw.min.x) * ptrdiff_t(slice->xStride);
                s.xStride = ptrdiff_t(slice->xStride);
                s.yStride = ptrdiff_t(slice->yStride);
            }
            sources.push_back(s);
        }
        std::atomic<int> calls{0};
        const ExrBlockLines lines = [&](int y0, int y1, unsigned char* raw) {
            ++calls;
            std::vector<ExrChannelSource> block = sources;
            for (ExrChannelSource& s : block)
                if (s.base) s.base += ptrdiff_t(y0) * s.yStride;
            gatherExrLines(block, TestImage::kW, y1 - y0, raw);
        };
        for (int threads : {1, 2, 0}) {
            CAPTURE(threads);
            calls = 0;
            const std::string path = (dir.path() / "streamed.exr").string();
            writeExrZipFile(path, exrHeaderOf(image.header), lines, threads);
            CHECK(readAll(path) == expected);
            const int perBlock = compression == Imf::ZIP_COMPRESSION ? 16 : 1;
            CHECK(calls == (TestImage::kH + perBlock - 1) / perBlock);  // each block once
        }
        CHECK_THROWS_AS(writeExrZipFile((dir.path() / "missing/x.exr").string(), exrHeaderOf(image.header),
                                        lines, 1),
                        std::runtime_error);
        // A block callback's exception reaches the caller.
        const ExrBlockLines failing = [&](int y0, int, unsigned char*) {
            if (y0 > dw.min.y + 16) throw std::runtime_error("block failed");
        };
        CHECK_THROWS_WITH_AS(writeExrZipFile((dir.path() / "failing.exr").string(), exrHeaderOf(image.header),
                                             failing, 2),
                             "block failed", std::runtime_error);
    }
}

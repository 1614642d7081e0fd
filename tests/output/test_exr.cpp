#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include "renderer/cryptomatte_id.h"
#include "renderer/io/errors.h"
#include "renderer/io/exr_reader.h"
#include "renderer/io/exr_writer.h"
#include "support/temp_dir.h"

using namespace raylab;
using raylab::test::TempDir;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

/// 3x2 film with a different value in every channel of every pixel; pixel
/// (2, 1) is background (Z = distance = 1e10, objectId = -1, zero normal and albedo).
Film makeFilm() {
    Film f(3, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) {
            const size_t i = f.index(x, y);
            const float k = float(i);
            f.rgba[4 * i + 0] = 0.1f + 0.3f * k;  // 0.1 .. 1.6: mostly not half-exact
            f.rgba[4 * i + 1] = 0.2f * k;
            f.rgba[4 * i + 2] = 1000.123f + k;
            f.rgba[4 * i + 3] = 1.0f - 0.25f * k;
            if (x == 2 && y == 1) continue;  // background pixel keeps the Film defaults
            f.z[i] = 1.5f + 2.25f * k + 1e-3f;
            f.distance[i] = 1.75f + 2.25f * k + 1e-3f;
            f.normal[3 * i + 0] = 0.6f;
            f.normal[3 * i + 1] = -0.8f + 1e-7f * k;
            f.normal[3 * i + 2] = 0.0f;
            f.albedo[3 * i + 0] = 0.7f;
            f.albedo[3 * i + 1] = 0.05f * k;
            f.albedo[3 * i + 2] = 0.333f;
            f.objectId[i] = float(i * 7);
        }
    return f;
}

float viaHalf(float v) { return float(Imath::half(v)); }

ExrOptions makeOptions(bool floatPixels) {
    ExrOptions o;
    o.floatPixels = floatPixels;
    o.settings = "width=3 height=2 spp=4";
    o.software = "raylab 0.1.0";
    o.scenePath = "scenes/demo.json";
    o.accel = "embree";
    o.spp = 4;
    o.maxDepth = 5;
    return o;
}

std::map<std::string, Imf::PixelType> channelTypes(const std::string& path) {
    Imf::InputFile in(path.c_str());
    std::map<std::string, Imf::PixelType> types;
    for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it)
        types[it.name()] = it.channel().type;
    return types;
}

}  // namespace

TEST_CASE("exr: exact channel list, types, compression and header attributes") {
    TempDir dir;
    const std::string path = dir.file("img.exr");
    writeExr(path, makeFilm(), makeOptions(false));
    CHECK(dir.entries() == std::vector<std::string>{"img.exr"});  // no temporary left

    const std::map<std::string, Imf::PixelType> expected = {
        {"R", Imf::HALF},        {"G", Imf::HALF},        {"B", Imf::HALF},
        {"A", Imf::HALF},        {"Z", Imf::FLOAT},       {"N.X", Imf::FLOAT},
        {"N.Y", Imf::FLOAT},     {"N.Z", Imf::FLOAT},     {"albedo.R", Imf::HALF},
        {"albedo.G", Imf::HALF}, {"albedo.B", Imf::HALF}, {"objectId", Imf::FLOAT},
        {"distance", Imf::FLOAT},
        {"CryptoObject00.R", Imf::FLOAT}, {"CryptoObject00.G", Imf::FLOAT},
        {"CryptoObject00.B", Imf::FLOAT}, {"CryptoObject00.A", Imf::FLOAT},
        {"CryptoObject01.R", Imf::FLOAT}, {"CryptoObject01.G", Imf::FLOAT},
        {"CryptoObject01.B", Imf::FLOAT}, {"CryptoObject01.A", Imf::FLOAT},
        {"CryptoObject02.R", Imf::FLOAT}, {"CryptoObject02.G", Imf::FLOAT},
        {"CryptoObject02.B", Imf::FLOAT}, {"CryptoObject02.A", Imf::FLOAT}};
    CHECK(channelTypes(path) == expected);

    Imf::InputFile in(path.c_str());
    const Imf::Header& h = in.header();
    CHECK(h.compression() == Imf::ZIP_COMPRESSION);
    CHECK(h.dataWindow().min.x == 0);
    CHECK(h.dataWindow().min.y == 0);
    CHECK(h.dataWindow().max.x == 2);
    CHECK(h.dataWindow().max.y == 1);
    REQUIRE(h.findTypedAttribute<Imf::StringAttribute>("raylab/settings"));
    CHECK(h.typedAttribute<Imf::StringAttribute>("raylab/settings").value() ==
          "width=3 height=2 spp=4");
    CHECK(h.find("raylab/command") == h.end());  // never the raw command line
    REQUIRE(h.findTypedAttribute<Imf::StringAttribute>("software"));
    CHECK(h.typedAttribute<Imf::StringAttribute>("software").value() == "raylab 0.1.0");
    REQUIRE(h.findTypedAttribute<Imf::IntAttribute>("raylab/spp"));
    CHECK(h.typedAttribute<Imf::IntAttribute>("raylab/spp").value() == 4);
    REQUIRE(h.findTypedAttribute<Imf::IntAttribute>("raylab/maxDepth"));
    CHECK(h.typedAttribute<Imf::IntAttribute>("raylab/maxDepth").value() == 5);
    // Nothing run-dependent (such as a render time) is recorded.
    CHECK(h.find("raylab/renderSeconds") == h.end());
    REQUIRE(h.findTypedAttribute<Imf::StringAttribute>("raylab/scene"));
    CHECK(h.typedAttribute<Imf::StringAttribute>("raylab/scene").value() == "scenes/demo.json");
    REQUIRE(h.findTypedAttribute<Imf::StringAttribute>("raylab/accel"));
    CHECK(h.typedAttribute<Imf::StringAttribute>("raylab/accel").value() == "embree");
}

TEST_CASE("exr: --float-pixels switches only RGBA to FLOAT, empty scene/accel are omitted") {
    TempDir dir;
    const std::string path = dir.file("img.exr");
    ExrOptions o = makeOptions(true);
    o.scenePath.clear();
    o.accel.clear();
    writeExr(path, makeFilm(), o);
    const auto types = channelTypes(path);
    CHECK(types.size() == 25);
    for (const char* c : {"R", "G", "B", "A", "Z", "distance", "N.X", "N.Y", "N.Z", "objectId"})
        CHECK(types.at(c) == Imf::FLOAT);
    for (const char* c : {"albedo.R", "albedo.G", "albedo.B"}) CHECK(types.at(c) == Imf::HALF);
    Imf::InputFile in(path.c_str());
    CHECK(in.header().findTypedAttribute<Imf::StringAttribute>("raylab/scene") == nullptr);
    CHECK(in.header().findTypedAttribute<Imf::StringAttribute>("raylab/accel") == nullptr);
    CHECK(in.header().findTypedAttribute<Imf::StringAttribute>("raylab/settings"));
}

TEST_CASE("exr: values round-trip (FLOAT exact, HALF to the nearest half, background depth 1e10)") {
    TempDir dir;
    const Film src = makeFilm();
    for (bool floatPixels : {false, true}) {
        CAPTURE(floatPixels);
        const std::string path = dir.file(floatPixels ? "f.exr" : "h.exr");
        writeExr(path, src, makeOptions(floatPixels));
        const Film back = readExr(path);
        REQUIRE(back.width == 3);
        REQUIRE(back.height == 2);
        REQUIRE(back.rgba.size() == src.rgba.size());
        REQUIRE(back.z.size() == src.z.size());
        REQUIRE(back.distance.size() == src.distance.size());
        REQUIRE(back.normal.size() == src.normal.size());
        REQUIRE(back.albedo.size() == src.albedo.size());
        REQUIRE(back.objectId.size() == src.objectId.size());
        for (size_t i = 0; i < src.rgba.size(); ++i) {
            // HALF: the stored value is the half nearest to the input, which
            // widens back to float exactly; relative error <= 2^-11.
            const float expected = floatPixels ? src.rgba[i] : viaHalf(src.rgba[i]);
            CHECK(back.rgba[i] == expected);
            CHECK(std::fabs(back.rgba[i] - src.rgba[i]) <= std::fabs(src.rgba[i]) * 0x1p-11f);
        }
        for (size_t i = 0; i < src.z.size(); ++i) CHECK(back.z[i] == src.z[i]);
        for (size_t i = 0; i < src.distance.size(); ++i) CHECK(back.distance[i] == src.distance[i]);
        CHECK(back.z[src.index(2, 1)] == 1e10f);  // finite, as Blender writes it
        CHECK(back.distance[src.index(2, 1)] == 1e10f);
        for (size_t i = 0; i < src.normal.size(); ++i) CHECK(back.normal[i] == src.normal[i]);
        for (size_t i = 0; i < src.albedo.size(); ++i)
            CHECK(back.albedo[i] == viaHalf(src.albedo[i]));
        for (size_t i = 0; i < src.objectId.size(); ++i)
            CHECK(back.objectId[i] == src.objectId[i]);
        CHECK(back.objectId[src.index(2, 1)] == -1.f);
    }
    // 0.1f is not representable in half: make sure the HALF path really rounded.
    CHECK(viaHalf(0.1f) != 0.1f);
}

TEST_CASE("exr: out-of-range and non-finite colour is clamped, never Inf or NaN") {
    TempDir dir;
    Film f(2, 2);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // Pixel 0: above half range, +inf, NaN, below -half range.
    f.rgba[0] = 1e6f;
    f.rgba[1] = kInf;
    f.rgba[2] = nan;
    f.rgba[3] = -1e6f;
    // Pixel 1: 65519 rounds to 65504 in half, 65520 would round to Inf without the clamp.
    f.rgba[4] = 65519.f;
    f.rgba[5] = 65520.f;
    f.rgba[6] = 65504.f;
    f.rgba[7] = 1.f;
    f.albedo[0] = 1e9f;  // albedo is HALF too
    f.normal[0] = nan;   // FLOAT layers: NaN -> 0
    f.z[3] = nan;        // Z: NaN or Inf means "no hit" -> 1e10
    f.distance[2] = kInf;

    writeExr(dir.file("h.exr"), f, makeOptions(false));
    const Film h = readExr(dir.file("h.exr"));
    CHECK(h.rgba[0] == 65504.f);
    CHECK(h.rgba[1] == 65504.f);
    CHECK(h.rgba[2] == 0.f);
    CHECK(h.rgba[3] == -65504.f);
    CHECK(h.rgba[4] == 65504.f);
    CHECK(h.rgba[5] == 65504.f);
    CHECK(h.rgba[6] == 65504.f);
    CHECK(h.albedo[0] == 65504.f);
    CHECK(h.normal[0] == 0.f);
    CHECK(h.z[3] == 1e10f);
    CHECK(h.distance[2] == 1e10f);
    for (float v : h.rgba) CHECK(std::isfinite(v));

    writeExr(dir.file("f.exr"), f, makeOptions(true));
    const Film fl = readExr(dir.file("f.exr"));
    CHECK(fl.rgba[0] == 1e6f);  // FLOAT keeps large finite values
    CHECK(fl.rgba[1] == std::numeric_limits<float>::max());
    CHECK(fl.rgba[2] == 0.f);
    CHECK(fl.rgba[3] == -1e6f);
    CHECK(fl.rgba[5] == 65520.f);
}

TEST_CASE("exr: reader fills missing channels (A = 1, absent layers empty)") {
    TempDir dir;
    const std::string path = dir.file("rgb.exr");
    // An RGB-only file written directly with OpenEXR, data window not at the origin.
    const int w = 2, h = 1;
    float rgb[w * h * 3] = {0.25f, 0.5f, 0.75f, 1.f, 2.f, 3.f};
    Imf::Header header(Imath::Box2i({0, 0}, {9, 9}), Imath::Box2i({4, 7}, {5, 7}));
    Imf::FrameBuffer fb;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
        fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, rgb + c, header.dataWindow(),
                                             3 * sizeof(float), 3 * sizeof(float) * w));
    }
    {
        Imf::OutputFile out(path.c_str(), header);
        out.setFrameBuffer(fb);
        out.writePixels(h);
    }
    const Film f = readExr(path);
    CHECK(f.width == 2);
    CHECK(f.height == 1);
    CHECK(f.rgba == FilmPlane{0.25f, 0.5f, 0.75f, 1.f, 1.f, 2.f, 3.f, 1.f});
    CHECK(f.z.empty());
    CHECK(f.distance.empty());
    CHECK(f.normal.empty());
    CHECK(f.albedo.empty());
    CHECK(f.objectId.empty());
}

TEST_CASE("exr: errors are InputErrors naming the file, nothing is left behind") {
    TempDir dir;
    const std::string missing = dir.file("missing.exr");
    try {
        readExr(missing);
        FAIL("expected InputError");
    } catch (const InputError& e) {
        CHECK(e.file() == missing);
    }

    const std::string garbage = dir.file("garbage.exr");
    std::ofstream(garbage) << "this is not an EXR file";
    CHECK_THROWS_AS(readExr(garbage), InputError);

    const std::string badDir = dir.file("nope/out.exr");
    try {
        writeExr(badDir, makeFilm(), makeOptions(false));
        FAIL("expected InputError");
    } catch (const InputError& e) {
        CHECK(e.file() == badDir);
    }

    CHECK_THROWS_AS(writeExr(dir.file("empty.exr"), Film(), makeOptions(false)), InputError);
    Film broken = makeFilm();
    broken.normal.resize(5);
    CHECK_THROWS_AS(writeExr(dir.file("broken.exr"), broken, makeOptions(false)), InputError);
    CHECK(dir.entries() == std::vector<std::string>{"garbage.exr"});
}

TEST_CASE("exr: the same film gives byte-identical files") {
    TempDir dir;
    writeExr(dir.file("a.exr"), makeFilm(), makeOptions(false));
    writeExr(dir.file("b.exr"), makeFilm(), makeOptions(false));
    const std::string a = raylab::test::readFile(dir.file("a.exr"));
    CHECK(!a.empty());
    CHECK(a == raylab::test::readFile(dir.file("b.exr")));
}

TEST_CASE("exr: the file bytes do not depend on the compression thread count") {
    TempDir dir;
    // Tall enough for many 16-line ZIP blocks, so several are in flight at once.
    Film f(64, 200);
    for (size_t i = 0; i < f.rgba.size(); ++i) f.rgba[i] = float(i % 251) / 7.f;
    for (size_t i = 0; i < f.z.size(); ++i) f.z[i] = float(i % 13);
    ExrOptions o = makeOptions(false);
    o.threads = 1;
    writeExr(dir.file("one.exr"), f, o);
    o.threads = 4;
    writeExr(dir.file("four.exr"), f, o);
    const std::string one = raylab::test::readFile(dir.file("one.exr"));
    CHECK(one.size() > 1000);
    CHECK(one == raylab::test::readFile(dir.file("four.exr")));
    CHECK(readExr(dir.file("four.exr")).z == f.z);
}

TEST_CASE("exr: empty AOV vectors are written as the Film defaults") {
    TempDir dir;
    Film f(2, 1);
    f.rgba = {1.f, 0.5f, 0.25f, 1.f, 0.f, 0.f, 0.f, 0.f};
    f.z.clear();
    f.distance.clear();
    f.mattes.clear();
    f.normal.clear();
    f.albedo.clear();
    f.objectId.clear();
    writeExr(dir.file("rgba.exr"), f, makeOptions(false));
    CHECK(channelTypes(dir.file("rgba.exr")).size() == 25);
    const Film back = readExr(dir.file("rgba.exr"));
    CHECK(back.rgba == f.rgba);  // all four values are exact in half
    CHECK(back.z == FilmPlane{1e10f, 1e10f});
    CHECK(back.distance == FilmPlane{1e10f, 1e10f});
    CHECK(back.normal == FilmPlane(6, 0.f));
    CHECK(back.albedo == FilmPlane(6, 0.f));
    CHECK(back.objectId == FilmPlane{-1.f, -1.f});
}

TEST_CASE("exr: every lossless compression stores the same values, and says which it used") {
    TempDir dir;
    // Large enough for several blocks of every scheme, with runs (for RLE),
    // smooth gradients and a background region.
    Film f(70, 40);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 70; ++x) {
            const size_t i = f.index(x, y);
            for (int c = 0; c < 4; ++c) f.rgba[4 * i + c] = x < 20 ? 0.5f : float(x * y + c) / 97.f;
            if (y < 30) {
                f.z[i] = 1.f + float(x) / 3.f;
                f.distance[i] = 1.f + float(x) / 2.f;
                for (int c = 0; c < 3; ++c) {
                    f.normal[3 * i + c] = float(c) - 0.25f * float(y % 5);
                    f.albedo[3 * i + c] = float((x + c) % 7) / 7.f;
                }
                f.objectId[i] = float(x / 10);
                f.mattes[i * kMatteRanks] = {x / 10, 0.75f};
                f.mattes[i * kMatteRanks + 1] = {x / 10 + 1, 0.25f};
            }
        }
    ExrOptions o = makeOptions(false);
    o.compression = ExrCompression::Zip;
    writeExr(dir.file("zip.exr"), f, o);
    const Film reference = readExr(dir.file("zip.exr"));
    const Imf::Compression imf[] = {Imf::NO_COMPRESSION, Imf::RLE_COMPRESSION,
                                    Imf::ZIPS_COMPRESSION, Imf::ZIP_COMPRESSION,
                                    Imf::PIZ_COMPRESSION};
    for (size_t k = 0; k < std::size(kExrCompressionNames); ++k) {
        CAPTURE(kExrCompressionNames[k]);
        const std::string path = dir.file(std::string(kExrCompressionNames[k]) + ".exr");
        o.compression = ExrCompression(k);
        writeExr(path, f, o);
        CHECK(Imf::InputFile(path.c_str()).header().compression() == imf[k]);
        const Film back = readExr(path);
        CHECK(back.rgba == reference.rgba);
        CHECK(back.z == reference.z);
        CHECK(back.distance == reference.distance);
        CHECK(back.normal == reference.normal);
        CHECK(back.albedo == reference.albedo);
        CHECK(back.objectId == reference.objectId);
    }
    // Compression does something: the uncompressed file is the largest.
    CHECK(raylab::test::readFile(dir.file("none.exr")).size() >
          raylab::test::readFile(dir.file("zip.exr")).size());
}

TEST_CASE("exr: a rendered film's FLOAT layers are written from the film as they are") {
    // The writer skips its safe copy when no value needs fixing; the bytes
    // must be exactly those of the values, -0 and denormals included.
    TempDir dir;
    Film f(4, 1);
    f.z = {0.f, -0.f, 1e-40f, kNoHitDepth};
    f.distance = {1.f, -0.f, 1e-41f, kNoHitDepth};
    f.normal = {1.f, -0.f, 1e-42f, 0.f, 0.f, 0.f, 0.5f, 0.25f, 0.125f, 3.f, 2.f, 1.f};
    f.objectId = {-1.f, 0.f, 1.f, 16777216.f};
    writeExr(dir.file("a.exr"), f, makeOptions(false));
    const Film back = readExr(dir.file("a.exr"));
    CHECK(std::memcmp(back.z.data(), f.z.data(), 4 * sizeof(float)) == 0);
    CHECK(std::memcmp(back.distance.data(), f.distance.data(), 4 * sizeof(float)) == 0);
    CHECK(std::memcmp(back.normal.data(), f.normal.data(), 12 * sizeof(float)) == 0);
    CHECK(std::memcmp(back.objectId.data(), f.objectId.data(), 4 * sizeof(float)) == 0);
    // And a non-finite depth (never rendered) becomes the "no hit" depth.
    f.z[0] = -kInf;
    f.distance[1] = std::numeric_limits<float>::quiet_NaN();
    writeExr(dir.file("b.exr"), f, makeOptions(false));
    CHECK(readExr(dir.file("b.exr")).z[0] == kNoHitDepth);
    CHECK(readExr(dir.file("b.exr")).distance[1] == kNoHitDepth);
}

namespace {

/// Every CryptoObject channel of `path`, by name.
std::map<std::string, std::vector<float>> cryptoChannels(const std::string& path) {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    const size_t w = size_t(dw.max.x - dw.min.x + 1), h = size_t(dw.max.y - dw.min.y + 1);
    std::map<std::string, std::vector<float>> planes;
    Imf::FrameBuffer fb;
    for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
        const std::string name = it.name();
        if (name.rfind("CryptoObject", 0) != 0) continue;
        std::vector<float>& plane = planes[name];
        plane.assign(w * h, -7.f);
        fb.insert(name, Imf::Slice::Make(Imf::FLOAT, plane.data(), dw, sizeof(float), sizeof(float) * w));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return planes;
}

}  // namespace

TEST_CASE("exr: the Cryptomatte layers written are those the ranks need, with the same values") {
    // Pixel 0: three objects (ranks 0..2), pixel 1: one, the rest none.
    TempDir dir;
    Film f = makeFilm();
    f.mattes[0] = {3, 0.5f};
    f.mattes[1] = {1, 0.25f};
    f.mattes[2] = {4, 0.25f};
    f.mattes[kMatteRanks] = {2, 1.f};
    ExrOptions all = makeOptions(false);
    writeExr(dir.file("all.exr"), f, all);  // the default: every rank
    const auto reference = cryptoChannels(dir.file("all.exr"));
    REQUIRE(reference.size() == 12);
    // Hand values: rank 2 of pixel 0 is object 4 with coverage 0.25.
    CHECK(reference.at("CryptoObject01.G")[0] == 0.25f);
    CHECK(reference.at("CryptoObject01.R")[0] != 0.f);
    CHECK(reference.at("CryptoObject01.G")[1] == 0.f);

    // (ranks asked, layers written): one layer per two ranks, never fewer
    // than pixel 0's three objects need, however few were asked for.
    for (const auto& entry : {std::pair{1, 2}, std::pair{2, 2}, std::pair{3, 2},
                              std::pair{4, 2}, std::pair{5, 3}, std::pair{6, 3}}) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& ranks = entry.first;
        const auto& layers = entry.second;
        CAPTURE(ranks);
        ExrOptions o = all;
        o.matteRanks = ranks;
        const std::string path = dir.file("r" + std::to_string(ranks) + ".exr");
        writeExr(path, f, o);
        const auto written = cryptoChannels(path);
        CHECK(written.size() == size_t(4 * layers));
        for (const auto& channel : reference) {
            // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
            const auto& name = channel.first;
            const auto& plane = channel.second;
            CAPTURE(name);
            if (written.count(name)) {
                CHECK(std::memcmp(written.at(name).data(), plane.data(), plane.size() * 4) == 0);
            } else {  // a layer left out held nothing
                for (float v : plane) CHECK(v == 0.f);
            }
        }
        // The other layers are untouched by the choice.
        const Film back = readExr(path), full = readExr(dir.file("all.exr"));
        CHECK(back.rgba == full.rgba);
        CHECK(back.objectId == full.objectId);
    }
    // One object per pixel and one rank asked: CryptoObject00 alone.
    Film single = makeFilm();
    single.mattes[0] = {3, 1.f};
    ExrOptions one = all;
    one.matteRanks = 1;
    writeExr(dir.file("one.exr"), single, one);
    const auto oneLayer = cryptoChannels(dir.file("one.exr"));
    CHECK(oneLayer.size() == 4);
    CHECK(oneLayer.at("CryptoObject00.G")[0] == 1.f);
    CHECK(channelTypes(dir.file("one.exr")).size() == 17);
}

TEST_CASE("exr: the manifest also names the objects the film covers beyond the scene's names") {
    // Objects 2 and 3 have no name in the options: the manifest lists them as
    // "objectN", after the scene's names, as the matte ranks' ids do.
    TempDir dir;
    const std::string path = dir.file("m.exr");
    Film f(2, 1);
    f.mattesOf(0)[0] = {1, 1.f};
    f.mattesOf(1)[0] = {3, 1.f};
    ExrOptions o = makeOptions(false);
    o.objectNames = {"a", "b"};
    writeExr(path, f, o);
    Imf::InputFile in(path.c_str());
    const std::string key = "cryptomatte/" + cryptomatteLayerKey(kCryptoObjectLayer) + "/manifest";
    const auto* manifest = in.header().findTypedAttribute<Imf::StringAttribute>(key);
    REQUIRE(manifest != nullptr);
    CHECK(manifest->value() == cryptomatteManifest({"a", "b", "object2", "object3"}));
}

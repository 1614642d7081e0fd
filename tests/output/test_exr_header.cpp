// ExrHeader: raylab's own EXR header writes the bytes Imf::Header::writeTo
// writes for the same attributes (OpenEXR is the reference), reads back
// through Imf::Header::readFrom, and a few values are checked by hand.

#include <doctest/doctest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfVecAttribute.h>

#include <cstring>
#include <stdexcept>
#include <string>

#include "renderer/io/exr_header.h"
#include "renderer/io/exr_zip_file.h"
#include "support/exr_zip_reference.h"

using namespace raylab;
using raylab::test::exrHeaderOf;

namespace {

std::string imfBytes(const Imf::Header& h) {
    Imf::StdOSStream os;
    h.writeTo(os);
    return os.str();
}

std::string ownBytes(const ExrHeader& h) {
    std::string out;
    h.appendTo(out);
    return out;
}

/// The same header both ways: raylab's attributes (strings, ints, matrices,
/// a long Cryptomatte-like manifest), channels of both types in any order.
struct BothHeaders {
    Imf::Header imf;
    ExrHeader own;
    BothHeaders(const ExrBox& display, const ExrBox& data)
        : imf(Imath::Box2i({display.xMin, display.yMin}, {display.xMax, display.yMax}),
              Imath::Box2i({data.xMin, data.yMin}, {data.xMax, data.yMax})),
          own(display, data) {}
    void channel(const std::string& name, ExrPixelType type) {
        imf.channels().insert(name, Imf::Channel(Imf::PixelType(type)));
        own.addChannel(name, type);
    }
    void string(const std::string& name, const std::string& value) {
        imf.insert(name, Imf::StringAttribute(value));
        own.setString(name, value);
    }
    void integer(const std::string& name, int value) {
        imf.insert(name, Imf::IntAttribute(value));
        own.setInt(name, value);
    }
    void matrix(const std::string& name, float seed) {
        float m[4][4];
        Imath::M44f im;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) im[i][j] = m[i][j] = seed * float(4 * i + j) - 1.5f;
        imf.insert(name, Imf::M44fAttribute(im));
        own.setM44f(name, m);
    }
    void compression(ExrCompressionId c) {
        imf.compression() = Imf::Compression(c);
        own.setCompression(c);
    }
};

}  // namespace

TEST_CASE("exr header: the bytes of Imf::Header::writeTo for the same attributes") {
    SUBCASE("the eight attributes every file has, no channel") {
        BothHeaders h({0, 0, 63, 47}, {0, 0, 63, 47});
        CHECK(ownBytes(h.own) == imfBytes(h.imf));
    }
    SUBCASE("raylab's attributes, a crop window, channels out of order") {
        BothHeaders h({0, 0, 511, 383}, {17, 40, 300, 201});
        for (const char* c : {"R", "G", "B", "A"}) h.channel(c, ExrPixelType::Half);
        for (const char* c : {"objectId", "Z", "N.X", "N.Y", "N.Z", "distance"})
            h.channel(c, ExrPixelType::Float);
        for (const char* c : {"albedo.R", "albedo.G", "albedo.B"}) h.channel(c, ExrPixelType::Half);
        for (const char* c : {"CryptoObject00.R", "CryptoObject00.A", "CryptoObject01.G"})
            h.channel(c, ExrPixelType::Float);
        h.channel("count", ExrPixelType::Uint);
        h.string("software", "raylab 0.1.0");
        h.matrix("worldToCamera", 0.25f);
        h.matrix("worldToNDC", -3.0f);
        std::string manifest = "{";
        for (int k = 0; k < 3000; ++k) manifest += "\"object" + std::to_string(k) + "\":\"0a1b2c3d\",";
        manifest += "}";
        h.string("cryptomatte/ae4e6c4/manifest", manifest);
        h.string("cryptomatte/ae4e6c4/name", "CryptoObject");
        h.string("raylab/settings", "");  // an empty string is a size-0 value
        h.integer("raylab/spp", 4);
        h.integer("raylab/maxDepth", -7);
        h.string("raylab/scene", "scenes/demo.json");
        for (ExrCompressionId c : {ExrCompressionId::None, ExrCompressionId::Rle,
                                   ExrCompressionId::Zips, ExrCompressionId::Zip,
                                   ExrCompressionId::Piz}) {
            CAPTURE(int(c));
            h.compression(c);
            CHECK(ownBytes(h.own) == imfBytes(h.imf));
        }
    }
    SUBCASE("a name sorting before 'channels' goes first, as in OpenEXR's map") {
        BothHeaders h({0, 0, 3, 3}, {0, 0, 3, 3});
        h.channel("Y", ExrPixelType::Float);
        h.string("Channels", "upper case sorts first");
        h.string("aperture", "a");
        h.string("chan", "a prefix of channels");
        h.integer("channelsX", 1);
        CHECK(ownBytes(h.own) == imfBytes(h.imf));
    }
    SUBCASE("replacing an attribute or a channel's type keeps one of each") {
        BothHeaders h({0, 0, 9, 9}, {0, 0, 9, 9});
        h.channel("R", ExrPixelType::Half);
        h.channel("R", ExrPixelType::Float);
        h.string("software", "old");
        h.string("software", "new");
        CHECK(ownBytes(h.own) == imfBytes(h.imf));
    }
}

TEST_CASE("exr header: the long-names flag follows OpenEXR's rule") {
    ExrHeader h({0, 0, 1, 1}, {0, 0, 1, 1});
    h.addChannel(std::string(31, 'c'), ExrPixelType::Half);
    h.setString(std::string(31, 'a'), "x");
    CHECK_FALSE(h.usesLongNames());
    SUBCASE("a channel of 32 characters") {
        h.addChannel(std::string(32, 'c'), ExrPixelType::Half);
        CHECK(h.usesLongNames());
    }
    SUBCASE("an attribute of 32 characters") {
        h.setString(std::string(32, 'a'), "x");
        CHECK(h.usesLongNames());
    }
    SUBCASE("a type name of 32 characters") {
        h.setAttribute("x", std::string(32, 't'), "");
        CHECK(h.usesLongNames());
    }
}

TEST_CASE("exr header: values by hand, and OpenEXR reads the bytes back") {
    ExrHeader h({0, 0, 9, 4}, {2, 1, 5, 3});
    h.addChannel("R", ExrPixelType::Half);
    h.setInt("raylab/frame", 12);
    std::string bytes;
    h.appendTo(bytes);
    // The first attribute: "channels", "chlist", size 18 (R\0, type 1, pLinear
    // and 3 reserved bytes, sampling 1 and 1), then the list's end byte.
    const char expected[] = "channels\0chlist\0\x13\0\0\0R\0\x01\0\0\0\0\0\0\0\x01\0\0\0\x01\0\0\0";
    REQUIRE(bytes.size() > sizeof expected);
    CHECK(bytes.compare(0, sizeof expected - 1, std::string(expected, sizeof expected - 1)) == 0);
    CHECK(bytes[sizeof expected - 1] == '\0');  // end of the channel list
    CHECK(bytes.back() == '\0');                // end of the header

    Imf::StdISStream is;
    is.str(bytes);
    Imf::Header read;
    int version = 2;
    read.readFrom(is, version);
    CHECK(read.dataWindow().min.x == 2);
    CHECK(read.dataWindow().max.y == 3);
    CHECK(read.displayWindow().max.x == 9);
    CHECK(read.compression() == Imf::ZIP_COMPRESSION);
    CHECK(read.channels().findChannel("R")->type == Imf::HALF);
    CHECK(read.typedAttribute<Imf::IntAttribute>("raylab/frame").value() == 12);
    CHECK(exrLinesPerBlock(ExrCompressionId::Zip) == 16);
    CHECK(exrLinesPerBlock(ExrCompressionId::Zips) == 1);
    CHECK(exrLinesPerBlock(ExrCompressionId::Piz) == 32);
}

TEST_CASE("exr header: exrHeaderOf an OpenEXR header writes its bytes") {
    Imf::Header imf(Imath::Box2i({0, 0}, {99, 49}), Imath::Box2i({10, 5}, {20, 30}));
    imf.channels().insert("B", Imf::Channel(Imf::FLOAT));
    imf.channels().insert("A", Imf::Channel(Imf::HALF));
    imf.insert("owner", Imf::StringAttribute("test"));
    imf.insert("exposure", Imf::FloatAttribute(1.25f));  // types raylab does not set itself
    imf.insert("offset", Imf::V2fAttribute(Imath::V2f(0.5f, -2.0f)));
    CHECK(ownBytes(exrHeaderOf(imf)) == imfBytes(imf));
}

TEST_CASE("exr header: names a file cannot hold are refused") {
    ExrHeader h({0, 0, 1, 1}, {0, 0, 1, 1});
    CHECK_THROWS_AS(h.addChannel("", ExrPixelType::Half), std::invalid_argument);
    CHECK_THROWS_AS(h.setString(std::string(256, 'a'), "x"), std::invalid_argument);
    CHECK_THROWS_AS(h.setString(std::string("a\0b", 3), "x"), std::invalid_argument);
    CHECK_THROWS_AS(h.setString("channels", "x"), std::invalid_argument);
    CHECK_THROWS_AS(ExrHeader({0, 0, -1, 1}, {0, 0, 1, 1}), std::invalid_argument);
}

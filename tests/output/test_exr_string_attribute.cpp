// ExrStringAttribute: the bytes of Imf::StringAttribute, written in one call,
// and read back as a plain StringAttribute.

#include <doctest/doctest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <memory>
#include <string>
#include <vector>

#include "renderer/io/exr_string_attribute.h"
#include "support/temp_dir.h"

using namespace raylab;
using raylab::test::TempDir;

namespace {

template <class A>
std::string bytesOf(const A& attribute) {
    Imf::StdOSStream os;
    attribute.writeValueTo(os, 2);
    return os.str();
}

}  // namespace

TEST_CASE("ExrStringAttribute: the same bytes as Imf::StringAttribute, type string") {
    std::string big;
    for (int k = 0; k < 20000; ++k) big += "\"sphere@" + std::to_string(k) + "\":\"5bcef9e8\",";
    for (const std::string& value : {std::string(), std::string("MurmurHash3_32"),
                                     std::string("a\0b", 3), std::string("\xc3\xa9t\xc3\xa9"), big}) {
        CAPTURE(value.size());
        const ExrStringAttribute ours(value);
        CHECK(std::string(ours.typeName()) == "string");
        CHECK(bytesOf(ours) == bytesOf(Imf::StringAttribute(value)));
        CHECK(bytesOf(ours).size() == value.size());
        // A copy (what Header::insert keeps) writes the same.
        const std::unique_ptr<Imf::Attribute> copy(ours.copy());
        CHECK(bytesOf(*copy) == bytesOf(ours));
    }
}

TEST_CASE("ExrStringAttribute: a file's header reads back as a StringAttribute") {
    TempDir dir;
    const std::string path = dir.file("header.exr");
    std::string manifest = "{";
    for (int k = 0; k < 5000; ++k) manifest += (k ? ",\"o@" : "\"o@") + std::to_string(k) + "\":\"00000001\"";
    manifest += "}";
    {
        Imf::Header header(2, 1);
        header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
        header.insert("cryptomatte/abc/manifest", ExrStringAttribute(manifest));
        header.insert("note", ExrStringAttribute("x"));
        std::vector<float> y{1.f, 2.f};
        Imf::FrameBuffer fb;
        fb.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(y.data()), sizeof(float),
                                  2 * sizeof(float)));
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(fb);
        file.writePixels(1);
    }
    {
        Imf::InputFile file(path.c_str());
        const auto* m = file.header().findTypedAttribute<Imf::StringAttribute>("cryptomatte/abc/manifest");
        REQUIRE(m != nullptr);
        CHECK(m->value() == manifest);
        const auto* note = file.header().findTypedAttribute<Imf::StringAttribute>("note");
        REQUIRE(note != nullptr);
        CHECK(note->value() == "x");
    }
}

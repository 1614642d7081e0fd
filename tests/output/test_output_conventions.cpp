// End-to-end checks of what `raylab render` writes for compositors
// (docs/output.md): depth conventions, camera matrices, Cryptomatte, alpha
// modes, byte-identical files for any thread count, and every output format
// read back through OpenImageIO.

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenImageIO/imageio.h>

#include "renderer/camera.h"
#include "renderer/cryptomatte_id.h"
#include "renderer/film.h"
#include "renderer/io/json.h"
#include "renderer/io/json_string.h"
#include "renderer/io/png_writer.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

using namespace raylab;
using raylab::test::runCommand;
using raylab::test::TempDir;

namespace {

std::string raylabCmd(const std::string& args) { return std::string(RAYLAB_BINARY) + " " + args; }

void writeText(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

/// Every channel of an EXR as floats, by name.
struct ExrImage {
    int width = 0, height = 0;
    std::map<std::string, std::vector<float>> channels;
    const float& at(const std::string& c, int x, int y) const {
        return channels.at(c)[size_t(y) * size_t(width) + size_t(x)];
    }
};

ExrImage readAll(const std::string& path) {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    ExrImage img;
    img.width = dw.max.x - dw.min.x + 1;
    img.height = dw.max.y - dw.min.y + 1;
    Imf::FrameBuffer fb;
    for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
        auto& plane = img.channels[it.name()];
        plane.assign(size_t(img.width) * size_t(img.height), 0.f);
        fb.insert(it.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(plane.data()),
                                        sizeof(float), sizeof(float) * size_t(img.width)));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return img;
}

std::string stringAttribute(const std::string& path, const std::string& name) {
    Imf::InputFile in(path.c_str());
    const auto* a = in.header().findTypedAttribute<Imf::StringAttribute>(name);
    return a ? a->value() : std::string("<absent>");
}

uint32_t bitsOf(float f) {
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

// A tilted plane seen by a 90-degree camera at the origin looking down -z:
// the plane through (0, -1, -4) with normal (0, 1, 1)/sqrt(2) is hit by
// every pixel's centre ray (its rays have y < 1 on the image plane z = -1).
const char* kTiltedPlane = R"({
  "image": {"width": 8, "height": 8},
  "camera": {"eye": [0, 0, 0], "look_at": [0, 0, -1], "up": [0, 1, 0], "fov": 90},
  "background": [0.25, 0.5, 0.75],
  "lights": [{"type": "point", "position": [0, 5, 0], "intensity": 1}],
  "objects": [{"type": "plane", "name": "tilted floor", "point": [0, -1, -4],
               "normal": [0, 1, 1], "half_extent": 1000}]
})";

// Three overlapping spheres in front of the background.
const char* kThreeBalls = R"({
  "image": {"width": 24, "height": 16},
  "camera": {"eye": [0, 0, 6], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
  "background": [0.2, 0.3, 0.4],
  "lights": [{"type": "point", "position": [3, 5, 6], "intensity": 1}],
  "objects": [
    {"type": "sphere", "name": "red ball", "center": [-1.1, 0, 0], "radius": 0.9},
    {"type": "sphere", "name": "green ball", "center": [0.4, 0.2, -0.5], "radius": 0.9},
    {"type": "sphere", "name": "blue ball", "center": [1.5, -0.3, 0.6], "radius": 0.6}
  ]
})";

}  // namespace

TEST_CASE("output: MurmurHash3_x86_32 and the Cryptomatte id conversion") {
    // Reference values of MurmurHash3_x86_32 with seed 0 (as Python's mmh3.hash gives them).
    CHECK(murmurHash3_x86_32("", 0) == 0u);
    CHECK(murmurHash3_x86_32("foo", 3) == 0xf6a5c420u);    // mmh3.hash("foo") = -156908512
    CHECK(murmurHash3_x86_32("hello", 5) == 0x248bfa47u);  // mmh3.hash("hello") = 613153351
    // An id never has exponent 0 or 255: the specification flips bit 23 of those hashes.
    int fixedOnes = 0;
    for (int i = 0; i < 4000; ++i) {
        const std::string name = "object" + std::to_string(i);
        const uint32_t hash = murmurHash3_x86_32(name.data(), name.size());
        const uint32_t exponent = (hash >> 23) & 255u;
        const uint32_t bits = cryptomatteIdBits(name);
        if (exponent == 0 || exponent == 255) {
            ++fixedOnes;
            CHECK(bits == (hash ^ (1u << 23)));
        } else {
            CHECK(bits == hash);
        }
        CHECK(std::isnormal(cryptomatteIdFloat(bits)));
    }
    CHECK(fixedOnes > 0);  // about 2 in 256 names need the fix
    CHECK(cryptomatteHex(0x0a1b2c3du) == "0a1b2c3d");
    CHECK(cryptomatteLayerKey("CryptoObject") == cryptomatteHex(cryptomatteIdBits("CryptoObject")).substr(0, 7));
    CHECK(cryptomatteManifest({"a", "b \"q\"", "a"}) ==
          "{\"a\":\"" + cryptomatteHex(cryptomatteIdBits("a")) + "\",\"b \\\"q\\\"\":\"" +
              cryptomatteHex(cryptomatteIdBits("b \"q\"")) + "\"}");
}

TEST_CASE("output: the Cryptomatte manifest of thousands of names, as a plain reference makes it") {
    // Repeats, quotes, empty names, and two names with one id (MurmurHash3
    // collides on them): every name's first occurrence, in order, as a
    // std::set finds them (the manifest's own table is keyed by the ids).
    REQUIRE(cryptomatteIdBits("obj5041") == cryptomatteIdBits("obj13556"));
    std::vector<std::string> names;
    for (int i = 0; i < 5000; ++i)
        names.push_back(i % 7 == 3 ? "quote\"" + std::to_string(i % 11)
                                   : "obj" + std::to_string((i * 7919) % 1237));
    for (const char* name : {"", "obj5041", "", "obj13556", "obj5041"}) names.push_back(name);
    std::set<std::string> seen;
    std::string expected = "{";
    for (const std::string& name : names) {
        if (!seen.insert(name).second) continue;
        if (expected.size() > 1) expected += ',';
        expected += jsonString(name) + ":\"" + cryptomatteHex(cryptomatteIdBits(name)) + "\"";
    }
    expected += "}";
    CHECK(seen.size() == 1237 + 11 + 3);
    const std::string manifest = cryptomatteManifest(names);
    CHECK(manifest == expected);
    CHECK(manifest.find("\"obj13556\"") != std::string::npos);
    CHECK(cryptomatteManifest({}) == "{}");
}

TEST_CASE("output: Z is planar depth, distance is Euclidean, on a tilted plane") {
    TempDir dir;
    writeText(dir.file("plane.json"), kTiltedPlane);
    const auto ok = runCommand(raylabCmd("render " + dir.file("plane.json") + " -o " +
                                      dir.file("p.exr") + " --quiet"));
    REQUIRE_MESSAGE(ok.exitCode == 0, ok.err);
    const ExrImage img = readAll(dir.file("p.exr"));
    REQUIRE(img.width == 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            CAPTURE(x);
            CAPTURE(y);
            // Centre ray through (sx, sy, -1) on the image plane at distance 1
            // (tan 45 = 1); it meets n.(p - p0) = 0 at t = 5 / (1 - sy), so
            // the planar depth is t (the ray's z is -1) and the distance t |d|.
            const double sx = 2.0 * (x + 0.5) / 8 - 1, sy = 1 - 2.0 * (y + 0.5) / 8;
            const double t = 5.0 / (1.0 - sy);
            const double distance = t * std::sqrt(sx * sx + sy * sy + 1);
            CHECK(img.at("Z", x, y) == doctest::Approx(t).epsilon(1e-6));
            CHECK(img.at("distance", x, y) == doctest::Approx(distance).epsilon(1e-6));
        }
    // Hand values: the top row is 40 away along the axis, row 4 is 5/1.125.
    CHECK(img.at("Z", 0, 0) == doctest::Approx(40.0).epsilon(1e-6));
    CHECK(img.at("Z", 7, 0) == doctest::Approx(40.0).epsilon(1e-6));
    CHECK(img.at("Z", 3, 4) == doctest::Approx(40.0 / 9.0).epsilon(1e-6));
    CHECK(img.at("distance", 0, 0) == doctest::Approx(40.0 * std::sqrt(2.53125)).epsilon(1e-6));
}

TEST_CASE("output: EXR channels, attributes and camera matrices") {
    TempDir dir;
    writeText(dir.file("balls.json"), kThreeBalls);
    const std::string exr = dir.file("b.exr");
    const auto r = runCommand(raylabCmd("render " + dir.file("balls.json") + " -o " + exr +
                                     " --quiet --width 30 --height 20 --eye 1,2,6 --fov 35"));
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    const ExrImage img = readAll(exr);
    std::vector<std::string> names;
    for (const auto& [name, plane] : img.channels) names.push_back(name);
    // One sample per pixel: one object per pixel, so one Cryptomatte layer
    // (ranks 0 and 1; the next test has the layers of other samplings).
    CHECK(names == std::vector<std::string>{
                       "A", "B", "CryptoObject00.A", "CryptoObject00.B", "CryptoObject00.G",
                       "CryptoObject00.R", "G", "N.X", "N.Y", "N.Z", "R", "Z", "albedo.B",
                       "albedo.G", "albedo.R", "distance", "objectId"});
    // Background: finite depth and distance, as Blender writes them.
    CHECK(img.at("Z", 0, 0) == 1e10f);
    CHECK(img.at("distance", 0, 0) == 1e10f);
    for (const auto& [name, plane] : img.channels)
        for (float v : plane) REQUIRE(std::isfinite(v));

    CHECK(stringAttribute(exr, "software") == "raylab 0.1.0");
    const std::string settings = stringAttribute(exr, "raylab/settings");
    CHECK(settings.find("width=30 height=20 spp=1") == 0);
    CHECK(settings.find("alpha=background") != std::string::npos);
    CHECK(settings.find("threads") == std::string::npos);
    CHECK(stringAttribute(exr, "raylab/command") == "<absent>");
    const std::string key = cryptomatteLayerKey("CryptoObject");
    CHECK(stringAttribute(exr, "cryptomatte/" + key + "/name") == "CryptoObject");
    CHECK(stringAttribute(exr, "cryptomatte/" + key + "/hash") == "MurmurHash3_32");
    CHECK(stringAttribute(exr, "cryptomatte/" + key + "/conversion") == "uint32_to_float32");

    // worldToCamera: the eye to the origin, the look-at point onto +z (RenderMan's
    // left-handed camera space); worldToNDC: a pixel centre's world point to
    // ((x + 0.5) / W, (y + 0.5) / H), (0, 0) the top-left corner.
    Imf::InputFile in(exr.c_str());
    const auto* w2c = in.header().findTypedAttribute<Imf::M44fAttribute>("worldToCamera");
    const auto* w2n = in.header().findTypedAttribute<Imf::M44fAttribute>("worldToNDC");
    REQUIRE(w2c);
    REQUIRE(w2n);
    Imath::V3f c;
    w2c->value().multVecMatrix(Imath::V3f(1, 2, 6), c);
    CHECK(c.length() < 1e-5f);
    w2c->value().multVecMatrix(Imath::V3f(0, 0, 0), c);
    CHECK(c.x == doctest::Approx(0).epsilon(1e-5));
    CHECK(c.y == doctest::Approx(0).epsilon(1e-5));
    CHECK(c.z == doctest::Approx(std::sqrt(1.0 + 4 + 36)).epsilon(1e-5));
    // A point above the eye's right is at camera +x, +y.
    const Camera camera = Camera::perspective({1, 2, 6}, {0, 0, 0}, {0, 1, 0}, 35);
    w2c->value().multVecMatrix(Imath::V3f(float(camera.frame().u.x + camera.frame().v.x),
                                          float(camera.frame().u.y + camera.frame().v.y),
                                          float(camera.frame().u.z + camera.frame().v.z)) +
                                   Imath::V3f(1, 2, 6),
                               c);
    CHECK(c.x == doctest::Approx(1).epsilon(1e-5));
    CHECK(c.y == doctest::Approx(1).epsilon(1e-5));
    for (const auto& [px, py] : std::vector<std::pair<int, int>>{{0, 0}, {29, 0}, {7, 13}, {29, 19}}) {
        const Ray ray = camera.generateRay(px + 0.5, py + 0.5, 30, 20);
        const Vec3 p = ray.o + ray.d * 3.7;
        Imath::V3f ndc;
        w2n->value().multVecMatrix(Imath::V3f(float(p.x), float(p.y), float(p.z)), ndc);
        CHECK(ndc.x == doctest::Approx((px + 0.5) / 30).epsilon(1e-5));
        CHECK(ndc.y == doctest::Approx((py + 0.5) / 20).epsilon(1e-5));
    }
}

TEST_CASE("output: Cryptomatte rank 0 decodes to the object at the pixel, coverage sums to 1") {
    TempDir dir;
    writeText(dir.file("balls.json"), kThreeBalls);
    const std::string exr = dir.file("c.exr");
    const std::string stats = dir.file("c.json");
    const auto r = runCommand(raylabCmd("render " + dir.file("balls.json") + " -o " + exr +
                                     " --float --spp 16 --quiet --stats " + stats));
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    const ExrImage img = readAll(exr);

    // The manifest maps names to the hex of the id bits.
    const std::string key = cryptomatteLayerKey("CryptoObject");
    const JsonValue manifest = parseJson(stringAttribute(exr, "cryptomatte/" + key + "/manifest"), "manifest");
    std::map<std::string, std::string> nameOfHex;
    for (size_t i = 0; i < manifest.size(); ++i) nameOfHex[manifest.at(i).asString()] = manifest.key(i);
    REQUIRE(nameOfHex.size() == 3);
    const std::vector<std::string> objects = {"red ball", "green ball", "blue ball"};

    // --stats lists the objects with their objectId and the same hex id.
    const JsonValue s = parseJson(raylab::test::readFile(stats), stats);
    const JsonValue* list = s.find("objects");
    REQUIRE(list);
    REQUIRE(list->size() == 3);
    for (size_t i = 0; i < 3; ++i) {
        CHECK(list->at(i).find("id")->asNumber() == double(i));
        CHECK(list->at(i).find("name")->asString() == objects[i]);
        CHECK(nameOfHex.at(list->at(i).find("cryptomatte")->asString()) == objects[i]);
    }

    int full = 0, edges = 0, empty = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            CAPTURE(x);
            CAPTURE(y);
            double sum = 0;
            int ranks = 0;
            for (int layer = 0; layer < 3; ++layer) {
                const std::string base = "CryptoObject0" + std::to_string(layer) + ".";
                for (const auto& [id, cov] : {std::pair{"R", "G"}, std::pair{"B", "A"}}) {
                    const float coverage = img.at(base + cov, x, y);
                    const float idValue = img.at(base + id, x, y);
                    if (coverage == 0.f) {
                        CHECK(idValue == 0.f);
                        continue;
                    }
                    ++ranks;
                    sum += coverage;
                    CHECK(nameOfHex.count(cryptomatteHex(bitsOf(idValue))) == 1);
                }
            }
            const float alpha = img.at("A", x, y);  // object coverage (--alpha background)
            CHECK(sum == doctest::Approx(alpha).epsilon(1e-6));
            const float rank0 = img.at("CryptoObject00.R", x, y);
            const int objectId = int(img.at("objectId", x, y));
            if (alpha == 1.f) {
                CHECK(sum == doctest::Approx(1.0).epsilon(1e-6));
                if (img.at("CryptoObject00.G", x, y) == 1.f) {
                    // One object covers every sample: rank 0 names it, and so does objectId.
                    ++full;
                    REQUIRE(objectId >= 0);
                    CHECK(nameOfHex.at(cryptomatteHex(bitsOf(rank0))) == objects[size_t(objectId)]);
                }
            }
            if (ranks >= 2) ++edges;
            if (ranks == 0) {
                ++empty;
                CHECK(objectId == -1);
            }
            // The first sample's object (objectId) is among the pixel's ranks.
            if (objectId >= 0) {
                bool found = false;
                for (int layer = 0; layer < 3; ++layer)
                    for (const char* id : {"R", "B"})
                        found = found || nameOfHex[cryptomatteHex(bitsOf(img.at(
                                             "CryptoObject0" + std::to_string(layer) + "." + id, x, y)))] ==
                                             objects[size_t(objectId)];
                CHECK(found);
            }
        }
    CHECK(full > 20);
    CHECK(edges > 5);   // antialiased edges: several objects (or object and background) share a pixel
    CHECK(empty > 20);  // background
}

TEST_CASE("output: the Cryptomatte layers are those the sampling can fill, whatever the picture") {
    // One rank per sample a pixel averages, two ranks per layer, at most
    // three layers (six ranks): the same for every frame of a sequence.
    TempDir dir;
    writeText(dir.file("balls.json"), kThreeBalls);
    const std::pair<std::string, int> cases[] = {
        {"", 1}, {"--spp 2", 1}, {"--spp 3", 2}, {"--spp 4", 2}, {"--spd", 2},
        {"--spp 5", 3}, {"--spp 16", 3}, {"--adaptive 0.1", 3}};
    for (const auto& entry : cases) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& flags = entry.first;
        const auto& layers = entry.second;
        CAPTURE(flags);
        const std::string exr = dir.file("m.exr");
        const auto r = runCommand(raylabCmd("render " + dir.file("balls.json") + " -o " + exr +
                                            " --quiet --width 30 --height 20 " + flags));
        REQUIRE_MESSAGE(r.exitCode == 0, r.err);
        const ExrImage img = readAll(exr);
        int crypto = 0;
        for (const auto& [name, plane] : img.channels) crypto += name.rfind("CryptoObject", 0) == 0;
        CHECK(crypto == 4 * layers);
        CHECK(img.channels.size() == size_t(13 + 4 * layers));
    }
}

TEST_CASE("output: --threads 1 and --threads 2 write byte-identical EXRs") {
    TempDir dir;
    const std::string scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json";
    for (const char* threads : {"1", "2"}) {
        const auto r = runCommand(raylabCmd("render " + scene + " -o " + dir.file(std::string("t") + threads + ".exr") +
                                         " --width 64 --height 48 --spp 4 --quiet --threads " + threads));
        REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    }
    const std::string one = raylab::test::readFile(dir.file("t1.exr"));
    CHECK(one.size() > 10000);
    CHECK(one == raylab::test::readFile(dir.file("t2.exr")));
}

TEST_CASE("output: --alpha background|transparent|opaque") {
    TempDir dir;
    writeText(dir.file("balls.json"), kThreeBalls);
    std::map<std::string, ExrImage> images;
    for (const char* mode : {"background", "transparent", "opaque"}) {
        const std::string exr = dir.file(std::string(mode) + ".exr");
        const auto r = runCommand(raylabCmd("render " + dir.file("balls.json") + " -o " + exr +
                                         " --float --spp 4 --quiet --alpha " + mode));
        REQUIRE_MESSAGE(r.exitCode == 0, r.err);
        CHECK(stringAttribute(exr, "raylab/alpha") == mode);
        images[mode] = readAll(exr);
    }
    const ExrImage& bg = images["background"];
    const ExrImage& tr = images["transparent"];
    const ExrImage& op = images["opaque"];
    // Pixel (0, 0) is background: the colour is there (or not), A is 0 (or 1).
    CHECK(bg.at("R", 0, 0) == 0.2f);
    CHECK(bg.at("B", 0, 0) == 0.4f);
    CHECK(bg.at("A", 0, 0) == 0.f);
    CHECK(tr.at("R", 0, 0) == 0.f);
    CHECK(tr.at("A", 0, 0) == 0.f);
    CHECK(op.at("R", 0, 0) == 0.2f);
    CHECK(op.at("A", 0, 0) == 1.f);
    for (size_t i = 0; i < bg.channels.at("A").size(); ++i) {
        CHECK(op.channels.at("A")[i] == 1.f);
        CHECK(op.channels.at("R")[i] == bg.channels.at("R")[i]);  // opaque: colour unchanged
        CHECK(tr.channels.at("A")[i] == bg.channels.at("A")[i]);
        if (bg.channels.at("A")[i] == 1.f)  // fully covered: nothing of the background anywhere
            CHECK(tr.channels.at("G")[i] == bg.channels.at("G")[i]);
    }
    const auto bad = runCommand(raylabCmd("render " + dir.file("balls.json") + " -o " +
                                       dir.file("x.exr") + " --alpha premultiplied"));
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("--alpha") != std::string::npos);
}

TEST_CASE("output: -o by extension writes EXR, PNG, JPEG, HDR and TIFF, read back by OpenImageIO") {
    TempDir dir;
    writeText(dir.file("balls.json"), kThreeBalls);
    const auto r = runCommand(raylabCmd("render " + dir.file("balls.json") + " --float --spp 4 --quiet" +
                                     " -o " + dir.file("a.exr") + " -o " + dir.file("a.png") +
                                     " -o " + dir.file("a.JPG") + " -o " + dir.file("a.hdr") +
                                     " -o " + dir.file("a.tif") + " --png " + dir.file("b.png")));
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    CHECK(dir.entries() == std::vector<std::string>{"a.JPG", "a.exr", "a.hdr", "a.png", "a.tif",
                                                    "b.png", "balls.json"});
    const ExrImage exr = readAll(dir.file("a.exr"));
    const auto readOiio = [&](const std::string& name, int channels, std::vector<float>& pixels) {
        auto in = OIIO::ImageInput::open(dir.file(name));
        REQUIRE_MESSAGE(in, OIIO::geterror());
        const OIIO::ImageSpec& spec = in->spec();
        CHECK(spec.width == 24);
        CHECK(spec.height == 16);
        CHECK(spec.nchannels == channels);
        pixels.assign(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels), 0.f);
        REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
        // Radiance HDR has no place for it; raylab's libpng writer does not add one.
        const bool tagged = name == "a.JPG" || name == "a.tif";
        CHECK(in->spec().get_string_attribute("Software") == (tagged ? "raylab 0.1.0" : ""));
        CHECK(in->spec().get_string_attribute("DateTime").empty());  // same render, same bytes
        in->close();
    };
    std::vector<float> png, png2, jpg, hdr, tif;
    readOiio("a.png", 3, png);
    readOiio("b.png", 3, png2);
    readOiio("a.JPG", 3, jpg);
    readOiio("a.hdr", 3, hdr);
    readOiio("a.tif", 4, tif);
    CHECK(png == png2);  // --png is -o FILE.png
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            const size_t i = size_t(y) * 24 + size_t(x);
            const float rgba[4] = {exr.at("R", x, y), exr.at("G", x, y), exr.at("B", x, y), exr.at("A", x, y)};
            const auto srgb = toneMapSrgb8(rgba[0], rgba[1], rgba[2], 0);
            for (int c = 0; c < 3; ++c) {
                CHECK(png[3 * i + size_t(c)] * 255.f == doctest::Approx(srgb[size_t(c)]).epsilon(1e-6));
                CHECK(std::fabs(jpg[3 * i + size_t(c)] * 255.f - srgb[size_t(c)]) < 24.f);  // lossy
                // RGBE: 8 mantissa bits shared by the three channels.
                CHECK(std::fabs(hdr[3 * i + size_t(c)] - rgba[c]) <= 0.01f * std::max({rgba[0], rgba[1], rgba[2]}) + 1e-6f);
            }
            for (int c = 0; c < 4; ++c) CHECK(tif[4 * i + size_t(c)] == rgba[c]);  // float, exact
        }
}

TEST_CASE("output: output names are checked (extension, --png, duplicates)") {
    TempDir dir;
    writeText(dir.file("balls.json"), kThreeBalls);
    const std::string render = "render " + dir.file("balls.json") + " --quiet ";
    auto r = runCommand(raylabCmd(render + "-o " + dir.file("a.bmp")));
    CHECK(r.exitCode == 2);
    CHECK(r.err.find(".exr, .png, .jpg/.jpeg, .hdr, .tif/.tiff") != std::string::npos);
    r = runCommand(raylabCmd(render + "--png " + dir.file("a.jpg")));
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("--png: the name must end in .png") != std::string::npos);
    r = runCommand(raylabCmd(render + "-o " + dir.file("a.exr") + " -o " + dir.file("a.exr")));
    CHECK(r.exitCode == 2);
    r = runCommand(raylabCmd(render));
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("missing -o") != std::string::npos);
    // A PNG alone is a complete render now.
    r = runCommand(raylabCmd(render + "-o " + dir.file("only.png")));
    CHECK_MESSAGE(r.exitCode == 0, r.err);
    CHECK(dir.entries() == std::vector<std::string>{"balls.json", "only.png"});
}

TEST_CASE("output: robust traversal is the default, --no-robust and JSON robust false turn it off") {
    TempDir dir;
    writeText(dir.file("balls.json"), kThreeBalls);
    std::string fast = kThreeBalls;
    const size_t brace = fast.find('{');
    REQUIRE(brace != std::string::npos);
    fast.insert(brace + 1, "\"render\": {\"robust\": false},");
    writeText(dir.file("fast.json"), fast);
    const auto robustSetting = [&](const std::string& scene, const std::string& flags) {
        const std::string exr = dir.file("r.exr");
        const auto r = runCommand(raylabCmd("render " + dir.file(scene) + " -o " + exr +
                                            " --quiet --width 8 --height 6 " + flags));
        REQUIRE_MESSAGE(r.exitCode == 0, r.err);
        const std::string settings = stringAttribute(exr, "raylab/settings");
        if (settings.find(" robust=on ") != std::string::npos) return std::string("on");
        if (settings.find(" robust=off ") != std::string::npos) return std::string("off");
        return settings;
    };
    CHECK(robustSetting("balls.json", "") == "on");
    CHECK(robustSetting("balls.json", "--no-robust") == "off");
    CHECK(robustSetting("balls.json", "--no-robust --robust") == "on");
    CHECK(robustSetting("fast.json", "") == "off");
    CHECK(robustSetting("fast.json", "--robust") == "on");
}

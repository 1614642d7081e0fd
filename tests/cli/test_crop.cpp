// --crop X0,X1,Y0,Y1 (pbrt's --cropwindow): the crop's pixels are the same
// pixels of the full render, bit for bit, in every layer and in every
// sampling mode; the EXR keeps the full image as its display window.
#include <doctest/doctest.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <png.h>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "renderer/film.h"
#include "renderer/io/exr_reader.h"

using raylab::Film;

namespace {

// Reflection, refraction and a polygon: every ray type crosses the crop's edges.
const std::string kScene = R"({
  "image": {"width": 37, "height": 23},
  "camera": {"type": "perspective", "eye": [0, 1.5, 6], "look_at": [0, 0.3, 0], "up": [0, 1, 0], "fov": 45},
  "ambient": [0.1, 0.1, 0.1],
  "lights": [{"type": "point", "position": [3, 5, 4], "color": [1, 1, 1], "intensity": 1}],
  "materials": {"mirror": {"kd": [0.2, 0.2, 0.2], "ks": [0.6, 0.6, 0.6], "km": [0.5, 0.5, 0.5], "shininess": 40},
                "glass": {"kd": [0.05, 0.05, 0.05], "kt": [0.8, 0.8, 0.8], "ior": 1.5},
                "floor": {"kd": [0.7, 0.7, 0.5]}},
  "objects": [{"type": "sphere", "center": [-0.8, 0.5, 0], "radius": 0.7, "material": "mirror"},
              {"type": "sphere", "center": [0.9, 0.5, 0.5], "radius": 0.6, "material": "glass"},
              {"type": "polygon", "vertices": [[-4, -0.2, -4], [4, -0.2, -4], [4, -0.2, 4], [-4, -0.2, 4]],
               "material": "floor"}]
})";

/// The Cryptomatte channels of an EXR as floats over its data window
/// (readExr keeps no mattes), with the window's origin.
struct CryptoChannels {
    int x0 = 0, y0 = 0, width = 0, height = 0;
    std::map<std::string, std::vector<float>> planes;
};

CryptoChannels readCryptoChannels(const std::string& path) {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    CryptoChannels c;
    c.x0 = dw.min.x;
    c.y0 = dw.min.y;
    c.width = dw.max.x - dw.min.x + 1;
    c.height = dw.max.y - dw.min.y + 1;
    Imf::FrameBuffer fb;
    for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
        const std::string name = it.name();
        if (name.rfind("CryptoObject", 0) != 0) continue;
        auto& plane = c.planes[name];
        plane.assign(size_t(c.width) * size_t(c.height), 0.f);
        fb.insert(name, Imf::Slice::Make(Imf::FLOAT, plane.data(), dw, sizeof(float),
                                         sizeof(float) * size_t(c.width)));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return c;
}

/// Every layer of `crop` equals the same pixels of `full`, bit for bit.
void checkSamePixels(const Film& full, const Film& crop) {
    REQUIRE(crop.width > 0);
    const auto same = [](const raylab::FilmPlane& a, size_t ia, const raylab::FilmPlane& b,
                         size_t ib, size_t n) {
        return std::memcmp(&a[ia * n], &b[ib * n], n * sizeof(float)) == 0;
    };
    int differing = 0;
    for (int y = 0; y < crop.height; ++y) {
        for (int x = 0; x < crop.width; ++x) {
            const size_t c = size_t(y) * crop.width + x;
            const size_t f = full.index(crop.originX + x, crop.originY + y);
            const bool ok = same(full.rgba, f, crop.rgba, c, 4) && same(full.z, f, crop.z, c, 1) &&
                            same(full.distance, f, crop.distance, c, 1) &&
                            same(full.normal, f, crop.normal, c, 3) &&
                            same(full.albedo, f, crop.albedo, c, 3) &&
                            same(full.objectId, f, crop.objectId, c, 1);
            differing += !ok;
        }
    }
    CHECK(differing == 0);
}

std::vector<unsigned char> readPngRgb(const std::string& path, int& w, int& h) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&image, path.c_str()));
    image.format = PNG_FORMAT_RGB;
    std::vector<unsigned char> px(PNG_IMAGE_SIZE(image));
    REQUIRE(png_image_finish_read(&image, nullptr, px.data(), 0, nullptr));
    w = int(image.width);
    h = int(image.height);
    return px;
}

}  // namespace

TEST_CASE("crop: the EXR's data window is the crop, its pixels those of the full frame") {
    cli::TempDir dir;
    const std::string scene = dir.write("s.json", kScene);
    // x: ceil(0.3·37) = 12 .. ceil(0.77·37) = 29 (exclusive); y: ceil(0.2·23) = 5 .. ceil(0.9·23) = 21.
    // The window starts and ends inside 16-pixel tiles.
    // Each mode with the Cryptomatte layers its sampling needs (one per two
    // objects a pixel's samples can see: 1 sample, 5, adaptive, 4 corners).
    const std::pair<std::string, size_t> modes[] = {{"", 1},
                                                    {"--spp 5 --seed 7", 3},
                                                    {"--adaptive 0.02 --adaptive-levels 2", 3},
                                                    {"--spd --width 37 --height 23", 2},
                                                    {"--min-weight 0.05 --depth 8", 1}};
    for (const auto& entry : modes) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& mode = entry.first;
        const auto& matteLayers = entry.second;
        CAPTURE(mode);
        const std::string common = " --float -q --threads 2 " + mode;
        REQUIRE(cli::run("render " + scene + " -o " + dir.file("full.exr") + " --png " +
                         dir.file("full.png") + common).exitCode == 0);
        const cli::Result r = cli::run("render " + scene + " -o " + dir.file("crop.exr") + " --png " +
                                       dir.file("crop.png") + " --crop 0.3,0.77,0.2,0.9" + common);
        REQUIRE_MESSAGE(r.exitCode == 0, r.err);
        const Film full = raylab::readExr(dir.file("full.exr"));
        const Film crop = raylab::readExr(dir.file("crop.exr"));
        CHECK(full.width == 37);
        CHECK(full.height == 23);
        CHECK_FALSE(full.isCrop());
        CHECK(crop.originX == 12);
        CHECK(crop.originY == 5);
        CHECK(crop.width == 29 - 12);
        CHECK(crop.height == 21 - 5);
        CHECK(crop.fullWidth == 37);
        CHECK(crop.fullHeight == 23);
        checkSamePixels(full, crop);
        // The Cryptomatte channels too, written through the same data window.
        const CryptoChannels fullMattes = readCryptoChannels(dir.file("full.exr"));
        const CryptoChannels cropMattes = readCryptoChannels(dir.file("crop.exr"));
        CHECK(cropMattes.x0 == 12);
        CHECK(cropMattes.y0 == 5);
        REQUIRE(cropMattes.planes.size() == 4 * matteLayers);
        REQUIRE(fullMattes.planes.size() == 4 * matteLayers);
        int differingMattes = 0;
        for (const auto& [name, plane] : cropMattes.planes)
            for (int y = 0; y < cropMattes.height; ++y)
                for (int x = 0; x < cropMattes.width; ++x)
                    differingMattes +=
                        std::memcmp(&plane[size_t(y) * cropMattes.width + x],
                                    &fullMattes.planes.at(name)[size_t(y + 5) * fullMattes.width + x + 12],
                                    sizeof(float)) != 0;
        CHECK(differingMattes == 0);

        // The PNG is the crop, the same 8-bit pixels as the full PNG's.
        int fw = 0, fh = 0, cw = 0, ch = 0;
        const std::vector<unsigned char> fp = readPngRgb(dir.file("full.png"), fw, fh);
        const std::vector<unsigned char> cp = readPngRgb(dir.file("crop.png"), cw, ch);
        REQUIRE(cw == crop.width);
        REQUIRE(ch == crop.height);
        int differing = 0;
        for (int y = 0; y < ch; ++y)
            differing += std::memcmp(&cp[size_t(y) * cw * 3], &fp[(size_t(y + 5) * fw + 12) * 3],
                                     size_t(cw) * 3) != 0;
        CHECK(differing == 0);
    }
}

TEST_CASE("crop: adjacent windows tile the frame, the whole window is the full render") {
    cli::TempDir dir;
    const std::string scene = dir.write("s.json", kScene);
    REQUIRE(cli::run("render " + scene + " -o " + dir.file("full.exr") + " -q --float").exitCode == 0);
    REQUIRE(cli::run("render " + scene + " -o " + dir.file("whole.exr") + " -q --float --crop 0,1,0,1")
                .exitCode == 0);
    // The same pixels and window; the header records the --crop flag, so the
    // files differ in that attribute only.
    const Film wholeFilm = raylab::readExr(dir.file("whole.exr"));
    const Film fullFilm = raylab::readExr(dir.file("full.exr"));
    CHECK(wholeFilm.originX == 0);
    CHECK(wholeFilm.originY == 0);
    CHECK(wholeFilm.width == fullFilm.width);
    CHECK(wholeFilm.height == fullFilm.height);
    checkSamePixels(fullFilm, wholeFilm);
    // Left and right halves at 0.5: pixels 0..18 and 19..36 (ceil(18.5) = 19).
    const cli::Result left = cli::run("render " + scene + " -o " + dir.file("l.exr") + " --float --crop=0,0.5,0,1");
    REQUIRE(left.exitCode == 0);
    CHECK(left.out.rfind("raylab: 37x23 (crop 19x23 at 0,0), ", 0) == 0);
    REQUIRE(cli::run("render " + scene + " -o " + dir.file("r.exr") + " -q --float --crop=0.5,1,0,1").exitCode == 0);
    const Film full = raylab::readExr(dir.file("full.exr"));
    const Film l = raylab::readExr(dir.file("l.exr")), r = raylab::readExr(dir.file("r.exr"));
    CHECK(l.originX == 0);
    CHECK(l.width == 19);
    CHECK(r.originX == 19);
    CHECK(r.width == 18);
    checkSamePixels(full, l);
    checkSamePixels(full, r);
}

TEST_CASE("crop: bad windows are usage errors") {
    cli::TempDir dir;
    const std::string scene = dir.write("s.json", kScene);
    for (const char* crop : {"0,1,0", "0,1,0,1,0", "0.5,0.4,0,1", "0,1,0.5,0.5", "-0.1,1,0,1",
                             "0,1.5,0,1", "a,b,c,d", "0,1,,1", "nan,1,0,1"}) {
        CAPTURE(crop);
        const cli::Result r = cli::run("render " + scene + " -o " + dir.file("x.exr") + " --crop '" + crop + "'");
        CHECK(r.exitCode == 2);
        CHECK(cli::lineCount(r.err) == 1);
        CHECK(r.err.find("--crop: expected X0,X1,Y0,Y1") != std::string::npos);
    }
    // Thinner than a pixel: ceil(0.01·37) = ceil(0.02·37) = 1.
    const cli::Result thin = cli::run("render " + scene + " -o " + dir.file("x.exr") + " --crop 0.01,0.02,0,1");
    CHECK(thin.exitCode == 2);
    CHECK(thin.err.find("--crop: the window holds no pixel of the 37x23 image") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.file("x.exr")));
}

// OpenEXR sits behind dlopen (renderer/io/exr_module.h): raylab writes ZIP
// and ZIPS files itself, header included, so its default output and PNGs
// never load OpenEXR's libraries; the other compressions and reading an EXR
// load the module on first use, and its files are the bytes OpenEXR writes.

#include <doctest/doctest.h>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStdIO.h>

#include <filesystem>
#include <string>

#include "renderer/io/errors.h"
#include "renderer/io/exr_module_loader.h"
#include "renderer/io/exr_reader.h"
#include "renderer/io/exr_writer.h"
#include "renderer/io/png_writer.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

using namespace raylab;
using raylab::test::errorLines;

namespace {

Film testFilm() {
    Film film(5, 3);
    for (size_t i = 0; i < film.rgba.size(); ++i) film.rgba[i] = float(i % 7) * 0.125f;
    return film;
}

/// A file's header as OpenEXR writes it, with the compression set to ZIP (so
/// two files of different compressions compare on everything else).
std::string headerBytes(const std::string& path) {
    Imf::InputFile file(path.c_str());
    Imf::Header header = file.header();
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::StdOSStream os;
    header.writeTo(os);
    return os.str();
}

}  // namespace

TEST_CASE("exr module: ZIP, ZIPS and PNG outputs never load it, the first PIZ file does") {
    // ctest runs every case in a process of its own; run with the other
    // cases of this executable, an earlier one may have loaded it already.
    if (exrModuleLoaded()) {
        MESSAGE("module loaded by an earlier case of this process; run alone to check");
        return;
    }
    test::TempDir dir;
    const Film film = testFilm();
    ExrOptions zip, zips, piz, rle;
    zips.compression = ExrCompression::Zips;
    piz.compression = ExrCompression::Piz;
    rle.compression = ExrCompression::Rle;
    writeExr(dir.file("zip.exr"), film, zip);
    writeExr(dir.file("zips.exr"), film, zips);
    writePng(dir.file("a.png"), film);
    prepareExrWriter(dir.file("zip.exr"), ExrCompression::Zip);
    CHECK_FALSE(exrModuleLoaded());
    writeExr(dir.file("piz.exr"), film, piz);
    CHECK(exrModuleLoaded());
    writeExr(dir.file("rle.exr"), film, rle);
    // Every file reads back (through the module) as the same pixels.
    const Film a = readExr(dir.file("zip.exr"));
    for (const char* name : {"zips.exr", "piz.exr", "rle.exr"}) {
        CAPTURE(name);
        const Film b = readExr(dir.file(name));
        REQUIRE(b.width == 5);
        REQUIRE(b.height == 3);
        CHECK(b.rgba == a.rgba);
        CHECK(b.objectId == a.objectId);
    }
}

TEST_CASE("exr module: its files carry the header raylab's own writer writes") {
    // Everything raylab puts in a header: strings (a Cryptomatte manifest of
    // 400 names), ints, the camera matrices, a crop window.
    test::TempDir dir;
    Film film(4, 3, 2, 1, 9, 7);
    ExrOptions zip, piz;
    zip.software = "raylab test";
    zip.settings = "spp 1";
    zip.scenePath = "scene.json";
    zip.frame = 3;
    zip.camera = CameraMatrices{};
    for (int k = 0; k < 400; ++k) zip.objectNames.push_back("object number " + std::to_string(k));
    piz = zip;
    piz.compression = ExrCompression::Piz;
    writeExr(dir.file("zip.exr"), film, zip);
    writeExr(dir.file("piz.exr"), film, piz);
    const std::string a = headerBytes(dir.file("zip.exr"));
    CHECK(a.find("object number 399") != std::string::npos);
    CHECK(a == headerBytes(dir.file("piz.exr")));
}

TEST_CASE("exr module: a module that cannot be loaded is one error line, before the render") {
    // A copy of raylab with a broken raylab-openexr.so beside it: the loader
    // takes the module beside the executable first, and reports it rather
    // than falling back to the build tree's.
    const test::TempDir dir;
    const std::string copy = dir.file("raylab");
    std::filesystem::copy_file(RAYLAB_BINARY, copy);
    dir.write("raylab-openexr.so", "not a shared object\n");
    const std::string scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json";
    const std::string render = copy + " render " + scene + " --width 16 --height 12 --quiet -o ";
    const test::CommandResult piz = test::runCommand(render + dir.file("piz.exr") + " --compression piz");
    CHECK(piz.exitCode == 1);
    const std::string line = "raylab: error: " + dir.file("piz.exr") +
                             ": cannot write EXR: OpenEXR is not available (" +
                             dir.file("raylab-openexr.so") + ": ";
    CHECK_MESSAGE(piz.err.rfind(line, 0) == 0, piz.err);
    CHECK_MESSAGE(errorLines(piz.err) == 1, piz.err);
    CHECK_FALSE(std::filesystem::exists(dir.file("piz.exr")));
    // ZIP, the default, is raylab's own: it does not need the module.
    const test::CommandResult zip = test::runCommand(render + dir.file("zip.exr"));
    CHECK_MESSAGE(zip.exitCode == 0, zip.err);
    CHECK(std::filesystem::exists(dir.file("zip.exr")));
    // Reading does.
    const test::CommandResult compare =
        test::runCommand(copy + " compare " + dir.file("zip.exr") + " " + dir.file("zip.exr"));
    CHECK(compare.exitCode == 1);
    CHECK_MESSAGE(compare.err.rfind("raylab: error: " + dir.file("zip.exr") +
                                        ": cannot read EXR: OpenEXR is not available (",
                                    0) == 0,
                  compare.err);
    CHECK_MESSAGE(errorLines(compare.err) == 1, compare.err);
}

TEST_CASE("exr module: reading loads it, and its errors name the file") {
    test::TempDir dir;
    const Film film = testFilm();
    writeExr(dir.file("a.exr"), film, ExrOptions{});
    const Film back = readExr(dir.file("a.exr"));
    CHECK(exrModuleLoaded());
    CHECK(back.fullWidth == 5);
    // R of pixel 2 is value 8: (8 % 7) * 0.125, exact in HALF.
    CHECK(back.rgba[8] == 0.125f);
    CHECK(back.rgba[3] == 0.375f);  // A of pixel 0: 3 * 0.125
    CHECK_THROWS_WITH_AS(readExr(dir.file("missing.exr")),
                         doctest::Contains("cannot read EXR"), InputError);
}

TEST_CASE("the raylab executable names no OpenEXR library: they are its module's") {
    // ld.so lists what it would load (as ldd does) and runs nothing.
    const test::CommandResult r =
        test::runCommand("LD_TRACE_LOADED_OBJECTS=1 '" + std::string(RAYLAB_BINARY) + "'");
    REQUIRE(r.exitCode == 0);
    REQUIRE(r.out.find("libembree3") != std::string::npos);  // the listing is there
    for (const char* lib : {"libOpenEXR", "libImath", "libIex", "libIlmThread"})
        CHECK_MESSAGE(r.out.find(lib) == std::string::npos, lib, "\n", r.out);
}

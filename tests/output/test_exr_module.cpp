// OpenEXR sits behind dlopen (renderer/io/exr_module.h): raylab writes ZIP
// and ZIPS files itself, header included, so its default output and PNGs
// never load OpenEXR's libraries; the other compressions and reading an EXR
// load the module on first use, and its files are the bytes OpenEXR writes.

#include <doctest/doctest.h>

#include <string>

#include "renderer/io/errors.h"
#include "renderer/io/exr_module_loader.h"
#include "renderer/io/exr_reader.h"
#include "renderer/io/exr_writer.h"
#include "renderer/io/png_writer.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

using namespace raylab;

namespace {

Film testFilm() {
    Film film(5, 3);
    for (size_t i = 0; i < film.rgba.size(); ++i) film.rgba[i] = float(i % 7) * 0.125f;
    return film;
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

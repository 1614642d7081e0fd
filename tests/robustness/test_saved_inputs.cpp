// Replays every saved input through the steps the fuzz targets take
// (tests/fuzz/fuzz_harness.h): the seed corpora, and the inputs under
// tests/robustness/inputs/ that once crashed, hung or escaped as the wrong
// exception. Inputs there are named <reader>-<what>.<ext>, reader being nff,
// json or obj (OBJ inputs carry their MTL after a "#MTL" line).
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz/fuzz_harness.h"
#include "fuzz/fuzz_scratch.h"
#include "robustness_helpers.h"

namespace fs = std::filesystem;
using namespace raylab::robust;

namespace {

std::vector<fs::path> filesIn(const fs::path& dir) {
    std::vector<fs::path> out;
    if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir))
            if (e.is_regular_file()) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

/// Runs one input through its reader's fuzz steps; "" when handled properly.
std::string replay(const std::string& reader, const std::string& bytes,
                   bool* accepted = nullptr) {
    raylab::test::TempDir dir;
    if (reader == "nff") return raylab::fuzz::runNffInput(bytes, accepted);
    if (reader == "json") {
        raylab::fuzz::writeJsonSideFiles(dir);
        return raylab::fuzz::runJsonInput(bytes, dir, accepted);
    }
    if (reader == "obj") return raylab::fuzz::runObjInput(bytes, dir, accepted);
    return "unknown reader '" + reader + "' in the file name";
}

const fs::path kSource = RAYLAB_SOURCE_DIR;

}  // namespace

TEST_CASE("saved inputs: the seed corpora load and render") {
    int count = 0;
    for (const std::string reader : {"nff", "json", "obj"}) {
        for (const fs::path& p : filesIn(kSource / "tests/fuzz/corpus" / reader)) {
            CAPTURE(p.string());
            bool accepted = false;
            CHECK(replay(reader, readFile(p.string()), &accepted) == "");
            CHECK(accepted);  // seeds are valid files
            ++count;
        }
    }
    CHECK(count >= 9);
}

TEST_CASE("saved inputs: every regression input is refused or rendered, never worse") {
    for (const fs::path& p : filesIn(kSource / "tests/robustness/inputs")) {
        const std::string name = p.filename().string();
        const std::string reader = name.substr(0, name.find('-'));
        CAPTURE(name);
        CHECK(replay(reader, readFile(p.string())) == "");
    }
}

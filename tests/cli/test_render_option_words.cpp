// `raylab render` with the flags that take a word (--accel, --bvh-quality,
// --precision, --effects) and the same words in the scene file: every word
// renders, any other is refused where it was typed (a flag: usage error, exit
// 2; the file: FILE:LINE, exit 1) without writing anything, and --help lists
// exactly the words the parser accepts.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_helpers.h"
#include "renderer/render_option_names.h"

using namespace raylab;

namespace {

/// A lit sphere; `render` is the members of its "render" block (line 4).
std::string tinyScene(const std::string& render = "") {
    return "{\"image\": {\"width\": 8, \"height\": 6},\n"
           "\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
           "\"render\": {\n" +
           render +
           "},\n"
           "\"lights\": [{\"type\": \"point\", \"position\": [2, 4, 3], \"color\": [1, 1, 1]}],\n"
           "\"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}]}\n";
}

struct WordFlag {
    std::string flag;
    std::vector<std::string> words;  ///< as README.md and --help document them
};

const std::vector<WordFlag> kFlags = {
    {"--accel", {"embree", "naive"}},
    {"--bvh-quality", {"low", "medium", "high"}},
    {"--precision", {"float", "double"}},
    {"--effects", {"auto", "all"}},
};

}  // namespace

TEST_CASE("cli: every word of --accel, --bvh-quality, --precision and --effects renders") {
    cli::TempDir dir;
    const std::string scene = dir.write("s.json", tinyScene());
    for (const WordFlag& f : kFlags) {
        for (const std::string& word : f.words) {
            CAPTURE(f.flag);
            CAPTURE(word);
            const cli::Result r = cli::run("render " + scene + " -o " + dir.file("o.exr") +
                                           " --stats " + dir.file("o.json") + " --quiet " +
                                           f.flag + " " + word);
            CHECK(r.exitCode == 0);
            CHECK(r.err.empty());
            const std::string stats = cli::readFile(dir.file("o.json"));
            if (f.flag == "--accel") CHECK(stats.find("\"accel\": \"" + word + "\"") != std::string::npos);
            // The general kernel names every effect; this scene alone has no reflection.
            if (f.flag == "--effects")
                CHECK((stats.find("\"reflection\"", stats.find("\"effects\"")) != std::string::npos) ==
                      (word == "all"));
        }
    }
}

TEST_CASE("cli: an unknown word after a flag is a usage error naming the words (exit 2)") {
    cli::TempDir dir;
    const std::string scene = dir.write("s.json", tinyScene());
    for (const WordFlag& f : kFlags) {
        for (const std::string& bad : std::vector<std::string>{"bogus", "", f.words.front() + " ", "EMBREE"}) {
            CAPTURE(f.flag);
            CAPTURE(bad);
            const cli::Result r = cli::run("render " + scene + " -o " + dir.file("o.exr") + " " +
                                           f.flag + " '" + bad + "'");
            CHECK(r.exitCode == 2);
            std::string list;
            for (const std::string& w : f.words) list += (list.empty() ? "" : "|") + w;
            CHECK(r.err == "raylab: error: " + f.flag + ": expected " + list + " (got '" + bad +
                               "')\n");
            CHECK_FALSE(std::filesystem::exists(dir.file("o.exr")));
        }
    }
}

TEST_CASE("cli: the scene file's words render, an unknown one is FILE:LINE (exit 1)") {
    cli::TempDir dir;
    for (const char* ok : {"\"accel\": \"naive\"", "\"bvh_quality\": \"low\"",
                           "\"precision\": \"float\""}) {
        CAPTURE(ok);
        const std::string scene = dir.write("ok.json", tinyScene(ok));
        const cli::Result r = cli::run("render " + scene + " -o " + dir.file("ok.exr") + " --quiet");
        CHECK(r.exitCode == 0);
    }
    const std::string bad = dir.write("bad.json", tinyScene("\"bvh_quality\": \"max\""));
    const cli::Result r = cli::run("render " + bad + " -o " + dir.file("bad.exr"));
    CHECK(r.exitCode == 1);
    CHECK(r.err == "raylab: error: " + bad +
                       ":4: render.bvh_quality: must be one of 'low', 'medium', 'high' (got 'max')\n");
    CHECK_FALSE(std::filesystem::exists(dir.file("bad.exr")));
}

TEST_CASE("cli: render --help lists exactly the words the parser accepts") {
    const cli::Result r = cli::run("render --help");
    REQUIRE(r.exitCode == 0);
    CHECK(r.out.find("--accel " + joinedNames(acceleratorNames(), "|")) != std::string::npos);
    CHECK(r.out.find("--bvh-quality " + joinedNames(bvhQualityNames(), "|")) != std::string::npos);
    CHECK(r.out.find("--precision " + joinedNames(precisionNames(), "|")) != std::string::npos);
}

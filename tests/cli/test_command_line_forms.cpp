// The command line as pbrt and Mitsuba users type it: "--flag=value" and
// "--flag value" alike, -q and -o, "did you mean" for a mistyped flag or
// command, "raylab help CMD", and every flag a command accepts in its --help.
#include <doctest/doctest.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "apps/commands.h"
#include "cli_helpers.h"

namespace fs = std::filesystem;
using raylab::CommandFlags;

namespace {

const std::string kScene = R"({
  "image": {"width": 20, "height": 12},
  "camera": {"type": "perspective", "eye": [0, 1, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
  "lights": [{"type": "point", "position": [2, 4, 3], "color": [1, 1, 1], "intensity": 1}],
  "materials": {"red": {"kd": [0.8, 0.1, 0.1]}},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"}]
})";

/// The option lines of a help text: lines "  --name ..." or "  -x, --name ...".
/// Each gives the long name and the character after it ('\n' at the line's end).
/// (Plain string scanning: GCC 12's <regex> warns under the sanitizers.)
std::vector<std::pair<std::string, char>> optionLines(const std::string& help) {
    std::vector<std::pair<std::string, char>> lines;
    std::istringstream in(help);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("  ", 0) != 0) continue;
        size_t at = 2;
        if (line.size() > at + 3 && line[at] == '-' && line[at + 1] >= 'a' && line[at + 1] <= 'z' &&
            line.compare(at + 2, 2, ", ") == 0)
            at += 4;  // "-q, "
        if (line.compare(at, 2, "--") != 0) continue;
        size_t end = at + 2;
        while (end < line.size() && ((line[end] >= 'a' && line[end] <= 'z') || line[end] == '-')) ++end;
        if (end == at + 2) continue;
        lines.emplace_back(line.substr(at, end - at), end < line.size() ? line[end] : '\n');
    }
    return lines;
}

std::vector<const CommandFlags*> allCommands() {
    return {&raylab::kRenderFlags,      &raylab::kAccuracyFlags,    &raylab::kCompareFlags,
            &raylab::kBenchAccelFlags,  &raylab::kBenchLimitFlags,  &raylab::kBenchEffectsFlags,
            &raylab::kBenchPrimitivesFlags, &raylab::kBenchTexturesFlags, &raylab::kBenchIngestFlags};
}

}  // namespace

TEST_CASE("command line: every flag a command accepts is in its --help, and the reverse") {
    for (const CommandFlags* c : allCommands()) {
        CAPTURE(c->command);
        const std::string help = c->help;
        const std::vector<std::pair<std::string, char>> options = optionLines(help);
        for (const raylab::FlagSpec& f : c->flags) {
            CAPTURE(f.name);
            // Listed as an option line: the name at the start of a line's text.
            bool inOptionList = false;
            for (const auto& [name, next] : options)
                inOptionList |= name == f.name && (next == ' ' || next == '=' || next == ',' || next == '\n');
            const bool inUsage = help.find(f.name) != std::string::npos;  // e.g. "[--width W ...]"
            CHECK((inOptionList || inUsage));
            if (!f.shortName.empty()) CHECK(help.find(f.shortName + ", " + f.name) != std::string::npos);
        }
        // Every option line of the help names a flag the parser knows.
        for (const auto& option : options) {
            const std::string& name = option.first;
            CAPTURE(name);
            CHECK((name == "--help" || c->find(name) != nullptr));
        }
    }
    // The flags the issue names in particular.
    CHECK(raylab::kRenderFlags.find("--effects") != nullptr);
    CHECK(std::string(raylab::kRenderHelp).find("--effects auto|all") != std::string::npos);
    CHECK(raylab::kRenderFlags.find("-q") != nullptr);
    CHECK(raylab::kAccuracyFlags.find("-q") != nullptr);
}

TEST_CASE("command line: --flag=value and --flag value give the same render") {
    cli::TempDir dir;
    const std::string scene = dir.write("s.json", kScene);
    const cli::Result spaced = cli::run("render " + scene + " -o " + dir.file("a.exr") +
                                        " --width 16 --height 9 --spp 4 --accel naive -q");
    const cli::Result joined = cli::run("render " + scene + " --output=" + dir.file("b.exr") +
                                        " --width=16 --height=9 --spp=4 --accel=naive --quiet");
    REQUIRE(spaced.exitCode == 0);
    REQUIRE(joined.exitCode == 0);
    CHECK(spaced.out.empty());  // -q: no summary
    CHECK(joined.out.empty());
    CHECK(cli::readFile(dir.file("a.exr")) == cli::readFile(dir.file("b.exr")));
    // Without -q: the summary on stdout, and no progress bar on a non-terminal.
    const cli::Result loud = cli::run("render " + scene + " -o " + dir.file("c.exr"));
    CHECK(loud.exitCode == 0);
    CHECK(loud.out.find("raylab: 20x12") != std::string::npos);
    CHECK(loud.err.empty());
}

TEST_CASE("command line: the '=' form in every command") {
    cli::TempDir dir;
    const std::string scene = dir.write("s.json", kScene);
    CHECK(cli::run("compare --threshold=0.5 " + scene).exitCode == 2);  // one file: usage, not the flag
    CHECK(cli::run("bench primitives --iterations=x").err.find("--iterations: expected an integer") !=
          std::string::npos);
    CHECK(cli::run("bench accel --runs=0").err.find("--runs: expected an integer in [1, 1000] (got '0')") !=
          std::string::npos);
    CHECK(cli::run("bench limit " + scene + " --runs=0").err.find("--runs: expected an integer") !=
          std::string::npos);
    CHECK(cli::run("bench effects " + scene + " --width=0").err.find("--width: expected an integer") !=
          std::string::npos);
    CHECK(cli::run("accuracy " + scene + " --visible=-1").err.find("--visible: expected an integer") !=
          std::string::npos);
    // A flag that takes no value refuses one; an empty value is a bad value.
    const cli::Result q = cli::run("render " + scene + " -o " + dir.file("x.exr") + " --quiet=yes");
    CHECK(q.exitCode == 2);
    CHECK(q.err == "raylab: error: --quiet: takes no value (got '--quiet=yes')\n");
    const cli::Result empty = cli::run("render " + scene + " -o " + dir.file("x.exr") + " --width=");
    CHECK(empty.exitCode == 2);
    CHECK(empty.err.find("--width: expected an integer in [1, 65536] (got '')") != std::string::npos);
    // Given twice, in either form.
    const cli::Result twice = cli::run("render " + scene + " -o " + dir.file("x.exr") + " --width=4 --width 5");
    CHECK(twice.exitCode == 2);
    CHECK(twice.err.find("--width: given more than once") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.file("x.exr")));
    // -o is the one repeatable flag (one output per use), in either form too.
    const cli::Result outTwice = cli::run("render " + scene + " -o " + dir.file("x.exr") +
                                          " --output=" + dir.file("y.exr") + " -q");
    CHECK(outTwice.exitCode == 0);
    CHECK(outTwice.err.empty());
    CHECK(cli::readFile(dir.file("x.exr")) == cli::readFile(dir.file("y.exr")));
}

TEST_CASE("command line: did you mean, for flags, commands and benchmarks") {
    cli::TempDir dir;
    const std::string scene = dir.write("s.json", kScene);
    const cli::Result flag = cli::run("render " + scene + " -o " + dir.file("x.exr") + " --wdith 5");
    CHECK(flag.exitCode == 2);
    CHECK(flag.err ==
          "raylab: error: render: unknown option '--wdith' (did you mean '--width'?) (see 'raylab "
          "render --help')\n");
    CHECK(cli::run("render " + scene + " -o x.exr --adaptive-level=2").err.find(
              "did you mean '--adaptive-levels'?") != std::string::npos);
    CHECK(cli::run("accuracy " + scene + " --refrence-spp 4").err.find(
              "did you mean '--reference-spp'?") != std::string::npos);
    CHECK(cli::run("bench accel --naive-budgte 1").err.find("did you mean '--naive-budget'?") !=
          std::string::npos);
    const cli::Result far = cli::run("render " + scene + " -o x.exr --frobnicate");
    CHECK(far.exitCode == 2);
    CHECK(far.err.find("unknown option '--frobnicate' (see 'raylab render --help')") != std::string::npos);

    const cli::Result command = cli::run("rendr " + scene);
    CHECK(command.exitCode == 2);
    CHECK(command.err == "raylab: error: unknown command 'rendr' (did you mean 'render'?)\n");
    CHECK(cli::run("--verison").err.find("did you mean '--version'?") != std::string::npos);
    const cli::Result bench = cli::run("bench acel");
    CHECK(bench.exitCode == 2);
    CHECK(bench.err == "raylab: error: bench: unknown benchmark 'acel' (did you mean 'accel'?)\n");
}

TEST_CASE("command line: raylab help CMD is raylab CMD --help, --version is listed") {
    const cli::Result main = cli::run("help");
    CHECK(main.exitCode == 0);
    CHECK(main.out.find("--version") != std::string::npos);
    CHECK(main.out.find("raylab help <command>") != std::string::npos);
    for (const char* command : {"render", "accuracy", "compare", "bench", "bench accel", "bench limit",
                                "bench effects", "bench primitives"}) {
        CAPTURE(command);
        const cli::Result viaHelp = cli::run(std::string("help ") + command);
        const cli::Result viaFlag = cli::run(std::string(command) + " --help");
        CHECK(viaHelp.exitCode == 0);
        CHECK(viaFlag.exitCode == 0);
        CHECK(viaHelp.out == viaFlag.out);
        CHECK(viaHelp.out.rfind("usage: raylab", 0) == 0);
    }
    CHECK(cli::run("help rendr").err.find("did you mean 'render'?") != std::string::npos);
    const cli::Result version = cli::run("--version");
    CHECK(version.exitCode == 0);
    CHECK(version.out.rfind("raylab ", 0) == 0);
}

// The measurement commands' help texts live in apps/ (the front end owns its
// words): each one is printed by --help, starts with its usage line, and names
// every option its parser accepts; an unknown option is a usage error.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "cli_helpers.h"

namespace {

struct Command {
    std::string name;                ///< as typed after "raylab"
    std::vector<std::string> flags;  ///< every option the command's parser accepts
};

const std::vector<Command> kCommands = {
    {"bench", {}},
    {"bench accel",
     {"--width", "--height", "--runs", "--threads", "--naive-budget", "--out", "--plot", "--quick"}},
    {"bench limit", {"--width", "--height", "--runs", "--threads", "--spd", "--out"}},
    {"bench effects", {"--width", "--height", "--runs", "--threads", "--spd"}},
    {"bench primitives", {"--iterations"}},
    {"accuracy",
     {"--width", "--height", "--runs", "--threads", "--reference-spp", "--knobs", "--visible",
      "--quick", "--out", "--plot", "--quiet"}},
    {"compare", {"--threshold"}},
};

}  // namespace

TEST_CASE("cli: every measurement command prints its help, naming each of its options") {
    for (const Command& c : kCommands) {
        CAPTURE(c.name);
        const cli::Result r = cli::run(c.name + " --help");
        CHECK(r.exitCode == 0);
        CHECK(r.err.empty());
        CHECK(r.out.rfind("usage: raylab " + c.name + " ", 0) == 0);
        for (const std::string& flag : c.flags) CHECK_MESSAGE(r.out.find(flag) != std::string::npos, flag);
    }
}

TEST_CASE("cli: an unknown option of a measurement command is a usage error (exit 2)") {
    for (const Command& c : kCommands) {
        if (c.name == "bench") continue;  // its first word names the benchmark
        CAPTURE(c.name);
        const cli::Result r = cli::run(c.name + " --no-such-option");
        CHECK(r.exitCode == 2);
        CHECK(cli::lineCount(r.err) == 1);
        CHECK(r.err.find("--no-such-option") != std::string::npos);
    }
}

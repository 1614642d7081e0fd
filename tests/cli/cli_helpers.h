#pragma once
// Runs the built raylab binary and captures its exit code and output; the
// scratch directory and file reading the CLI tests share with the others.

#include <string>

#include "support/run_command.h"
#include "support/temp_dir.h"

namespace cli {

using raylab::test::readFile;
using raylab::test::TempDir;

using Result = raylab::test::CommandResult;

/// Runs `raylab ARGS` (ARGS already shell-quoted as needed).
inline Result run(const std::string& args) {
    return raylab::test::runCommand(std::string(RAYLAB_BINARY) + " " + args);
}

inline int lineCount(const std::string& s) {
    int n = 0;
    for (char c : s) n += c == '\n';
    return n;
}

}  // namespace cli

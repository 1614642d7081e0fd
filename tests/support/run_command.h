#pragma once
// Runs a shell command line (the raylab binary, mpirun, ...) the way a user's
// shell would, with no input, and captures its exit code, stdout and stderr.

#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "support/temp_dir.h"

namespace raylab::test {

struct CommandResult {
    int exitCode = -1;  ///< 128 + signal number when a signal ended it
    std::string out;    ///< stdout
    std::string err;    ///< stderr
};

/// Runs `command` through /bin/sh (already shell-quoted as needed), stdin from /dev/null.
inline CommandResult runCommand(const std::string& command) {
    const TempDir io;
    const std::string cmd =
        command + " >" + io.file("out") + " 2>" + io.file("err") + " </dev/null";
    const int status = std::system(cmd.c_str());
    CommandResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = readFile(io.file("out"));
    r.err = readFile(io.file("err"));
    return r;
}

/// How many lines of `text` start with "raylab: error:" (a failure is one).
inline int errorLines(const std::string& text) {
    int n = text.rfind("raylab: error:", 0) == 0;
    for (size_t at = text.find("\nraylab: error:"); at != std::string::npos;
         at = text.find("\nraylab: error:", at + 1))
        ++n;
    return n;
}

}  // namespace raylab::test

#pragma once
// How the raylab process reacts to signals and to closed standard streams.
//
// SIGINT, SIGTERM, SIGHUP: the first one asks every phase to stop
// (requestCancel, renderer/cancel.h); the command unwinds from its next check
// point, removes its temporaries and exits 128+signal with one line. A phase
// without check points (a parse inside tinyobjloader, an EXR being
// compressed, one very deep ray tree) is ended from outside instead: a
// watchdog thread waits kForcedExitDelaySeconds (a second signal: not at all),
// then removes the temporaries, prints the same line and _exits, but never
// while an output commit is renaming files (it waits for the commit, which
// sees the request and undoes its renames).
// SIGPIPE is ignored: a closed stdout pipe does not fail a finished render.
// File descriptors 0-2, when closed, are opened on /dev/null, so that no
// output file can be given descriptor 1 or 2 and receive messages.

#include <string>

namespace raylab {

constexpr double kForcedExitDelaySeconds = 0.5;

/// Installs the handlers and starts the watchdog; first thing in main().
void installSignalHandling();

/// What an interruption would leave behind if it came now, for its message:
/// "no output written", "frames 1-3 written, 4 and later not", ...
void setInterruptOutcome(const std::string& outcome);

/// Prints "raylab: interrupted by SIG...: <outcome>" unless the watchdog
/// already did (one line either way) and returns 128 + the signal.
int reportInterrupted();

/// The command is returning: the watchdog no longer prints or exits.
void claimExit();

}  // namespace raylab

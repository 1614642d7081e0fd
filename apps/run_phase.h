#pragma once
// The phases of `raylab render`, marked as the command enters them. A test
// hook: with RAYLAB_TEST_STOP_AT=<phase> (or <phase>:<n>) in the environment,
// the process stops itself (SIGSTOP) on entering that phase the first (n-th)
// time, so that the signal tests can deliver a signal in exactly that phase
// (stopped, signal, SIGCONT) without guessing from timings.

namespace raylab {

enum class Phase { Parse, Build, Render, Write, Commit };

/// "parse", "build", "render", "write", "commit".
const char* phaseName(Phase phase);

void enterPhase(Phase phase);

}  // namespace raylab

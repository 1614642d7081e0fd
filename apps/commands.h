#pragma once
// Sub-commands of the raylab executable. Each returns the process exit code
// and throws UsageError (exit 2) or InputError (exit 1) on bad input.

#include <atomic>
#include <string>
#include <vector>

namespace raylab {

/// Set by the SIGINT handler; long-running commands poll it.
extern std::atomic<bool> g_interrupted;

int renderCommand(const std::vector<std::string>& args, const std::string& commandLine);
int benchCommand(const std::vector<std::string>& args);
int accuracyCommand(const std::vector<std::string>& args);
int compareCommand(const std::vector<std::string>& args);

extern const char* const kRenderHelp;

}  // namespace raylab

#pragma once
// Sub-commands of the raylab executable. Each returns the process exit code
// and throws UsageError (exit 2) or InputError (exit 1) on bad input.

#include <atomic>
#include <string>
#include <vector>

#include "apps/arg_parser.h"
#include "renderer/cancel.h"

namespace raylab {

/// Set by the SIGINT, SIGTERM and SIGHUP handlers (apps/signals.h); long-running
/// commands poll it. The process-wide stop request of renderer/cancel.h.
inline std::atomic<bool>& g_interrupted = g_cancelRequested;

int renderCommand(const std::vector<std::string>& args);
int benchCommand(const std::vector<std::string>& args);
int accuracyCommand(const std::vector<std::string>& args);
int compareCommand(const std::vector<std::string>& args);

extern const char* const kRenderHelp;

/// The flags of every command and benchmark (help text included), for the
/// tests that check each is in its --help.
extern const CommandFlags kRenderFlags, kAccuracyFlags, kCompareFlags, kBenchAccelFlags,
    kBenchLimitFlags, kBenchEffectsFlags, kBenchPrimitivesFlags, kBenchTexturesFlags,
    kBenchIngestFlags;

}  // namespace raylab

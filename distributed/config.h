#pragma once
// How the distributed renderer waits, and what the environment may change
// about it (docs/distributed.md): RAYLAB_MPI_TIMEOUT and RAYLAB_MPI_ROOT_RENDERS.

#include <chrono>

namespace raylab {

/// Idle wait of the MPI threads between polls: short against a tile's render
/// time, long enough that polling costs no noticeable CPU.
constexpr auto kPollInterval = std::chrono::microseconds(500);

/// Seconds of silence after which a peer counts as failed: RAYLAB_MPI_TIMEOUT,
/// default 120. Throws std::runtime_error when it is not a number > 0.
double timeoutSeconds();

/// False when RAYLAB_MPI_ROOT_RENDERS=0 and there are other ranks: rank 0
/// then only serves the queue and assembles the frame (when it runs on a
/// login node, or to measure the workers alone).
bool rootRenders(int ranks);

}  // namespace raylab

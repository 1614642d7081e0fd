#pragma once
// Before the first frame of an MPI job, the ranks check that they render the
// same picture: every rank sends rank 0 its RenderIdentity (render_identity.h),
// rank 0 compares each with its own and tells every rank the verdict.

#include <string>

#include "distributed/mpi_session.h"
#include "distributed/render_identity.h"

namespace raylab {

/// "" when every rank's identity equals rank 0's (and without mpirun or with
/// one rank); otherwise, on every rank, the line naming the first rank that
/// differs and what differs (disagreement()). Every rank must call it once,
/// before its first renderDistributed. A rank silent for RAYLAB_MPI_TIMEOUT
/// seconds makes the waiting side throw std::runtime_error.
std::string compareRanks(const MpiSession& mpi, const RenderIdentity& mine);

}  // namespace raylab

#pragma once
// <mpi.h>, its C API only: Open MPI's and MPICH's deprecated C++ bindings
// would otherwise be pulled in with their warnings. Included only by the
// MPI module (mpi_module.cpp), the one file that calls MPI.

#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#pragma once
// The scratch directory of the fuzz targets that must hand the loader a real
// file (the OBJ reader opens its MTL libraries by name): one per process,
// removed at exit. A failure to create or write it throws, which ends the
// fuzzer at once, as it must.

#include "support/temp_dir.h"

namespace raylab::fuzz {

/// The process-wide scratch directory (created on first use).
inline test::TempDir& scratch() {
    static test::TempDir dir;
    return dir;
}

}  // namespace raylab::fuzz

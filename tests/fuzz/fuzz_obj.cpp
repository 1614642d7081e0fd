// libFuzzer target: the OBJ/MTL path. The input is split at the first line
// "#MTL": the bytes before it become fuzz.obj, those after it fuzz.mtl, in a
// scratch directory; the OBJ is then loaded the way `raylab render x.obj`
// loads it (loadObjScene: the OBJ and MTL parsers, the MTL mapping,
// the auto-framed camera) and the scene goes through a tiny render.
//
// loadObjScene prints warnings to stderr; run with -close_fd_mask=2 to keep
// the fuzzer's own output readable (scripts/fuzz.sh does).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_harness.h"
#include "fuzz_scratch.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string problem = raylab::fuzz::runObjInput(
        std::string(reinterpret_cast<const char*>(data), size), raylab::fuzz::scratch());
    if (!problem.empty()) {
        std::fprintf(stderr, "raylab fuzz finding: %s\n", problem.c_str());
        std::abort();  // libFuzzer saves the input as crash-<sha1>
    }
    return 0;
}

// libFuzzer target: the JSON scene reader on arbitrary bytes (loadJsonScene),
// then the accepted scene through a tiny render (fuzz_harness.h). The scene
// lives in a scratch directory holding a small mesh.obj + mesh.mtl, so
// {"type": "mesh", "file": "mesh.obj"} objects exercise the mesh path too.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_harness.h"
#include "fuzz_scratch.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    raylab::fuzz::writeJsonSideFiles(raylab::fuzz::scratch());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string problem = raylab::fuzz::runJsonInput(
        std::string(reinterpret_cast<const char*>(data), size), raylab::fuzz::scratch());
    if (!problem.empty()) {
        std::fprintf(stderr, "raylab fuzz finding: %s\n", problem.c_str());
        std::abort();  // libFuzzer saves the input as crash-<sha1>
    }
    return 0;
}

// libFuzzer target: the NFF reader on arbitrary bytes (loadNffScene), then
// the accepted scene through a tiny render (fuzz_harness.h).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string problem =
        raylab::fuzz::runNffInput(std::string(reinterpret_cast<const char*>(data), size));
    if (!problem.empty()) {
        std::fprintf(stderr, "raylab fuzz finding: %s\n", problem.c_str());
        std::abort();  // libFuzzer saves the input as crash-<sha1>
    }
    return 0;
}

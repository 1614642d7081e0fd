// libFuzzer target: the OBJ/MTL path. The input is split at the first line
// "#MTL": the bytes before it become fuzz.obj, those after it fuzz.mtl, in a
// scratch directory; the OBJ is then loaded the way `raylab render x.obj`
// loads it (loadObjScene: the OBJ and MTL parsers, the MTL mapping,
// the auto-framed camera) and the scene goes through a tiny render.
//
// The OBJ part is also read by raylab's parser and by tinyobjloader and
// compared (tests/support/obj_differential.h, issue 20 bar 4): a file
// tinyobjloader refuses must be refused, a file both read must give the same
// vertices, faces, smoothing groups and material names (up to the documented
// differences), and the parse in 13-byte chunks must equal the parse in one.
//
// loadObjScene prints warnings to stderr; run with -close_fd_mask=2 to keep
// the fuzzer's own output readable (scripts/fuzz.sh does).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_harness.h"
#include "fuzz_scratch.h"
#include "support/obj_differential.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    const size_t cut = bytes.find(raylab::fuzz::kMtlSeparator);
    const raylab::test::ObjDifferential d = raylab::test::compareObjParsers(
        cut == std::string::npos ? bytes : bytes.substr(0, cut + 1));
    if (!d.mismatch.empty()) {
        std::fprintf(stderr, "raylab fuzz finding: raylab and tinyobjloader differ: %s\n",
                     d.mismatch.c_str());
        std::abort();
    }
    const std::string problem = raylab::fuzz::runObjInput(bytes, raylab::fuzz::scratch());
    if (!problem.empty()) {
        std::fprintf(stderr, "raylab fuzz finding: %s\n", problem.c_str());
        std::abort();  // libFuzzer saves the input as crash-<sha1>
    }
    return 0;
}

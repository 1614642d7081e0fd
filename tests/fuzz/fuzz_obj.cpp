// libFuzzer target: the OBJ/MTL path. The input is split at the first line
// "#MTL": the bytes before it become fuzz.obj, those after it fuzz.mtl, in a
// scratch directory; the OBJ is then loaded the way `raylab render x.obj`
// loads it (loadObjScene: tinyobjloader, our index checks, the MTL mapping,
// the auto-framed camera) and the scene goes through a tiny render.
//
// loadObjScene prints warnings to stderr; run with -close_fd_mask=2 to keep
// the fuzzer's own output readable (scripts/fuzz.sh does).

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_harness.h"
#include "fuzz_scratch.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const char kSeparator[] = "\n#MTL\n";
    const char* bytes = reinterpret_cast<const char*>(data);
    const std::string input(bytes, size);
    const size_t cut = input.find(kSeparator);
    const raylab::fuzz::ScratchDir& dir = raylab::fuzz::scratch();
    std::string objPath;
    if (cut == std::string::npos) {
        objPath = dir.write("fuzz.obj", bytes, size);
        dir.write("fuzz.mtl", "", 0);
    } else {
        objPath = dir.write("fuzz.obj", bytes, cut + 1);
        const size_t mtlStart = cut + std::strlen(kSeparator);
        dir.write("fuzz.mtl", bytes + mtlStart, size - mtlStart);
    }
    try {
        raylab::Scene scene = raylab::loadObjScene(objPath);
        raylab::fuzz::exerciseScene(scene);
    } catch (const raylab::InputError&) {
        // Refused with a located message: the expected outcome for bad input.
    }
    return 0;
}

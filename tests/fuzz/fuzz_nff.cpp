// libFuzzer target: the NFF reader on arbitrary bytes (loadNffScene), then
// the accepted scene through a tiny render (fuzz_harness.h).

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_harness.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        raylab::Scene scene = raylab::loadNffScene(text, "fuzz.nff");
        raylab::fuzz::exerciseScene(scene);
    } catch (const raylab::InputError&) {
        // Refused with a located message: the expected outcome for bad input.
    }
    return 0;
}

// libFuzzer target: the JSON scene reader on arbitrary bytes (loadJsonScene),
// then the accepted scene through a tiny render (fuzz_harness.h). The scene
// "lives" in a scratch directory holding a small mesh.obj + mesh.mtl, so
// {"type": "mesh", "file": "mesh.obj"} objects exercise the mesh path too.

#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_harness.h"
#include "fuzz_scratch.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"

namespace {

const char* const kMeshObj =
    "mtllib mesh.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vn 0 0 1\n"
    "usemtl glass\n"
    "f 1//1 2//1 3//1\n"
    "usemtl red\n"
    "f 1 3 4\n";
const char* const kMeshMtl =
    "newmtl red\nKd 0.8 0.1 0.1\nKs 0.2 0.2 0.2\nNs 20\nillum 2\n"
    "newmtl glass\nKd 0 0 0\nKs 1 1 1\nTf 0.9 0.9 0.9\nNi 1.5\nillum 7\n";

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    raylab::fuzz::scratch().write("mesh.obj", kMeshObj);
    raylab::fuzz::scratch().write("mesh.mtl", kMeshMtl);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string path = raylab::fuzz::scratch().file("fuzz.json");
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        raylab::Scene scene = raylab::loadJsonScene(text, path);
        raylab::fuzz::exerciseScene(scene);
    } catch (const raylab::InputError&) {
        // Refused with a located message: the expected outcome for bad input.
    }
    return 0;
}

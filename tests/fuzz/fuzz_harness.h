#pragma once
// What the fuzz targets do with one input, shared with the regression tests
// (tests/robustness/test_saved_inputs.cpp), which replay saved inputs through
// exactly the same steps.
//
// A reader either refuses the input with raylab::InputError, or returns a
// scene the rest of the pipeline must be able to use: every accepted scene
// goes through the steps of `raylab render` (option resolution, the memory
// budget, an accelerator, a render) at 4x3 pixels, depth 3, single-threaded,
// with the naive accelerator. Any other exception, or a non-finite pixel, is
// a finding; crashes and sanitizer reports are findings by themselves.

#include <cmath>
#include <cstring>
#include <exception>
#include <memory>
#include <string>

#include "fuzz_scratch.h"
#include "renderer/accel/accelerator.h"
#include "renderer/accelerator_kind.h"
#include "renderer/effects.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "renderer/scene.h"

namespace raylab::fuzz {

/// Renders an accepted scene at 4x3 pixels; returns "" or the problem found.
/// An InputError from the memory budget is a proper refusal.
inline std::string exerciseScene(Scene& scene) {
    // The budget check sees the scene's own resolution (it must refuse absurd
    // ones instead of failing later); the render itself is tiny.
    checkMemoryBudget(scene, resolveRenderOptions(scene, RenderOverrides{}));

    RenderOverrides tiny;
    tiny.width = 4;
    tiny.height = 3;
    tiny.maxDepth = 3;
    tiny.spp = 1;
    tiny.threads = 1;
    tiny.accel = AcceleratorKind::Naive;
    const RenderOptions options = resolveRenderOptions(scene, tiny);
    const std::unique_ptr<Accelerator> accel =
        makeAccelerator(options.accel, scene, options.accelOptions);
    const EffectSet effects = analyseEffects(scene, options);

    // FrameRenderer directly rather than render(): no TBB pool per input.
    const FrameRenderer frame(scene, *accel, options, effects);
    FrameBuffers buffers = frame.makeBuffers();
    WorkCounters counters;
    for (int item = 0; item < frame.workItemCount(); ++item)
        frame.renderWorkItem(item, buffers, counters);
    frame.finish(buffers);
    for (float v : buffers.film.rgba)
        if (!std::isfinite(v)) return "non-finite pixel in the film";
    return "";
}

/// Runs `load` then exerciseScene; returns "" when the input was rendered or
/// refused with InputError, else a description of the finding. `accepted`
/// (optional) tells whether the reader accepted the input.
template <class Load>
std::string loadAndExercise(Load&& load, bool* accepted) {
    if (accepted) *accepted = false;
    try {
        Scene scene = load();
        if (accepted) *accepted = true;
        return exerciseScene(scene);
    } catch (const InputError&) {
        return "";  // refused with a located message: the right outcome for bad input
    } catch (const std::exception& e) {
        return std::string("exception other than InputError: ") + e.what();
    } catch (...) {
        return "exception of unknown type";
    }
}

/// The NFF reader on `bytes`.
inline std::string runNffInput(const std::string& bytes, bool* accepted = nullptr) {
    return loadAndExercise([&] { return loadNffScene(bytes, "fuzz.nff"); }, accepted);
}

/// A small OBJ and MTL that JSON inputs can name as {"type": "mesh", "file": "mesh.obj"}.
inline void writeJsonSideFiles(const test::TempDir& dir) {
    dir.write("mesh.obj",
              "mtllib mesh.mtl\n"
              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
              "vn 0 0 1\n"
              "usemtl glass\n"
              "f 1//1 2//1 3//1\n"
              "usemtl red\n"
              "f 1 3 4\n");
    dir.write("mesh.mtl",
              "newmtl red\nKd 0.8 0.1 0.1\nKs 0.2 0.2 0.2\nNs 20\nillum 2\n"
              "newmtl glass\nKd 0 0 0\nKs 1 1 1\nTf 0.9 0.9 0.9\nNi 1.5\nillum 7\n");
}

/// The JSON scene reader on `bytes`, as the file fuzz.json in `dir` (which
/// must hold the side files of writeJsonSideFiles).
inline std::string runJsonInput(const std::string& bytes, const test::TempDir& dir,
                                bool* accepted = nullptr) {
    const std::string path = dir.file("fuzz.json");
    return loadAndExercise([&] { return loadJsonScene(bytes, path); }, accepted);
}

/// The line that separates the OBJ from the MTL in an OBJ fuzz input.
constexpr const char* kMtlSeparator = "\n#MTL\n";

/// The OBJ path on `bytes`: the bytes up to the first "#MTL" line become
/// fuzz.obj, the rest fuzz.mtl, in `dir`; then loadObjScene, as
/// `raylab render fuzz.obj` does.
inline std::string runObjInput(const std::string& bytes, const test::TempDir& dir,
                               bool* accepted = nullptr) {
    const size_t cut = bytes.find(kMtlSeparator);
    std::string objPath;
    if (cut == std::string::npos) {
        objPath = dir.write("fuzz.obj", bytes);
        dir.write("fuzz.mtl", "");
    } else {
        objPath = dir.write("fuzz.obj", bytes.substr(0, cut + 1));
        dir.write("fuzz.mtl", bytes.substr(cut + std::strlen(kMtlSeparator)));
    }
    return loadAndExercise([&] { return loadObjScene(objPath); }, accepted);
}

}  // namespace raylab::fuzz

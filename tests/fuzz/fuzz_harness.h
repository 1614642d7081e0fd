#pragma once
// Shared by the libFuzzer targets: what to do with a scene a reader accepted.
//
// A reader that returns normally must have produced a scene the rest of the
// pipeline can use, so every accepted scene goes through the same steps as
// `raylab render`: option resolution, the memory budget, the naive
// accelerator and a tiny single-threaded render (4x3 pixels, depth 3). Only
// raylab::InputError counts as a proper refusal; any other exception, a
// crash, a sanitizer report or a non-finite pixel is a finding.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/io/errors.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "renderer/scene.h"

namespace raylab::fuzz {

/// Stops the fuzzer with a message; libFuzzer saves the input as a crash.
[[noreturn]] inline void finding(const char* what) {
    std::fprintf(stderr, "raylab fuzz finding: %s\n", what);
    std::abort();
}

/// Runs an accepted scene through the render pipeline at 4x3 pixels.
/// Returns normally when the scene is rendered or refused with InputError.
inline void exerciseScene(Scene& scene) {
    try {
        // The budget check sees the scene's own resolution (it must refuse
        // absurd ones instead of failing later); the render itself is tiny.
        RenderOptions own = resolveRenderOptions(scene, RenderOverrides{});
        checkMemoryBudget(scene, own);

        RenderOverrides tiny;
        tiny.width = 4;
        tiny.height = 3;
        tiny.maxDepth = 3;
        tiny.spp = 1;
        tiny.threads = 1;
        tiny.accel = "naive";
        const RenderOptions options = resolveRenderOptions(scene, tiny);
        applyPrecision(scene, options.precision);
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
            if (!std::isfinite(v)) finding("non-finite pixel in the film");
    } catch (const InputError&) {
        // A refusal (memory budget): the correct outcome for bad input.
    }
}

}  // namespace raylab::fuzz

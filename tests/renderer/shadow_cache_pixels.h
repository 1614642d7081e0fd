#pragma once
// Shared by the tests that the shadow cache changes no pixel (cut-outs,
// filtered and opaque shadows through glass, a mirror): every pixel centre
// traced with and without a cache, through both accelerators. Only Embree
// with opaque feelers (or filtered ones without a surface filter) keeps a
// cache (Accelerator::usesOcclusionHints); elsewhere both paths are the same.

#include <doctest/doctest.h>

#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/render_options.h"
#include "renderer/scene.h"
#include "renderer/shadow_cache.h"
#include "renderer/whitted_integrator.h"

namespace raylab {

/// The pixel centres of a width x height view of `scene`, row by row, each
/// traced twice through `integrator`: with one shadow cache carried from
/// pixel to pixel (as a render's worker carries it, so one pixel's occluder
/// is the next one's hint) and without a cache. Checks that both give the
/// same bits; returns the pixels.
inline std::vector<Color> pixelsWithAndWithoutCache(const Scene& scene,
                                                    const WhittedIntegrator& integrator,
                                                    int width, int height) {
    ShadowCache cache;
    std::vector<Color> pixels;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray = scene.camera.generateRay(x + 0.5, y + 0.5, width, height);
            RayCounters counters;
            SampleRays spent;
            const Color cached = integrator.Li(ray, counters, nullptr, spent, &cache);
            const Color uncached = integrator.Li(ray, counters, nullptr, spent, nullptr);
            CAPTURE(x);
            CAPTURE(y);
            CHECK(cached.r == uncached.r);
            CHECK(cached.g == uncached.g);
            CHECK(cached.b == uncached.b);
            pixels.push_back(cached);
        }
    }
    return pixels;
}

/// pixelsWithAndWithoutCache through the naive loop and through Embree (two
/// independent paths): checks that both give the same bits at every pixel;
/// returns the pixels.
inline std::vector<Color> pixelsInBothAccelerators(const Scene& scene, const Accelerator& naive,
                                                   const Accelerator& embree,
                                                   const RenderOptions& options,
                                                   const EffectSet& effects, int width,
                                                   int height) {
    const WhittedIntegrator fromNaive(scene, naive, options, effects);
    const WhittedIntegrator fromEmbree(scene, embree, options, effects);
    const std::vector<Color> reference = pixelsWithAndWithoutCache(scene, fromNaive, width, height);
    const std::vector<Color> pixels = pixelsWithAndWithoutCache(scene, fromEmbree, width, height);
    REQUIRE(pixels.size() == reference.size());
    for (size_t i = 0; i < pixels.size(); ++i) {
        CAPTURE(i);
        CHECK(reference[i].r == pixels[i].r);
        CHECK(reference[i].g == pixels[i].g);
        CHECK(reference[i].b == pixels[i].b);
    }
    return pixels;
}

}  // namespace raylab

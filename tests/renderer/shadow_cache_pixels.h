#pragma once
// Shared by the tests that the shadow cache changes no pixel (cut-outs,
// filtered shadows): every pixel centre traced with and without a cache.

#include <doctest/doctest.h>

#include <vector>

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

}  // namespace raylab

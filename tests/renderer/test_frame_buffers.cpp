// The frame's buffers as makeBuffers hands them to the render: Film's
// constructor (planes filled in parallel) gives every value its blank value,
// and the SPD corner grid starts as zero bytes without a serial pass over it.

#include <doctest/doctest.h>

#include <cstring>

#include "renderer/render.h"
#include "renderer/render_setup.h"

using namespace raylab;

namespace {

/// Whether `plane` holds `count` values, each with the bytes of `blank`.
template <class Plane, class Value>
bool allBlank(const Plane& plane, size_t count, const Value& blank) {
    if (plane.size() != count) return false;
    for (const auto& v : plane)
        if (std::memcmp(&v, &blank, sizeof blank) != 0) return false;
    return true;
}

}  // namespace

TEST_CASE("frame buffers: Film's constructor gives every plane its blank value") {
    // Small (operator new) and large (huge-page mappings) planes, a crop window.
    for (const auto& entry : {std::pair{3, 2}, std::pair{512, 512}, std::pair{301, 77}}) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& w = entry.first;
        const auto& h = entry.second;
        CAPTURE(w);
        CAPTURE(h);
        const Film got(w, h, 5, 9, w + 20, h + 30);
        const size_t n = size_t(w) * size_t(h);
        CHECK(got.width == w);
        CHECK(got.height == h);
        CHECK(got.originX == 5);
        CHECK(got.originY == 9);
        CHECK(got.fullWidth == w + 20);
        CHECK(got.fullHeight == h + 30);
        CHECK(allBlank(got.rgba, n * 4, 0.f));
        CHECK(allBlank(got.z, n, kNoHitDepth));
        CHECK(allBlank(got.distance, n, kNoHitDepth));
        CHECK(allBlank(got.normal, n * 3, 0.f));
        CHECK(allBlank(got.albedo, n * 3, 0.f));
        CHECK(allBlank(got.objectId, n, -1.f));
        CHECK(allBlank(got.mattes, n * size_t(got.matteRanks), MatteEntry{-1, 0.f}));
    }
}

TEST_CASE("frame buffers: the SPD corner grid is (W+1)x(H+1) zero corners") {
    for (int size : {4, 300}) {  // below and above the huge-page threshold
        Scene scene;
        scene.camera = Camera::perspective({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45);
        RenderOverrides o;
        o.spd = true;
        RenderOptions options = resolveRenderOptions(scene, o);
        REQUIRE(options.spd);
        options.width = size;  // --spd's own 512x512 otherwise
        options.height = size / 2;
        const auto accel = makeAccelerator("naive", scene, options.accelOptions);
        const FrameRenderer frame(scene, *accel, options, analyseEffects(scene, options));
        const FrameBuffers b = frame.makeBuffers();
        REQUIRE(b.corners.size() == size_t(size + 1) * size_t(size / 2 + 1));
        size_t nonZero = 0;
        const auto* bytes = reinterpret_cast<const unsigned char*>(b.corners.data());
        for (size_t i = 0; i < b.corners.size() * sizeof(CornerSample); ++i)
            nonZero += bytes[i] != 0;
        CHECK(nonZero == 0);
        CHECK(b.cornerStride == size + 1);
    }
}

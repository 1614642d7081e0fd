// The frame's buffers as makeBuffers hands them to the render: blankFilm
// (planes filled in parallel) is exactly Film's constructor, and the SPD
// corner grid starts as zero bytes without a serial pass over it.

#include <doctest/doctest.h>

#include <cstring>

#include "renderer/render.h"
#include "renderer/render_setup.h"

using namespace raylab;

namespace {

template <class Plane>
bool sameBytes(const Plane& a, const Plane& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(typename Plane::value_type)) == 0;
}

}  // namespace

TEST_CASE("frame buffers: blankFilm is Film's constructor, byte for byte") {
    // Small (operator new) and large (huge-page mappings) planes, a crop window.
    for (const auto& [w, h] : {std::pair{3, 2}, std::pair{512, 512}, std::pair{301, 77}}) {
        CAPTURE(w);
        CAPTURE(h);
        const Film want(w, h, 5, 9, w + 20, h + 30);
        const Film got = blankFilm(w, h, 5, 9, w + 20, h + 30);
        CHECK(got.width == want.width);
        CHECK(got.height == want.height);
        CHECK(got.originX == want.originX);
        CHECK(got.originY == want.originY);
        CHECK(got.fullWidth == want.fullWidth);
        CHECK(got.fullHeight == want.fullHeight);
        CHECK(sameBytes(got.rgba, want.rgba));
        CHECK(sameBytes(got.z, want.z));
        CHECK(sameBytes(got.distance, want.distance));
        CHECK(sameBytes(got.normal, want.normal));
        CHECK(sameBytes(got.albedo, want.albedo));
        CHECK(sameBytes(got.objectId, want.objectId));
        CHECK(sameBytes(got.mattes, want.mattes));
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

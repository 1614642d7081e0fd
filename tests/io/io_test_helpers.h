#pragma once
// Shared by the io tests: error capture (the scratch directory is support/temp_dir.h).

#include <doctest/doctest.h>

#include <functional>
#include <string>

#include "geometry/triangle_mesh.h"
#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/io/errors.h"
#include "renderer/io/obj_loader.h"
#include "renderer/render.h"
#include "renderer/render_option_names.h"
#include "renderer/render_setup.h"
#include "renderer/scene.h"
#include "support/temp_dir.h"

namespace raylab::test {

/// What an InputError said; line -1 when nothing was thrown.
struct Failure {
    std::string file;
    int line = -1;
    std::string message;
    std::string located;
};

inline Failure failureOf(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const InputError& e) {
        return {e.file(), e.line(), e.what(), e.located()};
    }
    return {};
}

inline bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

/// OBJ loading options that keep warnings in the model instead of printing them.
inline ObjLoadOptions quiet() {
    ObjLoadOptions o;
    o.printWarnings = false;
    return o;
}

/// The triangle mesh behind a loaded object, or null for an analytic shape.
inline const TriangleMesh* meshOf(const Object& o) {
    return o.shape ? o.shape->nativeTriangles() : nullptr;
}

/// Renders `scene` at width x height, one sample per pixel, with accelerator
/// `accel` ("embree" or "naive"): the film with RGBA and the depth layer.
inline Film renderFilm(const Scene& scene, const std::string& accel, int width, int height) {
    RenderOverrides o;
    o.width = width;
    o.height = height;
    o.spp = 1;
    for (const auto& [word, kind] : acceleratorNames())
        if (word == accel) o.accel = kind;
    REQUIRE(o.accel);
    const RenderOptions options = resolveRenderOptions(scene, o);
    const auto a = makeAccelerator(options.accel, scene, options.accelOptions);
    return render(scene, *a, options, analyseEffects(scene, options)).film;
}

}  // namespace raylab::test

#include "renderer/io/scene_loader.h"

#include <cstdio>
#include <string>

#include "renderer/first_look.h"
#include "renderer/io/errors.h"
#include "renderer/io/loading_file.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/text_file.h"

namespace raylab {

namespace {

/// How far from the camera a framed model may reach: Embree traces
/// coordinates within 1e18 of the camera (NUMERICS.md §1), with margin.
constexpr double kMaxFramedDistance = 1e17;

}  // namespace

Scene loadScene(const std::string& path, const SceneLoadOptions& options) {
    const LoadingFile loading(path);  // names the scene if its parse runs out of memory
    const std::string ext = lowerExtension(path);
    if (ext == ".json") return loadJsonScene(readTextFile(path), path);
    if (ext == ".obj") return loadObjScene(path, options);
    if (ext == ".nff") return loadNffScene(readTextFile(path), path);  // nff_loader.cpp
    if (ext.empty())
        throw InputError(path, 0,
                         "unknown scene format (no file extension; expected .json, .obj or .nff)");
    throw InputError(path, 0, "unknown scene format '" + ext + "' (expected .json, .obj or .nff)");
}

Scene loadObjScene(const std::string& path, const SceneLoadOptions& options) {
    ObjLoadOptions load;
    load.normals = options.normals;
    const ObjModel model = loadObj(path, load);
    Scene scene;
    scene.sourcePath = path;
    appendObjModel(scene, model, path);

    std::vector<Vec3> points;
    Bounds3 box;
    for (const ObjMeshPart& part : model.parts) {
        points.insert(points.end(), part.mesh->positions.begin(), part.mesh->positions.end());
        box.expand(part.mesh->bounds());
    }
    scene.camera = frameModel(points, options.up, options.aspect);
    // The camera stands a few model sizes away: a model too large for that
    // is refused here, by its size, rather than by the accelerator later.
    const Vec3 eye = scene.camera.frame().eye;
    const double reach = std::max(maxComponent(abs(box.lo - eye)), maxComponent(abs(box.hi - eye)));
    if (!(reach <= kMaxFramedDistance)) {
        const auto shown = [](double v) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.3g", v);
            return std::string(buf);
        };
        throw InputError(path, 0,
                         "the model is " + shown(maxComponent(box.extent())) +
                             " units across; framed whole, it would lie " + shown(reach) +
                             " from the camera, beyond the " + shown(kMaxFramedDistance) +
                             " raylab traces: scale it down (a JSON scene's mesh \"transform\")");
    }
    scene.lights = studioLights(scene.camera);
    scene.ambient = kFirstLookAmbient;
    scene.background = kFirstLookBackground;
    return scene;
}

}  // namespace raylab

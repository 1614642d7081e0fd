#include "renderer/io/scene_loader.h"

#include <cmath>

#include "renderer/io/errors.h"
#include "renderer/io/loading_file.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/text_file.h"

namespace raylab {

Scene loadScene(const std::string& path) {
    const LoadingFile loading(path);  // names the scene if its parse runs out of memory
    const std::string ext = lowerExtension(path);
    if (ext == ".json") return loadJsonScene(readTextFile(path), path);
    if (ext == ".obj") return loadObjScene(path);
    if (ext == ".nff") return loadNffScene(readTextFile(path), path);  // nff_loader.cpp
    if (ext.empty())
        throw InputError(path, 0,
                         "unknown scene format (no file extension; expected .json, .obj or .nff)");
    throw InputError(path, 0, "unknown scene format '" + ext + "' (expected .json, .obj or .nff)");
}

Scene loadObjScene(const std::string& path) {
    const ObjModel model = loadObj(path);
    Scene scene;
    scene.sourcePath = path;
    appendObjModel(scene, model, path);

    Bounds3 box;
    for (const ObjMeshPart& part : model.parts) box.expand(part.mesh->bounds());
    const Vec3 centre = box.centre();
    // Radius of the box's bounding sphere; a point-like mesh still gets a camera.
    double radius = 0.5 * length(box.extent());
    if (!(radius > 0)) radius = 1;

    // Look at the centre from the front-right and slightly above, far enough
    // that the bounding sphere fits the vertical field of view with a 5% margin
    // (the image is at least as wide as it is tall in the default settings).
    constexpr double kFovDegrees = 40;
    constexpr double kPi = 3.14159265358979323846;
    const Vec3 viewFrom = normalize(Vec3(1, 0.6, 1.5));
    const double distance = 1.05 * radius / std::sin(0.5 * kFovDegrees * kPi / 180.0);
    scene.camera =
        Camera::perspective(centre + viewFrom * distance, centre, Vec3(0, 1, 0), kFovDegrees);

    // Key light above and to the left of the camera, white; a dim ambient
    // term so faces turned away from the key are not black.
    Light key;
    key.type = Light::Type::Point;
    key.position = centre + normalize(Vec3(-0.5, 1.5, 1.2)) * (2 * distance);
    key.intensity = Color(1, 1, 1);
    scene.lights.push_back(key);
    scene.ambient = Color(0.15, 0.15, 0.15);
    scene.background = Color(0.1, 0.1, 0.12);
    return scene;
}

}  // namespace raylab

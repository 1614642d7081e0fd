#pragma once
// The scene as plain data: camera, image settings, lights, materials and
// objects. Loaders produce it; accelerators and the integrator read it.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geometry/shape.h"
#include "renderer/accel/hit.h"
#include "renderer/camera.h"
#include "renderer/camera_path.h"
#include "renderer/render_overrides.h"
#include "shading/color.h"
#include "shading/light.h"
#include "shading/material.h"
#include "shading/texture.h"

namespace raylab {

/// Render settings a scene file may carry; command-line flags override them.
struct ImageSettings {
    int width = 640;
    int height = 480;
    int spp = 1;        ///< samples per pixel
    int maxDepth = 5;   ///< ray-tree depth limit; the camera ray has depth 1
    int sizeLine = 0;   ///< the scene file's line that sets width/height (0: defaults)
};

/// One scene object: a shape (any kind: analytic primitive or triangle mesh)
/// with its material. The shape is shared so that instances can refer to it.
struct Object {
    std::string name;
    std::shared_ptr<Shape> shape;
    uint32_t material = 0;                ///< index into Scene::materials
    std::vector<uint32_t> faceMaterials;  ///< per-primitive material, or empty

    uint32_t primitiveCount() const { return shape ? shape->primitiveCount() : 0; }
    uint32_t materialOf(uint32_t prim) const {
        return faceMaterials.empty() ? material : faceMaterials[prim];
    }
};

/// Everything the shading code needs about the winning hit: the shape's
/// surface record plus which object and material.
struct SurfaceInteraction : SurfaceGeometry {
    uint32_t object = 0;
    uint32_t prim = 0;
    uint32_t material = 0;
};

struct Scene {
    std::string sourcePath;  ///< file the scene came from (for messages)
    Camera camera;
    std::optional<CameraPath> cameraPath;  ///< JSON "camera_path": the cameras of --frames
    double cameraNear = 0;   ///< camera rays start at this distance from the eye (NFF hither)
    ImageSettings image;
    RenderOverrides settings;  ///< the scene file's "render" block (accuracy knobs)
    Color background{0, 0, 0};
    Color ambient{0, 0, 0};  ///< Ia
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<Texture> textures;  ///< what Material::maps index; images shared by file
    std::vector<Object> objects;

    /// Total primitive count (analytic shapes + triangles).
    size_t primitiveCount() const;
    /// Bounds of all objects.
    Bounds3 bounds() const;
    /// Bytes of the textures' MIP pyramids, each shared image once.
    double textureBytes() const;
    /// Surface data for a hit found by any accelerator, from the hit object's
    /// shape (triangle hits are recomputed in double from the chosen triangle,
    /// so Embree and the naive loop hand identical data to shading whenever
    /// they agree on the primitive).
    SurfaceInteraction surfaceAt(const Ray& ray, const Hit& hit, const IntersectOptions& opt = {},
                                 SurfaceDetail detail = SurfaceDetail::Normals) const;
};

}  // namespace raylab

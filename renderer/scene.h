#pragma once
// The scene as plain data: camera, image settings, lights, materials and
// objects. Loaders produce it; accelerators and the integrator read it.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry/shape.h"
#include "geometry/triangle_mesh.h"
#include "renderer/camera.h"
#include "renderer/render_overrides.h"
#include "shading/color.h"
#include "shading/light.h"
#include "shading/material.h"

namespace raylab {

/// Render settings a scene file may carry; command-line flags override them.
struct ImageSettings {
    int width = 640;
    int height = 480;
    int spp = 1;        ///< samples per pixel
    int maxDepth = 5;   ///< ray-tree depth limit; the camera ray has depth 1
    int sizeLine = 0;   ///< the scene file's line that sets width/height (0: defaults)
};

/// One scene object: an analytic shape or a triangle mesh, with its material.
struct Object {
    std::string name;
    std::unique_ptr<Shape> shape;              ///< analytic primitive, or null
    std::shared_ptr<const TriangleMesh> mesh;  ///< triangle mesh, or null
    uint32_t material = 0;                     ///< index into Scene::materials
    std::vector<uint32_t> faceMaterials;       ///< meshes: per-triangle material, or empty
    /// Meshes: which side of a triangle can be hit; the front is where its
    /// vertices run counter-clockwise. Two-sided by default (OBJ); NFF's
    /// opaque triangles are one-sided. Analytic shapes carry their own.
    Sidedness meshSides = Sidedness::Both;

    bool isMesh() const { return mesh != nullptr; }
    size_t primitiveCount() const { return isMesh() ? mesh->triangleCount() : 1; }
    uint32_t materialOf(uint32_t prim) const {
        return faceMaterials.empty() ? material : faceMaterials[prim];
    }
};

/// What the accelerators report: which primitive was hit and where along the ray.
struct Hit {
    double t = 0;
    uint32_t object = 0;  ///< index into Scene::objects
    uint32_t prim = 0;    ///< triangle index for meshes, 0 for analytic shapes
    double u = 0, v = 0;  ///< primitive-local parameters (analytic shapes)
};

/// Everything the shading code needs about the winning hit.
struct SurfaceInteraction {
    double t = 0;
    Vec3 p;        ///< hit point
    Vec3 ng;       ///< unit geometric normal, outward
    Vec3 ns;       ///< unit shading normal, outward
    bool frontFace = true;
    /// Extent around p of the primitive's float-rounded geometry, which sizes
    /// the secondary-ray offset (geometry/spawn.h): a triangle's largest
    /// vertex distance from p, a float-precision shape's distance from p to
    /// its bounds' centre, 0 for shapes intersected in double.
    double span = 0;
    uint32_t object = 0;
    uint32_t material = 0;
};

struct Scene {
    std::string sourcePath;  ///< file the scene came from (for messages)
    Camera camera;
    double cameraNear = 0;   ///< camera rays start at this distance from the eye (NFF hither)
    ImageSettings image;
    RenderOverrides settings;  ///< the scene file's "render" block (accuracy knobs)
    Color background{0, 0, 0};
    Color ambient{0, 0, 0};  ///< Ia
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<Object> objects;

    /// Total primitive count (analytic shapes + triangles).
    size_t primitiveCount() const;
    /// Bounds of all objects.
    Bounds3 bounds() const;
    /// Full surface data for a hit found by any accelerator. Triangle hits are
    /// recomputed in double from the chosen triangle, so Embree and the naive
    /// loop hand identical data to shading whenever they agree on the primitive.
    SurfaceInteraction surfaceAt(const Ray& ray, const Hit& hit) const;
};

}  // namespace raylab

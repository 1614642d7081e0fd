#include "renderer/polygon_options.h"

#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "geometry/triangle_mesh.h"

namespace raylab {

size_t triangulatePolygons(Scene& scene) {
    auto mesh = std::make_shared<TriangleMesh>();
    std::vector<uint32_t> faceMaterials;
    std::vector<Object> kept;
    size_t replaced = 0;
    bool anyNormals = false;
    for (Object& o : scene.objects) {
        const auto* p = dynamic_cast<const Polygon*>(o.shape.get());
        if (p && !p->normals().empty()) anyNormals = true;
    }
    for (Object& o : scene.objects) {
        const auto* p = dynamic_cast<const Polygon*>(o.shape.get());
        if (!p) {
            kept.push_back(std::move(o));
            continue;
        }
        const uint32_t base = uint32_t(mesh->positions.size());
        const std::vector<Vec3>& v = p->vertices();
        mesh->positions.insert(mesh->positions.end(), v.begin(), v.end());
        // A mesh has normals for every vertex or none: polygons without
        // normals contribute their flat normal.
        if (anyNormals) {
            if (p->normals().empty())
                mesh->normals.insert(mesh->normals.end(), v.size(), p->normal());
            else
                mesh->normals.insert(mesh->normals.end(), p->normals().begin(), p->normals().end());
        }
        for (const auto& t : triangulatePolygon(v)) {
            mesh->triangles.push_back({base + t[0], base + t[1], base + t[2]});
            faceMaterials.push_back(o.material);
        }
        ++replaced;
    }
    if (!mesh->triangles.empty()) {
        Object m;
        m.name = "triangulated polygons";
        m.material = faceMaterials.front();
        m.faceMaterials = std::move(faceMaterials);
        m.shape = std::move(mesh);
        kept.push_back(std::move(m));
    }
    scene.objects = std::move(kept);
    return replaced;
}

}  // namespace raylab

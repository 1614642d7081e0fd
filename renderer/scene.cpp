#include "renderer/scene.h"

#include <set>

namespace raylab {

size_t Scene::primitiveCount() const {
    size_t n = 0;
    for (const Object& o : objects) n += o.primitiveCount();
    return n;
}

Bounds3 Scene::bounds() const {
    Bounds3 b;
    for (const Object& o : objects)
        if (o.shape) b.expand(o.shape->bounds());
    return b;
}

double Scene::textureBytes() const {
    std::set<const MipMap*> seen;
    double bytes = 0;
    for (const Texture& t : textures)
        if (t.image() && seen.insert(t.image()).second) bytes += double(t.image()->bytes());
    return bytes;
}

SurfaceInteraction Scene::surfaceAt(const Ray& ray, const Hit& hit, const IntersectOptions& opt,
                                    SurfaceDetail detail) const {
    const Object& object = objects[hit.object];
    // The shape's record initialises the base in place (a prvalue of the
    // same type); GCC had already elided most of the former assign-over copy.
    return SurfaceInteraction{
        object.shape->surfaceAt(hit.prim, ray, ShapeHit{hit.t, hit.u, hit.v}, opt, detail),
        hit.object, hit.prim, object.materialOf(hit.prim)};
}

}  // namespace raylab

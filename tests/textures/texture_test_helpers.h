#pragma once
// Scenes built in code for the texture tests: the project ships no image, so
// every texture here is generated.

#include <cmath>
#include <memory>
#include <vector>

#include "geometry/primitives.h"
#include "renderer/render_options.h"
#include "renderer/render_setup.h"
#include "renderer/scene.h"

namespace raylab::testing {

/// A width × height RGB image of a few colours in a pattern that shows
/// orientation and wrapping: x and y gradients in red and green, blue on
/// every other texel.
inline std::shared_ptr<const MipMap> patternImage(int width, int height) {
    std::vector<float> v;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            v.push_back(float(x + 0.5) / float(width));
            v.push_back(float(y + 0.5) / float(height));
            v.push_back(float((x + y) % 2));
        }
    return std::make_shared<const MipMap>(width, height, 3, std::move(v));
}

/// Adds `t` to the scene and a material with kd textured by it.
inline uint32_t addTexturedMaterial(Scene& s, const Texture& t, const Color& kd = Color(1)) {
    s.textures.push_back(t);
    Material m;
    m.name = "textured " + std::to_string(s.materials.size());
    m.kd = kd;
    m.ka = Color(0.2);
    m.maps.kd = uint32_t(s.textures.size() - 1);
    s.materials.push_back(m);
    return uint32_t(s.materials.size() - 1);
}

inline void addObject(Scene& s, std::unique_ptr<Shape> shape, uint32_t material,
                      const std::string& name) {
    Object o;
    o.name = name;
    o.shape = std::move(shape);
    o.material = material;
    s.objects.push_back(std::move(o));
}

/// Render options for a scene at a size, with the given texture knobs.
inline RenderOptions textureOptions(const Scene& s, int width, int height, TextureFilter filter,
                                    TextureFootprint footprint, int spp = 1) {
    RenderOverrides o;
    o.width = width;
    o.height = height;
    o.spp = spp;
    o.textureFilter = filter;
    o.textureFootprint = footprint;
    return resolveRenderOptions(s, o);
}

}  // namespace raylab::testing

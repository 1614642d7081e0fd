#include "shading/material_textures.h"

#include <array>

namespace raylab {

SurfaceOptics evaluateOptics(const Material& m, const std::vector<Texture>& textures,
                             const TextureCoords& tc, TextureFilter filter) {
    SurfaceOptics out = m;
    const MaterialMaps& maps = m.maps;
    // The colour maps looked up so far: a map that gives the same colours as
    // one of them (MTL's map_Ka and map_Kd naming one file, a JSON material
    // with the same texture on ka and kd) reuses its value instead of a
    // second lookup with the same footprint.
    // Left uninitialised (only the first `count` are read): zeroing them
    // would cost a `rep stos` at every textured hit.
    std::array<uint32_t, 5> done;
    struct Value {
        double r, g, b;
    };
    std::array<Value, 5> values;
    size_t count = 0;
    const auto modulate = [&](uint32_t map, Color& c) {
        if (map == MaterialMaps::kNone) return;
        const Texture& t = textures[map];
        for (size_t i = 0; i < count; ++i)
            if (done[i] == map || textures[done[i]].sameColors(t)) {
                c = c * Color(values[i].r, values[i].g, values[i].b);
                return;
            }
        const Color v = t.color(tc, filter);
        done[count] = map;
        values[count++] = Value{v.r, v.g, v.b};
        c = c * v;
    };
    modulate(maps.ka, out.ka);
    modulate(maps.kd, out.kd);
    modulate(maps.ks, out.ks);
    modulate(maps.km, out.km);
    modulate(maps.kt, out.kt);
    if (maps.shininess != MaterialMaps::kNone)
        out.shininess = m.shininess * textures[maps.shininess].scalar(tc, filter);
    return out;
}

}  // namespace raylab

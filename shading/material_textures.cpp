#include "shading/material_textures.h"

namespace raylab {

SurfaceOptics evaluateOptics(const Material& m, const std::vector<Texture>& textures,
                             const TextureCoords& tc, TextureFilter filter) {
    SurfaceOptics out = m;
    const MaterialMaps& maps = m.maps;
    const auto modulate = [&](uint32_t map, Color& c) {
        if (map != MaterialMaps::kNone) c = c * textures[map].color(tc, filter);
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

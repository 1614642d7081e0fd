#include "shading/material_textures.h"

namespace raylab {

namespace {

/// The textured colours, in the order of the lookup masks' bits.
constexpr std::array<Color SurfaceOptics::*, 5> kColours = {
    &SurfaceOptics::ka, &SurfaceOptics::kd, &SurfaceOptics::ks, &SurfaceOptics::km, &SurfaceOptics::kt};

std::array<uint32_t, 5> colourMaps(const MaterialMaps& maps) {
    return {maps.ka, maps.kd, maps.ks, maps.km, maps.kt};
}

}  // namespace

MaterialLookups::MaterialLookups(const Material& m, const std::vector<Texture>& textures) {
    const std::array<uint32_t, 5> maps = colourMaps(m.maps);
    for (size_t i = 0; i < maps.size(); ++i) {
        const uint32_t map = maps[i];
        if (map == MaterialMaps::kNone) continue;
        int group = 0;
        while (group < m_count && m_lookups[size_t(group)].texture != map &&
               !textures[m_lookups[size_t(group)].texture].sameColors(textures[map]))
            ++group;
        if (group == m_count) m_lookups[size_t(m_count++)] = Lookup{map, 0};
        m_lookups[size_t(group)].colours = uint8_t(m_lookups[size_t(group)].colours | (1u << i));
    }
}

SurfaceOptics MaterialLookups::evaluate(const Material& m, const std::vector<Texture>& textures,
                                        const TextureCoords& tc, TextureFilter filter) const {
    SurfaceOptics out = m;
    for (int k = 0; k < m_count; ++k) {
        const Lookup& lookup = m_lookups[size_t(k)];
        const Color v = textures[lookup.texture].color(tc, filter);
        for (size_t i = 0; i < kColours.size(); ++i)
            if (lookup.colours & (1u << i)) out.*kColours[i] = out.*kColours[i] * v;
    }
    if (m.maps.shininess != MaterialMaps::kNone)
        out.shininess = m.shininess * textures[m.maps.shininess].scalar(tc, filter);
    return out;
}

SurfaceOptics evaluateOptics(const Material& m, const std::vector<Texture>& textures,
                             const TextureCoords& tc, TextureFilter filter) {
    return MaterialLookups(m, textures).evaluate(m, textures, tc, filter);
}

}  // namespace raylab

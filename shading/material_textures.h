#pragma once
// A textured material's values at one surface point: each constant times its
// texture (MTL: map_Kd × Kd), looked up once per hit.

#include <array>
#include <cstdint>
#include <vector>

#include "shading/material.h"
#include "shading/texture.h"

namespace raylab {

/// The colour lookups of one material, planned once per render: each
/// distinct map with the colours (ka, kd, ks, km, kt) it multiplies. Maps
/// that give the same colours (MTL's map_Ka and map_Kd naming one file, a
/// JSON material with one texture on ka and kd; Texture::sameColors) share
/// one lookup, so a hit does no search.
class MaterialLookups {
public:
    /// The plan of `m`, whose maps index `textures`.
    MaterialLookups(const Material& m, const std::vector<Texture>& textures);

    /// The optical values of `m` (the material the plan was made for) at `tc`.
    SurfaceOptics evaluate(const Material& m, const std::vector<Texture>& textures,
                           const TextureCoords& tc, TextureFilter filter) const;

private:
    struct Lookup {
        uint32_t texture;  ///< the first map of the group, in the order ka, kd, ks, km, kt
        uint8_t colours;   ///< bit i: colour i of that order takes its value
    };
    std::array<Lookup, 5> m_lookups;  ///< the first m_count are used
    int m_count = 0;
};

/// The optical values of `m` at `tc`; `textures` is what m.maps indexes
/// (MaterialLookups planned and evaluated at once).
SurfaceOptics evaluateOptics(const Material& m, const std::vector<Texture>& textures,
                             const TextureCoords& tc, TextureFilter filter);

}  // namespace raylab

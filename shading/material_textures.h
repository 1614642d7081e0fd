#pragma once
// A textured material's values at one surface point: each constant times its
// texture (MTL: map_Kd × Kd), looked up once per hit.

#include <vector>

#include "shading/material.h"
#include "shading/texture.h"

namespace raylab {

/// The optical values of `m` at `tc`; `textures` is what m.maps indexes.
SurfaceOptics evaluateOptics(const Material& m, const std::vector<Texture>& textures,
                             const TextureCoords& tc, TextureFilter filter);

}  // namespace raylab

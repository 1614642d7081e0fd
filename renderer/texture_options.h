#pragma once
// The texture knobs of a render (--texture-filter, --texture-footprint and
// the JSON "render" keys of the same names) and their names; the command line
// and the scene reader parse them through render_option_names.h.

#include "shading/texture.h"

namespace raylab {

/// How a ray's footprint is carried to its hits for filtered lookups.
enum class TextureFootprint {
    Cones,          ///< ray cones: a width and a spread angle per ray
    Differentials,  ///< Igehy's ray differentials: four vectors per ray
};

struct TextureOptions {
    TextureFilter filter = TextureFilter::Trilinear;
    TextureFootprint footprint = TextureFootprint::Differentials;  // docs/accuracy.md: the knee
};

const char* textureFilterName(TextureFilter f);
const char* textureFootprintName(TextureFootprint f);

}  // namespace raylab

#pragma once
// The texture knobs of a render (--texture-filter, --texture-footprint and
// the JSON "render" keys of the same names), and their names, shared by the
// command line, the scene reader and the statistics.

#include <optional>
#include <string>

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
/// nullopt for an unknown name.
std::optional<TextureFilter> parseTextureFilter(const std::string& name);
std::optional<TextureFootprint> parseTextureFootprint(const std::string& name);

}  // namespace raylab

#include "renderer/texture_options.h"

namespace raylab {

const char* textureFilterName(TextureFilter f) {
    switch (f) {
    case TextureFilter::Point: return "point";
    case TextureFilter::Bilinear: return "bilinear";
    case TextureFilter::Trilinear: return "trilinear";
    case TextureFilter::Anisotropic: return "anisotropic";
    }
    return "?";
}

const char* textureFootprintName(TextureFootprint f) {
    return f == TextureFootprint::Cones ? "cones" : "differentials";
}

std::optional<TextureFilter> parseTextureFilter(const std::string& name) {
    for (TextureFilter f : {TextureFilter::Point, TextureFilter::Bilinear, TextureFilter::Trilinear,
                            TextureFilter::Anisotropic})
        if (name == textureFilterName(f)) return f;
    return std::nullopt;
}

std::optional<TextureFootprint> parseTextureFootprint(const std::string& name) {
    for (TextureFootprint f : {TextureFootprint::Cones, TextureFootprint::Differentials})
        if (name == textureFootprintName(f)) return f;
    return std::nullopt;
}

}  // namespace raylab

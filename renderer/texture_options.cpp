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

}  // namespace raylab

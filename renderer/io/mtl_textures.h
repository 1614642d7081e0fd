#pragma once
// MTL texture maps as raylab textures (docs/scene-format.md, "OBJ and MTL"):
//   map_Kd, map_Ka, map_Ks  colour maps multiplying Kd, Ka, Ks (sRGB-decoded)
//   map_Ns                  scalar map multiplying Ns
//   bump, map_bump          height map; -bm scales the height (scene units)
//   norm                    tangent-space normal map (the convention of
//                           shading/normal_mapping.h)
// Options: -o u v (offset) and -s u v (scale) place the map in (u, v),
// -clamp on clamps instead of repeating, -bm scales bump heights, -imfchan
// picks the channel of a scalar map; the other options (-blendu, -blendv,
// -boost, -mm, -t, -texres, -cc, -type) and any option on a map it does not
// apply to are ignored with one warning each at the statement's line.
// A map whose file cannot be read is one warning; the material renders
// without it. map_d (cut-outs) and the other maps are left to their own
// readers (a warning says they are ignored).

#include <string>
#include <vector>

#include "geometry/vec2.h"
#include "renderer/io/load_warnings.h"
#include "renderer/io/mtl_reader.h"
#include "renderer/io/texture_library.h"
#include "shading/material.h"
#include "shading/texture.h"

namespace raylab {

/// What the options before a map's file name say.
struct MtlTextureOptions {
    Vec2 offset{0, 0};
    Vec2 scale{1, 1};
    bool clamp = false;
    double bumpMultiplier = 1;
    bool bumpMultiplierGiven = false;
    char channel = 0;  ///< -imfchan r|g|b|m|l|z, 0 when not given
    std::vector<std::string> ignored;   ///< options parsed but not honoured, as written
    std::vector<std::string> problems;  ///< options that could not be read
};

/// Parses an MTL map's option text ("-s 2 2 -clamp on -bm 0.5").
MtlTextureOptions parseMtlTextureOptions(const std::string& options);

/// Whether raylab reads this map keyword (map_Kd, bump, norm, ...).
bool isSupportedMtlMap(const std::string& keyword);

/// Reads the supported maps of `statements` into `material`'s maps: textures
/// are appended to `textures` (indices as Material::maps stores them),
/// images come from `library`, warnings go to `warn` at each statement.
void applyMtlTextures(const MtlMaterial& statements, Material& material,
                      std::vector<Texture>& textures, TextureLibrary& library,
                      LoadWarnings& warn);

}  // namespace raylab

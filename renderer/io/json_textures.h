#pragma once
// Textured values of JSON materials (docs/scene-format.md, "Textures"):
//   a colour (ka, kd, ks, km, kt) may be an image texture
//     {"texture": "file.png", "scale": [su, sv], "offset": [ou, ov],
//      "wrap": "repeat"|"clamp"|"black", "required": false}
//   or a procedural checkerboard in uv
//     {"checker": [colour, colour], "scale": [su, sv], "offset": [ou, ov]};
//   "bump": an image texture plus "height" (scene units per unit of the map),
//   "normal_map": an image texture (tangent-space normals),
//   "alpha": an image texture (its alpha channel, or its grey level when it
//     has none) or a checker (the luminance of its colours): a cut-out mask.
// The texture's file is relative to the scene file. A file that cannot be
// read is one warning ("FILE:LINE: PATH: texture 'x.png' not read (why);
// rendered without it") unless "required": true makes it an error.

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/io/image_reader.h"
#include "renderer/io/json_fields.h"
#include "renderer/io/texture_library.h"
#include "shading/texture.h"

namespace raylab {

/// Where a JSON texture goes and what it may say.
enum class JsonTextureUse {
    Colour,     ///< a material colour: image (sRGB-decoded) or checker
    Bump,       ///< "bump": an image read as data, with "height"
    NormalMap,  ///< "normal_map": an image read as data
    Alpha,      ///< "alpha": an image read as data (its alpha channel, else its grey), or a checker
};

struct JsonTexture {
    uint32_t index = 0;  ///< into the scene's textures; only when `present`
    bool present = false;
    double height = 1;   ///< Bump: "height"
};

/// Reads the texture object `v` at `path` and appends it to `textures`.
JsonTexture readJsonTexture(const JsonFieldReader& reader, const JsonValue& v,
                            const std::string& path, JsonTextureUse use,
                            TextureLibrary& library, std::vector<Texture>& textures);

}  // namespace raylab

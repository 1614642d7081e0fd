#include "renderer/io/json_textures.h"

#include <cstdio>

#include "renderer/io/errors.h"
#include "renderer/io/text_file.h"

namespace raylab {

namespace {

Vec2 pair(const JsonFieldReader& reader, const JsonValue& v, const std::string& path) {
    if (!v.isArray() || v.size() != 2)
        reader.fail(v, path, std::string("expected [u, v], got ") +
                                 (v.isArray() ? "an array of " + std::to_string(v.size()) : v.typeName()));
    return {reader.number(v.at(0), indexPath(path, 0)), reader.number(v.at(1), indexPath(path, 1))};
}

}  // namespace

JsonTexture readJsonTexture(const JsonFieldReader& reader, const JsonValue& v,
                            const std::string& path, JsonTextureUse use,
                            TextureLibrary& library, std::vector<Texture>& textures) {
    const bool checker = (use == JsonTextureUse::Colour || use == JsonTextureUse::Alpha) &&
                         v.isObject() && v.find("checker");
    std::vector<std::string> keys = {"scale", "offset"};
    if (checker) {
        keys.push_back("checker");
    } else {
        keys.insert(keys.end(), {"texture", "wrap", "required"});
        if (use == JsonTextureUse::Bump) keys.push_back("height");
    }
    const JsonFields f(reader, v, path,
                       checker ? "a checker texture"
                               : use == JsonTextureUse::Bump ? "a bump map"
                               : use == JsonTextureUse::NormalMap ? "a normal map"
                               : use == JsonTextureUse::Alpha     ? "an alpha mask"
                                                                  : "a texture",
                       keys);
    JsonTexture out;
    if (const JsonValue* h = f.get("height")) out.height = reader.number(*h, f.path("height"));
    // Every key is checked before any file is read: a typo is an error even
    // when the image is missing.
    WrapMode wrap = WrapMode::Repeat;
    if (const JsonValue* w = f.get("wrap"))
        wrap = reader.choice<WrapMode>(
            *w, f.path("wrap"),
            {{"repeat", WrapMode::Repeat}, {"clamp", WrapMode::Clamp}, {"black", WrapMode::Black}});
    const Vec2 scale = f.has("scale") ? pair(reader, *f.get("scale"), f.path("scale")) : Vec2{1, 1};
    const Vec2 offset = f.has("offset") ? pair(reader, *f.get("offset"), f.path("offset")) : Vec2{0, 0};
    Texture tex;
    if (checker) {
        const JsonValue& c = reader.array(f.need("checker"), f.path("checker"));
        if (c.size() != 2)
            reader.fail(c, f.path("checker"),
                        "expected 2 colours [even, odd], got " + std::to_string(c.size()));
        tex = Texture::checker(reader.color(c.at(0), indexPath(f.path("checker"), 0)),
                               reader.color(c.at(1), indexPath(f.path("checker"), 1)));
    } else {
        const JsonValue& fileValue = f.need("texture");
        const std::string& file = reader.string(fileValue, f.path("texture"));
        if (file.empty()) reader.fail(fileValue, f.path("texture"), "must not be empty");
        const bool required =
            f.has("required") && reader.boolean(*f.get("required"), f.path("required"));
        const ImageRole role = use == JsonTextureUse::Colour ? ImageRole::Color : ImageRole::Data;
        const TextureLibrary::Result image =
            library.load(resolveRelativeTo(reader.file(), file), role);
        if (!image.image) {
            const std::string message = "texture '" + file + "' not read (" + image.error + ")";
            if (required) reader.fail(fileValue, f.path("texture"), message);
            if (image.firstFailure)
                std::fprintf(stderr, "raylab: warning: %s\n",
                             terminalSafe(reader.file() + ":" + std::to_string(fileValue.line()) +
                                          ": " + f.path("texture") + ": " + message +
                                          "; rendered without it")
                                 .c_str());
            return out;
        }
        tex = Texture::fromImage(image.image, file);
        tex.wrap = wrap;
    }
    if (use == JsonTextureUse::Alpha) tex.channel = TextureChannel::Matte;
    tex.scale = scale;
    tex.offset = offset;
    textures.push_back(tex);
    out.index = uint32_t(textures.size() - 1);
    out.present = true;
    return out;
}

}  // namespace raylab

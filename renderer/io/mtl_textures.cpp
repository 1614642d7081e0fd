#include "renderer/io/mtl_textures.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace raylab {

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

bool isNumber(const std::string& s, double& out) {
    if (s.empty()) return false;
    char* end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return end && *end == '\0' && std::isfinite(out);
}

/// The option's numeric arguments: up to `most`, at least `least`.
bool takeNumbers(std::vector<std::string>& words, size_t& i, size_t least, size_t most,
                 std::vector<double>& out) {
    out.clear();
    double v;
    while (out.size() < most && i + 1 < words.size() && isNumber(words[i + 1], v)) {
        out.push_back(v);
        ++i;
    }
    return out.size() >= least;
}

enum class MapKind { Colour, Scalar, Bump, Normal, Alpha };

struct MapSpec {
    const char* keyword;
    MapKind kind;
    uint32_t MaterialMaps::*slot;
};

const MapSpec* mapSpec(const std::string& keyword) {
    static const MapSpec kMaps[] = {
        {"map_kd", MapKind::Colour, &MaterialMaps::kd},
        {"map_ka", MapKind::Colour, &MaterialMaps::ka},
        {"map_ks", MapKind::Colour, &MaterialMaps::ks},
        {"map_ns", MapKind::Scalar, &MaterialMaps::shininess},
        {"bump", MapKind::Bump, &MaterialMaps::bump},
        {"map_bump", MapKind::Bump, &MaterialMaps::bump},
        {"norm", MapKind::Normal, &MaterialMaps::normal},
        {"map_d", MapKind::Alpha, &MaterialMaps::alpha},
    };
    const std::string k = lower(keyword);
    for (const MapSpec& m : kMaps)
        if (k == m.keyword) return &m;
    return nullptr;
}

TextureChannel channelOf(char c) {
    switch (c) {
    case 'r': return TextureChannel::Red;
    case 'g': return TextureChannel::Green;
    case 'b': return TextureChannel::Blue;
    case 'm': return TextureChannel::Matte;
    default: return TextureChannel::Luminance;
    }
}

}  // namespace

MtlTextureOptions parseMtlTextureOptions(const std::string& options) {
    MtlTextureOptions o;
    std::istringstream in(options);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    std::vector<double> nums;
    for (size_t i = 0; i < words.size(); ++i) {
        const std::string flag = lower(words[i]);
        if (flag == "-o" || flag == "-s") {
            // u [v [w]]: w (3D textures) has no meaning on a surface.
            if (!takeNumbers(words, i, 1, 3, nums)) {
                o.problems.push_back(flag + " needs numbers");
                continue;
            }
            const Vec2 v{nums[0], nums.size() > 1 ? nums[1] : (flag == "-s" ? 1.0 : 0.0)};
            (flag == "-o" ? o.offset : o.scale) = v;
        } else if (flag == "-clamp" || flag == "-blendu" || flag == "-blendv" || flag == "-cc") {
            const std::string value = i + 1 < words.size() ? lower(words[i + 1]) : "";
            if (value != "on" && value != "off") {
                o.problems.push_back(flag + " needs on or off");
                continue;
            }
            ++i;
            if (flag == "-clamp")
                o.clamp = value == "on";
            else if ((flag == "-cc") == (value == "on"))  // blend off, cc on: not honoured
                o.ignored.push_back(flag + " " + value);
        } else if (flag == "-bm") {
            if (!takeNumbers(words, i, 1, 1, nums)) {
                o.problems.push_back("-bm needs a number");
                continue;
            }
            o.bumpMultiplier = nums[0];
            o.bumpMultiplierGiven = true;
        } else if (flag == "-imfchan") {
            const std::string value = i + 1 < words.size() ? lower(words[i + 1]) : "";
            if (value.size() != 1 || std::string("rgbmlz").find(value[0]) == std::string::npos) {
                o.problems.push_back("-imfchan needs one of r g b m l z");
                continue;
            }
            ++i;
            o.channel = value[0];
            if (value[0] == 'z') o.ignored.push_back("-imfchan z (read as l)");
        } else if (flag == "-boost" || flag == "-texres") {
            takeNumbers(words, i, 1, 1, nums);
            o.ignored.push_back(flag);
        } else if (flag == "-mm") {
            takeNumbers(words, i, 1, 2, nums);
            o.ignored.push_back(flag);
        } else if (flag == "-t") {
            takeNumbers(words, i, 1, 3, nums);
            o.ignored.push_back(flag);
        } else if (flag == "-type") {
            if (i + 1 < words.size()) ++i;
            o.ignored.push_back(flag);
        } else {
            o.problems.push_back("unknown option '" + words[i] + "'");
        }
    }
    return o;
}

bool isSupportedMtlMap(const std::string& keyword) { return mapSpec(keyword) != nullptr; }

void applyMtlTextures(const MtlMaterial& statements, Material& material,
                      std::vector<Texture>& textures, TextureLibrary& library,
                      LoadWarnings& warn) {
    for (const MtlTexture& t : statements.textures) {
        const MapSpec* spec = mapSpec(t.keyword);
        if (!spec) continue;  // the material policy warns about the others
        const std::string what = "material '" + statements.name + "': " + t.keyword + ": ";
        const auto note = [&](const std::string& message) {
            warn.add(what + message, t.line, statements.file);
        };
        const MtlTextureOptions o = parseMtlTextureOptions(t.options);
        for (const std::string& p : o.problems) note(p + "; option ignored");
        for (const std::string& p : o.ignored) note("option " + p + " is not supported; ignored");
        if (o.bumpMultiplierGiven && spec->kind != MapKind::Bump)
            note("option -bm applies to bump maps only; ignored");
        if (o.channel && (spec->kind == MapKind::Colour || spec->kind == MapKind::Normal))
            note("option -imfchan applies to scalar maps only; ignored");
        const ImageRole role = spec->kind == MapKind::Colour ? ImageRole::Color : ImageRole::Data;
        // t.file is already resolved beside the library (obj_materials.cpp).
        const TextureLibrary::Result image = library.load(t.file, role);
        if (!image.image) {
            if (image.firstFailure) note("texture not read (" + image.error + "); rendered without it");
            continue;
        }
        Texture tex = Texture::fromImage(image.image, t.file);
        tex.offset = o.offset;
        tex.scale = o.scale;
        tex.wrap = o.clamp ? WrapMode::Clamp : WrapMode::Repeat;
        if (spec->kind == MapKind::Bump || spec->kind == MapKind::Scalar)
            tex.channel = channelOf(o.channel ? o.channel : 'l');
        // map_d: exporters name an RGBA image (often the map_Kd one) meaning
        // its alpha; a grey mask has none, and then its grey level counts.
        if (spec->kind == MapKind::Alpha) tex.channel = channelOf(o.channel ? o.channel : 'm');
        textures.push_back(tex);
        material.maps.*(spec->slot) = uint32_t(textures.size() - 1);
        if (spec->kind == MapKind::Bump) material.maps.bumpScale = o.bumpMultiplier;
    }
}

}  // namespace raylab

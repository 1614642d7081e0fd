#include "renderer/io/mtl_material.h"

#include <cmath>
#include <string>

#include "renderer/io/errors.h"

namespace raylab {

namespace {
Color colorOf(const tinyobj::real_t c[3]) { return Color(c[0], c[1], c[2]); }
}  // namespace

Material materialFromMtl(const tinyobj::material_t& m, size_t index,
                         const MtlLibraryReader& libraries, LoadWarnings& warn) {
    // Warnings and errors point at the MTL statement they are about.
    const auto note = [&](std::initializer_list<const char*> keywords, const std::string& what) {
        const auto [file, line] = libraries.locate(index, m.name, keywords);
        warn.add("material '" + m.name + "': " + what, line, file);
    };
    Material out;
    out.name = m.name;
    out.ka = colorOf(m.ambient);
    out.kd = colorOf(m.diffuse);
    out.ks = colorOf(m.specular);
    out.shininess = m.shininess;
    int illum = m.illum;
    if (illum < 0 || illum > 10) {
        note({"illum"}, "illum " + std::to_string(illum) + " is unknown; read as illum 2");
        illum = 2;
    }
    if (illum == 0) out.ka = Color(0);
    if (illum <= 1) out.ks = Color(0);
    if (illum >= 3 && illum <= 7) out.km = colorOf(m.specular);
    if (illum == 4 || illum == 6 || illum == 7) {
        const Color tf = colorOf(m.transmittance);
        out.kt = !tf.isBlack() ? tf : Color(1.0 - double(m.dissolve));
    } else if (m.dissolve < 1) {
        note({"d", "Tr"}, "dissolve d < 1 is ignored with illum " + std::to_string(illum) +
                              " (transparency needs illum 4, 6 or 7)");
    }
    out.ior = m.ior > 0 ? m.ior : 1.0;
    if (!m.diffuse_texname.empty() || !m.specular_texname.empty() || !m.bump_texname.empty() ||
        !m.ambient_texname.empty() || !m.alpha_texname.empty())
        note({"map_Kd", "map_Ks", "map_Ka", "map_d", "bump", "map_bump"},
             "texture maps are not supported and are ignored");

    const auto refuse = [&](std::initializer_list<const char*> keywords, const std::string& what) {
        const auto [file, line] = libraries.locate(index, m.name, keywords);
        return InputError(file, line, "material '" + m.name + "': " + what);
    };
    const auto bad = [](const Color& c) { return !c.isFinite() || c.r < 0 || c.g < 0 || c.b < 0; };
    const char* const colourRule = ": colours must be finite and >= 0";
    if (bad(out.ka)) throw refuse({"Ka"}, std::string("Ka") + colourRule);
    if (bad(out.kd)) throw refuse({"Kd"}, std::string("Kd") + colourRule);
    if (bad(out.ks) || bad(out.km)) throw refuse({"Ks"}, std::string("Ks") + colourRule);
    // The transmission comes from Tf (or Kt), else from 1 - dissolve (d, Tr).
    if (bad(out.kt)) {
        if (!colorOf(m.transmittance).isBlack())
            throw refuse({"Tf", "Kt"}, std::string("Tf") + colourRule);
        throw refuse({"d", "Tr"}, "the dissolve d (or 1 - Tr) must be in [0, 1]");
    }
    if (!(out.shininess >= 0 && std::isfinite(out.shininess)))
        throw refuse({"Ns"}, "Ns must be finite and >= 0");
    if (!std::isfinite(out.ior)) throw refuse({"Ni"}, "Ni must be finite");
    return out;
}

}  // namespace raylab

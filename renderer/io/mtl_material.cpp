#include "renderer/io/mtl_material.h"

#include <strings.h>

#include <string>

#include "renderer/io/mtl_textures.h"

namespace raylab {

namespace {
/// The highlight exponent of a material without Ns: raylab's JSON default.
constexpr double kDefaultShininess = 32;
/// Kd of a material without Kd: raylab's default grey (black would hide the surface).
constexpr double kDefaultDiffuse = 0.8;
}  // namespace

Material materialFromMtl(const MtlMaterial& m, LoadWarnings& warn) {
    // Warnings about a library hold once per file (LoadWarnings counts repeats).
    const auto note = [&](int line, const std::string& what) { warn.add(what, line, m.file); };
    Material out;
    out.name = m.name;
    out.kd = m.kd.given() ? m.kd.value : Color(kDefaultDiffuse);
    // Without Ka, ambient light is reflected like the diffuse light (Ka = Kd):
    // shadowed sides keep the surface's colour instead of going black.
    out.ka = m.ka.given() ? m.ka.value : out.kd;
    // ... the diffuse colour as shaded, so also where map_Kd or vertex colours
    // vary it (unless the file gives an ambient map of its own).
    bool ambientMap = false;
    for (const MtlTexture& t : m.textures)
        ambientMap = ambientMap || ::strcasecmp(t.keyword.c_str(), "map_Ka") == 0;
    out.ambientFollowsDiffuse = !m.ka.given() && !ambientMap;
    out.ks = m.ks.given() ? m.ks.value : Color(0);
    out.shininess = m.ns.given() ? m.ns.value : kDefaultShininess;
    out.ior = m.ni.given() && m.ni.value > 0 ? m.ni.value : 1.0;

    // The MTL spec's default illumination model is 2 (highlights on); most
    // exporters write none.
    int illum = m.illum.given() ? m.illum.value : 2;
    if (illum < 0 || illum > 10) {
        warn.add("material '" + m.name + "': illum " + std::to_string(illum) +
                     " is unknown; read as illum 2",
                 m.illum.line, m.file, "unknown illum values");
        illum = 2;
    }
    if (illum == 0) {
        out.ka = Color(0);
        out.ambientFollowsDiffuse = false;
    }
    if (illum <= 1) out.ks = Color(0);
    // An exponent below 1 spreads the highlight over the whole lit side (Ns 0
    // with Ks 0.9 paints it white): such a surface is matte.
    if (m.ns.given() && m.ns.value < 1 && !out.ks.isBlack()) {
        note(m.ns.line, "Ns below 1 makes the highlight cover the whole surface; read as no "
                        "highlight (ks = 0)");
        out.ks = Color(0);
    }
    if (illum >= 3 && illum <= 7) out.km = m.ks.given() ? m.ks.value : Color(0);
    const double dissolve = m.dissolve.given() ? m.dissolve.value : 1.0;
    // Only illum 6 and 7 ask for refraction ("Refraction on"); there the light
    // that passes is Tf, or 1 - d, bent by Ni.
    const bool refracting = illum == 6 || illum == 7;
    if (refracting) {
        const bool tf = m.tf.given() && !m.tf.value.isBlack();
        out.kt = tf ? m.tf.value : Color(1.0 - dissolve);
    } else {
        // Dissolve, in every other model (the spec: "dissolve works on all
        // illumination models" and "does not depend upon material thickness"):
        // the surface is d opaque and 1 - d see-through, rays pass straight.
        if (dissolve < 1) {
            out.ka = out.ka * dissolve;
            out.kd = out.kd * dissolve;
            out.ks = out.ks * dissolve;
            out.km = out.km * dissolve;
            out.kt = Color(1.0 - dissolve);
            out.ior = 1.0;
        }
        if (m.tf.given())
            note(m.tf.line, "'Tf' (transmission filter) is only used with illum 6 or 7 (refraction); ignored");
    }
    if (m.ke.given() && !m.ke.value.isBlack())
        note(m.ke.line, "'Ke' (emission) is not simulated by raylab; ignored");
    // Colour, exponent, bump, normal and alpha maps are read by mtl_textures.cpp.
    for (const MtlTexture& t : m.textures)
        if (!isSupportedMtlMap(t.keyword))
            warn.add("material '" + m.name + "': texture maps other than map_Kd, map_Ka, map_Ks, "
                         "map_Ns, bump, norm and map_d are not supported and are ignored (" +
                         t.keyword + " " + t.file + ")",
                     t.line, m.file, "texture maps");
    return out;
}

}  // namespace raylab

#pragma once
// Whitted material: plain data, no behaviour.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "shading/color.h"

namespace raylab {

/// The specular highlight model.
enum class Highlight {
    BlinnPhong,  ///< (N·H)^s: the default
    Phong,       ///< (R·V)^s: NFF/SPD scenes
};

/// The optical values shading reads at one surface point: a material's
/// constants, or (textured materials) their product with its textures there.
struct SurfaceOptics {
    Color ka{0, 0, 0};       ///< ambient reflectance (multiplies the scene ambient Ia)
    Color kd{0.8, 0.8, 0.8}; ///< Lambert diffuse reflectance
    Color ks{0, 0, 0};       ///< specular (highlight) reflectance
    double shininess = 32;   ///< specular exponent s
    Highlight highlight = Highlight::BlinnPhong;
    Color km{0, 0, 0};       ///< ideal mirror reflection weight
    Color kt{0, 0, 0};       ///< transmission (refraction) weight
    double ior = 1.0;        ///< index of refraction of the inside medium
    /// Ambient reflected like the diffuse light, colour for colour: kd as
    /// textured, times the surface's vertex colours, instead of ka. An MTL
    /// material without Ka and map_Ka (docs/obj.md: Ka = Kd).
    bool ambientFollowsDiffuse = false;

    bool reflective() const { return !km.isBlack(); }
    bool transmissive() const { return !kt.isBlack(); }
    bool hasLocalShading() const { return !kd.isBlack() || !ks.isBlack(); }
};

/// A material's textures: indices into Scene::textures, kNone where a value
/// is constant. A colour map multiplies its constant (MTL: map_Kd × Kd);
/// shininess likewise. docs/scene-format.md lists the JSON and MTL keys.
struct MaterialMaps {
    static constexpr uint32_t kNone = 0xFFFFFFFFu;
    uint32_t ka = kNone, kd = kNone, ks = kNone, km = kNone, kt = kNone;
    uint32_t shininess = kNone;  ///< scalar map multiplying the exponent (map_Ns)
    uint32_t bump = kNone;       ///< scalar height map (bump, map_bump)
    double bumpScale = 1;        ///< height = bumpScale × map value, in scene units (-bm)
    uint32_t normal = kNone;     ///< tangent-space normal map (norm)
    uint32_t alpha = kNone;      ///< scalar coverage mask (map_d, JSON "alpha"): see Material

    /// Every texture slot, for code that must treat them all alike (a loader
    /// offsetting indices into a scene's textures): a new slot goes here.
    std::array<uint32_t*, 9> slots() {
        return {&ka, &kd, &ks, &km, &kt, &shininess, &bump, &normal, &alpha};
    }

    /// Whether shading reads a texture (the alpha mask is read by the
    /// accelerators' surface filter, before shading).
    bool any() const {
        return ka != kNone || kd != kNone || ks != kNone || km != kNone || kt != kNone ||
               shininess != kNone || bump != kNone || normal != kNone;
    }
};

struct Material : SurfaceOptics {
    std::string name;
    MaterialMaps maps;
    /// Coverage for cut-outs: alpha × the alpha map (when present) at the
    /// hit's uv; where it is below alphaCutoff the surface is a hole for
    /// every ray (camera, secondary and shadow). Not a blend: Whitted rays
    /// either hit or pass.
    double alpha = 1;
    double alphaCutoff = 0.5;

    /// The cut-off in force: `override` (--alpha-cutoff) when set, else alphaCutoff.
    double cutoff(const std::optional<double>& override = std::nullopt) const {
        return override.value_or(alphaCutoff);
    }
    /// Whether some hit on this material may be a hole (renderer/surface_filter).
    bool cutsOut(const std::optional<double>& override = std::nullopt) const {
        return maps.alpha != MaterialMaps::kNone || alpha < cutoff(override);
    }
};

}  // namespace raylab

#pragma once
// The set of optical effects a scene actually calls for. The integrator is
// specialised on it, so a matte scene runs code with no reflection branch and
// a scene without lights never builds a shadow ray.

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

struct Scene;
struct RenderOptions;

/// Effects that change the per-ray kernel (template bits of the integrator).
enum EffectBits : unsigned {
    kShadows = 1u << 0,     ///< lights exist and some material has a diffuse or specular term
    kHighlights = 1u << 1,  ///< some material has ks > 0 (Blinn-Phong)
    kReflection = 1u << 2,  ///< some material has km > 0 (SPD mode: ks > 0 or kt > 0)
    kRefraction = 1u << 3,  ///< some material has kt > 0
    kKernelBits = 4,
    kAllKernelEffects = (1u << kKernelBits) - 1,  ///< what the general kernel (--effects all) forces
    /// Some material in use has a texture: surface parameters, footprints and
    /// texture lookups at every hit. A kernel bit of its own, outside
    /// kAllKernelEffects: the general kernel of an untextured scene has none.
    kTextures = 1u << kKernelBits,
};

struct EffectSet {
    unsigned kernel = 0;        ///< EffectBits
    bool smoothNormals = false; ///< some mesh or polygon carries vertex normals
    bool antialiasing = false;  ///< spp > 1 or adaptive supersampling
    bool aovs = false;          ///< depth/normal/albedo/objectId layers requested
    /// Shadow feelers pass through transmitters (ShadowMode::Filtered, and
    /// some shaded surface can see a transmitter between it and a light).
    bool filteredShadows = false;
    /// Some material has an alpha cut-out: the accelerators filter its hits
    /// (no kernel of its own: a hole is decided before shading).
    bool cutOuts = false;

    bool has(EffectBits b) const { return (kernel & b) != 0; }
    bool textures() const { return has(kTextures); }
    /// Names for the summary and --stats ("shadows", "reflection", ...).
    std::vector<std::string> names() const;
};

/// Derives the effect set from what is in the scene and the options.
EffectSet analyseEffects(const Scene& scene, const RenderOptions& options);

}  // namespace raylab

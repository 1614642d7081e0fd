#pragma once
// The words of the render options that take one of a few values, one table
// per option. The command line (apps/) and the scene file's "render" block
// (io/) both parse through these tables, so they accept exactly the same
// words, list the same choices on a mistake, and hand the renderer enums:
// an unknown word is an error where it is typed, never a silent default.

#include <string>
#include <utility>
#include <vector>

#include "geometry/shape.h"
#include "renderer/accel/accel_options.h"
#include "renderer/accelerator_kind.h"
#include "renderer/render_overrides.h"
#include "renderer/shadow_mode.h"
#include "renderer/texture_options.h"

namespace raylab {

/// The accepted words of an option and the value each one means, in the
/// order help texts and error messages list them.
template <class E>
using OptionNames = std::vector<std::pair<std::string, E>>;

/// --accel, "accel": embree, naive.
const OptionNames<AcceleratorKind>& acceleratorNames();
/// --bvh-quality, "bvh_quality": low, medium, high.
const OptionNames<AccelOptions::BvhQuality>& bvhQualityNames();
/// --precision, "precision": float, double.
const OptionNames<Precision>& precisionNames();
/// --effects: auto, all.
const OptionNames<EffectsMode>& effectsModeNames();
/// --shadows, "shadows": opaque, filtered.
const OptionNames<ShadowMode>& shadowModeNames();
/// --texture-filter, "texture_filter": point, bilinear, trilinear, anisotropic.
const OptionNames<TextureFilter>& textureFilterNames();
/// --texture-footprint, "texture_footprint": cones, differentials.
const OptionNames<TextureFootprint>& textureFootprintNames();

/// "float" or "double" (the word of --precision).
const char* precisionName(Precision precision);

/// The words of `names` joined by `separator` ("embree|naive").
template <class E>
std::string joinedNames(const OptionNames<E>& names, const std::string& separator) {
    std::string list;
    for (const auto& entry : names) list += (list.empty() ? "" : separator) + entry.first;
    return list;
}

}  // namespace raylab

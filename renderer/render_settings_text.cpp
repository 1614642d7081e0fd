#include "renderer/render_settings_text.h"

#include <cstdio>

#include "renderer/render_option_names.h"

namespace raylab {

namespace {

/// A double as text that reads back to the same bits.
std::string exact(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string exact(const Vec3& v) { return exact(v.x) + "," + exact(v.y) + "," + exact(v.z); }

}  // namespace

std::string renderSettingsText(const RenderOptions& o) {
    std::string s;
    const auto add = [&s](const char* name, const std::string& value) {
        s += (s.empty() ? "" : " ") + std::string(name) + "=" + value;
    };
    add("width", std::to_string(o.width));
    add("height", std::to_string(o.height));
    add("spp", std::to_string(o.spp));
    add("depth", std::to_string(o.maxDepth));
    add("min_weight", exact(o.minWeight));
    add("adaptive", exact(o.adaptiveThreshold));
    add("adaptive_levels", std::to_string(o.adaptiveMaxLevel));
    add("seed", std::to_string(o.seed));
    add("max_rays", std::to_string(o.maxRaysPerSample));
    add("accel", acceleratorName(o.accel));
    add("bvh_quality", bvhQualityName(o.accelOptions.quality));
    add("robust", o.accelOptions.robust ? "on" : "off");
    add("accel_origin", exact(o.accelOptions.origin));
    const IntersectOptions& in = o.accelOptions.intersect;
    add("precision", in.precision == Precision::Float ? "float" : "double");
    add("polygons", !in.polygonTest                             ? "each"
                    : *in.polygonTest == PolygonTest::Projected ? "projected"
                                                                : "watertight");
    add("spawn", o.spawn.mode == OffsetMode::Robust ? "robust" : "epsilon");
    add("epsilon", exact(o.spawn.epsilon));
    add("spawn_reference", exact(o.spawn.reference));
    add("spd", o.spd ? "on" : "off");
    add("shadows", shadowModeName(o.shadows));
    add("alpha", alphaModeName(o.alpha));
    add("alpha_cutoff",
        o.accelOptions.alphaCutoff ? exact(*o.accelOptions.alphaCutoff) : "materials");
    add("texture_filter", textureFilterName(o.textures.filter));
    add("texture_footprint", textureFootprintName(o.textures.footprint));
    add("effects", o.forceAllEffects ? "all" : "auto");
    add("aovs", o.wantAovs ? "on" : "off");
    add("crop", exact(o.crop.x0) + "," + exact(o.crop.x1) + "," + exact(o.crop.y0) + "," +
                    exact(o.crop.y1));
    return s;
}

}  // namespace raylab

#include "distributed/render_identity.h"

#include <cstdio>

#include "renderer/content_hash.h"

namespace raylab {

namespace {

/// A double as text that reads back to the same bits.
std::string exact(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string exact(const Vec3& v) { return exact(v.x) + "," + exact(v.y) + "," + exact(v.z); }

/// Every field of RenderOptions that changes pixels (not `threads`: the
/// image does not depend on it). A field added there that changes pixels
/// belongs here too.
std::string optionWords(const RenderOptions& o) {
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
    add("alpha_cutoff", o.accelOptions.alphaCutoff ? exact(*o.accelOptions.alphaCutoff) : "materials");
    add("texture_filter", textureFilterName(o.textures.filter));
    add("texture_footprint", textureFootprintName(o.textures.footprint));
    add("effects", o.forceAllEffects ? "all" : "auto");
    add("aovs", o.wantAovs ? "on" : "off");
    add("crop", exact(o.crop.x0) + "," + exact(o.crop.x1) + "," + exact(o.crop.y0) + "," +
                    exact(o.crop.y1));
    return s;
}

/// The first word where two settings texts differ, from each ("" past the end).
std::pair<std::string, std::string> firstDifference(const std::string& a, const std::string& b) {
    size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        const size_t ei = std::min(a.find(' ', i), a.size());
        const size_t ej = std::min(b.find(' ', j), b.size());
        std::string wa = a.substr(i, ei - i), wb = b.substr(j, ej - j);
        if (wa != wb) return {wa, wb};
        i = ei + 1;
        j = ej + 1;
    }
    return {"", ""};
}

std::string filesText(const RenderIdentity& id) {
    return id.scene + " (" + std::to_string(id.files) + (id.files == 1 ? " file, " : " files, ") +
           std::to_string(id.bytes) + " bytes)";
}

}  // namespace

RenderIdentity renderIdentity(const std::string& scenePath, const std::vector<InputFile>& inputs,
                              const RenderOptions& options, const std::optional<FrameRange>& frames,
                              bool triangulated) {
    RenderIdentity id;
    id.scene = scenePath;
    ContentHash hash;
    for (const InputFile& f : inputs) {
        // Each file's length and hash: where one file ends and the next begins matters.
        hash.addNumber(f.bytes).addNumber(f.contentHash);
        id.bytes += f.bytes;
    }
    id.files = uint32_t(inputs.size());
    id.sceneHash = hash.value();
    id.settings = optionWords(options);
    id.settings +=
        frames ? " frames=" + std::to_string(frames->first) + ":" + std::to_string(frames->last)
               : std::string(" frames=none");
    id.settings += triangulated ? " triangulated=yes" : " triangulated=no";
    return id;
}

std::string disagreement(const RenderIdentity& root, const RenderIdentity& other,
                         const std::string& otherName) {
    const std::string advice = "; every rank must render the same scene with the same options";
    if (other.sceneHash != root.sceneHash || other.files != root.files || other.bytes != root.bytes)
        return "ranks disagree: " + otherName +
               " read other scene bytes than rank 0: " + filesText(other) + " against " +
               filesText(root) + advice;
    if (other.settings != root.settings) {
        const auto [mine, theirs] = firstDifference(root.settings, other.settings);
        return "ranks disagree: " + otherName + " renders with " +
               (theirs.empty() ? "fewer settings" : theirs) + ", rank 0 with " +
               (mine.empty() ? "fewer settings" : mine) + advice;
    }
    return "";
}

}  // namespace raylab

#include "distributed/render_identity.h"

#include <cstdio>

#include "renderer/content_hash.h"
#include "renderer/render_settings_text.h"

namespace raylab {

namespace {

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
    id.settings = renderSettingsText(options);
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

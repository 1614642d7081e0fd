#include "renderer/render_stats.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "renderer/cryptomatte_id.h"
#include "renderer/io/json_string.h"

namespace raylab {

namespace {

/// Minimal pretty-printing JSON writer: objects open one level of two-space
/// indentation, arrays of numbers stay on one line.
class JsonWriter {
public:
    void beginObject(const char* key = nullptr) {
        item(key);
        m_out += '{';
        m_first = true;
        ++m_depth;
    }
    void endObject() {
        --m_depth;
        if (!m_first) newline();
        m_out += '}';
        m_first = false;
    }
    void number(const char* key, uint64_t v) {
        item(key);
        m_out += std::to_string(v);
    }
    void number(const char* key, int v) {
        item(key);
        m_out += std::to_string(v);
    }
    void number(const char* key, double v) {
        item(key);
        m_out += formatDouble(v);
    }
    void string(const char* key, const std::string& v) {
        item(key);
        appendJsonString(m_out, v);
    }
    void beginArray(const char* key) {
        item(key);
        m_out += '[';
        m_first = true;
        ++m_depth;
    }
    void endArray() {
        --m_depth;
        if (!m_first) newline();
        m_out += ']';
        m_first = false;
    }
    void numberArray(const char* key, const std::vector<uint64_t>& values) {
        item(key);
        m_out += '[';
        for (size_t i = 0; i < values.size(); ++i) {
            if (i) m_out += ", ";
            m_out += std::to_string(values[i]);
        }
        m_out += ']';
    }
    void stringArray(const char* key, const std::vector<std::string>& values) {
        item(key);
        m_out += '[';
        for (size_t i = 0; i < values.size(); ++i) {
            if (i) m_out += ", ";
            appendJsonString(m_out, values[i]);
        }
        m_out += ']';
    }
    /// Room for `bytes` of text (the objects' list can be a megabyte).
    void reserve(size_t bytes) { m_out.reserve(bytes); }
    /// The document, with a final newline, moved out (the writer is done).
    std::string take() {
        m_out += '\n';
        return std::move(m_out);
    }

private:
    // JSON has no NaN/Inf; a timing can never be one, but stay valid anyway.
    static std::string formatDouble(double v) {
        if (!std::isfinite(v)) return "null";
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", v);
        return buf;
    }
    void newline() {
        m_out += '\n';
        m_out.append(size_t(2 * m_depth), ' ');
    }
    void item(const char* key) {
        if (m_depth > 0) {
            if (!m_first) m_out += ',';
            newline();
        }
        m_first = false;
        if (key) {
            appendJsonString(m_out, key);
            m_out += ": ";
        }
    }
    std::string m_out;
    int m_depth = 0;
    bool m_first = true;
};

/// Counts for depths 1.. of one ray type, trimmed after the last non-zero
/// entry. The last tracked slot also holds every deeper ray.
std::vector<uint64_t> depthHistogram(const RayCounters& rays, RayType type) {
    const auto& counts = rays.byDepth[size_t(type)];
    size_t last = 0;  // highest depth with a non-zero count (0: none)
    for (size_t d = 1; d < counts.size(); ++d)
        if (counts[d] != 0) last = d;
    return std::vector<uint64_t>(counts.begin() + 1, counts.begin() + 1 + last);
}

}  // namespace

std::string RenderStats::toJson() const {
    const RayType types[] = {RayType::Camera, RayType::Shadow, RayType::Reflection,
                             RayType::Refraction};
    JsonWriter json;
    // About 90 bytes per object (id, name, Cryptomatte id), a few KB besides.
    size_t objectBytes = 0;
    for (const std::string& name : objects) objectBytes += 90 + name.size();
    json.reserve(4096 + objectBytes);
    json.beginObject();

    json.beginObject("rays");
    for (RayType t : types) json.number(rayTypeName(t), rays.total(t));
    json.number("total", rays.total());
    json.beginObject("by_depth");
    for (RayType t : types) json.numberArray(rayTypeName(t), depthHistogram(rays, t));
    json.endObject();
    json.endObject();

    json.number("camera_hits", rays.cameraHits);

    json.beginObject("time_s");
    json.number("parse", parseSeconds);
    json.number("build", buildSeconds);
    json.number("render", renderSeconds);
    json.number("write", writeSeconds);
    json.endObject();

    json.number("mrays_per_s", mraysPerSecond());
    json.number("primitives", primitives);
    json.stringArray("effects", effects);
    json.number("threads", threads);
    json.string("accel", accel);

    json.beginObject("image");
    json.number("width", width);
    json.number("height", height);
    json.number("spp", spp);
    json.number("max_depth", maxDepth);
    json.endObject();

    json.number("non_finite_samples", nonFiniteSamples);
    json.beginObject("ray_cap");
    json.number("rays_per_sample", maxRaysPerSample);
    json.number("capped_samples", cappedSamples);
    json.number("most_rays_in_a_sample", maxSampleRays);
    json.endObject();
    json.beginObject("surface_filter");
    json.number("cut_out_candidates", filter.cutOut);
    json.number("attenuating_crossings", filter.attenuated);
    json.endObject();

    // id (objectId in the EXR), name, Cryptomatte id as in the manifest.
    json.beginArray("objects");
    for (size_t i = 0; i < objects.size(); ++i) {
        json.beginObject();
        json.number("id", int(i));
        json.string("name", objects[i]);
        json.string("cryptomatte", cryptomatteHex(cryptomatteIdBits(objects[i])));
        json.endObject();
    }
    json.endArray();
    if (textures) {
        json.beginObject("textures");
        json.string("filter", textures->filter);
        json.string("footprint", textures->footprint);
        json.number("count", textures->count);
        json.number("mib", textures->mebibytes);
        json.endObject();
    }
    json.endObject();
    return json.take();
}

}  // namespace raylab

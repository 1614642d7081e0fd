#pragma once
// Counters and timings of one render; written by --stats as JSON and printed
// in the end-of-render summary.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/filter_counts.h"

namespace raylab {

enum class RayType { Camera = 0, Shadow, Reflection, Refraction, Count };

inline const char* rayTypeName(RayType t) {
    switch (t) {
        case RayType::Camera: return "camera";
        case RayType::Shadow: return "shadow";
        case RayType::Reflection: return "reflection";
        case RayType::Refraction: return "refraction";
        default: return "?";
    }
}

/// Ray counts per type and per depth (depth 1 = camera ray). Plain counters,
/// one instance per thread, summed at the end (deterministic).
struct RayCounters {
    static constexpr int kMaxTrackedDepth = 64;
    std::array<std::array<uint64_t, kMaxTrackedDepth + 1>, size_t(RayType::Count)> byDepth{};
    uint64_t cameraHits = 0;

    void count(RayType type, int depth) {
        byDepth[size_t(type)][depth < 0 ? 0 : (depth < kMaxTrackedDepth ? depth : kMaxTrackedDepth)]++;
    }
    uint64_t total(RayType type) const {
        uint64_t n = 0;
        for (uint64_t c : byDepth[size_t(type)]) n += c;
        return n;
    }
    uint64_t total() const {
        uint64_t n = 0;
        for (size_t t = 0; t < size_t(RayType::Count); ++t) n += total(RayType(t));
        return n;
    }
    RayCounters& operator+=(const RayCounters& o) {
        for (size_t t = 0; t < byDepth.size(); ++t)
            for (size_t d = 0; d < byDepth[t].size(); ++d) byDepth[t][d] += o.byDepth[t][d];
        cameraHits += o.cameraHits;
        return *this;
    }
};

struct RenderStats {
    RayCounters rays;
    double parseSeconds = 0;
    double buildSeconds = 0;
    double renderSeconds = 0;
    double writeSeconds = 0;
    uint64_t primitives = 0;
    std::vector<std::string> effects;
    int threads = 0;
    std::string accel;
    int width = 0, height = 0, spp = 0, maxDepth = 0;
    uint64_t nonFiniteSamples = 0;  ///< samples whose radiance was NaN/Inf and was replaced
    uint64_t maxRaysPerSample = 0;  ///< the cap (RenderOptions::maxRaysPerSample)
    uint64_t cappedSamples = 0;     ///< samples that reached it (their trees were cut)
    uint64_t maxSampleRays = 0;     ///< the most rays one sample traced
    /// Candidate hits cut out and transmitter crossings of shadow feelers
    /// (this process's accelerator: under mpirun, rank 0's share).
    FilterCounts filter;
    /// Textured scenes only ("textures" effect): the lookup settings, the
    /// number of textures and the MiB of their MIP pyramids.
    struct Textures {
        std::string filter, footprint;
        uint64_t count = 0;
        double mebibytes = 0;
    };
    std::optional<Textures> textures;

    /// Million rays (all types) per second of render time.
    double mraysPerSecond() const {
        return renderSeconds > 0 ? double(rays.total()) / renderSeconds * 1e-6 : 0;
    }

    /// The --stats JSON document.
    std::string toJson() const;
};

}  // namespace raylab

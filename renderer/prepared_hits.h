#pragma once
// Camera hits shaded up to their shadow feelers ahead of their ray trees
// (WhittedIntegrator::prepareCameraHits). The feelers of neighbouring camera
// hits towards one light are nearly parallel, so the accelerator answers
// them together, as a packet, for less traversal than one at a time; each
// answer is exactly the single feeler's, so Li computes the same radiance.
// The lights' terms are computed there too, lane after lane: the square
// roots and divisions of one hit overlap with the next one's, where in the
// ray tree each waits for the one before.
// A worker keeps one PreparedHits and reuses it packet after packet.

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/spawn.h"
#include "renderer/accel/accelerator.h"
#include "renderer/scene.h"
#include "shading/color.h"

namespace raylab {

/// What a light that arrives at a hit adds there, in this order: Lambert's
/// term, then the highlight's where there is one (WhittedIntegrator::lightTerms).
struct LightTerms {
    Color diffuse;
    Color highlight;           ///< set where highlighted
    bool highlighted = false;  ///< the highlight is added (a zero added could turn -0 into +0)
};

/// One light as seen from a prepared hit, as shadeLocal would find it: the
/// unit direction towards it (kept for the terms) and its cosine with the
/// shading normal (on the side the ray arrives from); where the integrator
/// traces the light's feeler, what the feeler brought back (filtered
/// shadows: the transmittance; otherwise black where blocked, white where
/// lit), and whether the light then arrives (`lit`: let through and facing
/// the normal) with the terms it adds.
struct PreparedFeeler {
    Vec3 l;
    double nDotL = 0;
    Color through;
    bool lit = false;
    LightTerms terms;  ///< set where lit
};

/// One camera hit, prepared: the camera ray's unit direction, the hit's
/// surface record, its spawner and, per light, its feeler (PreparedFeeler).
struct PreparedHit {
    Vec3 dir;  ///< normalize(ray.d), as traceHit computes it
    SurfaceInteraction si;
    std::optional<RaySpawner> spawn;          ///< the hit's spawned rays, as traceHit makes them
    const PreparedFeeler* feelers = nullptr;  ///< indexed by light
};

/// The prepared camera hits of one packet of camera rays.
class PreparedHits {
public:
    PreparedHits() = default;
    /// A worker's scratch, valid for one packet: a copy (WorkCounters are
    /// copied and summed) starts with no lane prepared.
    PreparedHits(const PreparedHits&) {}
    PreparedHits& operator=(const PreparedHits&) {
        m_ready.fill(false);
        return *this;
    }

    /// Lane k's prepared hit, or null (a miss, or nothing was prepared).
    const PreparedHit* lane(int k) const { return m_ready[size_t(k)] ? &m_hits[size_t(k)] : nullptr; }

    /// No lane prepared, room for the feelers of `lights` lights per lane
    /// (before a packet is prepared, or when none will be).
    void clear(size_t lights) {
        m_ready.fill(false);
        m_lights = lights;
        if (m_feelers.size() < m_hits.size() * lights) m_feelers.resize(m_hits.size() * lights);
    }
    /// Lane k is prepared: its direction and surface record are to be
    /// filled in, its feelers go to feelers(k).
    PreparedHit& prepare(int k) {
        m_ready[size_t(k)] = true;
        m_hits[size_t(k)].feelers = feelers(k);
        return m_hits[size_t(k)];
    }
    /// Lane k's feelers, by light.
    PreparedFeeler* feelers(int k) { return m_feelers.data() + size_t(k) * m_lights; }

private:
    std::array<PreparedHit, Accelerator::kPacketRays> m_hits;
    std::array<bool, Accelerator::kPacketRays> m_ready{};
    size_t m_lights = 0;
    std::vector<PreparedFeeler> m_feelers;  ///< lane-major: lane · lights + light
};

}  // namespace raylab

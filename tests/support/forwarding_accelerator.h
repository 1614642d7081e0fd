#pragma once
// An accelerator that asks another for every answer, for tests that change
// one query (a test derives and overrides it) or that need the same answers
// asked one ray at a time: packets are not forwarded, so intersectPacket is
// Accelerator's ray-by-ray default and tracesPackets() is false.
// Header-only, included as "support/forwarding_accelerator.h". A subclass
// that changes occluded() or transmittance() overrides the hinted forms too:
// the integrator asks those whenever the inner accelerator uses hints.

#include <optional>
#include <string>

#include "renderer/accel/accelerator.h"

namespace raylab::test {

class ForwardingAccelerator : public Accelerator {
public:
    explicit ForwardingAccelerator(const Accelerator& inner) : m_inner(inner) {}
    using Accelerator::intersect;
    using Accelerator::occluded;
    using Accelerator::transmittance;
    std::optional<Hit> intersect(const Ray& r, double tMin, double tMax,
                                 Departure from) const override {
        return m_inner.intersect(r, tMin, tMax, from);
    }
    bool occluded(const Ray& r, double tMin, double tMax, Departure from) const override {
        return m_inner.occluded(r, tMin, tMax, from);
    }
    bool occluded(const Ray& r, double tMin, double tMax, Departure from,
                  OcclusionHint& h) const override {
        return m_inner.occluded(r, tMin, tMax, from, h);
    }
    bool usesOcclusionHints(bool filtered) const override {
        return m_inner.usesOcclusionHints(filtered);
    }
    Color transmittance(const Ray& r, double tMin, double tMax, Departure from) const override {
        return m_inner.transmittance(r, tMin, tMax, from);
    }
    Color transmittance(const Ray& r, double tMin, double tMax, Departure from,
                        OcclusionHint& h) const override {
        return m_inner.transmittance(r, tMin, tMax, from, h);
    }
    std::string name() const override { return m_inner.name(); }
    double buildSeconds() const override { return m_inner.buildSeconds(); }
    FilterCounts filterCounts() const override { return m_inner.filterCounts(); }

private:
    const Accelerator& m_inner;
};

}  // namespace raylab::test

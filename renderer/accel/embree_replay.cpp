#include "renderer/accel/embree_replay.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <stdexcept>

#include "renderer/accel/embree_accelerator.h"
#include "renderer/timing.h"

namespace raylab {

/// A ray ready for Embree: the converted ray (and an empty hit record) plus
/// the index of the recorded ray it came from.
struct PreparedRay {
    RTCRayHit rayhit;
    uint32_t index;
    bool occlusion;
};

struct EmbreeReplay::Impl {
    const EmbreeAccelerator* accel = nullptr;
    const std::vector<RecordedRay>* rays = nullptr;
    std::vector<PreparedRay> prepared;
    std::vector<uint8_t> results;

    /// One query, as EmbreeAccelerator::intersect/occluded make it, minus
    /// the conversion (done up front) and the decoding of the hit.
    void trace(const PreparedRay& p, RTCScene scene) {
        const RecordedRay& r = (*rays)[p.index];
        EmbreeQueryContext ctx;
        ctx.init(&r.ray, r.tMin, r.tMax);
        if (p.occlusion) {
            RTCRay ray = p.rayhit.ray;
            rtcOccluded1(scene, &ctx.rtc, &ray);
            results[p.index] = ray.tfar < 0.0f;
        } else {
            RTCRayHit rayhit = p.rayhit;
            rtcIntersect1(scene, &ctx.rtc, &rayhit);
            results[p.index] = rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
};

EmbreeReplay::EmbreeReplay(const Accelerator& accel, const std::vector<RecordedRay>& rays)
    : m_impl(std::make_unique<Impl>()) {
    m_impl->accel = dynamic_cast<const EmbreeAccelerator*>(&accel);
    if (!m_impl->accel)
        throw std::invalid_argument("replay: the accelerator is '" + accel.name() +
                                    "', bare replay needs the Embree back end");
    m_impl->rays = &rays;
    m_impl->results.assign(rays.size(), 0);
    m_impl->prepared.reserve(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) {
        const RecordedRay& r = rays[i];
        PreparedRay p;
        if (!m_impl->accel->toEmbreeRay(r.ray, r.tMin, r.tMax, p.rayhit.ray)) continue;
        p.rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        p.rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
        p.rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        p.index = uint32_t(i);
        p.occlusion = r.occlusion;
        m_impl->prepared.push_back(p);
    }
}

EmbreeReplay::~EmbreeReplay() = default;

size_t EmbreeReplay::tracedCount() const { return m_impl->prepared.size(); }

double EmbreeReplay::run(int threads) {
    Impl& impl = *m_impl;
    std::fill(impl.results.begin(), impl.results.end(), uint8_t(0));
    const RTCScene scene = impl.accel->rtcHandle();
    const auto start = std::chrono::steady_clock::now();
    if (threads == 1) {
        for (const PreparedRay& p : impl.prepared) impl.trace(p, scene);
    } else {
        std::unique_ptr<tbb::global_control> limit;
        if (threads > 1)
            limit = std::make_unique<tbb::global_control>(
                tbb::global_control::max_allowed_parallelism, size_t(threads));
        // Chunks of consecutive rays keep the recorded (pixel) coherence.
        tbb::parallel_for(tbb::blocked_range<size_t>(0, impl.prepared.size(), 1024),
                          [&](const tbb::blocked_range<size_t>& range) {
                              for (size_t i = range.begin(); i != range.end(); ++i)
                                  impl.trace(impl.prepared[i], scene);
                          });
    }
    return secondsSince(start);
}

const std::vector<uint8_t>& EmbreeReplay::results() const { return m_impl->results; }

}  // namespace raylab

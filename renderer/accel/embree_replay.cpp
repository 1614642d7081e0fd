#include "renderer/accel/embree_replay.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "renderer/accel/embree_accelerator.h"
#include "renderer/timing.h"

namespace raylab {

struct EmbreeReplay::Impl {
    const EmbreeAccelerator* accel = nullptr;
    const std::vector<RecordedRay>* rays = nullptr;
    size_t traced = 0;
    std::vector<uint8_t> results;

    /// One query, as EmbreeAccelerator::intersect/occluded make it, minus the
    /// decoding of the hit. The ray is converted here rather than up front:
    /// a second array of converted rays (88 bytes each, 1.4 M of them on
    /// balls --spd) made the replay read two streams of memory per query and
    /// run slower than the Accelerator interface itself on this machine
    /// (its instruction count was 10% lower).
    void trace(size_t i, RTCScene scene) {
        const RecordedRay& r = (*rays)[i];
        RTCRayHit rayhit;
        if (!accel->toEmbreeRay(r.ray, r.tMin, r.tMax, rayhit.ray)) return;  // a miss
        EmbreeQueryContext ctx;
        ctx.init(&r.ray, r.tMin, r.tMax, r.departed);  // the render's callback work, departure too
        if (r.occlusion) {
            rtcOccluded1(scene, &ctx.rtc, &rayhit.ray);
            results[i] = rayhit.ray.tfar < 0.0f;
        } else {
            rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
            rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &ctx.rtc, &rayhit);
            results[i] = rayhit.hit.geomID != RTC_INVALID_GEOMETRY_ID;
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
    for (const RecordedRay& r : rays) {
        RTCRay converted;
        m_impl->traced += m_impl->accel->toEmbreeRay(r.ray, r.tMin, r.tMax, converted);
    }
}

EmbreeReplay::~EmbreeReplay() = default;

size_t EmbreeReplay::tracedCount() const { return m_impl->traced; }

double EmbreeReplay::run(int threads) {
    const auto start = std::chrono::steady_clock::now();
    run(threads, 0, m_impl->rays->size());
    return secondsSince(start);
}

void EmbreeReplay::run(int threads, size_t begin, size_t end) {
    Impl& impl = *m_impl;
    std::fill(impl.results.begin() + std::ptrdiff_t(begin), impl.results.begin() + std::ptrdiff_t(end),
              uint8_t(0));
    const RTCScene scene = impl.accel->rtcHandle();
    forEachReplayedRay(threads, begin, end, [&](size_t i) { impl.trace(i, scene); });
}

const std::vector<uint8_t>& EmbreeReplay::results() const { return m_impl->results; }

}  // namespace raylab

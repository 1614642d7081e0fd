#pragma once
// Bare replay of recorded rays through Embree: rtcIntersect1 / rtcOccluded1
// on an EmbreeAccelerator's RTCScene, with no shading, no Hit decoding and no
// virtual dispatch. The one entry point into the Embree adaptor's internals
// that tools need (`raylab bench limit`). Each ray is converted exactly as
// EmbreeAccelerator converts it (float, relative to its origin, mask all
// ones), at its query (any caller must), and every query passes the same extended context (the exact double
// ray for the analytic shapes, and the object the render's query left out,
// its Departure), so the work inside Embree is the renderer's.
// Embree types stay in the .cpp: this header is safe to include anywhere.

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/accel/ray_recorder.h"

namespace raylab {

/// Calls one(i) for every recorded ray i in [begin, end), threaded as a
/// replay is: threads 1 = a plain loop on the calling thread; n > 1 = a TBB
/// loop limited to n threads; 0 = a TBB loop on all cores. Chunks of
/// consecutive rays keep the recorded (pixel) coherence.
template <class F>
void forEachReplayedRay(int threads, size_t begin, size_t end, F&& one) {
    if (threads == 1) {
        for (size_t i = begin; i < end; ++i) one(i);
        return;
    }
    std::unique_ptr<tbb::global_control> limit;
    if (threads > 1)
        limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                      size_t(threads));
    tbb::parallel_for(tbb::blocked_range<size_t>(begin, end, 1024),
                      [&](const tbb::blocked_range<size_t>& range) {
                          for (size_t i = range.begin(); i != range.end(); ++i) one(i);
                      });
}

class EmbreeReplay {
public:
    /// \brief Prepares `rays` (which must outlive this object) for replay on
    ///   `accel`, which must be an EmbreeAccelerator.
    /// \throws std::invalid_argument when `accel` is not the Embree back end.
    EmbreeReplay(const Accelerator& accel, const std::vector<RecordedRay>& rays);
    ~EmbreeReplay();
    EmbreeReplay(const EmbreeReplay&) = delete;
    EmbreeReplay& operator=(const EmbreeReplay&) = delete;

    /// Rays handed to Embree; the others (non-finite, empty interval) are
    /// misses that EmbreeAccelerator never traces either.
    size_t tracedCount() const;

    /// \brief Traces every prepared ray once, in recorded order.
    /// \param threads 1 = a plain loop on the calling thread; n > 1 = a TBB
    ///   loop limited to n threads; 0 = a TBB loop on all cores.
    /// \return wall-clock seconds of the loop (preparation excluded).
    double run(int threads);

    /// Traces the recorded rays [begin, end) once (a slice of run's work),
    /// setting their results; the others keep theirs.
    void run(int threads, size_t begin, size_t end);

    /// Per recorded ray, from the last run: 1 = hit (intersect) or occluded
    /// (occlusion query), 0 = miss or not traced.
    const std::vector<uint8_t>& results() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace raylab

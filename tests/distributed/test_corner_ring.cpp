// render() keeps the SPD corner rows in a ring of 64 (FrameBuffers) and takes
// rows in order from one counter; the distributed renderer keeps the whole
// grid and takes items in any order. Both must give the same film, bit for
// bit, for frames whose corner rows wrap around the ring several times, any
// thread count, and a crop window.

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>
#include <thread>

#include "distributed/distributed_test_helpers.h"
#include "support/forwarding_accelerator.h"

using namespace raylab;

namespace {

/// The film of `p`'s frame from the whole corner grid: every item rendered on
/// one thread, last row first, then every pixel row averaged.
Film wholeGridFilm(const test::PreparedScene& p) {
    const FrameRenderer frame(p.scene, *p.accel, p.options, p.effects);
    FrameBuffers buffers = frame.makeBuffers();
    REQUIRE(buffers.cornerRows == frame.workItemCount());  // no ring
    WorkCounters counters;
    for (int item = frame.workItemCount() - 1; item >= 0; --item)
        frame.renderWorkItem(item, buffers, counters);
    frame.finish(buffers);
    return std::move(buffers.film);
}

/// The scene's accelerator, except that its n-th intersect query throws
/// (an allocation failure deep inside a work item).
class ThrowingAccelerator final : public test::ForwardingAccelerator {
public:
    ThrowingAccelerator(const Accelerator& inner, long n)
        : ForwardingAccelerator(inner), m_throwAt(n) {}
    using ForwardingAccelerator::intersect;
    std::optional<Hit> intersect(const Ray& r, double a, double b, Departure from) const override {
        if (++m_calls == m_throwAt) throw std::bad_alloc();
        return ForwardingAccelerator::intersect(r, a, b, from);
    }
    double buildSeconds() const override { return 0; }

private:
    mutable std::atomic<long> m_calls{0};
    long m_throwAt;
};

}  // namespace

TEST_CASE("render: the SPD corner-row ring gives the whole grid's film, any thread count") {
    for (bool cropped : {false, true}) {
        CAPTURE(cropped);
        RenderOverrides o;
        o.spd = true;
        auto p = test::prepare(std::string(RAYLAB_SOURCE_DIR) + "/scenes/primitives.json", o);
        p->options.width = 48;  // --spd's own 512x512 otherwise
        p->options.height = 200;  // 201 corner rows: the 64-row ring wraps three times
        if (cropped) p->options.crop = CropWindow{0.1, 0.8, 0.3, 0.95};  // x0, x1, y0, y1
        const Film expected = wholeGridFilm(*p);
        const FrameRenderer frame(p->scene, *p->accel, p->options, p->effects);
        CHECK(frame.makeBuffers(64).cornerRows == 64);
        for (int threads : {1, 2, 3}) {
            CAPTURE(threads);
            p->options.threads = threads;
            const RenderResult r = render(p->scene, *p->accel, p->options, p->effects);
            CHECK(test::filmDifference(r.film, expected) == "");
        }
    }
}

TEST_CASE("render: an exception inside an SPD work item reaches the caller, never a hang") {
    // The throwing row's pixel rows are never finished, so the row 64 later
    // could wait for its ring place forever (review of 23678f2 reproduced it
    // at 2 threads); it must see the loop's cancellation and let the
    // exception out. A watchdog ends the process rather than hang ctest.
    std::atomic<bool> finished{false};
    std::thread watchdog([&] {
        for (int i = 0; i < 600 && !finished; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (!finished) {
            std::fprintf(stderr, "render did not return 30 s after a work item threw\n");
            std::_Exit(3);
        }
    });
    for (int threads : {1, 2, 3})
        for (long row : {20L, 150L}) {
            CAPTURE(threads);
            CAPTURE(row);
            RenderOverrides o;
            o.spd = true;
            auto p = test::prepare(std::string(RAYLAB_SOURCE_DIR) + "/scenes/primitives.json", o);
            p->options.width = 48;
            p->options.height = 300;
            p->options.threads = threads;
            const ThrowingAccelerator accel(*p->accel, 48 * row);
            CHECK_THROWS_AS(render(p->scene, accel, p->options, p->effects), std::bad_alloc);
        }
    finished = true;
    watchdog.join();
}

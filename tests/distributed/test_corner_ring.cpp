// render() keeps the SPD corner rows in a ring of 64 (FrameBuffers) and takes
// rows in order from one counter; the distributed renderer keeps the whole
// grid and takes items in any order. Both must give the same film, bit for
// bit, for frames whose corner rows wrap around the ring several times, any
// thread count, and a crop window.

#include <doctest/doctest.h>

#include <string>

#include "distributed/distributed_test_helpers.h"

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

#pragma once
// The TBB-parallel tile loop: camera rays → integrator → film.

#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/film.h"
#include "renderer/huge_array.h"
#include "renderer/render_options.h"
#include "renderer/render_stats.h"
#include "renderer/scene.h"
#include "renderer/whitted_integrator.h"

namespace raylab {

/// Called from worker threads with the fraction of tiles finished (0..1);
/// calls are serialised by the renderer.
using ProgressCallback = std::function<void(double fraction)>;

/// One radiance sample with what the camera ray saw first.
struct Sample {
    Color c;
    FirstHit first;
};

/// One corner of the SPD procedure's grid: all that the pixels around it read
/// from it (the AOV layers come from each pixel's top-left corner and are
/// stored straight into the film), 32 bytes instead of a Sample's 112. The
/// object id (for the Cryptomatte coverage of the four pixels around it) fits
/// in what was padding.
struct CornerSample {
    Color c;
    bool hit;
    int32_t objectId;  ///< first object hit, -1 for none
};
static_assert(sizeof(CornerSample) == 32, "a corner stays 32 bytes");

/// Ray counts and replaced non-finite samples of one worker (or the sum of
/// several: integer sums and a maximum, the same whatever the split), and the
/// shadow cache its ray trees share (renderer/shadow_cache.h) and the camera
/// hits it prepares, packet after packet (renderer/prepared_hits.h).
struct WorkCounters {
    RayCounters rays;
    uint64_t nonFinite = 0;
    uint64_t cappedSamples = 0;  ///< samples whose ray tree the per-sample cap cut short
    uint64_t maxSampleRays = 0;  ///< the most rays one sample traced
    ShadowCache shadows;         ///< not summed: a per-worker speed aid
    PreparedHits prepared;       ///< not summed: the worker's camera hits of one packet

    WorkCounters& operator+=(const WorkCounters& o);
};

/// Where a frame is assembled: the film, plus the corner samples of the SPD
/// procedure (of the crop window's pixels in a crop render): all (W+1)·(H+1)
/// of them, or a ring of `cornerRows` rows that corner row y shares with rows
/// y ± cornerRows (render(), which takes rows in order and reuses a row's
/// place once both pixel rows that average it are done).
struct FrameBuffers {
    Film film;
    /// Zero bytes until the render writes them: no serial pass over its
    /// megabytes before the render (huge_array.h); each corner-row item
    /// touches its own row first, on whichever thread runs it.
    HugeArray<CornerSample> corners;
    int cornerX0 = 0, cornerY0 = 0;  ///< full-image corner at corners[0]
    int cornerStride = 0;            ///< corners per row
    int cornerRows = 0;              ///< rows held (H+1: the whole grid)

    /// Corner (x, y) of the full image's corner grid.
    CornerSample& corner(int x, int y) { return corners[cornerIndex(x, y)]; }
    const CornerSample& corner(int x, int y) const { return corners[cornerIndex(x, y)]; }

private:
    size_t cornerIndex(int x, int y) const {
        return size_t((y - cornerY0) % cornerRows) * size_t(cornerStride) + size_t(x - cornerX0);
    }
};

/// The rectangle a work item writes: pixels [x0,x1)×[y0,y1) of the film, or
/// in SPD mode corners [x0,x1)×[y0,y1) of the corner grid.
struct WorkRegion {
    int x0, y0, x1, y1;
};

/// One frame cut into independent work items: 16×16 pixel tiles, or rows of
/// pixel corners in SPD mode. A crop render (options.crop) has the tiles of
/// the full frame that meet the window, cut to it: coordinates stay those of
/// the full image, so each pixel is computed exactly as in the full frame. Items can run in any order, on any thread or
/// process; each writes only its own region, so the frame is deterministic.
/// render() drives it with TBB; the distributed renderer hands items to ranks.
class FrameRenderer {
public:
    FrameRenderer(const Scene& scene, const Accelerator& accel, const RenderOptions& options,
                  const EffectSet& effects);
    ~FrameRenderer();

    int workItemCount() const;
    WorkRegion region(int item) const;
    /// The film and, in SPD mode, the corner grid: every row, or (cornerRing
    /// > 0) a ring of that many rows for a caller that renders the rows in
    /// order (FrameBuffers).
    FrameBuffers makeBuffers(int cornerRing = 0) const;
    /// Renders one item into `buffers` (thread-safe for distinct items). In
    /// SPD mode an item is corner row y (of the window): the film's AOV layers of pixel row y
    /// are written too (from each pixel's top-left corner), its RGBA only by
    /// finishRow once corner rows y and y + 1 both exist.
    void renderWorkItem(int item, FrameBuffers& buffers, WorkCounters& counters) const;
    /// SPD mode: pixel row y (full-image coordinates, inside the window)
    /// becomes the mean of its corners (needs corner rows y and y + 1;
    /// thread-safe for distinct rows). Nothing to do otherwise.
    void finishRow(FrameBuffers& buffers, int y) const;
    /// After every item: finishRow for every pixel row of the window (in parallel).
    void finish(FrameBuffers& buffers) const;

private:
    /// Tile `item` of the full frame's grid, cut to the image but not to the window.
    WorkRegion tile(int item) const;

    const Scene& m_scene;
    RenderOptions m_options;
    std::unique_ptr<WhittedIntegrator> m_integrator;
    PixelWindow m_window;      ///< the pixels rendered (the whole image without --crop)
    int m_tileX0, m_tileY0;    ///< first tile of the full grid that meets the window
    int m_tilesX, m_tilesY;    ///< tiles that meet it
};

struct RenderResult {
    Film film;
    RayCounters rays;
    double renderSeconds = 0;
    uint64_t nonFiniteSamples = 0;  ///< samples that were NaN/Inf and were replaced by black
    uint64_t cappedSamples = 0;     ///< samples that reached RenderOptions::maxRaysPerSample
    uint64_t maxSampleRays = 0;     ///< the most rays one sample traced
    bool cancelled = false;

    /// Takes the counts of every worker (called once with their sum).
    void setCounters(const WorkCounters& c);
};

/// Renders the scene. Deterministic: the film and the counters are
/// bit-identical for any thread count. `cancel` (may be null) stops the render
/// promptly between tiles, and the process-wide stop request (cancel.h)
/// between pixels; the result then has cancelled = true.
RenderResult render(const Scene& scene, const Accelerator& accel, const RenderOptions& options,
                    const EffectSet& effects, const ProgressCallback& progress = {},
                    const std::atomic<bool>* cancel = nullptr);

}  // namespace raylab

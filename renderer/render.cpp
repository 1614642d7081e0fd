#include "renderer/render.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <memory>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "geometry/random.h"
#include "renderer/cancel.h"
#include "renderer/late_value.h"
#include "renderer/matte_coverage.h"
#include "renderer/sampler.h"
#include "renderer/whitted_integrator.h"
#include "renderer/timing.h"
#include "shading/radiance_range.h"

namespace raylab {

namespace {

constexpr int kTileSize = 16;
/// SPD corner rows render() keeps (a ring: FrameBuffers): 64 rows of a
/// 512-wide frame are 1 MB, and let a thread run 60 rows ahead of another
/// before it waits.
constexpr int kCornerRingRows = 64;
/// cornerRowsDone's value once a pixel row has been averaged.
constexpr int kRowFinished = 3;

/// No NaN or Inf may ever reach a pixel. The integrator saturates overflows
/// (shading/radiance_range.h), so a non-finite sample is a defect: counted,
/// an Inf kept as the largest double (never hidden as black), a NaN black.
Color sanitize(const Color& c, uint64_t& nonFinite) {
    if (c.isFinite()) return c;
    ++nonFinite;
    const auto fix = [](double v) { return std::isnan(v) ? 0.0 : saturated(v); };
    return {fix(c.r), fix(c.g), fix(c.b)};
}

void storeFirstHit(Film& film, size_t i, const FirstHit& f) {
    film.z[i] = f.depth;
    film.distance[i] = f.distance;
    film.normal[3 * i + 0] = float(f.normal.x);
    film.normal[3 * i + 1] = float(f.normal.y);
    film.normal[3 * i + 2] = float(f.normal.z);
    film.albedo[3 * i + 0] = float(f.albedo.r);
    film.albedo[3 * i + 1] = float(f.albedo.g);
    film.albedo[3 * i + 2] = float(f.albedo.b);
    film.objectId[i] = f.objectId;
}

/// Per-pixel seed: a 64-bit mix of the render seed and the pixel index.
uint64_t pixelSeed(uint64_t seed, uint64_t pixel) {
    return mix64(seed * SplitMix64::kGamma + pixel + 0x632BE59BD9B4E019ULL);
}

/// One camera sample through (px, py). `given`, when set, is its camera ray
/// and that ray's first hit, already asked of the accelerator (a packet),
/// and the hit prepared up to its feelers (or null).
struct GivenCameraRay {
    const Ray& ray;
    const std::optional<Hit>& hit;
    const PreparedHit* prepared;
};

Sample traceSample(const WhittedIntegrator& integrator, const Scene& scene,
                   const RenderOptions& opt, double px, double py, WorkCounters& tc,
                   const GivenCameraRay* given = nullptr) {
    Sample s;
    const Ray ray = given ? given->ray : scene.camera.generateRay(px, py, opt.width, opt.height);
    SampleRays spent;
    s.c = sanitize(integrator.Li(ray, tc.rays, &s.first, spent, &tc.shadows,
                                 given ? &given->hit : nullptr, given ? given->prepared : nullptr),
                   tc.nonFinite);
    tc.cappedSamples += spent.capped;
    tc.maxSampleRays = std::max(tc.maxSampleRays, spent.traced);
    if (s.first.hit && opt.wantAovs) {
        // Planar depth: the hit point's distance from the eye plane, along the view axis.
        const CameraFrame& f = scene.camera.frame();
        const Vec3 forward = -f.w;
        const double d = dot(ray.o - f.eye, forward) +
                         double(s.first.distance) * dot(ray.d, forward) / length(ray.d);
        s.first.depth = float(std::min(d, double(FLT_MAX)));
    } else if (!s.first.hit && opt.alpha == AlphaMode::Transparent) {
        s.c = Color{};  // the background is left out: RGB premultiplied by coverage
    }
    return s;
}

double maxDifference(const Color& a, const Color& b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

/// Whitted's adaptive supersampling over one tile: trace the four corners of
/// each pixel; where they differ by more than the threshold, split the square
/// into four and recurse, up to adaptiveMaxLevel. Corners are shared between
/// neighbouring squares and pixels of the tile through a sparse cache (keyed
/// on the tile's finest grid), so a smooth region costs about one ray per
/// pixel. Box filter: each square contributes the mean of its corners,
/// weighted by its area.
class AdaptiveTile {
public:
    AdaptiveTile(const WhittedIntegrator& integrator, const Scene& scene,
                 const RenderOptions& opt, const WorkRegion& tile, WorkCounters& tc)
        : m_integrator(integrator), m_scene(scene), m_opt(opt), m_tile(tile), m_tc(tc),
          m_res(1 << opt.adaptiveMaxLevel),
          m_gridWidth(uint64_t(tile.x1 - tile.x0) * uint64_t(m_res) + 1) {}

    /// Radiance and coverage of pixel (x, y); `first` gets its top-left
    /// corner, `mattes` (may be null) the object coverage of its leaf squares.
    Color pixel(int x, int y, double& coverage, FirstHit& first, MatteCoverage* mattes) {
        const int i = (x - m_tile.x0) * m_res, j = (y - m_tile.y0) * m_res;
        m_mattes = mattes;
        const Color c = square(i, j, m_res, coverage);
        first = corner(i, j).first;
        return c;
    }

private:
    const Sample& corner(int i, int j) {
        const uint64_t key = uint64_t(j) * m_gridWidth + uint64_t(i);
        auto it = m_cache.find(key);
        if (it == m_cache.end()) {
            const double px = m_tile.x0 + double(i) / m_res, py = m_tile.y0 + double(j) / m_res;
            it = m_cache.emplace(key, traceSample(m_integrator, m_scene, m_opt, px, py, m_tc)).first;
        }
        return it->second;
    }

    /// Square with top-left grid corner (i, j) and side `size` grid steps.
    Color square(int i, int j, int size, double& coverage) {
        const Sample& a = corner(i, j);
        const Sample& b = corner(i + size, j);
        const Sample& c = corner(i, j + size);
        const Sample& d = corner(i + size, j + size);
        const double diff = std::max({maxDifference(a.c, b.c), maxDifference(a.c, c.c),
                                      maxDifference(a.c, d.c), maxDifference(b.c, c.c),
                                      maxDifference(b.c, d.c), maxDifference(c.c, d.c)});
        if (size > 1 && diff > m_opt.adaptiveThreshold) {
            const int h = size / 2;
            double cov[4];
            const Color sum = square(i, j, h, cov[0]) + square(i + h, j, h, cov[1]) +
                              square(i, j + h, h, cov[2]) + square(i + h, j + h, h, cov[3]);
            coverage = 0.25 * (cov[0] + cov[1] + cov[2] + cov[3]);
            return sum * 0.25;
        }
        coverage = 0.25 * (a.first.hit + b.first.hit + c.first.hit + d.first.hit);
        if (m_mattes) {
            // Each corner stands for a quarter of this square's share of the pixel.
            const double w = 0.25 * (double(size) / m_res) * (double(size) / m_res);
            for (const Sample* s : {&a, &b, &c, &d}) m_mattes->add(int(s->first.objectId), w);
        }
        return (a.c + b.c + c.c + d.c) * 0.25;
    }

    const WhittedIntegrator& m_integrator;
    const Scene& m_scene;
    const RenderOptions& m_opt;
    WorkRegion m_tile;
    WorkCounters& m_tc;
    int m_res;             ///< finest grid steps per pixel side: 2^maxLevel
    uint64_t m_gridWidth;  ///< corners per row of the tile's finest grid
    std::unordered_map<uint64_t, Sample> m_cache;  // node-based: references stay valid
    MatteCoverage* m_mattes = nullptr;             ///< the current pixel's, or null
};

/// A finite double that may exceed the float range, clamped so that storing
/// it never creates an Inf.
float toFiniteFloat(double v) { return float(std::clamp(v, -double(FLT_MAX), double(FLT_MAX))); }

void storePixel(Film& film, size_t i, const Color& c, double coverage, AlphaMode alpha) {
    film.rgba[4 * i + 0] = toFiniteFloat(c.r);
    film.rgba[4 * i + 1] = toFiniteFloat(c.g);
    film.rgba[4 * i + 2] = toFiniteFloat(c.b);
    film.rgba[4 * i + 3] = alpha == AlphaMode::Opaque ? 1.f : float(coverage);
}

/// One pixel's stratified supersampling: where its samples go in the pixel
/// (seeded by the pixel's index in the full image, so a crop renders it
/// alike) and the sum of what they bring back, in sample order.
class PixelSamples {
public:
    PixelSamples() = default;
    /// Starts pixel (x, y): n = opt.spp samples, none traced yet.
    void start(const RenderOptions& opt, int x, int y) {
        m_n = std::max(1, opt.spp);
        m_gridSide = squareGridSide(m_n);
        m_rng = Pcg32(pixelSeed(opt.seed, size_t(y) * size_t(opt.width) + size_t(x)), 0);
        // n-rooks permutation for non-square sample counts (Fisher-Yates).
        if (m_n > 1 && m_gridSide == 0) {
            m_perm.resize(m_n);
            std::iota(m_perm.begin(), m_perm.end(), 0);
            for (int k = m_n - 1; k > 0; --k) std::swap(m_perm[k], m_perm[m_rng.next() % uint32_t(k + 1)]);
        } else {
            m_perm.clear();
        }
        m_added = 0;
        m_sum = Color{};
        m_hits = 0;
        m_mattes.clear();
    }
    int count() const { return m_n; }
    /// Sample k's offset in the pixel; k = 0, 1, ... in order (it draws from the pixel's generator).
    std::pair<double, double> position(int k) {
        return stratifiedSample(k, m_n, m_gridSide, m_rng, m_perm.data());
    }
    /// Adds the next sample (in sample order) of pixel i; after the last,
    /// stores the pixel in the film.
    void add(const Sample& s, Film& film, size_t i, const RenderOptions& opt) {
        m_sum += s.c;
        m_hits += s.first.hit;
        // The AOV layers come from the first sample (the centre when spp = 1),
        // the object coverage from all of them.
        if (m_added == 0 && s.first.hit && opt.wantAovs) storeFirstHit(film, i, s.first);
        if (opt.wantAovs) m_mattes.add(int(s.first.objectId), 1.0);
        if (++m_added < m_n) return;
        if (opt.wantAovs) m_mattes.store({film.mattesOf(i), size_t(film.matteRanks)}, double(m_n));
        storePixel(film, i, m_sum / double(m_n), double(m_hits) / m_n, opt.alpha);
    }

private:
    int m_n = 1, m_gridSide = 1, m_added = 0;
    Pcg32 m_rng{0, 0};
    std::vector<int> m_perm;
    Color m_sum;
    int m_hits = 0;
    MatteCoverage m_mattes;
};

/// Renders pixel (x, y) with stratified supersampling.
void renderPixel(const WhittedIntegrator& integrator, const Scene& scene,
                 const RenderOptions& opt, Film& film, int x, int y, WorkCounters& tc) {
    PixelSamples pixel;
    pixel.start(opt, x, y);
    for (int k = 0; k < pixel.count(); ++k) {
        const auto [sx, sy] = pixel.position(k);
        pixel.add(traceSample(integrator, scene, opt, x + sx, y + sy, tc), film, film.index(x, y), opt);
    }
}

/// renderPixel over the pixels [x0, x1) of row y (at most kTileSize), with
/// their camera rays asked of the accelerator 16 at a time: the samples of
/// one pixel, then of the next, in renderPixel's order. Each sample's ray,
/// its hit (exactly the single ray's) and its ray tree are renderPixel's, and
/// each pixel sums its samples in the same order: every pixel is the same.
void renderRowInPackets(const WhittedIntegrator& integrator, const Scene& scene,
                        const RenderOptions& opt, Film& film, int y, int x0, int x1,
                        WorkCounters& tc) {
    constexpr int kPacket = Accelerator::kPacketRays;
    PixelSamples pixels[kTileSize];
    Ray rays[kPacket];
    std::optional<Hit> hits[kPacket];
    int owner[kPacket];  // each lane's pixel, x - x0
    int count = 0;
    const auto trace = [&] {
        integrator.cameraHits(rays, count, hits);
        integrator.prepareCameraHits(rays, hits, count, tc.prepared, &tc.shadows);
        for (int j = 0; j < count; ++j) {
            const GivenCameraRay given{rays[j], hits[j], tc.prepared.lane(j)};
            pixels[owner[j]].add(traceSample(integrator, scene, opt, 0, 0, tc, &given), film,
                                 film.index(x0 + owner[j], y), opt);
        }
        count = 0;
    };
    for (int x = x0; x < x1 && !cancelRequested(); ++x) {  // a stop cuts the row short
        PixelSamples& pixel = pixels[x - x0];
        pixel.start(opt, x, y);
        for (int k = 0; k < pixel.count(); ++k) {
            const auto [sx, sy] = pixel.position(k);
            const double px = x + sx, py = y + sy;  // a lambda may not capture a binding (C++17)
            rebuildInPlace(rays[count], [&] {
                return scene.camera.generateRay(px, py, opt.width, opt.height);
            });
            owner[count] = x - x0;
            if (++count == kPacket) trace();
        }
    }
    if (count > 0) trace();
}

}  // namespace

WorkCounters& WorkCounters::operator+=(const WorkCounters& o) {
    rays += o.rays;
    nonFinite += o.nonFinite;
    cappedSamples += o.cappedSamples;
    maxSampleRays = std::max(maxSampleRays, o.maxSampleRays);
    return *this;
}

void RenderResult::setCounters(const WorkCounters& c) {
    rays = c.rays;
    nonFiniteSamples = c.nonFinite;
    cappedSamples = c.cappedSamples;
    maxSampleRays = c.maxSampleRays;
}

FrameRenderer::FrameRenderer(const Scene& scene, const Accelerator& accel,
                             const RenderOptions& options, const EffectSet& effects)
    : m_scene(scene), m_options(options),
      m_integrator(std::make_unique<WhittedIntegrator>(scene, accel, options, effects)),
      m_window(cropPixels(options.crop, options.width, options.height)),
      m_tileX0(m_window.x0 / kTileSize), m_tileY0(m_window.y0 / kTileSize),
      m_tilesX(m_window.empty() ? 0 : (m_window.x1 - 1) / kTileSize - m_tileX0 + 1),
      m_tilesY(m_window.empty() ? 0 : (m_window.y1 - 1) / kTileSize - m_tileY0 + 1) {
    if (m_window.empty())
        throw std::invalid_argument("crop window holds no pixel of a " +
                                    std::to_string(options.width) + "x" +
                                    std::to_string(options.height) + " image");
}

FrameRenderer::~FrameRenderer() = default;

int FrameRenderer::workItemCount() const {
    return m_options.spd ? m_window.height() + 1 : m_tilesX * m_tilesY;
}

FrameBuffers FrameRenderer::makeBuffers(int cornerRing) const {
    FrameBuffers b;
    b.film = Film(m_window.width(), m_window.height(), m_window.x0, m_window.y0, m_options.width,
                  m_options.height, matteRanksOfSampling(m_options), m_options.wantAovs);
    if (m_options.spd) {
        b.cornerX0 = m_window.x0;
        b.cornerY0 = m_window.y0;
        b.cornerStride = m_window.width() + 1;
        b.cornerRows = cornerRing > 0 ? std::min(cornerRing, m_window.height() + 1)
                                      : m_window.height() + 1;
        b.corners = HugeArray<CornerSample>(size_t(b.cornerStride) * size_t(b.cornerRows));
    }
    return b;
}

WorkRegion FrameRenderer::tile(int item) const {
    const int x0 = (m_tileX0 + item % m_tilesX) * kTileSize;
    const int y0 = (m_tileY0 + item / m_tilesX) * kTileSize;
    return {x0, y0, std::min(x0 + kTileSize, m_options.width), std::min(y0 + kTileSize, m_options.height)};
}

WorkRegion FrameRenderer::region(int item) const {
    if (m_options.spd)
        return {m_window.x0, m_window.y0 + item, m_window.x1 + 1, m_window.y0 + item + 1};
    const WorkRegion t = tile(item);
    return {std::max(t.x0, m_window.x0), std::max(t.y0, m_window.y0), std::min(t.x1, m_window.x1),
            std::min(t.y1, m_window.y1)};
}

void FrameRenderer::renderWorkItem(int item, FrameBuffers& buffers, WorkCounters& counters) const {
    const WorkRegion r = region(item);
    if (m_options.spd) {
        // SPD procedure: one eye ray through every pixel corner, (W+1)·(H+1)
        // rays; a work item is one row of corners. Corner (i, y) is the
        // top-left corner of pixel (i, y), whose AOV layers come from it.
        const bool aovRow = r.y0 < m_window.y1 && m_options.wantAovs;
        const auto store = [&](int i, const Sample& s) {
            buffers.corner(i, r.y0) = {s.c, s.first.hit, int32_t(s.first.objectId)};
            if (aovRow && i < m_window.x1 && s.first.hit)
                storeFirstHit(buffers.film, buffers.film.index(i, r.y0), s.first);
        };
        if (!m_integrator->tracesPackets()) {
            for (int i = r.x0; i < r.x1 && !cancelRequested(); ++i)
                store(i, traceSample(*m_integrator, m_scene, m_options, i, r.y0, counters));
            return;
        }
        // The accelerator traces packets: the camera rays of 16 neighbouring
        // corners are asked together (one Embree packet with AVX-512, two
        // without; each lane's answer exactly its own); each corner's ray tree then goes on alone, in the
        // same order as without.
        constexpr int kPacket = Accelerator::kPacketRays;
        Ray rays[kPacket];
        std::optional<Hit> hits[kPacket];
        for (int i0 = r.x0; i0 < r.x1 && !cancelRequested(); i0 += kPacket) {
            const int count = std::min(kPacket, r.x1 - i0);
            for (int k = 0; k < count; ++k)
                rebuildInPlace(rays[k], [&] {  // not copied from a temporary (late_value.h)
                    return m_scene.camera.generateRay(i0 + k, r.y0, m_options.width,
                                                      m_options.height);
                });
            m_integrator->cameraHits(rays, count, hits);
            m_integrator->prepareCameraHits(rays, hits, count, counters.prepared, &counters.shadows);
            for (int k = 0; k < count; ++k) {
                const GivenCameraRay given{rays[k], hits[k], counters.prepared.lane(k)};
                store(i0 + k, traceSample(*m_integrator, m_scene, m_options, i0 + k, r.y0, counters,
                                          &given));
            }
        }
        return;
    }
    if (m_options.adaptiveThreshold > 0) {
        // The corner grid is the whole tile's, as in the full frame, even
        // where the crop window cuts the tile.
        AdaptiveTile adaptive(*m_integrator, m_scene, m_options, tile(item), counters);
        for (int y = r.y0; y < r.y1; ++y) {
            for (int x = r.x0; x < r.x1 && !cancelRequested(); ++x) {
                double coverage = 0;
                FirstHit first;
                MatteCoverage mattes;
                const Color c =
                    adaptive.pixel(x, y, coverage, first, m_options.wantAovs ? &mattes : nullptr);
                const size_t i = buffers.film.index(x, y);
                if (first.hit && m_options.wantAovs) storeFirstHit(buffers.film, i, first);
                if (m_options.wantAovs)
                    mattes.store({buffers.film.mattesOf(i), size_t(buffers.film.matteRanks)});
                storePixel(buffers.film, i, c, coverage, m_options.alpha);
            }
        }
        return;
    }
    if (m_integrator->tracesPackets()) {
        for (int y = r.y0; y < r.y1 && !cancelRequested(); ++y)
            renderRowInPackets(*m_integrator, m_scene, m_options, buffers.film, y, r.x0, r.x1,
                               counters);
        return;
    }
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1 && !cancelRequested(); ++x)  // a stop cuts the tile short
            renderPixel(*m_integrator, m_scene, m_options, buffers.film, x, y, counters);
}

void FrameRenderer::finishRow(FrameBuffers& buffers, int y) const {
    if (!m_options.spd) return;
    // Each pixel is the mean of its four corners.
    Film& film = buffers.film;
    const CornerSample* top = &buffers.corner(m_window.x0, y);
    const CornerSample* bottom = &buffers.corner(m_window.x0, y + 1);
    for (int x = m_window.x0, k = 0; x < m_window.x1; ++x, ++k) {
        const CornerSample &a = top[k], &b = top[k + 1], &c = bottom[k], &d = bottom[k + 1];
        const size_t i = film.index(x, y);
        if (m_options.wantAovs) {
            const MatteSpan out{film.mattesOf(i), size_t(film.matteRanks)};
            if (a.objectId == b.objectId && a.objectId == c.objectId && a.objectId == d.objectId) {
                // Inside one object (or the background), as most pixels are:
                // four corners of 0.25 sum to exactly 1.
                MatteCoverage::storeSingle(out, a.objectId, 1.0f);
            } else {
                MatteCoverage mattes;
                for (const CornerSample* s : {&a, &b, &c, &d}) mattes.add(s->objectId, 0.25);
                mattes.store(out);
            }
        }
        storePixel(film, i, (a.c + b.c + c.c + d.c) * 0.25, 0.25 * (a.hit + b.hit + c.hit + d.hit),
                   m_options.alpha);
    }
}

void FrameRenderer::finish(FrameBuffers& buffers) const {
    if (!m_options.spd) return;
    tbb::parallel_for(m_window.y0, m_window.y1, [&](int y) { finishRow(buffers, y); });
}

RenderResult render(const Scene& scene, const Accelerator& accel, const RenderOptions& options,
                    const EffectSet& effects, const ProgressCallback& progress,
                    const std::atomic<bool>* cancel) {
    std::unique_ptr<tbb::global_control> threadLimit;
    if (options.threads > 0)
        threadLimit = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, size_t(options.threads));

    const FrameRenderer frame(scene, accel, options, effects);
    // SPD: corner rows live in a ring (FrameBuffers), the frame's 8 MB corner
    // grid cut to ~1 MB of fresh memory, which costs ~1.2-3 ms per MB on this
    // project's VMs (docs/benchmarks.md, "Fresh memory").
    FrameBuffers buffers = frame.makeBuffers(kCornerRingRows);
    const int items = frame.workItemCount();
    tbb::enumerable_thread_specific<WorkCounters> counters;
    std::atomic<int> done{0};
    std::mutex progressMutex;

    // SPD mode: pixel row y is averaged as soon as corner rows y and y + 1
    // are both done, by the thread that finished the second one (while the
    // corners are still in its cache), instead of in a serial pass at the end.
    // Item k is corner row y0 + k of the (crop) window; counted per film row,
    // and set to kRowFinished once the row is averaged.
    const int pixelRows = options.spd ? buffers.film.height : 0;
    const int rowY0 = buffers.film.originY;
    std::unique_ptr<std::atomic<int>[]> cornerRowsDone(new std::atomic<int>[size_t(pixelRows)]);
    for (int y = 0; y < pixelRows; ++y) cornerRowsDone[y] = 0;
    // Also when another item threw: TBB then cancels the loop, but a body
    // waiting for a row the thrower never finished would spin forever and
    // the exception would never reach the caller.
    const auto stopped = [&] {
        return (cancel && cancel->load(std::memory_order_relaxed)) || cancelRequested() ||
               tbb::is_current_task_group_canceling();
    };
    // Corner row k takes the ring place of row k - cornerRows, which pixel
    // rows k - cornerRows - 1 and k - cornerRows average: both must be done.
    // Rows are taken in order, so this waits only on rows other threads
    // hold (the oldest row in flight never waits), and with 64 rows of slack
    // it hardly ever waits at all. Nothing an item runs may use TBB: a
    // nested wait could start another loop below on this thread, which could
    // then spin on a row the suspended one holds.
    const auto placeFree = [&](int k) {
        const int old = k - buffers.cornerRows;
        for (int y = old - 1; y <= old; ++y)
            if (y >= 0 && y < pixelRows &&
                cornerRowsDone[y].load(std::memory_order_acquire) != kRowFinished)
                return false;
        return true;
    };

    RenderResult result;
    const auto start = std::chrono::steady_clock::now();
    // Items in order from one counter, whichever thread asks (the ring needs
    // it; for tiles it is TBB's order as good as any): one loop per thread.
    std::atomic<int> nextItem{0};
    const int loops = std::max(1, tbb::this_task_arena::max_concurrency());
    tbb::parallel_for(
        0, loops,
        [&](int) {
            WorkCounters& local = counters.local();
            for (int item = nextItem++; item < items; item = nextItem++) {
                if (cancel && cancel->load(std::memory_order_relaxed)) return;
                if (tbb::is_current_task_group_canceling()) return;  // another item threw
                if (options.spd)
                    while (!placeFree(item)) {
                        if (stopped()) return;
                        std::this_thread::yield();
                    }
                frame.renderWorkItem(item, buffers, local);
                // Corner row y0 + item borders film rows item - 1 and item.
                for (int y = item - 1; y <= item; ++y)
                    if (y >= 0 && y < pixelRows && ++cornerRowsDone[y] == 2) {
                        frame.finishRow(buffers, rowY0 + y);
                        cornerRowsDone[y].store(kRowFinished, std::memory_order_release);
                    }
                const int n = ++done;
                if (progress) {
                    std::lock_guard<std::mutex> lock(progressMutex);
                    progress(double(n) / items);
                }
            }
        },
        tbb::simple_partitioner());
    // A stop request also cuts tiles short (per pixel), whatever `cancel` is.
    result.cancelled = (cancel && cancel->load()) || cancelRequested();
    result.renderSeconds =
        secondsSince(start);

    // Integer sums: the same totals whatever the thread count.
    WorkCounters sum;
    for (const WorkCounters& c : counters) sum += c;
    result.setCounters(sum);
    result.film = std::move(buffers.film);
    return result;
}

}  // namespace raylab

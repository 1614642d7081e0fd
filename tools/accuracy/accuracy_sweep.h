#pragma once
// The accuracy study behind `raylab accuracy`: render a high-quality reference
// of a scene, then sweep the renderer's accuracy knobs (samples per pixel,
// adaptive supersampling, ray-tree depth, min-weight pruning, intersector
// precision, self-intersection strategy, Embree build quality and robust
// traversal) one at a time, plus a few combinations, and measure for each
// setting what it costs (build and render time, rays) and what it loses
// (error against the reference). docs/accuracy.md has the results.

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "geometry/shape.h"
#include "geometry/spawn.h"
#include "renderer/accel/accelerator.h"
#include "renderer/film.h"
#include "renderer/texture_options.h"
#include "renderer/scene.h"
#include "renderer/shadow_mode.h"

namespace raylab {

/// One point of the sweep: every accuracy knob, spelled out (the scene file's
/// own image settings are not used, so every scene is swept the same way).
struct AccuracySetting {
    std::string name;  ///< row label, e.g. "spp 4"
    std::string knob;  ///< group: reference, default, spp, adaptive, depth, min-weight,
                       ///< precision, offset, bvh, shadows, texture, alpha-cutoff,
                       ///< combo
    int spp = 1;
    double adaptiveThreshold = 0;  ///< 0 = off (stratified spp)
    int adaptiveLevels = 2;
    int maxDepth = 5;
    double minWeight = 0;
    Precision precision = Precision::Double;
    OffsetMode offset = OffsetMode::Robust;
    double epsilon = 1e-4;  ///< FixedEpsilon only
    AccelOptions::BvhQuality quality = AccelOptions::BvhQuality::Medium;
    bool robust = true;  ///< RTC_SCENE_FLAG_ROBUST (false: --no-robust)
    ShadowMode shadows = ShadowMode::Filtered;  ///< feelers through transmitters (or blocked)
    TextureOptions textures;  ///< texture filter and footprint (textured scenes)
    /// --alpha-cutoff for every material (scenes with cut-outs); unset: each
    /// material's own alpha_cutoff.
    std::optional<double> alphaCutoff;
    /// The reference of a scene with cut-outs: the mean of this many renders
    /// at cut-offs (k + 0.5) / n, k = 0..n-1, spread evenly over (0, 1). A
    /// hit is kept where alpha >= the cut-off, so for one mask layer the mean
    /// keeps a fraction alpha of it: alpha as partial coverage, the image of
    /// a renderer that blends by alpha. 0: one render.
    int coverageCutoffs = 0;

    /// The equivalent `raylab render` flags ("--spp 4 --depth 5 ...", every knob).
    std::string flags() const;
};

/// The renderer's defaults (1 spp through pixel centres, depth 5, double
/// precision, robust offset, medium BVH, robust traversal).
AccuracySetting defaultAccuracySetting();

/// \brief The reference: `spp` stratified jittered samples per pixel, depth
///   12, double precision, robust Embree traversal, robust offset, no pruning,
///   point-sampled textures (the samples themselves do the filtering).
AccuracySetting referenceAccuracySetting(int spp);

/// \brief The settings swept: the default, each knob varied alone from the
///   default, and a few combinations. `quick` keeps a handful (smoke runs).
///   `textured` adds the "texture" group: every texture filter and footprint.
///   `cutOuts` adds the "alpha-cutoff" group: --alpha-cutoff 0.1 ... 0.9.
std::vector<AccuracySetting> accuracySweepSettings(bool quick, bool textured = false,
                                                   bool cutOuts = false);

/// Whether some material of the scene may cut out (the sweep then has an
/// "alpha-cutoff" group and a coverage reference).
bool hasCutOuts(const Scene& scene);

/// Cut-offs the coverage reference averages over (AccuracySetting::coverageCutoffs).
constexpr int kCoverageCutoffs = 16;

/// Whether some material of the scene has a texture (the sweep then has a
/// "texture" group).
bool hasTextures(const Scene& scene);

/// The knob group names accuracySweepSettings uses, in table order.
std::vector<std::string> accuracyKnobNames();

/// How the sweep runs.
struct AccuracySweepOptions {
    int width = 160;
    int height = 120;
    int runs = 3;     ///< timed repetitions per setting (median reported), interleaved
    int threads = 0;  ///< 0 = all cores
    int referenceSpp = 64;
    /// Settings to measure; empty: accuracySweepSettings(false).
    std::vector<AccuracySetting> settings;
    /// A pixel counts as visibly different when its 8-bit sRGB value (the PNG
    /// preview's tone mapping, exposure 0) differs by more than this many levels.
    int visibleLevels = 2;
    /// Keep each setting's first image (and the reference's) in the results,
    /// for the HTML report.
    bool keepImages = false;
};

/// What one setting cost and what it lost.
struct AccuracyResult {
    AccuracySetting setting;
    double buildSeconds = 0;   ///< median over the runs
    double renderSeconds = 0;  ///< median over the runs
    double renderMinSeconds = 0, renderMaxSeconds = 0;
    /// CPU time of the whole process (all threads) for the build and the
    /// render, medians: unlike wall-clock time it does not grow when other
    /// processes compete for the cores, so it ranks settings reliably on a
    /// shared machine (on an idle one wall ≈ CPU / threads).
    double buildCpuSeconds = 0;
    double renderCpuSeconds = 0;
    uint64_t rays = 0;  ///< rays traced (all types), per render
    // Against the reference (the total error a user sees):
    double rmse = 0;             ///< linear RGB, over every channel of every pixel
    double psnr = 0;             ///< dB, peak 1.0; +inf when identical
    double maxError = 0;         ///< largest |Δ| of one linear RGB channel
    uint64_t visiblePixels = 0;  ///< pixels off by more than visibleLevels in 8-bit sRGB
    // Against the reference settings rendered with this setting's sampling
    // (same spp, same adaptive threshold): the error of every non-sampling
    // knob, without the aliasing this sample count has anyway. For the
    // default's 1 spp the reference-quality image at the same pixel centres.
    double knobRmse = 0;
    uint64_t knobVisiblePixels = 0;
    uint64_t nonFiniteSamples = 0;  ///< NaN/Inf radiance samples (replaced by black); must be 0
    uint64_t nonFinitePixels = 0;   ///< NaN/Inf values in the finished RGBA; must be 0
    bool deterministic = true;      ///< every run produced bit-identical RGBA
    bool pareto = false;            ///< on the error-vs-time Pareto front
    Film film;  ///< the image (first run) with AccuracySweepOptions::keepImages; else empty

    /// Build plus render wall-clock time: what a user waits for one frame.
    double frameSeconds() const { return buildSeconds + renderSeconds; }
    /// Build plus render CPU time: the work one frame costs.
    double frameCpuSeconds() const { return buildCpuSeconds + renderCpuSeconds; }
};

/// The outcome of a sweep.
struct AccuracyReport {
    std::string scene;  ///< path given
    int width = 0, height = 0, runs = 0, threads = 0;
    int visibleLevels = 2;
    std::string machine;       ///< CPU model and core count
    AccuracyResult reference;  ///< its timings (one run) and rays; errors are 0
    std::vector<AccuracyResult> results;
    bool cancelled = false;
};

/// Progress: (renders done, renders in total, label of the current setting).
using AccuracyProgress = std::function<void(int done, int total, const std::string& label)>;

/// \brief Runs the sweep on `scene`. While it runs, the scene's own "render"
///   block is set aside (every setting defines every knob) and its shapes'
///   precision changes; both are restored (precision to double) at the end.
/// \details Renders the reference once, then `runs` rounds over every
///   setting (interleaved, so drifts of a shared machine spread evenly), each
///   building a fresh Embree accelerator and rendering. Results are compared
///   with the reference and with the reference settings rendered at the same
///   sampling (one extra render per distinct sampling). The Pareto front is
///   marked.
///   `cancel` (may be null) stops between renders; the report is then marked
///   cancelled and holds no results.
/// \throws std::invalid_argument for a size or run count < 1.
AccuracyReport runAccuracySweep(Scene& scene, const std::string& scenePath,
                                const AccuracySweepOptions& options,
                                const AccuracyProgress& progress = {},
                                const std::atomic<bool>* cancel = nullptr);

/// \brief Pixels whose 8-bit sRGB values (toneMapSrgb8, exposure 0) differ by
///   more than `levels` in some channel. Films must have the same size.
/// \throws InputError when the sizes differ.
uint64_t countVisibleDifferences(const Film& a, const Film& b, int levels);

/// \brief Sets `pareto` on the results no other result beats: none has both a
///   frame CPU time <= and an RMSE <= with one of them strictly smaller.
///   Results with a non-finite RMSE are never on the front.
void markParetoFront(std::vector<AccuracyResult>& results);

/// CPU seconds used so far by the whole process, all threads
/// (CLOCK_PROCESS_CPUTIME_ID).
double processCpuSeconds();

}  // namespace raylab

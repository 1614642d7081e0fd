#include "tools/accuracy/accuracy_sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <map>
#include <memory>
#include <stdexcept>

#include "renderer/effects.h"
#include "renderer/image_compare.h"
#include "renderer/io/errors.h"
#include "renderer/io/png_writer.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "renderer/timing.h"
#include "tools/report/machine.h"
#include "tools/report/phase_clock.h"

namespace raylab {

namespace {

/// Shortest "%g" text that reads back as the same double (flags, labels).
std::string shortNumber(double v) {
    char buf[40];
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

AccuracySetting named(AccuracySetting s, std::string knob, std::string name) {
    s.knob = std::move(knob);
    s.name = std::move(name);
    return s;
}

/// The sampling of a setting: renders that share it trace their camera rays
/// through the same points of every pixel (adaptive: the same rule).
std::string samplingKey(const AccuracySetting& s) {
    if (s.adaptiveThreshold > 0)
        return "adaptive " + shortNumber(s.adaptiveThreshold) + "/" +
               std::to_string(s.adaptiveLevels);
    return "spp " + std::to_string(s.spp);
}

/// One build + render of a setting.
struct Rendered {
    Film film;
    double buildSeconds = 0;
    double renderSeconds = 0;
    double buildCpuSeconds = 0;
    double renderCpuSeconds = 0;
    uint64_t rays = 0;
    uint64_t nonFiniteSamples = 0;
    bool cancelled = false;
};

Rendered renderSetting(Scene& scene, const AccuracySetting& s, const AccuracySweepOptions& o,
                       const std::atomic<bool>* cancel) {
    // Through the same merge as `raylab render`, so the camera-relative
    // origin and the spawn reference are set exactly as in a real render.
    RenderOverrides ov;
    ov.width = o.width;
    ov.height = o.height;
    ov.spp = s.spp;
    ov.maxDepth = s.maxDepth;
    if (o.threads > 0) ov.threads = o.threads;
    if (s.adaptiveThreshold > 0) {
        ov.adaptiveThreshold = s.adaptiveThreshold;
        ov.adaptiveMaxLevel = s.adaptiveLevels;
    }
    ov.minWeight = s.minWeight;
    ov.seed = 0;
    ov.accel = AcceleratorKind::Embree;
    ov.bvhQuality = s.quality;
    ov.robust = s.robust;
    ov.precision = s.precision;
    if (s.offset == OffsetMode::FixedEpsilon) ov.epsilon = s.epsilon;
    ov.shadows = s.shadows;
    ov.textureFilter = s.textures.filter;
    ov.textureFootprint = s.textures.footprint;
    ov.alphaCutoff = s.alphaCutoff;
    const RenderOptions options = resolveRenderOptions(scene, ov);

    Rendered out;
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = processCpuSeconds();
    const std::unique_ptr<Accelerator> accel =
        makeAccelerator(options.accel, scene, options.accelOptions);
    out.buildSeconds = secondsSince(t0);
    const double c1 = processCpuSeconds();
    out.buildCpuSeconds = c1 - c0;
    RenderResult r = render(scene, *accel, options, analyseEffects(scene, options), {}, cancel);
    out.renderCpuSeconds = processCpuSeconds() - c1;
    out.cancelled = r.cancelled;
    out.renderSeconds = r.renderSeconds;
    out.rays = r.rays.total();
    out.nonFiniteSamples = r.nonFiniteSamples;
    out.film = std::move(r.film);
    return out;
}

/// renderSetting, or for a coverage reference the mean of its renders over
/// the cut-offs (times and rays summed: what the reference cost).
Rendered renderReference(Scene& scene, const AccuracySetting& s, const AccuracySweepOptions& o,
                         const std::atomic<bool>* cancel) {
    if (s.coverageCutoffs <= 0) return renderSetting(scene, s, o, cancel);
    Rendered out;
    std::vector<double> sum;
    for (int k = 0; k < s.coverageCutoffs; ++k) {
        AccuracySetting at = s;
        at.alphaCutoff = (k + 0.5) / s.coverageCutoffs;
        Rendered r = renderSetting(scene, at, o, cancel);
        if (r.cancelled) return r;
        if (k == 0) sum.assign(r.film.rgba.size(), 0.0);
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += r.film.rgba[i];
        out.buildSeconds += r.buildSeconds;
        out.renderSeconds += r.renderSeconds;
        out.buildCpuSeconds += r.buildCpuSeconds;
        out.renderCpuSeconds += r.renderCpuSeconds;
        out.rays += r.rays;
        out.nonFiniteSamples += r.nonFiniteSamples;
        if (k == 0) out.film = std::move(r.film);
    }
    for (size_t i = 0; i < sum.size(); ++i)
        out.film.rgba[i] = float(sum[i] / s.coverageCutoffs);
    return out;
}

uint64_t countNonFinite(const Film& f) {
    uint64_t n = 0;
    for (float v : f.rgba) n += !std::isfinite(v);
    return n;
}

bool sameRgba(const Film& a, const Film& b) {
    return a.rgba.size() == b.rgba.size() &&
           std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

}  // namespace

bool hasTextures(const Scene& scene) {
    for (const Material& m : scene.materials)
        if (m.maps.any()) return true;
    return false;
}

bool hasCutOuts(const Scene& scene) {
    for (const Material& m : scene.materials)
        if (m.cutsOut()) return true;
    return false;
}

std::string AccuracySetting::flags() const {
    std::string f;
    if (adaptiveThreshold > 0)
        f += "--adaptive " + shortNumber(adaptiveThreshold) + " --adaptive-levels " +
             std::to_string(adaptiveLevels);
    else
        f += "--spp " + std::to_string(spp);
    f += " --depth " + std::to_string(maxDepth);
    if (minWeight > 0) f += " --min-weight " + shortNumber(minWeight);
    f += std::string(" --precision ") + (precision == Precision::Float ? "float" : "double");
    if (offset == OffsetMode::FixedEpsilon) f += " --epsilon " + shortNumber(epsilon);
    f += std::string(" --bvh-quality ") + bvhQualityName(quality);
    f += robust ? " --robust" : " --no-robust";
    f += std::string(" --shadows ") + shadowModeName(shadows);
    const TextureOptions defaults;
    if (textures.filter != defaults.filter || textures.footprint != defaults.footprint)
        f += std::string(" --texture-filter ") + textureFilterName(textures.filter) +
             " --texture-footprint " + textureFootprintName(textures.footprint);
    if (alphaCutoff) f += " --alpha-cutoff " + shortNumber(*alphaCutoff);
    if (coverageCutoffs > 0)
        f += " (mean over --alpha-cutoff (k+0.5)/" + std::to_string(coverageCutoffs) + ")";
    return f;
}

AccuracySetting defaultAccuracySetting() { return named(AccuracySetting{}, "default", "default"); }

AccuracySetting referenceAccuracySetting(int spp) {
    AccuracySetting s;
    s.spp = spp;
    s.maxDepth = 12;
    s.robust = true;
    s.textures.filter = TextureFilter::Point;
    return named(s, "reference", "reference (" + std::to_string(spp) + " spp)");
}

std::vector<std::string> accuracyKnobNames() {
    return {"default",   "spp",    "adaptive", "depth",   "min-weight", "precision",
            "offset",    "bvh",    "shadows",  "texture", "alpha-cutoff", "combo"};
}

std::vector<AccuracySetting> accuracySweepSettings(bool quick, bool textured, bool cutOuts) {
    const AccuracySetting d = defaultAccuracySetting();
    std::vector<AccuracySetting> v{d};
    const auto add = [&](const char* knob, const std::string& name, auto&& change) {
        AccuracySetting s = d;
        change(s);
        v.push_back(named(s, knob, name));
    };

    const std::vector<int> spps = quick ? std::vector<int>{4} : std::vector<int>{4, 16};
    for (int n : spps)
        add("spp", "spp " + std::to_string(n), [n](AccuracySetting& s) { s.spp = n; });

    const std::vector<double> thresholds =
        quick ? std::vector<double>{0.03} : std::vector<double>{0.1, 0.03, 0.01};
    for (double t : thresholds)
        add("adaptive", "adaptive " + shortNumber(t),
            [t](AccuracySetting& s) { s.adaptiveThreshold = t; });
    if (!quick)
        add("adaptive", "adaptive 0.01, 3 levels", [](AccuracySetting& s) {
            s.adaptiveThreshold = 0.01;
            s.adaptiveLevels = 3;
        });

    const std::vector<int> depths =
        quick ? std::vector<int>{1, 3} : std::vector<int>{1, 2, 3, 4, 6, 8, 12};
    for (int n : depths)
        add("depth", "depth " + std::to_string(n), [n](AccuracySetting& s) { s.maxDepth = n; });

    // Hall & Greenberg's pruning replaces a fixed depth limit: swept at the
    // reference depth, where it has something to cut.
    const std::vector<double> weights =
        quick ? std::vector<double>{0.05} : std::vector<double>{0.01, 0.05, 0.1, 0.3};
    for (double w : weights)
        add("min-weight", "depth 12, min-weight " + shortNumber(w), [w](AccuracySetting& s) {
            s.maxDepth = 12;
            s.minWeight = w;
        });

    add("precision", "float intersectors",
        [](AccuracySetting& s) { s.precision = Precision::Float; });

    const std::vector<double> epsilons =
        quick ? std::vector<double>{1e-4} : std::vector<double>{1e-2, 1e-4, 1e-6};
    for (double e : epsilons)
        add("offset", "epsilon " + shortNumber(e), [e](AccuracySetting& s) {
            s.offset = OffsetMode::FixedEpsilon;
            s.epsilon = e;
        });

    add("bvh", "bvh low", [](AccuracySetting& s) { s.quality = AccelOptions::BvhQuality::Low; });
    if (!quick)
        add("bvh", "bvh high",
            [](AccuracySetting& s) { s.quality = AccelOptions::BvhQuality::High; });
    add("bvh", "fast traversal", [](AccuracySetting& s) { s.robust = false; });

    // The classic Whitted shadow: every transmitter blocks its light (only
    // scenes with transmitters differ; the reference dims it by their kt).
    add("shadows", "opaque shadows", [](AccuracySetting& s) { s.shadows = ShadowMode::Opaque; });
    if (textured) {
        // Every filter with every footprint (the footprint-free filters once).
        const TextureOptions defaults;
        for (TextureFilter f : {TextureFilter::Point, TextureFilter::Bilinear, TextureFilter::Trilinear,
                                TextureFilter::Anisotropic})
            for (TextureFootprint fp : {TextureFootprint::Cones, TextureFootprint::Differentials}) {
                if (!usesFootprint(f) && fp != defaults.footprint) continue;
                if (f == defaults.filter && fp == defaults.footprint) continue;
                std::string name = std::string("texture ") + textureFilterName(f);
                if (usesFootprint(f)) name += std::string(", ") + textureFootprintName(fp);
                add("texture", name, [f, fp](AccuracySetting& s) {
                    s.textures.filter = f;
                    s.textures.footprint = fp;
                });
            }
    }

    if (cutOuts) {
        // One cut-off for every material: where a soft-edged mask's alpha
        // ramps, the cut-off moves the silhouette (the reference blends).
        const std::vector<double> cutoffs = quick ? std::vector<double>{0.25, 0.75}
                                                  : std::vector<double>{0.1, 0.25, 0.5, 0.75, 0.9};
        for (double c : cutoffs)
            add("alpha-cutoff", "alpha cut-off " + shortNumber(c),
                [c](AccuracySetting& s) { s.alphaCutoff = c; });
    }

    add("combo", "preview: depth 2, float, bvh low", [](AccuracySetting& s) {
        s.maxDepth = 2;
        s.precision = Precision::Float;
        s.quality = AccelOptions::BvhQuality::Low;
    });
    if (!quick) {
        add("combo", "spp 4, depth 3", [](AccuracySetting& s) {
            s.spp = 4;
            s.maxDepth = 3;
        });
        add("combo", "adaptive 0.03, depth 12, min-weight 0.05", [](AccuracySetting& s) {
            s.adaptiveThreshold = 0.03;
            s.maxDepth = 12;
            s.minWeight = 0.05;
        });
        add("combo", "spp 16, depth 8", [](AccuracySetting& s) {
            s.spp = 16;
            s.maxDepth = 8;
        });
    }
    return v;
}

uint64_t countVisibleDifferences(const Film& a, const Film& b, int levels) {
    if (a.width != b.width || a.height != b.height || a.rgba.size() != b.rgba.size())
        throw InputError("visible differences: image sizes differ");
    uint64_t n = 0;
    for (size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
        const auto pa = toneMapSrgb8(a.rgba[i], a.rgba[i + 1], a.rgba[i + 2], 0);
        const auto pb = toneMapSrgb8(b.rgba[i], b.rgba[i + 1], b.rgba[i + 2], 0);
        for (int c = 0; c < 3; ++c) {
            if (std::abs(int(pa[c]) - int(pb[c])) > levels) {
                ++n;
                break;
            }
        }
    }
    return n;
}

double processCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void markParetoFront(std::vector<AccuracyResult>& results) {
    for (AccuracyResult& r : results) {
        r.pareto = std::isfinite(r.rmse) && std::isfinite(r.frameCpuSeconds());
        if (!r.pareto) continue;
        for (const AccuracyResult& o : results) {
            if (&o == &r || !std::isfinite(o.rmse)) continue;
            const bool noWorse = o.frameCpuSeconds() <= r.frameCpuSeconds() && o.rmse <= r.rmse;
            const bool better = o.frameCpuSeconds() < r.frameCpuSeconds() || o.rmse < r.rmse;
            if (noWorse && better) {
                r.pareto = false;
                break;
            }
        }
    }
}

AccuracyReport runAccuracySweep(Scene& scene, const std::string& scenePath,
                                const AccuracySweepOptions& options,
                                const AccuracyProgress& progress, const std::atomic<bool>* cancel) {
    if (options.width < 1 || options.height < 1)
        throw std::invalid_argument("accuracy: image size must be at least 1x1");
    if (options.runs < 1) throw std::invalid_argument("accuracy: runs must be >= 1");
    if (options.referenceSpp < 1)
        throw std::invalid_argument("accuracy: reference spp must be >= 1");
    const std::vector<AccuracySetting> settings =
        options.settings.empty()
            ? accuracySweepSettings(false, hasTextures(scene), hasCutOuts(scene))
            : options.settings;

    AccuracyReport report;
    report.scene = scenePath;
    report.width = options.width;
    report.height = options.height;
    report.runs = options.runs;
    report.threads = effectiveThreads(options.threads);
    report.visibleLevels = options.visibleLevels;
    report.machine = cpuModelName() + ", " + std::to_string(logicalCores()) + " logical cores";

    AccuracySetting ref = referenceAccuracySetting(options.referenceSpp);
    if (hasCutOuts(scene)) {
        // Alpha as partial coverage (AccuracySetting::coverageCutoffs).
        ref.coverageCutoffs = kCoverageCutoffs;
        ref.name = "reference (" + std::to_string(options.referenceSpp) + " spp, coverage of " +
                   std::to_string(kCoverageCutoffs) + " cut-offs)";
    }
    // One reference-quality render per distinct sampling (the reference's own
    // sampling reuses the reference).
    std::map<std::string, AccuracySetting> matched;
    for (const AccuracySetting& s : settings) {
        const std::string key = samplingKey(s);
        if (key == samplingKey(ref) || matched.count(key)) continue;
        AccuracySetting m = ref;
        m.spp = s.spp;
        m.adaptiveThreshold = s.adaptiveThreshold;
        m.adaptiveLevels = s.adaptiveLevels;
        matched.emplace(key, m);
    }
    const int total = 1 + int(matched.size()) + options.runs * int(settings.size());
    int done = 0;
    const auto step = [&](const std::string& label) {
        if (progress) progress(done, total, label);
        ++done;
    };
    // Every setting spells out every knob: the scene file's own "render"
    // block must not leak into the sweep (an "epsilon" there could not be
    // switched back to the robust offset by a flag). The guard puts it back
    // whatever happens next.
    struct SceneGuard {
        Scene& scene;
        RenderOverrides saved;
        ~SceneGuard() { scene.settings = saved; }
    } guard{scene, scene.settings};
    scene.settings = RenderOverrides{};
    const auto finish = [&]() -> AccuracyReport {
        if (report.cancelled) report.results.clear();
        return std::move(report);
    };

    step(ref.name);
    const Rendered reference = renderReference(scene, ref, options, cancel);
    report.cancelled = reference.cancelled;
    if (report.cancelled) return finish();
    report.reference.setting = ref;
    report.reference.buildSeconds = reference.buildSeconds;
    report.reference.renderSeconds = reference.renderSeconds;
    report.reference.buildCpuSeconds = reference.buildCpuSeconds;
    report.reference.renderCpuSeconds = reference.renderCpuSeconds;
    report.reference.renderMinSeconds = report.reference.renderMaxSeconds = reference.renderSeconds;
    report.reference.rays = reference.rays;
    report.reference.psnr = HUGE_VAL;
    report.reference.nonFiniteSamples = reference.nonFiniteSamples;
    report.reference.nonFinitePixels = countNonFinite(reference.film);
    if (options.keepImages) report.reference.film = reference.film;

    std::map<std::string, Film> matchedFilms;
    for (const auto& [key, m] : matched) {
        step("reference quality at " + key);
        Rendered r = renderReference(scene, m, options, cancel);
        report.cancelled = r.cancelled;
        if (report.cancelled) return finish();
        matchedFilms.emplace(key, std::move(r.film));
    }

    // Interleaved rounds: run k of every setting before run k + 1 of any.
    std::vector<std::vector<double>> build(settings.size()), renderTimes(settings.size());
    std::vector<std::vector<double>> buildCpu(settings.size()), renderCpu(settings.size());
    std::vector<Rendered> first(settings.size());
    std::vector<bool> deterministic(settings.size(), true);
    for (int run = 0; run < options.runs; ++run) {
        for (size_t i = 0; i < settings.size(); ++i) {
            step(settings[i].name);
            Rendered r = renderSetting(scene, settings[i], options, cancel);
            report.cancelled = r.cancelled;
            if (report.cancelled) return finish();
            build[i].push_back(r.buildSeconds);
            renderTimes[i].push_back(r.renderSeconds);
            buildCpu[i].push_back(r.buildCpuSeconds);
            renderCpu[i].push_back(r.renderCpuSeconds);
            if (run == 0)
                first[i] = std::move(r);
            else if (!sameRgba(first[i].film, r.film))
                deterministic[i] = false;
        }
    }
    if (progress) progress(total, total, "");

    for (size_t i = 0; i < settings.size(); ++i) {
        AccuracyResult res;
        res.setting = settings[i];
        res.buildSeconds = median(build[i]);
        res.renderSeconds = median(renderTimes[i]);
        res.buildCpuSeconds = median(buildCpu[i]);
        res.renderCpuSeconds = median(renderCpu[i]);
        res.renderMinSeconds = *std::min_element(renderTimes[i].begin(), renderTimes[i].end());
        res.renderMaxSeconds = *std::max_element(renderTimes[i].begin(), renderTimes[i].end());
        res.rays = first[i].rays;
        const Film& film = first[i].film;
        const ImageComparison c = compareImages(film, reference.film);
        res.rmse = c.rmse;
        res.psnr = c.psnr;
        res.maxError = c.maxAbsError;
        res.visiblePixels = countVisibleDifferences(film, reference.film, options.visibleLevels);
        const std::string key = samplingKey(settings[i]);
        const auto it = matchedFilms.find(key);
        const Film& same = it == matchedFilms.end() ? reference.film : it->second;
        res.knobRmse = compareImages(film, same).rmse;
        res.knobVisiblePixels = countVisibleDifferences(film, same, options.visibleLevels);
        res.nonFiniteSamples = first[i].nonFiniteSamples;
        res.nonFinitePixels = countNonFinite(film);
        res.deterministic = deterministic[i];
        if (options.keepImages) res.film = film;
        report.results.push_back(std::move(res));
    }
    markParetoFront(report.results);
    return finish();
}

}  // namespace raylab

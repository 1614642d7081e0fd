#include "tools/bench/accel_bench.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/huge_page_allocator.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/json_string.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "renderer/whitted_integrator.h"
#include "tools/bench/scene_generators.h"
#include "renderer/io/png_memory.h"
#include "tools/report/html_page.h"
#include "tools/report/machine.h"
#include "tools/report/phase_clock.h"
#include "tools/report/svg_plot.h"
#include "tools/report/table_format.h"

namespace raylab {

namespace {

using Clock = std::chrono::steady_clock;

/// One back end's measurement on one scene.
struct Timing {
    double buildSeconds = 0;   ///< median
    double renderSeconds = 0;  ///< median frame (or sample) time
    uint64_t rays = 0;         ///< rays traced in one frame (or sample)
    size_t stride = 1;         ///< 1 = full frame; k = every k-th pixel
    size_t pixels = 0;         ///< pixels traced

    double raysPerSecond() const { return renderSeconds > 0 ? double(rays) / renderSeconds : 0; }
    double nanosecondsPerRay() const {
        return rays > 0 ? renderSeconds / double(rays) * 1e9 : 0;
    }
};

struct Row {
    std::string family;  ///< generator name, or "file"
    std::string scene;   ///< "level 3", "N=1000", or the file name
    size_t parameter = 0;
    uint64_t primitives = 0;
    Timing embree, naive;
    /// The frames, kept for the HTML report: Embree's always, the naive
    /// loop's when it rendered full frames (else empty).
    Film embreeImage, naiveImage;

    /// Embree rays/s over naive rays/s (> 1: Embree is faster per ray).
    double speedup() const {
        const double n = naive.raysPerSecond();
        return n > 0 ? embree.raysPerSecond() / n : 0;
    }
};

struct Settings {
    int width, height, runs, threads;
    double naiveBudget;
    PhaseClock clock;  ///< CPU time of the working thread with one thread, else wall-clock
    bool keepImages = false;  ///< --html: keep each scene's frames
};

/// Traces the camera rays of every `stride`-th pixel (pixel centres, as
/// render() does with spp 1) through the integrator, in parallel like
/// render(); returns the time on `clock`, the rays traced and the pixels.
double renderPixelSample(const Scene& scene, const Accelerator& accel,
                         const RenderOptions& options, const EffectSet& effects, size_t stride,
                         const PhaseClock& clock, uint64_t& rays, size_t& pixels) {
    const size_t total = size_t(options.width) * size_t(options.height);
    const size_t first = stride / 2;
    const size_t count = first < total ? (total - first + stride - 1) / stride : 0;
    pixels = count;
    std::unique_ptr<tbb::global_control> limit;
    if (options.threads > 0)
        limit = std::make_unique<tbb::global_control>(
            tbb::global_control::max_allowed_parallelism, size_t(options.threads));
    const WhittedIntegrator integrator(scene, accel, options, effects);
    tbb::enumerable_thread_specific<RayCounters> counters;
    const double seconds = clock.time([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 4),
                          [&](const tbb::blocked_range<size_t>& range) {
                              RayCounters& c = counters.local();
                              for (size_t s = range.begin(); s != range.end(); ++s) {
                                  const size_t pixel = first + s * stride;
                                  const int x = int(pixel % size_t(options.width));
                                  const int y = int(pixel / size_t(options.width));
                                  const Ray ray = scene.camera.generateRay(
                                      x + 0.5, y + 0.5, options.width, options.height);
                                  SampleRays spent;
                                  integrator.Li(ray, c, nullptr, spent);
                              }
                          });
    });
    uint64_t n = 0;
    for (const RayCounters& c : counters) n += c.total();
    rays = n;
    return seconds;
}

/// One full frame through render(): the frame time on the settings' clock
/// (wall-clock: the renderer's own RenderResult::renderSeconds; CPU time: the
/// whole call) and the rays traced.
double timeFrame(const Scene& scene, const Accelerator& accel, const RenderOptions& options,
                 const EffectSet& effects, const PhaseClock& clock, uint64_t& rays) {
    RenderResult res;
    const double cpu = clock.time([&] { res = render(scene, accel, options, effects); });
    rays = res.rays.total();
    return clock.cpu() ? cpu : res.renderSeconds;
}

/// Builds the named back end `runs` times; returns the last one and the
/// median build time (Embree: its own BVH build time, device creation excluded).
std::unique_ptr<Accelerator> buildAccelerator(const std::string& name, const Scene& scene,
                                              const RenderOptions& options, int runs,
                                              double& medianSeconds) {
    std::vector<double> times;
    std::unique_ptr<Accelerator> accel;
    for (int r = 0; r < runs; ++r) {
        accel.reset();
        accel = makeAccelerator(name, scene, options.accelOptions);
        times.push_back(accel->buildSeconds());
    }
    medianSeconds = median(times);
    return accel;
}

Row measureScene(Scene& scene, const Settings& s, std::string family, std::string label,
                 size_t parameter) {
    Row row;
    row.family = std::move(family);
    row.scene = std::move(label);
    row.parameter = parameter;
    row.primitives = scene.primitiveCount();

    RenderOverrides o;
    o.width = s.width;
    o.height = s.height;
    o.spp = 1;
    if (s.threads > 0) o.threads = s.threads;
    const RenderOptions options = resolveRenderOptions(scene, o);
    const EffectSet effects = analyseEffects(scene, options);
    const size_t pixels = size_t(options.width) * size_t(options.height);

    // Repeated frames reuse their buffers' mappings (as render --frames does).
    const huge_pages::ReuseScope reuseFrameBuffers;

    // Embree: full frames through the renderer, after one warm-up frame.
    {
        const auto accel =
            buildAccelerator("embree", scene, options, s.runs, row.embree.buildSeconds);
        RenderResult warmUp = render(scene, *accel, options, effects);
        if (s.keepImages) row.embreeImage = std::move(warmUp.film);
        std::vector<double> times;
        for (int r = 0; r < s.runs; ++r)
            times.push_back(timeFrame(scene, *accel, options, effects, s.clock, row.embree.rays));
        row.embree.renderSeconds = median(times);
        row.embree.pixels = pixels;
    }

    // Naive: a pilot sample sized from a guess of 10 ns per primitive per ray
    // estimates the full frame; over budget, every k-th pixel only.
    {
        const auto accel =
            buildAccelerator("naive", scene, options, s.runs, row.naive.buildSeconds);
        const double raysPerPixel = double(row.embree.rays) / double(pixels);
        const double guessPerPixel = 10e-9 * double(std::max<uint64_t>(1, row.primitives)) *
                                     raysPerPixel;
        const double pilotPixels =
            std::clamp(0.1 * s.naiveBudget / guessPerPixel, 16.0, double(pixels));
        const size_t pilotStride =
            pixelSampleStride(size_t(std::max(1.0, std::floor(double(pixels) / pilotPixels))),
                              options.width);
        uint64_t pilotRays = 0;
        size_t pilotCount = 0;
        const double pilotSeconds = renderPixelSample(scene, *accel, options, effects, pilotStride,
                                                      s.clock, pilotRays, pilotCount);
        const double perRay = pilotSeconds / double(std::max<uint64_t>(1, pilotRays));
        const double fullEstimate = perRay * double(row.embree.rays);
        std::vector<double> times;
        if (fullEstimate <= s.naiveBudget) {
            for (int r = 0; r < s.runs; ++r)
                times.push_back(
                    timeFrame(scene, *accel, options, effects, s.clock, row.naive.rays));
            row.naive.stride = 1;
            row.naive.pixels = pixels;
            if (s.keepImages) row.naiveImage = render(scene, *accel, options, effects).film;  // untimed
        } else {
            row.naive.stride = pixelSampleStride(
                size_t(std::ceil(fullEstimate / s.naiveBudget)), options.width);
            for (int r = 0; r < s.runs; ++r)
                times.push_back(renderPixelSample(scene, *accel, options, effects,
                                                  row.naive.stride, s.clock, row.naive.rays,
                                                  row.naive.pixels));
        }
        row.naive.renderSeconds = median(times);
    }
    return row;
}

std::string formatMs(double seconds) {
    char buf[32];
    const double ms = seconds * 1e3;
    std::snprintf(buf, sizeof buf, ms < 10 ? "%.3f" : (ms < 1000 ? "%.1f" : "%.0f"), ms);
    return buf;
}

/// Three significant digits: 12.3, 0.0559, 6.4e-05 (naive rates span 8 decades).
std::string formatMrays(double raysPerSecond) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", raysPerSecond * 1e-6);
    return buf;
}

std::string sampleText(const Timing& t) {
    return t.stride <= 1 ? "full" : "1/" + std::to_string(t.stride);
}

void printHeader(std::ostream& out) {
    char buf[256];
    std::snprintf(buf, sizeof buf,
                  "%-12s %-14s %9s | %10s %10s %9s %9s | %10s %10s %9s %9s %7s | %9s\n", "family",
                  "scene", "prims", "build ms", "frame ms", "Mrays/s", "ns/ray", "build ms",
                  "frame ms", "Mrays/s", "ns/ray", "pixels", "speedup");
    out << "                                     | ----------------- embree ----------------- |"
           " ------------------------ naive ------------------------ |\n";
    out << buf;
}

void printRow(std::ostream& out, const Row& r) {
    char buf[320];
    char speed[32];
    std::snprintf(speed, sizeof speed, "%.1fx", r.speedup());
    std::snprintf(buf, sizeof buf,
                  "%-12s %-14s %9llu | %10s %10s %9s %9.0f | %10s %10s %9s %9.0f %7s | %9s\n",
                  r.family.c_str(), r.scene.c_str(), (unsigned long long)r.primitives,
                  formatMs(r.embree.buildSeconds).c_str(), formatMs(r.embree.renderSeconds).c_str(),
                  formatMrays(r.embree.raysPerSecond()).c_str(), r.embree.nanosecondsPerRay(),
                  formatMs(r.naive.buildSeconds).c_str(), formatMs(r.naive.renderSeconds).c_str(),
                  formatMrays(r.naive.raysPerSecond()).c_str(), r.naive.nanosecondsPerRay(),
                  sampleText(r.naive).c_str(), speed);
    out << buf << std::flush;
}

/// Where the naive loop stops winning within one family (rows by size).
struct Crossover {
    std::string family;
    std::optional<double> below;  ///< estimated primitive count; empty: none measured
    std::string text;
};

Crossover findCrossover(const std::string& family, std::vector<const Row*> rows) {
    std::sort(rows.begin(), rows.end(),
              [](const Row* a, const Row* b) { return a->primitives < b->primitives; });
    Crossover c;
    c.family = family;
    const auto naiveWins = [](const Row* r) { return r->speedup() < 1.0; };
    // First size from which Embree wins at every larger size.
    size_t j = rows.size();
    while (j > 0 && !naiveWins(rows[j - 1])) --j;
    if (rows.empty()) {
        c.text = "no measurements";
    } else if (j == 0) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "Embree faster at every size (%.1fx at %llu primitives)",
                      rows.front()->speedup(), (unsigned long long)rows.front()->primitives);
        c.text = buf;
    } else if (j == rows.size()) {
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "naive faster at every size measured (up to %llu primitives)",
                      (unsigned long long)rows.back()->primitives);
        c.text = buf;
    } else {
        // log-log interpolation of the speedup between the two sizes that straddle 1.
        const Row& a = *rows[j - 1];
        const Row& b = *rows[j];
        const double la = std::log(double(std::max<uint64_t>(1, a.primitives)));
        const double lb = std::log(double(std::max<uint64_t>(1, b.primitives)));
        const double sa = std::log(std::max(1e-300, a.speedup()));
        const double sb = std::log(std::max(1e-300, b.speedup()));
        const double f = sb != sa ? std::clamp(-sa / (sb - sa), 0.0, 1.0) : 0.5;
        c.below = std::exp(la + f * (lb - la));
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "naive faster below ~%.0f primitives (%.2fx at %llu, %.2fx at %llu)",
                      *c.below, a.speedup(), (unsigned long long)a.primitives, b.speedup(),
                      (unsigned long long)b.primitives);
        c.text = buf;
    }
    return c;
}

std::string csvTable(const std::vector<Row>& rows, const Settings& s, const std::string& cpu) {
    std::string t =
        "family,scene,parameter,primitives,embree_build_s,embree_frame_s,embree_rays,"
        "embree_mrays_per_s,embree_ns_per_ray,naive_build_s,naive_frame_s,naive_rays,"
        "naive_pixel_stride,naive_pixels,naive_mrays_per_s,naive_ns_per_ray,speedup,cpu,cores,"
        "threads,width,height,runs,clock\n";
    for (const Row& r : rows) {
        t += csvField(r.family) + "," + csvField(r.scene) + "," + std::to_string(r.parameter) +
             "," + std::to_string(r.primitives) + "," + jsonNumber(r.embree.buildSeconds) + "," +
             jsonNumber(r.embree.renderSeconds) + "," + std::to_string(r.embree.rays) + "," +
             jsonNumber(r.embree.raysPerSecond() * 1e-6) + "," +
             jsonNumber(r.embree.nanosecondsPerRay()) + "," + jsonNumber(r.naive.buildSeconds) +
             "," + jsonNumber(r.naive.renderSeconds) + "," + std::to_string(r.naive.rays) + "," +
             std::to_string(r.naive.stride) + "," + std::to_string(r.naive.pixels) + "," +
             jsonNumber(r.naive.raysPerSecond() * 1e-6) + "," +
             jsonNumber(r.naive.nanosecondsPerRay()) + "," + jsonNumber(r.speedup()) + "," +
             csvField(cpu) + "," + std::to_string(logicalCores()) + "," +
             std::to_string(effectiveThreads(s.threads)) + "," + std::to_string(s.width) + "," +
             std::to_string(s.height) + "," + std::to_string(s.runs) + "," +
             (s.clock.cpu() ? "thread_cpu" : "wall") + "\n";
    }
    return t;
}

std::string jsonTiming(const Timing& t, bool naive) {
    std::string j = "{\"build_seconds\": " + jsonNumber(t.buildSeconds) +
                    ", \"frame_seconds\": " + jsonNumber(t.renderSeconds) +
                    ", \"rays\": " + std::to_string(t.rays) +
                    ", \"mrays_per_second\": " + jsonNumber(t.raysPerSecond() * 1e-6) +
                    ", \"ns_per_ray\": " + jsonNumber(t.nanosecondsPerRay());
    if (naive)
        j += ", \"pixel_stride\": " + std::to_string(t.stride) +
             ", \"pixels\": " + std::to_string(t.pixels);
    return j + "}";
}

std::string jsonDocument(const std::vector<Row>& rows, const std::vector<Crossover>& crossovers,
                         const Settings& s, const std::string& cpu, double loadStart,
                         double loadEnd) {
    std::string j = "{\n  \"machine\": {\"cpu\": " + jsonString(cpu) +
                    ", \"cores\": " + std::to_string(logicalCores()) +
                    ", \"load_average_start\": " + jsonNumber(loadStart) +
                    ", \"load_average_end\": " + jsonNumber(loadEnd) + "},\n";
    j += "  \"clock\": " + std::string(s.clock.cpu() ? "\"thread_cpu\"" : "\"wall\"") + ",\n";
    j += "  \"threads\": " + std::to_string(effectiveThreads(s.threads)) +
         ",\n  \"width\": " + std::to_string(s.width) + ",\n  \"height\": " +
         std::to_string(s.height) + ",\n  \"runs\": " + std::to_string(s.runs) +
         ",\n  \"naive_budget_seconds\": " + jsonNumber(s.naiveBudget) + ",\n  \"rows\": [";
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        j += std::string(i ? "," : "") + "\n    {\"family\": " + jsonString(r.family) +
             ", \"scene\": " + jsonString(r.scene) +
             ", \"parameter\": " + std::to_string(r.parameter) +
             ", \"primitives\": " + std::to_string(r.primitives) +
             ",\n     \"embree\": " + jsonTiming(r.embree, false) +
             ",\n     \"naive\": " + jsonTiming(r.naive, true) +
             ",\n     \"speedup\": " + jsonNumber(r.speedup()) + "}";
    }
    j += "\n  ],\n  \"crossover\": [";
    for (size_t i = 0; i < crossovers.size(); ++i) {
        const Crossover& c = crossovers[i];
        j += std::string(i ? "," : "") + "\n    {\"family\": " + jsonString(c.family) +
             ", \"naive_faster_below_primitives\": " +
             (c.below ? jsonNumber(*c.below) : std::string("null")) +
             ", \"text\": " + jsonString(c.text) + "}";
    }
    return j + "\n  ]\n}\n";
}

PlotSpec makePlot(const std::vector<Row>& rows, const std::vector<std::string>& families,
                  const Settings& s, const std::string& cpu) {
    static const char* const colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};
    static const PlotMarker markers[] = {PlotMarker::Circle, PlotMarker::Square,
                                         PlotMarker::Triangle, PlotMarker::Diamond,
                                         PlotMarker::Circle};
    PlotSpec plot;
    const int threads = effectiveThreads(s.threads);
    plot.title = "Time per ray: Embree vs naive (" + std::to_string(s.width) + "x" +
                 std::to_string(s.height) + ", " + std::to_string(threads) +
                 (threads == 1 ? " thread, " : " threads, ") + cpu + ")";
    plot.x = {"primitives", true};
    plot.y = {std::string(s.clock.cpu() ? "CPU" : "wall") + " time per ray (ns)", true};
    plot.highlightLabel = "naive on a pixel sample";
    plot.width = 900;
    plot.height = 560;
    for (size_t f = 0; f < families.size(); ++f) {
        PlotSeries embree, naive;
        embree.name = families[f] + " (Embree)";
        naive.name = families[f] + " (naive)";
        embree.color = naive.color = colors[f % 5];
        // Scene files: circles in their own colour (a cross cannot be hollow).
        embree.marker = naive.marker =
            families[f] == "file" ? PlotMarker::Circle : markers[f % 5];
        naive.filled = false;
        naive.dashed = true;
        // Scene files are unrelated scenes: markers only.
        embree.line = naive.line = families[f] != "file";
        std::vector<const Row*> mine;
        for (const Row& r : rows)
            if (r.family == families[f]) mine.push_back(&r);
        std::sort(mine.begin(), mine.end(),
                  [](const Row* a, const Row* b) { return a->primitives < b->primitives; });
        for (const Row* r : mine) {
            embree.points.push_back({double(r->primitives), r->embree.nanosecondsPerRay(), false});
            naive.points.push_back(
                {double(r->primitives), r->naive.nanosecondsPerRay(), r->naive.stride > 1});
        }
        plot.series.push_back(std::move(embree));
        plot.series.push_back(std::move(naive));
    }
    return plot;
}

/// The benchmark as a page: the plot, the table, and every scene's frames
/// (Embree, the naive loop's where it rendered a full frame, and the error
/// map between the two, which is black where they agree bit for bit).
std::string accelHtml(const std::vector<Row>& rows, const std::vector<Crossover>& crossovers,
                      const PlotSpec& plot, const Settings& s, const std::string& cpu) {
    std::string body;
    body += "<p>" + std::to_string(s.width) + "x" + std::to_string(s.height) +
            ", 1 ray per pixel centre, median of " + std::to_string(s.runs) + " runs; " +
            escapeHtml(cpu) + ", " + std::to_string(effectiveThreads(s.threads)) +
            " threads; frame times: " + escapeHtml(s.clock.name()) + ".</p>\n";
    int expected = 0;
    for (const PlotSeries& series : plot.series)
        for (const PlotPoint& p : series.points) expected += p.x > 0 && p.y > 0;
    body += "<h2>Time per ray</h2>\n<div class=\"plot\" data-expected-points=\"" +
            std::to_string(expected) + "\">\n" + renderSvgPlot(plot) + "</div>\n";
    body += "<h2>Table</h2>\n<table>\n<tr><th>family</th><th>scene</th><th>primitives</th>"
            "<th>Embree build ms</th><th>Embree frame ms</th><th>Embree ns/ray</th>"
            "<th>naive build ms</th><th>naive frame ms</th><th>naive ns/ray</th><th>naive pixels</th>"
            "<th>speedup</th><th>same image</th></tr>\n";
    const auto td = [](const std::string& t) { return "<td>" + escapeHtml(t) + "</td>"; };
    std::vector<ViewerImage> images, naive, maps;
    for (const Row& r : rows) {
        char speed[32], eNs[32], nNs[32];
        std::snprintf(speed, sizeof speed, "%.1fx", r.speedup());
        std::snprintf(eNs, sizeof eNs, "%.0f", r.embree.nanosecondsPerRay());
        std::snprintf(nNs, sizeof nNs, "%.0f", r.naive.nanosecondsPerRay());
        std::string same = "-";
        const std::string label = r.family + " " + r.scene;
        if (r.embreeImage.width > 0)
            images.push_back({label, "Embree", std::to_string(r.primitives) + " primitives",
                              toneMappedImage(r.embreeImage)});
        if (r.naiveImage.width > 0 && r.embreeImage.width > 0) {
            same = r.naiveImage.rgba == r.embreeImage.rgba ? "yes" : "no";
            naive.push_back({label, "naive loop (full frames)", "", toneMappedImage(r.naiveImage)});
            maps.push_back({label, "naive vs Embree error maps", same == "yes" ? "bit-identical" : "differs",
                            errorMap(r.naiveImage, r.embreeImage)});
        }
        body += "<tr><td class=\"text\">" + escapeHtml(r.family) + "</td><td class=\"text\">" +
                escapeHtml(r.scene) + "</td>" + td(std::to_string(r.primitives)) +
                td(formatMs(r.embree.buildSeconds)) + td(formatMs(r.embree.renderSeconds)) + td(eNs) +
                td(formatMs(r.naive.buildSeconds)) + td(formatMs(r.naive.renderSeconds)) + td(nNs) +
                td(sampleText(r.naive)) + td(speed) + td(same) + "</tr>\n";
    }
    body += "</table>\n<h3>Crossover (naive loop faster than Embree per ray)</h3>\n<ul>\n";
    for (const Crossover& c : crossovers)
        body += "<li>" + escapeHtml(c.family + ": " + c.text) + "</li>\n";
    body += "</ul>\n";
    images.insert(images.end(), naive.begin(), naive.end());
    images.insert(images.end(), maps.begin(), maps.end());
    if (!images.empty()) {
        body += "<h2>Images</h2>\n<p>Each scene as Embree rendered it, the naive loop's frame "
                "where it rendered a full one, and the error map between them (black: the "
                "same value; <img class=\"legend-bar\" alt=\"colour scale\" src=\"" +
                pngDataUri(errorMapLegend(256, 12)) + "\"> from 1e-4 to 1, logarithmic).</p>\n";
        body += comparisonViewer(images);
    }
    return htmlDocument("raylab bench accel", body);
}

bool endsWithSvg(const std::string& path) {
    if (path.size() < 5) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".svg";
}

}  // namespace

size_t pixelSampleStride(size_t minStride, int width) {
    size_t k = std::max<size_t>(1, minStride);
    while (std::gcd(k, size_t(std::max(1, width))) != 1) ++k;
    return k;
}

int runAccelBench(const AccelBenchOptions& options, std::ostream& out) {
    // Every option is checked before the first (long) measurement starts.
    if (options.width < 1 || options.height < 1)
        throw UsageError("bench accel: width and height must be >= 1");
    if (options.runs < 1) throw UsageError("bench accel: runs must be >= 1");
    if (options.threads < 0) throw UsageError("bench accel: threads must be >= 0");
    if (!(options.naiveBudgetSeconds > 0) || !std::isfinite(options.naiveBudgetSeconds))
        throw UsageError("bench accel: the naive budget must be > 0 seconds");
    std::optional<TableFormat> format;
    if (!options.outPath.empty()) format = tableFormatOf(options.outPath, "bench accel: output");
    if (!options.plotPath.empty() && !endsWithSvg(options.plotPath))
        throw UsageError("bench accel: plot '" + options.plotPath + "' must end in .svg");

    if (!options.htmlDir.empty()) checkReportDir(options.htmlDir, "--html");

    Settings s{options.width, options.height, options.runs, options.threads,
               options.naiveBudgetSeconds, PhaseClock(effectiveThreads(options.threads) == 1),
               !options.htmlDir.empty()};
    if (options.quick) {
        s.width = std::min(s.width, 128);
        s.height = std::min(s.height, 128);
        s.runs = std::min(s.runs, 3);
        s.naiveBudget = std::min(s.naiveBudget, 0.5);
    }
    const std::string cpu = cpuModelName();
    const double loadAtStart = loadAverage();
    out << "raylab bench accel: " << s.width << "x" << s.height << ", 1 ray per pixel centre, "
        << "median of " << s.runs << " runs, naive budget " << s.naiveBudget << " s/frame\n"
        << "machine: " << cpu << ", " << logicalCores() << " logical cores; threads: "
        << effectiveThreads(s.threads) << "; load average " << loadAtStart << "\n"
        << "frame times: " << s.clock.name() << "; build times: wall-clock\n"
        << "speedup = Embree rays/s / naive rays/s; pixels = naive frame (full) or every k-th "
           "pixel (1/k)\n\n";
    printHeader(out);

    std::vector<Row> rows;
    std::vector<std::string> families;
    const auto start = Clock::now();
    for (const SceneGenerator& g : benchSceneGenerators()) {
        families.push_back(g.name);
        for (size_t p : options.quick ? g.quickSizes : g.sizes) {
            Scene scene = g.make(p);
            const std::string label = g.parameterName + " " + std::to_string(p);
            rows.push_back(measureScene(scene, s, g.name, label, p));
            printRow(out, rows.back());
        }
    }
    if (!options.sceneFiles.empty()) families.push_back("file");
    for (const std::string& path : options.sceneFiles) {
        Scene scene = loadScene(path);
        rows.push_back(measureScene(scene, s, "file", fileName(path), 0));
        printRow(out, rows.back());
    }

    std::vector<Crossover> crossovers;
    out << "\ncrossover (naive loop faster than Embree per ray):\n";
    for (const std::string& f : families) {
        if (f == "file") continue;
        std::vector<const Row*> mine;
        for (const Row& r : rows)
            if (r.family == f) mine.push_back(&r);
        crossovers.push_back(findCrossover(f, mine));
        out << "  " << f << ": " << crossovers.back().text << "\n";
    }
    char total[64];
    std::snprintf(total, sizeof total, "%.1f", secondsSince(start));
    const double loadAtEnd = loadAverage();
    out << "total benchmark time: " << total << " s; load average now " << loadAtEnd
        << " (a load above the core count means other work shared the cores, which inflates "
           "wall-clock times)\n";

    if (format) {
        const std::string doc =
            *format == TableFormat::Csv
                ? csvTable(rows, s, cpu)
                : jsonDocument(rows, crossovers, s, cpu, loadAtStart, loadAtEnd);
        writeFileAtomically(options.outPath, doc);
        out << "results: " << options.outPath << "\n";
    }
    if (!options.plotPath.empty()) {
        writeSvgPlot(options.plotPath, makePlot(rows, families, s, cpu));
        out << "plot: " << options.plotPath << "\n";
    }
    if (!options.htmlDir.empty()) {
        const std::string page = writeHtmlReport(
            options.htmlDir, accelHtml(rows, crossovers, makePlot(rows, families, s, cpu), s, cpu));
        out << "report: " << page << "\n";
    }
    return 0;
}

}  // namespace raylab

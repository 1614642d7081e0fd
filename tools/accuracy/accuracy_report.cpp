#include "tools/accuracy/accuracy_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "renderer/image_compare.h"
#include "renderer/render_option_names.h"
#include "renderer/io/json_string.h"
#include "tools/report/table_format.h"

namespace raylab {

namespace {

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

/// 19200 -> "19.2k", 4123456 -> "4.12M".
std::string countText(uint64_t n) {
    if (n >= 10000000) return format("%.1fM", double(n) * 1e-6);
    if (n >= 1000000) return format("%.2fM", double(n) * 1e-6);
    if (n >= 10000) return format("%.1fk", double(n) * 1e-3);
    return std::to_string(n);
}

std::string padRight(std::string s, size_t w) {
    if (s.size() < w) s.append(w - s.size(), ' ');
    return s;
}

std::string padLeft(const std::string& s, size_t w) {
    return s.size() < w ? std::string(w - s.size(), ' ') + s : s;
}

/// Million rays per CPU-second of rendering (per core: on an idle machine a
/// render on N threads traces about N times this per wall-clock second).
double mrays(const AccuracyResult& r) {
    return r.renderCpuSeconds > 0 ? double(r.rays) / r.renderCpuSeconds * 1e-6 : 0;
}

std::string jsonBool(bool b) { return b ? "true" : "false"; }

/// The JSON members of one result (without braces).
std::string resultJson(const AccuracyResult& r, const std::string& indent) {
    const AccuracySetting& s = r.setting;
    std::string j;
    const auto add = [&](const char* key, const std::string& value) {
        if (!j.empty()) j += ",\n";
        j += indent + jsonString(key) + ": " + value;
    };
    add("name", jsonString(s.name));
    add("knob", jsonString(s.knob));
    add("flags", jsonString(s.flags()));
    add("spp", std::to_string(s.spp));
    add("adaptive_threshold", jsonNumber(s.adaptiveThreshold));
    add("adaptive_levels", std::to_string(s.adaptiveLevels));
    add("depth", std::to_string(s.maxDepth));
    add("min_weight", jsonNumber(s.minWeight));
    add("precision", jsonString(precisionName(s.precision)));
    add("offset", jsonString(s.offset == OffsetMode::Robust ? "robust" : "epsilon"));
    add("epsilon", s.offset == OffsetMode::Robust ? "null" : jsonNumber(s.epsilon));
    add("bvh_quality", jsonString(bvhQualityName(s.quality)));
    add("robust", jsonBool(s.robust));
    add("build_ms", jsonNumber(r.buildSeconds * 1e3));
    add("render_ms", jsonNumber(r.renderSeconds * 1e3));
    add("render_ms_min", jsonNumber(r.renderMinSeconds * 1e3));
    add("render_ms_max", jsonNumber(r.renderMaxSeconds * 1e3));
    add("frame_ms", jsonNumber(r.frameSeconds() * 1e3));
    add("build_cpu_ms", jsonNumber(r.buildCpuSeconds * 1e3));
    add("render_cpu_ms", jsonNumber(r.renderCpuSeconds * 1e3));
    add("frame_cpu_ms", jsonNumber(r.frameCpuSeconds() * 1e3));
    add("rays", std::to_string(r.rays));
    add("mrays_per_cpu_s", jsonNumber(mrays(r)));
    add("rmse", jsonNumber(r.rmse));
    add("psnr_db", jsonNumber(r.psnr));  // +inf (identical) is written as null
    add("max_error", jsonNumber(r.maxError));
    add("visible_pixels", std::to_string(r.visiblePixels));
    add("same_samples_rmse", jsonNumber(r.knobRmse));
    add("same_samples_visible_pixels", std::to_string(r.knobVisiblePixels));
    add("non_finite_samples", std::to_string(r.nonFiniteSamples));
    add("non_finite_pixels", std::to_string(r.nonFinitePixels));
    add("deterministic", jsonBool(r.deterministic));
    add("pareto", jsonBool(r.pareto));
    return j;
}

}  // namespace

std::string accuracyTable(const AccuracyReport& rep) {
    std::string out;
    char line[512];
    std::snprintf(line, sizeof line,
                  "raylab accuracy: %s at %dx%d, median of %d run%s, %d thread%s (%s)\n",
                  rep.scene.c_str(), rep.width, rep.height, rep.runs, rep.runs == 1 ? "" : "s",
                  rep.threads, rep.threads == 1 ? "" : "s", rep.machine.c_str());
    out += line;
    const AccuracyResult& ref = rep.reference;
    std::snprintf(line, sizeof line, "reference: %s: build %.1f ms, render %.1f ms, %s rays\n",
                  ref.setting.flags().c_str(), ref.buildSeconds * 1e3, ref.renderSeconds * 1e3,
                  countText(ref.rays).c_str());
    out += line;
    std::snprintf(
        line, sizeof line,
        "errors: linear RGB against the reference; visible = pixels more than %d/255 "
        "off in 8-bit sRGB (of %d);\n"
        "same-samples = against the reference settings at the setting's own sampling "
        "(the non-sampling knobs alone);\n"
        "cpu ms = build + render CPU time of all threads (robust to other load), Mray/cpu-s "
        "= rays per render CPU-second;\n* = Pareto front (cpu ms vs RMSE)\n\n",
        rep.visibleLevels, rep.width * rep.height);
    out += line;

    size_t nameWidth = 9;
    for (const AccuracyResult& r : rep.results)
        nameWidth = std::max(nameWidth, r.setting.name.size() + 2);
    const std::vector<std::pair<const char*, size_t>> cols = {
        {"build ms", 9},    {"render ms", 10}, {"cpu ms", 9}, {"rays", 8},
        {"Mray/cpu-s", 11}, {"RMSE", 9},       {"PSNR", 7},   {"max err", 8},
        {"visible", 8},     {"ss RMSE", 9},    {"ss vis", 7}, {"NaN", 4},
    };
    std::string header = padRight("setting", nameWidth);
    for (const auto& [name, w] : cols) header += padLeft(name, w);
    out += header + "\n";
    out += std::string(header.size() + 2, '-') + "\n";

    std::string lastKnob;
    for (const AccuracyResult& r : rep.results) {
        if (!lastKnob.empty() && r.setting.knob != lastKnob) out += "\n";
        lastKnob = r.setting.knob;
        std::string row = padRight(r.setting.name, nameWidth);
        const std::vector<std::string> cells = {
            format("%.2f", r.buildSeconds * 1e3),
            format("%.1f", r.renderSeconds * 1e3),
            format("%.1f", r.frameCpuSeconds() * 1e3),
            countText(r.rays),
            format("%.2f", mrays(r)),
            format("%.2e", r.rmse),
            formatPsnr(r.psnr),
            format("%.3f", r.maxError),
            std::to_string(r.visiblePixels),
            format("%.2e", r.knobRmse),
            std::to_string(r.knobVisiblePixels),
            std::to_string(r.nonFiniteSamples + r.nonFinitePixels),
        };
        for (size_t c = 0; c < cells.size(); ++c) row += padLeft(cells[c], cols[c].second);
        if (r.pareto) row += " *";
        if (!r.deterministic) row += " (runs differ!)";
        out += row + "\n";
    }
    return out;
}

std::string accuracyCsv(const AccuracyReport& rep) {
    std::string out =
        "setting,knob,flags,spp,adaptive_threshold,adaptive_levels,depth,min_weight,precision,"
        "offset,epsilon,bvh_quality,robust,build_ms,render_ms,render_ms_min,render_ms_max,"
        "frame_ms,build_cpu_ms,render_cpu_ms,frame_cpu_ms,rays,mrays_per_cpu_s,rmse,psnr_db,"
        "max_error,visible_pixels,"
        "same_samples_rmse,same_samples_visible_pixels,non_finite_samples,non_finite_pixels,"
        "deterministic,pareto\n";
    const auto row = [&](const AccuracyResult& r) {
        const AccuracySetting& s = r.setting;
        const std::vector<std::string> f = {
            csvField(s.name),
            csvField(s.knob),
            csvField(s.flags()),
            std::to_string(s.spp),
            jsonNumber(s.adaptiveThreshold),
            std::to_string(s.adaptiveLevels),
            std::to_string(s.maxDepth),
            jsonNumber(s.minWeight),
            precisionName(s.precision),
            s.offset == OffsetMode::Robust ? "robust" : "epsilon",
            s.offset == OffsetMode::Robust ? "" : jsonNumber(s.epsilon),
            bvhQualityName(s.quality),
            s.robust ? "1" : "0",
            jsonNumber(r.buildSeconds * 1e3),
            jsonNumber(r.renderSeconds * 1e3),
            jsonNumber(r.renderMinSeconds * 1e3),
            jsonNumber(r.renderMaxSeconds * 1e3),
            jsonNumber(r.frameSeconds() * 1e3),
            jsonNumber(r.buildCpuSeconds * 1e3),
            jsonNumber(r.renderCpuSeconds * 1e3),
            jsonNumber(r.frameCpuSeconds() * 1e3),
            std::to_string(r.rays),
            jsonNumber(mrays(r)),
            jsonNumber(r.rmse),
            std::isinf(r.psnr) ? "inf" : jsonNumber(r.psnr),
            jsonNumber(r.maxError),
            std::to_string(r.visiblePixels),
            jsonNumber(r.knobRmse),
            std::to_string(r.knobVisiblePixels),
            std::to_string(r.nonFiniteSamples),
            std::to_string(r.nonFinitePixels),
            r.deterministic ? "1" : "0",
            r.pareto ? "1" : "0",
        };
        for (size_t i = 0; i < f.size(); ++i) out += (i ? "," : "") + f[i];
        out += "\n";
    };
    row(rep.reference);
    for (const AccuracyResult& r : rep.results) row(r);
    return out;
}

std::string accuracyJson(const AccuracyReport& rep) {
    std::string j = "{\n";
    j += "  \"scene\": " + jsonString(rep.scene) + ",\n";
    j += "  \"width\": " + std::to_string(rep.width) + ",\n";
    j += "  \"height\": " + std::to_string(rep.height) + ",\n";
    j += "  \"runs\": " + std::to_string(rep.runs) + ",\n";
    j += "  \"threads\": " + std::to_string(rep.threads) + ",\n";
    j += "  \"machine\": " + jsonString(rep.machine) + ",\n";
    j += "  \"visible_levels\": " + std::to_string(rep.visibleLevels) + ",\n";
    j += "  \"reference\": {\n" + resultJson(rep.reference, "    ") + "\n  },\n";
    j += "  \"settings\": [";
    for (size_t i = 0; i < rep.results.size(); ++i) {
        j += i ? ",\n    {\n" : "\n    {\n";
        j += resultJson(rep.results[i], "      ") + "\n    }";
    }
    j += rep.results.empty() ? "]\n}\n" : "\n  ]\n}\n";
    return j;
}

PlotSpec accuracyPlot(const AccuracyReport& rep) {
    PlotSpec spec;
    spec.title = "Error vs time: " + fileName(rep.scene) + ", " + std::to_string(rep.width) + "x" +
                 std::to_string(rep.height) + ", " + std::to_string(rep.threads) + " thread" +
                 (rep.threads == 1 ? "" : "s");
    spec.x.label = "CPU time per frame (build + render, all threads), ms";
    spec.x.log = true;
    spec.y.label = "RMSE (linear RGB)";
    spec.y.log = true;
    spec.highlightLabel = "on the Pareto front";
    const PlotMarker markers[] = {PlotMarker::Circle, PlotMarker::Square, PlotMarker::Triangle,
                                  PlotMarker::Diamond, PlotMarker::Cross};
    int group = 0;
    for (const std::string& knob : accuracyKnobNames()) {
        PlotSeries s;
        s.name = knob;
        s.marker = markers[group % 5];
        s.filled = group < 5;
        s.line = false;
        for (const AccuracyResult& r : rep.results)
            if (r.setting.knob == knob)
                s.points.push_back({r.frameCpuSeconds() * 1e3, r.rmse, r.pareto});
        if (!s.points.empty()) {
            spec.series.push_back(std::move(s));
            ++group;
        }
    }
    // The front itself, joined in time order.
    std::vector<const AccuracyResult*> front;
    for (const AccuracyResult& r : rep.results)
        if (r.pareto && r.rmse > 0) front.push_back(&r);
    std::sort(front.begin(), front.end(), [](const AccuracyResult* a, const AccuracyResult* b) {
        return a->frameCpuSeconds() < b->frameCpuSeconds();
    });
    if (!front.empty()) {
        PlotSeries f;
        f.name = "Pareto front";
        f.color = "#444444";
        f.marker = PlotMarker::None;
        f.dashed = true;
        for (const AccuracyResult* r : front)
            f.points.push_back({r->frameCpuSeconds() * 1e3, r->rmse});
        spec.series.push_back(std::move(f));
    }
    return spec;
}

}  // namespace raylab

#include "tools/accuracy/accuracy_html.h"

#include <cmath>
#include <cstdio>

#include "renderer/io/png_memory.h"
#include "tools/accuracy/accuracy_report.h"
#include "tools/report/html_page.h"
#include "tools/report/svg_plot.h"

namespace raylab {

namespace {

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

std::string cell(const std::string& text, bool isText = false) {
    return std::string(isText ? "<td class=\"text\">" : "<td>") + escapeHtml(text) + "</td>";
}

std::string psnrText(double psnr) { return std::isfinite(psnr) ? format("%.2f", psnr) : "inf"; }

std::string tableRow(const AccuracyResult& r, bool reference) {
    std::string row = r.pareto ? "<tr class=\"pareto\">" : "<tr>";
    row += cell(r.setting.name, true) + cell(r.setting.knob, true);
    row += cell(format("%.2f", r.frameCpuSeconds() * 1e3)) + cell(format("%.2f", r.frameSeconds() * 1e3));
    row += cell(std::to_string(r.rays));
    row += cell(reference ? "-" : format("%.3g", r.rmse)) + cell(reference ? "-" : psnrText(r.psnr));
    row += cell(reference ? "-" : format("%.3g", r.maxError));
    row += cell(reference ? "-" : std::to_string(r.visiblePixels));
    row += cell(reference ? "-" : format("%.3g", r.knobRmse));
    row += cell(std::to_string(r.nonFiniteSamples + r.nonFinitePixels));
    row += cell(r.pareto ? "yes" : "", true) + cell(r.setting.flags(), true);
    return row + "</tr>\n";
}

}  // namespace

std::string accuracyHtml(const AccuracyReport& rep) {
    std::string body;
    body += "<p>Scene <code>" + escapeHtml(rep.scene) + "</code>, " + std::to_string(rep.width) +
            "x" + std::to_string(rep.height) + ", " + std::to_string(rep.threads) +
            " threads, median of " + std::to_string(rep.runs) + " runs; " +
            escapeHtml(rep.machine) + ". Reference: " + escapeHtml(rep.reference.setting.name) +
            " (<code>" + escapeHtml(rep.reference.setting.flags()) + "</code>).</p>\n";

    // The plot, inline: its markers are what the page's self-check counts.
    const PlotSpec plot = accuracyPlot(rep);
    int expected = 0;
    for (const PlotSeries& s : plot.series)
        if (s.marker != PlotMarker::None)
            for (const PlotPoint& p : s.points)
                expected += std::isfinite(p.x) && p.x > 0 && std::isfinite(p.y) && p.y > 0;
    body += "<h2>Error against time</h2>\n<div class=\"plot\" data-expected-points=\"" +
            std::to_string(expected) + "\">\n" + renderSvgPlot(plot) + "</div>\n";
    body += "<p>Settings with an RMSE of 0 (identical to the reference) cannot be shown on the "
            "log axis. Ringed points, and yellow rows below, are on the Pareto front: no other "
            "setting is both faster (CPU time) and closer.</p>\n";

    body += "<h2>Table</h2>\n<table>\n<tr><th>setting</th><th>knob</th><th>CPU ms/frame</th>"
            "<th>wall ms/frame</th><th>rays</th><th>RMSE</th><th>PSNR dB</th><th>max error</th>"
            "<th>visible px</th><th>knob RMSE</th><th>NaN/Inf</th><th>Pareto</th>"
            "<th>flags</th></tr>\n";
    body += tableRow(rep.reference, true);
    for (const AccuracyResult& r : rep.results) body += tableRow(r, false);
    body += "</table>\n";

    // Images: the reference first, then every setting, then the error maps.
    std::vector<ViewerImage> images;
    const bool haveImages = rep.reference.film.width > 0;
    if (haveImages) {
        images.push_back({rep.reference.setting.name, "images", "reference",
                          toneMappedImage(rep.reference.film)});
        for (const AccuracyResult& r : rep.results)
            if (r.film.width > 0)
                images.push_back({r.setting.name, "images",
                                  "RMSE " + format("%.3g", r.rmse) + ", " +
                                      format("%.1f", r.frameCpuSeconds() * 1e3) + " ms",
                                  toneMappedImage(r.film)});
        for (const AccuracyResult& r : rep.results)
            if (r.film.width > 0)
                images.push_back({r.setting.name, "error maps",
                                  std::to_string(r.visiblePixels) + " pixels visibly off",
                                  errorMap(r.film, rep.reference.film)});
        body += "<h2>Images</h2>\n<p>Error maps: the largest linear-RGB channel difference to "
                "the reference, per pixel, black where identical; <img class=\"legend-bar\" "
                "alt=\"colour scale\" src=\"" + pngDataUri(errorMapLegend(256, 12)) +
                "\"> from 1e-4 (left) to 1 or more (right), logarithmic.</p>\n";
        body += comparisonViewer(images);
    }
    return htmlDocument("raylab accuracy: " + rep.scene, body);
}

}  // namespace raylab

// The hand-written SVG plot: well-formed XML, every series present, points
// where the axis mapping puts them, decade ticks on log axes.

#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "tools/report/svg_plot.h"

using namespace raylab;

namespace {

/// Minimal XML well-formedness check for the subset the writer emits: every
/// element closed in order, text and attribute values free of raw '<' and of
/// '&' outside the four entities, a single <svg> root.
bool wellFormed(const std::string& xml, std::string& why) {
    std::vector<std::string> open;
    size_t i = 0;
    bool sawRoot = false;
    const auto entityOk = [&](size_t at) {
        for (const char* e : {"&amp;", "&lt;", "&gt;", "&quot;"})
            if (xml.compare(at, std::string(e).size(), e) == 0) return true;
        return false;
    };
    while (i < xml.size()) {
        if (xml[i] == '&' && !entityOk(i)) {
            why = "raw & at " + std::to_string(i);
            return false;
        }
        if (xml[i] != '<') {
            ++i;
            continue;
        }
        // Find the end of the tag, skipping quoted attribute values.
        size_t j = i + 1;
        bool quoted = false;
        for (; j < xml.size(); ++j) {
            if (xml[j] == '"') quoted = !quoted;
            else if (quoted && xml[j] == '<') {
                why = "raw < in an attribute at " + std::to_string(j);
                return false;
            } else if (quoted && xml[j] == '&' && !entityOk(j)) {
                why = "raw & in an attribute at " + std::to_string(j);
                return false;
            } else if (!quoted && xml[j] == '>') break;
        }
        if (j >= xml.size()) {
            why = "unterminated tag";
            return false;
        }
        std::string tag = xml.substr(i + 1, j - i - 1);
        if (tag.empty()) {
            why = "empty tag";
            return false;
        }
        if (tag[0] == '/') {
            const std::string name = tag.substr(1);
            if (open.empty() || open.back() != name) {
                why = "mismatched </" + name + ">";
                return false;
            }
            open.pop_back();
        } else {
            const bool selfClosing = tag.back() == '/';
            const std::string name = tag.substr(0, tag.find_first_of(" /\n"));
            if (open.empty()) {
                if (sawRoot || name != "svg") {
                    why = "root is not a single <svg>";
                    return false;
                }
                sawRoot = true;
            }
            if (!selfClosing) open.push_back(name);
        }
        i = j + 1;
    }
    if (!open.empty()) {
        why = "unclosed <" + open.back() + ">";
        return false;
    }
    return sawRoot;
}

size_t countOf(const std::string& s, const std::string& what) {
    size_t n = 0;
    for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
}

PlotSpec logLogSpec() {
    PlotSpec spec;
    spec.title = "time per ray";
    spec.x = {"primitives", true};
    spec.y = {"ns per ray", true};
    PlotSeries a;
    a.name = "Embree";
    a.points = {{1, 10}, {10, 100}, {100, 1000}};
    PlotSeries b;
    b.name = "naive";
    b.marker = PlotMarker::Square;
    b.filled = false;
    b.dashed = true;
    b.points = {{1, 20}, {10, 200, true}};
    spec.series = {a, b};
    spec.highlightLabel = "sampled";
    return spec;
}

}  // namespace

TEST_CASE("svg plot: well-formed document with every series and the legend") {
    const std::string svg = renderSvgPlot(logLogSpec());
    CHECK(svg.rfind("<svg", 0) == 0);
    CHECK(svg.size() >= 7);
    CHECK(svg.substr(svg.size() - 7) == "</svg>\n");
    std::string why;
    CHECK_MESSAGE(wellFormed(svg, why), why);
    CHECK(countOf(svg, "<g class=\"series\"") == 2);
    CHECK(svg.find("data-name=\"Embree\"") != std::string::npos);
    CHECK(svg.find("data-name=\"naive\"") != std::string::npos);
    CHECK(svg.find(">time per ray</text>") != std::string::npos);
    CHECK(svg.find(">primitives</text>") != std::string::npos);
    CHECK(svg.find(">ns per ray</text>") != std::string::npos);
    CHECK(svg.find("stroke-dasharray") != std::string::npos);  // the dashed series
    CHECK(svg.find(">sampled</text>") != std::string::npos);   // highlight legend entry
}

TEST_CASE("svg plot: log-log points land where the decade mapping puts them") {
    // 800x520 with a title: frame x from 78 to 800-210 = 590, y from
    // 520-58 = 462 (bottom) to 46 (top). x spans decades 10^0..10^2 (the data
    // 1..100), y spans 10^1..10^3. So (10, 100) is at x = 78 + 512/2 = 334 and
    // y = 462 - 416/2 = 254; (1, 10) at the bottom-left corner, (100, 1000) at
    // the top-right.
    const std::string svg = renderSvgPlot(logLogSpec());
    CHECK(svg.find("<circle cx=\"334.00\" cy=\"254.00\"") != std::string::npos);
    CHECK(svg.find("<circle cx=\"78.00\" cy=\"462.00\"") != std::string::npos);
    CHECK(svg.find("<circle cx=\"590.00\" cy=\"46.00\"") != std::string::npos);
    // Decade labels 10^0, 10^1, 10^2 on x and 10^1..10^3 on y.
    for (int k = 0; k <= 3; ++k)
        CHECK(svg.find("10<tspan dy=\"-6\" font-size=\"10\">" + std::to_string(k) + "</tspan>") !=
              std::string::npos);
    // The highlighted point (10, 200) gets a ring: y = 462 - 416·(log10(200) - 1)/2.
    CHECK(countOf(svg, "r=\"8\"") == 2);  // ring on the point + its legend sample
}

TEST_CASE("svg plot: points a log axis cannot show are skipped, names are escaped") {
    PlotSpec spec;
    spec.x = {"x", true};
    spec.y = {"y", true};
    PlotSeries s;
    s.name = "a<b & \"c\"";
    s.marker = PlotMarker::Square;
    s.points = {{1, 1}, {10, 0}, {100, -5}, {1000, 10}};
    spec.series = {s};
    const std::string svg = renderSvgPlot(spec);
    std::string why;
    CHECK_MESSAGE(wellFormed(svg, why), why);
    CHECK(svg.find("a&lt;b &amp; &quot;c&quot;") != std::string::npos);
    // Rects: background, frame, clip path, then two plottable points and the
    // legend sample (square markers).
    CHECK(countOf(svg, "<rect x=") == 6);
    // The line breaks at the skipped points: two separate "M" moves.
    const size_t path = svg.find("<path d=\"M");
    REQUIRE(path != std::string::npos);
    const std::string d = svg.substr(path, svg.find('"', path + 9) - path);
    CHECK(countOf(d, "M") == 2);
    CHECK(countOf(d, "L") == 0);
}

TEST_CASE("svg plot: linear axes get 1-2-5 ticks") {
    PlotSpec spec;
    spec.x = {"error", false};
    spec.y = {"seconds", false};
    PlotSeries s;
    s.name = "runs";
    s.line = false;
    s.points = {{0, 0}, {0.5, 0.3}, {1, 1}};
    spec.series = {s};
    const std::string svg = renderSvgPlot(spec);
    std::string why;
    CHECK_MESSAGE(wellFormed(svg, why), why);
    // Range 0..1 in five steps of 0.2.
    for (const char* label : {">0<", ">0.2<", ">0.4<", ">0.6<", ">0.8<", ">1<"})
        CHECK(svg.find(label) != std::string::npos);
    CHECK(svg.find("<path") == std::string::npos);  // markers only
}

TEST_CASE("svg plot: invalid specifications are rejected") {
    PlotSpec spec = logLogSpec();
    spec.width = 0;
    CHECK_THROWS_AS(renderSvgPlot(spec), std::invalid_argument);
    spec = logLogSpec();
    spec.x.min = 5;
    spec.x.max = 1;
    CHECK_THROWS_AS(renderSvgPlot(spec), std::invalid_argument);
    spec = logLogSpec();
    spec.y.min = 0;  // log axis
    spec.y.max = 10;
    CHECK_THROWS_AS(renderSvgPlot(spec), std::invalid_argument);
    // An empty plot is still a valid document.
    PlotSpec empty;
    std::string why;
    CHECK_MESSAGE(wellFormed(renderSvgPlot(empty), why), why);
}

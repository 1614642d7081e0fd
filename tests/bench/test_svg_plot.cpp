// The hand-written SVG plot: well-formed XML, every series present, points
// where the axis mapping puts them, decade ticks on log axes.

#include <doctest/doctest.h>

#include <png.h>

#include <cstdlib>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/run_command.h"
#include "support/temp_dir.h"
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
    // Decade labels 10^0, 10^1, 10^2 on x and 10^1..10^3 on y: "10" and the
    // exponent as two texts (no <tspan dy>, which ImageMagick misplaces).
    CHECK(countOf(svg, ">10</text>") == 3 + 3);
    for (int k = 0; k <= 3; ++k)
        CHECK(svg.find("font-size=\"10\" stroke=\"none\">" + std::to_string(k) + "</text>") !=
              std::string::npos);
    CHECK(svg.find("tspan") == std::string::npos);
    CHECK(svg.find("clip-path") == std::string::npos);
    CHECK(countOf(svg, "class=\"point\"") == 5);  // data markers, not legend samples
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
    s.points = {{1, 1}, {2, 2}, {10, 0}, {100, -5}, {1000, 10}, {2000, 20}};
    spec.series = {s};
    const std::string svg = renderSvgPlot(spec);
    std::string why;
    CHECK_MESSAGE(wellFormed(svg, why), why);
    CHECK(svg.find("a&lt;b &amp; &quot;c&quot;") != std::string::npos);
    // Rects: background, frame, then four plottable points and the legend
    // sample (square markers).
    CHECK(countOf(svg, "<rect x=") == 7);
    // The line breaks at the skipped points: two separate "M" moves.
    const size_t path = svg.find("<path d=\"M");
    REQUIRE(path != std::string::npos);
    const std::string d = svg.substr(path, svg.find('"', path + 9) - path);
    CHECK(countOf(d, "M") == 2);
    CHECK(countOf(d, "L") == 2);
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

TEST_CASE("svg plot: data outside an explicit axis range is cut at the frame by hand") {
    // Linear 0..10 on both axes, frame x 78..590, y 462 (0) .. 46 (10) with a
    // title. The segment (5,5)-(15,5) leaves through x = 10 (pixel 590) at
    // y = 5 (pixel 254); the point (15, 5) is not drawn.
    PlotSpec spec;
    spec.title = "t";
    spec.x = {"x", false, 0, 10};
    spec.y = {"y", false, 0, 10};
    PlotSeries s;
    s.name = "s";
    s.points = {{5, 5}, {15, 5}, {15, 15}, {5, 8}};
    spec.series = {s};
    const std::string svg = renderSvgPlot(spec);
    std::string why;
    CHECK_MESSAGE(wellFormed(svg, why), why);
    CHECK(countOf(svg, "class=\"point\"") == 2);  // (5,5) and (5,8)
    const size_t path = svg.find("<path d=\"M");
    REQUIRE(path != std::string::npos);
    const std::string d = svg.substr(path + 9, svg.find('"', path + 9) - path - 9);
    // (5,5) = (334, 254) to the frame edge (590, 254); then (15,15)-(5,8)
    // enters at x = 10: t = 0.5, y = 11.5 is still above the top (y = 10), so
    // it enters through y = 10 at x = 15 - 10·(5/7) = 7.857 (pixel 480.29).
    CHECK(d == "M334.00 254.00L590.00 254.00M480.29 46.00L334.00 129.20");
}

namespace {

/// Whether `tool` can be run (found on PATH).
bool haveTool(const std::string& tool) {
    return std::system(("command -v " + tool + " >/dev/null 2>&1").c_str()) == 0;
}

struct Raster {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
    int count(int x0, int y0, int x1, int y1, const std::function<bool(const unsigned char*)>& f) const {
        int n = 0;
        for (int y = std::max(0, y0); y < std::min(height, y1); ++y)
            for (int x = std::max(0, x0); x < std::min(width, x1); ++x)
                n += f(&rgb[(size_t(y) * width + x) * 3]);
        return n;
    }
};

/// Rasterises `svg` with `command` (FILE.svg and OUT.png substituted) and reads the PNG back.
bool rasterise(const std::string& svg, const std::string& command, Raster& out, std::string& why) {
    const raylab::test::TempDir dir;
    const std::string in = dir.write("plot.svg", svg), png = dir.file("plot.png");
    std::string cmd = command;
    cmd.replace(cmd.find("IN"), 2, in);
    cmd.replace(cmd.find("OUT"), 3, png);
    const raylab::test::CommandResult r = raylab::test::runCommand(cmd);
    if (r.exitCode != 0) {
        why = cmd + ": exit " + std::to_string(r.exitCode) + ": " + r.err;
        return false;
    }
    if (!r.err.empty()) {  // ImageMagick reports a drawing it gave up on, then exits 0
        why = cmd + ": " + r.err;
        return false;
    }
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, png.c_str())) {
        why = "unreadable PNG from " + cmd;
        return false;
    }
    image.format = PNG_FORMAT_RGB;
    out.rgb.resize(PNG_IMAGE_SIZE(image));
    out.width = int(image.width);
    out.height = int(image.height);
    return png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr) != 0;
}

}  // namespace

TEST_CASE("svg plot: librsvg and ImageMagick draw the data, the axes and the labels") {
    // One red series of five points inside a log-log frame.
    PlotSpec spec;
    spec.title = "raster check";
    spec.x = {"primitives", true};
    spec.y = {"ns per ray", true};
    PlotSeries s;
    s.name = "data";
    s.color = "#d62728";
    s.points = {{1, 10}, {3, 30}, {10, 100}, {30, 300}, {100, 1000}};
    spec.series = {s};
    const std::string svg = renderSvgPlot(spec);

    std::vector<std::pair<std::string, std::string>> tools;  // name, command
    if (haveTool("rsvg-convert")) tools.push_back({"librsvg", "rsvg-convert -o OUT IN"});
    if (haveTool("convert")) {
        tools.push_back({"ImageMagick", "convert IN OUT"});
        // Its own renderer, when installed (else it hands SVG to rsvg-convert).
        if (raylab::test::runCommand("convert -list format").out.find("MSVG") != std::string::npos)
            tools.push_back({"ImageMagick MSVG", "convert MSVG:IN OUT"});
    }
    if (tools.empty()) {
        MESSAGE("raylab-test-skipped: neither rsvg-convert nor convert is installed "
                "(scripts/install-deps.sh --optional)");
        return;
    }
    for (const auto& entry : tools) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& name = entry.first;
        const auto& command = entry.second;
        CAPTURE(name);
        Raster r;
        std::string why;
        REQUIRE_MESSAGE(rasterise(svg, command, r, why), why);
        CHECK(r.width == 800);
        CHECK(r.height == 520);
        const auto red = [](const unsigned char* p) { return p[0] > 150 && p[1] < 90 && p[2] < 90; };
        const auto dark = [](const unsigned char* p) { return p[0] < 100 && p[1] < 100 && p[2] < 100; };
        // Markers and line inside the frame (x 78..590, y 46..462).
        CHECK(r.count(78, 46, 591, 463, red) > 200);
        // Nothing red outside it but the legend sample (right of x = 590).
        CHECK(r.count(0, 0, 70, 520, red) == 0);
        // Tick labels left of the frame and below it; the title above.
        CHECK(r.count(0, 40, 70, 470, dark) > 100);
        CHECK(r.count(70, 470, 600, 500, dark) > 100);
        CHECK(r.count(100, 0, 600, 40, dark) > 100);
    }
}

#include "tools/report/html_page.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"

namespace raylab {

namespace {

/// A perceptually ordered ramp (dark blue → purple → orange → yellow-white,
/// after "inferno"), linearly interpolated between these stops.
std::array<uint8_t, 3> ramp(double t) {
    static const double stops[][3] = {{0, 0, 4},      {40, 11, 84},    {101, 21, 110},
                                      {159, 42, 99},  {212, 72, 66},   {245, 125, 21},
                                      {250, 193, 39}, {252, 255, 164}};
    constexpr int n = 8;
    t = std::clamp(t, 0.0, 1.0) * (n - 1);
    const int i = std::min(int(t), n - 2);
    const double f = t - i;
    std::array<uint8_t, 3> c{};
    for (int k = 0; k < 3; ++k)
        c[k] = uint8_t(std::lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k])));
    return c;
}

/// Where an error lands on the ramp: log10 from -4 (0) to 0 (1).
double rampPosition(double error) { return (std::log10(std::max(error, 1e-4)) + 4.0) / 4.0; }

const char* const kStyle = R"css(
body { font-family: Helvetica, Arial, sans-serif; margin: 1.5em; color: #222; max-width: 1400px; }
h1 { font-size: 1.4em; } h2 { font-size: 1.15em; margin-top: 1.6em; }
table { border-collapse: collapse; font-size: 0.85em; }
th, td { border: 1px solid #ccc; padding: 2px 6px; text-align: right; white-space: nowrap; }
th { background: #f0f0f0; } td.text { text-align: left; }
tr.pareto td { background: #fff6d5; }
.viewer .controls { margin: 0.5em 0; display: flex; gap: 1em; flex-wrap: wrap; align-items: center; }
.viewer .panes { display: flex; gap: 8px; }
.viewer .pane { position: relative; overflow: auto; border: 1px solid #aaa; background: #333;
                width: 48%; height: 420px; }
.viewer.wipe .pane.right { display: none; }
.viewer.wipe .pane.left { width: 97%; }
.viewer img { image-rendering: pixelated; image-rendering: crisp-edges; display: block; }
.viewer .wipe-top { position: absolute; left: 0; top: 0; }
.viewer .label { color: #555; font-size: 0.85em; }
.gallery { display: flex; flex-wrap: wrap; gap: 10px; }
.gallery figure { margin: 0; font-size: 0.75em; text-align: center; cursor: pointer; max-width: 180px; }
.gallery img { border: 2px solid transparent; image-rendering: pixelated; max-width: 176px; }
.gallery img.selected-left { border-color: #1f77b4; } .gallery img.selected-right { border-color: #d62728; }
.legend-bar { vertical-align: middle; }
)css";

// The viewer: menus and gallery clicks pick the images (click: right pane,
// shift-click: left pane), the zoom scales both, the panes scroll together.
const char* const kViewerScript = R"js(
function raylabViewer(root) {
  const thumbs = Array.from(document.querySelectorAll('.gallery img'));
  const left = root.querySelector('select.left'), right = root.querySelector('select.right');
  const zoom = root.querySelector('input.zoom'), zoomText = root.querySelector('.zoom-text');
  const mode = root.querySelector('select.mode'), wipe = root.querySelector('input.wipe');
  const paneL = root.querySelector('.pane.left'), paneR = root.querySelector('.pane.right');
  const imgL = paneL.querySelector('img.base'), imgTop = paneL.querySelector('img.wipe-top');
  const imgR = paneR.querySelector('img.base');
  function show() {
    const a = thumbs[left.value], b = thumbs[right.value], z = Number(zoom.value);
    imgL.src = a.src; imgR.src = b.src; imgTop.src = b.src;
    for (const img of [imgL, imgR, imgTop]) img.style.width = (a.naturalWidth || a.width) * z + 'px';
    zoomText.textContent = z + 'x';
    const wiping = mode.value === 'wipe';
    root.classList.toggle('wipe', wiping);
    imgTop.style.display = wiping ? 'block' : 'none';
    imgTop.style.clipPath = 'inset(0 0 0 ' + wipe.value + '%)';
    thumbs.forEach((t, i) => {
      t.classList.toggle('selected-left', String(i) === left.value);
      t.classList.toggle('selected-right', String(i) === right.value);
    });
  }
  // Start with the first image as large as a pane shows it whole.
  const w0 = thumbs.length ? (thumbs[0].naturalWidth || thumbs[0].width) : 0;
  const h0 = thumbs.length ? (thumbs[0].naturalHeight || thumbs[0].height) : 0;
  if (w0 > 0 && h0 > 0)
    zoom.value = String(Math.max(1, Math.min(16, Math.floor(Math.min(paneL.clientWidth / w0,
                                                                      paneL.clientHeight / h0)))));
  for (const c of [left, right, zoom, mode, wipe]) c.addEventListener('input', show);
  thumbs.forEach((t, i) => t.addEventListener('click', (e) => {
    (e.shiftKey ? left : right).value = String(i); show();
  }));
  let syncing = false;
  for (const [from, to] of [[paneL, paneR], [paneR, paneL]])
    from.addEventListener('scroll', () => {
      if (syncing) { syncing = false; return; }
      syncing = true; to.scrollLeft = from.scrollLeft; to.scrollTop = from.scrollTop;
    });
  show();
}
)js";

// The self-check the browser test reads: every image decoded, plot markers drawn.
const char* const kCheckScript = R"js(
window.addEventListener('load', () => {
  // The images of the page itself (the viewer's panes get theirs below).
  const images = Array.from(document.images).filter((img) => img.getAttribute('src'));
  const decoded = images.filter((img) => img.complete && img.naturalWidth > 0 && img.naturalHeight > 0);
  document.body.setAttribute('data-images', decoded.length + '/' + images.length);
  let points = 0;
  for (const m of document.querySelectorAll('svg .series .point')) {
    const box = m.getBBox();
    if (box.width > 0 && box.height > 0) points++;
  }
  document.body.setAttribute('data-plot-points', String(points));
  const viewer = document.querySelector('.viewer');
  if (viewer) raylabViewer(viewer);
});
)js";

}  // namespace

std::string escapeHtml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&#39;"; break;
            default: out += c;
        }
    }
    return out;
}

std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* const alphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t b0 = bytes[i];
        const uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0;
        const uint32_t b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const uint32_t v = (b0 << 16) | (b1 << 8) | b2;
        out += alphabet[(v >> 18) & 63];
        out += alphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? alphabet[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[v & 63] : '=';
    }
    return out;
}

std::string pngDataUri(const Rgb8Image& image) {
    return "data:image/png;base64," + base64(encodePng(image));
}

Rgb8Image errorMap(const Film& image, const Film& reference) {
    if (image.width != reference.width || image.height != reference.height ||
        image.rgba.size() != reference.rgba.size())
        throw std::invalid_argument("error map: images of different sizes");
    Rgb8Image out;
    out.width = image.width;
    out.height = image.height;
    const size_t n = size_t(image.width) * size_t(image.height);
    out.pixels.assign(n * 3, 0);
    for (size_t i = 0; i < n; ++i) {
        double e = 0;
        for (int c = 0; c < 3; ++c)
            e = std::max(e, std::abs(double(image.rgba[4 * i + c]) - double(reference.rgba[4 * i + c])));
        if (!(e > 0)) continue;  // identical (or NaN, which stays black too)
        const std::array<uint8_t, 3> rgb = ramp(rampPosition(e));
        std::copy(rgb.begin(), rgb.end(), out.pixels.begin() + long(3 * i));
    }
    return out;
}

Rgb8Image errorMapLegend(int width, int height) {
    Rgb8Image out;
    out.width = width;
    out.height = height;
    out.pixels.resize(size_t(width) * size_t(height) * 3);
    for (int x = 0; x < width; ++x) {
        const std::array<uint8_t, 3> rgb = ramp(width > 1 ? double(x) / (width - 1) : 0);
        for (int y = 0; y < height; ++y)
            std::copy(rgb.begin(), rgb.end(), out.pixels.begin() + long(3 * (size_t(y) * width + x)));
    }
    return out;
}

std::string comparisonViewer(const std::vector<ViewerImage>& images) {
    std::string options;
    for (size_t i = 0; i < images.size(); ++i)
        options += "<option value=\"" + std::to_string(i) + "\">" +
                   escapeHtml(images[i].group + ": " + images[i].label) + "</option>";
    const auto select = [&](const char* cls, size_t chosen) {
        std::string s = "<select class=\"" + std::string(cls) + "\">" + options + "</select>";
        const std::string mark = "value=\"" + std::to_string(chosen) + "\"";
        const size_t at = s.find(mark);
        if (at != std::string::npos) s.insert(at + mark.size(), " selected");
        return s;
    };
    std::string html;
    html += "<div class=\"viewer\">\n<div class=\"controls\">";
    html += "<label>left " + select("left", 0) + "</label>";
    html += "<label>right " + select("right", images.size() > 1 ? 1 : 0) + "</label>";
    html += "<label>zoom <input class=\"zoom\" type=\"range\" min=\"1\" max=\"16\" value=\"2\"> "
            "<span class=\"zoom-text\">2x</span></label>";
    html += "<label>view <select class=\"mode\"><option value=\"side\">side by side</option>"
            "<option value=\"wipe\">wipe (right over left)</option></select></label>";
    html += "<label>wipe <input class=\"wipe\" type=\"range\" min=\"0\" max=\"100\" value=\"50\"></label>";
    html += "</div>\n<div class=\"panes\"><div class=\"pane left\"><img class=\"base\" alt=\"left\">"
            "<img class=\"wipe-top\" alt=\"right over left\" style=\"display:none\"></div>"
            "<div class=\"pane right\"><img class=\"base\" alt=\"right\"></div></div>\n";
    html += "<p class=\"label\">Click a thumbnail to show it on the right, shift-click for the "
            "left; the panes scroll together.</p>\n</div>\n";
    // The gallery, by group in order of first appearance.
    std::vector<std::string> groups;
    for (const ViewerImage& v : images)
        if (std::find(groups.begin(), groups.end(), v.group) == groups.end()) groups.push_back(v.group);
    for (const std::string& g : groups) {
        html += "<h3>" + escapeHtml(g) + "</h3>\n<div class=\"gallery\">\n";
        for (size_t i = 0; i < images.size(); ++i) {
            const ViewerImage& v = images[i];
            if (v.group != g) continue;
            html += "<figure><img data-index=\"" + std::to_string(i) + "\" alt=\"" +
                    escapeHtml(v.label) + "\" width=\"" + std::to_string(v.image.width) +
                    "\" height=\"" + std::to_string(v.image.height) + "\" src=\"" +
                    pngDataUri(v.image) + "\"><figcaption>" + escapeHtml(v.label) +
                    (v.caption.empty() ? "" : "<br>" + escapeHtml(v.caption)) +
                    "</figcaption></figure>\n";
        }
        html += "</div>\n";
    }
    return html;
}

std::string htmlDocument(const std::string& title, const std::string& body) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
           escapeHtml(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<h1>" +
           escapeHtml(title) + "</h1>\n" + body + "<script>" + kViewerScript + kCheckScript +
           "</script>\n</body>\n</html>\n";
}

void checkReportDir(const std::string& dir, const std::string& flag) {
    std::error_code ec;
    if (dir.empty()) throw UsageError(flag + ": expected a directory name");
    if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
        throw UsageError(flag + ": '" + dir + "' exists and is not a directory");
}

std::string writeHtmlReport(const std::string& dir, const std::string& html) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(dir, 0, "cannot create the report directory: " + ec.message());
    const std::string path = (std::filesystem::path(dir) / "index.html").string();
    writeFileAtomically(path, html);
    return path;
}

}  // namespace raylab

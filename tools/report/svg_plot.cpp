#include "tools/report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "renderer/io/atomic_file.h"

namespace raylab {

namespace {

/// Tableau-10: distinguishable colours for up to ten series.
constexpr const char* kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                    "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

std::string escapeXml(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

/// Coordinates with two decimals: sub-pixel precision, compact files.
std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

bool plottable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

/// One axis mapped onto a pixel interval, in data or log10(data) space.
class AxisMap {
public:
    AxisMap(const PlotAxis& axis, const std::vector<double>& values, const char* which)
        : m_log(axis.log) {
        double lo = std::numeric_limits<double>::infinity();
        double hi = -lo;
        for (double v : values) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        if (!std::isnan(axis.min)) lo = axis.min;
        if (!std::isnan(axis.max)) hi = axis.max;
        if (!std::isnan(axis.min) || !std::isnan(axis.max)) {
            if (!(lo < hi) || (m_log && !(lo > 0)))
                throw std::invalid_argument(std::string("plot: invalid ") + which +
                                            "-axis range");
        }
        if (!std::isfinite(lo) || !std::isfinite(hi)) {  // no data at all
            lo = m_log ? 1 : 0;
            hi = m_log ? 10 : 1;
        }
        if (m_log) {
            // Whole decades, so every end of the axis carries a labelled tick.
            m_lo = std::floor(std::log10(lo));
            m_hi = std::ceil(std::log10(hi));
            if (m_hi <= m_lo) m_hi = m_lo + 1;
        } else {
            if (hi <= lo) {
                const double pad = lo == 0 ? 1 : 0.5 * std::abs(lo);
                lo -= pad;
                hi += pad;
            }
            m_step = niceStep((hi - lo) / 5.0);
            m_lo = std::floor(lo / m_step) * m_step;
            m_hi = std::ceil(hi / m_step) * m_step;
        }
    }

    void setPixels(double p0, double p1) {
        m_p0 = p0;
        m_p1 = p1;
    }

    double toPixel(double v) const {
        const double s = m_log ? std::log10(v) : v;
        return m_p0 + (s - m_lo) / (m_hi - m_lo) * (m_p1 - m_p0);
    }

    struct Tick {
        double value;
        bool major;
        std::string label;     ///< tick label ("" for none); the base "10" on a log axis
        std::string exponent;  ///< log axes: the decade's exponent, drawn raised after the label
    };

    std::vector<Tick> ticks() const {
        std::vector<Tick> out;
        if (m_log) {
            const int decades = int(m_hi - m_lo);
            // Label every decade up to 12 decades, then every other one.
            const int labelEvery = decades > 12 ? 2 : 1;
            for (int k = int(m_lo); k <= int(m_hi); ++k) {
                const bool labelled = (k - int(m_lo)) % labelEvery == 0;
                out.push_back({std::pow(10.0, k), true, labelled ? "10" : "",
                               labelled ? std::to_string(k) : ""});
                if (k == int(m_hi)) break;
                if (decades <= 8)
                    for (int m = 2; m <= 9; ++m)
                        out.push_back({m * std::pow(10.0, k), false, "", ""});
            }
        } else {
            const int n = int(std::lround((m_hi - m_lo) / m_step));
            for (int i = 0; i <= n; ++i) {
                const double v = m_lo + i * m_step;
                char buf[32];
                std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-12 * m_step ? 0.0 : v);
                out.push_back({v, true, buf, ""});
            }
        }
        return out;
    }

private:
    /// 1, 2 or 5 times a power of ten, at least `raw`.
    static double niceStep(double raw) {
        const double p = std::pow(10.0, std::floor(std::log10(raw)));
        for (double m : {1.0, 2.0, 5.0, 10.0})
            if (m * p >= raw) return m * p;
        return 10 * p;
    }

    bool m_log;
    double m_lo = 0, m_hi = 1;  ///< range in data (linear) or log10 (log) units
    double m_step = 1;          ///< linear tick spacing
    double m_p0 = 0, m_p1 = 1;  ///< pixel positions of m_lo and m_hi
};

/// SVG for one marker centred at (x, y).
std::string marker(PlotMarker m, double x, double y, const std::string& color, bool filled) {
    const std::string fill = filled ? color : "white";
    const std::string style =
        " fill=\"" + fill + "\" stroke=\"" + color + "\" stroke-width=\"1.5\"";
    const double r = 4.0;
    switch (m) {
        case PlotMarker::Circle:
            return "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"" + num(r) + "\"" +
                   style + "/>";
        case PlotMarker::Square:
            return "<rect x=\"" + num(x - r) + "\" y=\"" + num(y - r) + "\" width=\"" +
                   num(2 * r) + "\" height=\"" + num(2 * r) + "\"" + style + "/>";
        case PlotMarker::Triangle:
            return "<polygon points=\"" + num(x) + "," + num(y - 1.2 * r) + " " +
                   num(x + 1.1 * r) + "," + num(y + 0.8 * r) + " " + num(x - 1.1 * r) + "," +
                   num(y + 0.8 * r) + "\"" + style + "/>";
        case PlotMarker::Diamond:
            return "<polygon points=\"" + num(x) + "," + num(y - 1.3 * r) + " " +
                   num(x + 1.3 * r) + "," + num(y) + " " + num(x) + "," + num(y + 1.3 * r) + " " +
                   num(x - 1.3 * r) + "," + num(y) + "\"" + style + "/>";
        case PlotMarker::Cross:
            return "<path d=\"M" + num(x - r) + " " + num(y - r) + "L" + num(x + r) + " " +
                   num(y + r) + "M" + num(x - r) + " " + num(y + r) + "L" + num(x + r) + " " +
                   num(y - r) + "\" stroke=\"" + color + "\" stroke-width=\"2\"/>";
        case PlotMarker::None: return "";
    }
    return "";
}

/// A tick label at (x, y) anchored at `anchor` ("middle" or "end"). A power
/// of ten is two texts, "10" and its raised exponent, placed side by side:
/// a <tspan dy> would be simpler, but ImageMagick's renderer draws it at the
/// wrong place (the "garbled exponents" of older plots).
std::string tickLabel(const std::string& base, const std::string& exponent, double x, double y,
                      const std::string& anchor) {
    if (exponent.empty())
        return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + anchor +
               "\" stroke=\"none\">" + base + "</text>\n";
    // Widths at 12 px for the base and 10 px for the exponent (about 0.6 em
    // a digit, 0.35 em a minus sign): close enough to centre or right-align.
    double expWidth = 0;
    for (char c : exponent) expWidth += c == '-' ? 3.5 : 6.0;
    const double baseWidth = 14.0;
    const double end = anchor == "middle" ? x + 0.5 * (baseWidth + expWidth) : x;
    const double split = end - expWidth;  // where "10" ends and the exponent starts
    return "<text x=\"" + num(split) + "\" y=\"" + num(y) +
           "\" text-anchor=\"end\" stroke=\"none\">" + base + "</text>\n" + "<text x=\"" +
           num(split + 0.5) + "\" y=\"" + num(y - 6) +
           "\" text-anchor=\"start\" font-size=\"10\" stroke=\"none\">" + exponent + "</text>\n";
}

/// The plot frame, for clipping by hand: ImageMagick's renderer applies
/// clipPath wrongly (it drew empty axes), so nothing outside the frame is
/// emitted at all.
struct Frame {
    double x0, y0, x1, y1;  ///< x0 < x1, y0 < y1 (pixels)
    bool contains(double x, double y) const {
        const double e = 1e-6;
        return x >= x0 - e && x <= x1 + e && y >= y0 - e && y <= y1 + e;
    }
    /// The part of segment a-b inside the frame (Liang-Barsky); false when none.
    bool clip(double& ax, double& ay, double& bx, double& by) const {
        double t0 = 0, t1 = 1;
        const double dx = bx - ax, dy = by - ay;
        const double p[4] = {-dx, dx, -dy, dy};
        const double q[4] = {ax - x0, x1 - ax, ay - y0, y1 - ay};
        for (int i = 0; i < 4; ++i) {
            if (p[i] == 0) {
                if (q[i] < 0) return false;
                continue;
            }
            const double t = q[i] / p[i];
            if (p[i] < 0) t0 = std::max(t0, t);
            else t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
        const double nax = ax + t0 * dx, nay = ay + t0 * dy;
        bx = ax + t1 * dx;
        by = ay + t1 * dy;
        ax = nax;
        ay = nay;
        return true;
    }
};

std::string ring(double x, double y) {
    return "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) +
           "\" r=\"8\" fill=\"none\" stroke=\"#222\" stroke-width=\"1.2\"/>";
}

}  // namespace

std::string renderSvgPlot(const PlotSpec& spec) {
    if (spec.width <= 0 || spec.height <= 0)
        throw std::invalid_argument("plot: width and height must be > 0");

    std::vector<double> xs, ys;
    for (const PlotSeries& s : spec.series) {
        for (const PlotPoint& p : s.points) {
            if (!plottable(p.x, spec.x.log) || !plottable(p.y, spec.y.log)) continue;
            xs.push_back(p.x);
            ys.push_back(p.y);
        }
    }
    AxisMap xMap(spec.x, xs, "x"), yMap(spec.y, ys, "y");

    // Frame: room on the left for tick labels and the y label, on the right
    // for the legend, at the top for the title.
    const double left = 78, right = 210, top = spec.title.empty() ? 20 : 46, bottom = 58;
    const double x0 = left, x1 = std::max(left + 10, spec.width - right);
    const double y0 = std::max(top + 10, spec.height - bottom), y1 = top;  // y grows downwards
    xMap.setPixels(x0, x1);
    yMap.setPixels(y0, y1);

    std::string svg;
    svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
           std::to_string(spec.width) + "\" height=\"" + std::to_string(spec.height) +
           "\" viewBox=\"0 0 " + std::to_string(spec.width) + " " + std::to_string(spec.height) +
           "\" font-family=\"DejaVu Sans\" font-size=\"12\">\n";
    // Fonts: browsers and librsvg take the style sheet's list; ImageMagick
    // ignores <style> and, given a list or a font it lacks, draws no text at
    // all, so the attribute names one font (DejaVu, on every Debian desktop).
    svg += "<style>text { font-family: Helvetica, Arial, 'DejaVu Sans', sans-serif; }</style>\n";
    svg += "<rect x=\"0\" y=\"0\" width=\"" + std::to_string(spec.width) + "\" height=\"" +
           std::to_string(spec.height) + "\" fill=\"white\"/>\n";
    if (!spec.title.empty())
        svg += "<text class=\"title\" stroke=\"none\" x=\"" + num(0.5 * (x0 + x1)) +
               "\" y=\"26\" text-anchor=\"middle\" font-size=\"15\" font-weight=\"bold\">" +
               escapeXml(spec.title) + "</text>\n";

    // Grid and ticks.
    svg += "<g class=\"axes\" stroke=\"#000\">\n";
    for (const AxisMap::Tick& t : xMap.ticks()) {
        const double px = xMap.toPixel(t.value);
        if (t.major)
            svg += "<line x1=\"" + num(px) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(px) +
                   "\" y2=\"" + num(y1) + "\" stroke=\"#ddd\"/>\n";
        svg += "<line x1=\"" + num(px) + "\" y1=\"" + num(y0) + "\" x2=\"" + num(px) +
               "\" y2=\"" + num(y0 + (t.major ? 6 : 3)) + "\"/>\n";
        if (!t.label.empty()) svg += tickLabel(t.label, t.exponent, px, y0 + 22, "middle");
    }
    for (const AxisMap::Tick& t : yMap.ticks()) {
        const double py = yMap.toPixel(t.value);
        if (t.major)
            svg += "<line x1=\"" + num(x0) + "\" y1=\"" + num(py) + "\" x2=\"" + num(x1) +
                   "\" y2=\"" + num(py) + "\" stroke=\"#ddd\"/>\n";
        svg += "<line x1=\"" + num(x0 - (t.major ? 6 : 3)) + "\" y1=\"" + num(py) + "\" x2=\"" +
               num(x0) + "\" y2=\"" + num(py) + "\"/>\n";
        if (!t.label.empty()) svg += tickLabel(t.label, t.exponent, x0 - 9, py + 4, "end");
    }
    svg += "<rect x=\"" + num(x0) + "\" y=\"" + num(y1) + "\" width=\"" + num(x1 - x0) +
           "\" height=\"" + num(y0 - y1) + "\" fill=\"none\"/>\n";
    svg += "</g>\n";
    svg += "<text class=\"xlabel\" stroke=\"none\" x=\"" + num(0.5 * (x0 + x1)) + "\" y=\"" +
           num(spec.height - 14.0) + "\" text-anchor=\"middle\">" + escapeXml(spec.x.label) +
           "</text>\n";
    svg += "<text class=\"ylabel\" stroke=\"none\" transform=\"translate(18," + num(0.5 * (y0 + y1)) +
           ") rotate(-90)\" text-anchor=\"middle\">" + escapeXml(spec.y.label) + "</text>\n";

    // Data, clipped to the frame (explicit axis ranges may cut points off).
    const Frame frame{x0, y1, x1, y0};
    bool anyHighlight = false;
    for (size_t i = 0; i < spec.series.size(); ++i) {
        const PlotSeries& s = spec.series[i];
        const std::string color = s.color.empty() ? kPalette[i % 10] : s.color;
        svg += "<g class=\"series\" data-name=\"" + escapeXml(s.name) + "\">\n";
        if (s.line) {
            std::string d;
            bool havePrevious = false, pen = false;
            double px0 = 0, py0 = 0;
            for (const PlotPoint& p : s.points) {
                if (!plottable(p.x, spec.x.log) || !plottable(p.y, spec.y.log)) {
                    havePrevious = pen = false;  // break the line at a point that cannot be shown
                    continue;
                }
                const double px1 = xMap.toPixel(p.x), py1 = yMap.toPixel(p.y);
                if (havePrevious) {
                    double ax = px0, ay = py0, bx = px1, by = py1;
                    if (frame.clip(ax, ay, bx, by)) {
                        // A new subpath where the previous segment left the frame.
                        if (!pen || ax != px0 || ay != py0) d += "M" + num(ax) + " " + num(ay);
                        d += "L" + num(bx) + " " + num(by);
                        pen = bx == px1 && by == py1;
                    } else {
                        pen = false;
                    }
                }
                px0 = px1;
                py0 = py1;
                havePrevious = true;
            }
            if (!d.empty())
                svg += "<path d=\"" + d + "\" fill=\"none\" stroke=\"" + color +
                       "\" stroke-width=\"1.5\"" +
                       (s.dashed ? " stroke-dasharray=\"6,4\"" : "") + "/>\n";
        }
        for (const PlotPoint& p : s.points) {
            if (!plottable(p.x, spec.x.log) || !plottable(p.y, spec.y.log)) continue;
            const double px = xMap.toPixel(p.x), py = yMap.toPixel(p.y);
            if (!frame.contains(px, py)) continue;
            std::string m = marker(s.marker, px, py, color, s.filled);
            // class "point": a data marker, as opposed to a legend sample.
            if (!m.empty()) svg += m.insert(m.size() - 2, " class=\"point\"") + "\n";
            if (p.highlighted) {
                svg += ring(px, py) + "\n";
                anyHighlight = true;
            }
        }
        svg += "</g>\n";
    }

    // Legend, right of the frame.
    svg += "<g class=\"legend\">\n";
    double ly = y1 + 8;
    const double lx = x1 + 16;
    for (size_t i = 0; i < spec.series.size(); ++i) {
        const PlotSeries& s = spec.series[i];
        const std::string color = s.color.empty() ? kPalette[i % 10] : s.color;
        if (s.line)
            svg += "<line x1=\"" + num(lx) + "\" y1=\"" + num(ly) + "\" x2=\"" + num(lx + 28) +
                   "\" y2=\"" + num(ly) + "\" stroke=\"" + color + "\" stroke-width=\"1.5\"" +
                   (s.dashed ? " stroke-dasharray=\"6,4\"" : "") + "/>\n";
        const std::string m = marker(s.marker, lx + 14, ly, color, s.filled);
        if (!m.empty()) svg += m + "\n";
        svg += "<text x=\"" + num(lx + 36) + "\" y=\"" + num(ly + 4) + "\" stroke=\"none\">" +
               escapeXml(s.name) + "</text>\n";
        ly += 20;
    }
    if (anyHighlight && !spec.highlightLabel.empty()) {
        svg += ring(lx + 14, ly) + "\n";
        svg += "<text x=\"" + num(lx + 36) + "\" y=\"" + num(ly + 4) + "\" stroke=\"none\">" +
               escapeXml(spec.highlightLabel) + "</text>\n";
    }
    svg += "</g>\n";
    svg += "</svg>\n";
    return svg;
}

void writeSvgPlot(const std::string& path, const PlotSpec& spec) {
    writeFileAtomically(path, renderSvgPlot(spec));
}

}  // namespace raylab

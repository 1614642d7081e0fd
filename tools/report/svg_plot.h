#pragma once
// A dependency-free SVG scatter/line plot: series of (x, y) points on linear
// or logarithmic axes, with markers, a title, axis labels, a legend and an
// optional highlighted subset (e.g. sampled measurements, or the Pareto front
// of an error-versus-time study). Log axes get a tick at every decade
// labelled 10^k, with unlabelled minor ticks at 2..9 × 10^k.

#include <limits>
#include <string>
#include <vector>

namespace raylab {

enum class PlotMarker { Circle, Square, Triangle, Diamond, Cross, None };

struct PlotPoint {
    double x = 0;
    double y = 0;
    bool highlighted = false;  ///< drawn with a ring around its marker
};

struct PlotSeries {
    std::string name;               ///< legend entry
    std::vector<PlotPoint> points;  ///< joined in this order when `line` is set
    std::string color;              ///< CSS colour ("#1f77b4"); empty: palette colour by index
    PlotMarker marker = PlotMarker::Circle;
    bool filled = true;             ///< filled or hollow markers
    bool line = true;               ///< connect consecutive points
    bool dashed = false;            ///< dashed connecting line
};

struct PlotAxis {
    std::string label;
    bool log = false;  ///< logarithmic (base 10); values <= 0 cannot be shown and are skipped
    /// Axis range; NaN = from the data (log axes widen to whole decades).
    double min = std::numeric_limits<double>::quiet_NaN();
    double max = std::numeric_limits<double>::quiet_NaN();
};

struct PlotSpec {
    std::string title;
    PlotAxis x, y;
    std::vector<PlotSeries> series;
    /// Legend text of the ring drawn around highlighted points; empty: no entry.
    std::string highlightLabel;
    int width = 800;   ///< pixels
    int height = 520;  ///< pixels
};

/// \brief The plot as a standalone SVG 1.1 document ("<svg ...>...</svg>\n").
/// \details Points with a non-finite coordinate, or a coordinate <= 0 on a log
///   axis, are skipped (a line is broken there). Text is XML-escaped. Every
///   series is one <g class="series" data-name="..."> group, so tests and
///   scripts can find it.
/// \throws std::invalid_argument for a non-positive size or an axis range
///   with min >= max (or min <= 0 on a log axis).
std::string renderSvgPlot(const PlotSpec& spec);

/// Data markers carry class="point" (legend samples do not).
/// Writes renderSvgPlot(spec) to `path` atomically; throws InputError on failure.
void writeSvgPlot(const std::string& path, const PlotSpec& spec);

}  // namespace raylab

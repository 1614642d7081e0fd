#pragma once
// Output of the accuracy sweep: a plain-text table for the terminal, CSV and
// JSON for scripts, and an SVG plot of error against time with the Pareto
// front marked.

#include <string>

#include "tools/accuracy/accuracy_sweep.h"
#include "tools/report/svg_plot.h"

namespace raylab {

/// The fixed-width table printed by `raylab accuracy` (header lines included).
std::string accuracyTable(const AccuracyReport& report);

/// One CSV row per setting, reference first; a header row names the columns.
std::string accuracyCsv(const AccuracyReport& report);

/// The whole report as one JSON document (scene, machine, reference, settings).
std::string accuracyJson(const AccuracyReport& report);

/// \brief The error-vs-time plot: RMSE against the reference (log y) over the
///   CPU time of a frame (build + render, all threads; log x), one series per
///   knob group, Pareto front highlighted and joined by a dashed line.
PlotSpec accuracyPlot(const AccuracyReport& report);

}  // namespace raylab

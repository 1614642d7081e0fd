#pragma once
// The accuracy study as a page to look at (raylab accuracy --html DIR).

#include <string>

#include "tools/accuracy/accuracy_sweep.h"

namespace raylab {

/// \brief DIR/index.html of a sweep run with keepImages: the reference, every
///   setting's image and its false-colour error map against the reference in
///   the comparison viewer, the error-vs-time plot with the Pareto front, and
///   the table (Pareto rows marked). Self-contained (html_page.h).
std::string accuracyHtml(const AccuracyReport& report);

}  // namespace raylab

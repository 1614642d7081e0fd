#pragma once
// Self-contained HTML report pages (raylab accuracy --html, raylab bench
// accel --html): one index.html with every image embedded as a data: URI,
// the plot as inline SVG, the table, and a comparison viewer (two images
// side by side or wiped one over the other, zoomed with nearest-neighbour
// pixels, the panes scrolling together) the way rendering papers publish
// comparisons. No script or style is loaded from anywhere else.
//
// On load the page checks itself and records the outcome on <body>:
// data-images="decoded/total" (every <img> decoded to a non-empty image) and
// data-plot-points="N" (markers drawn in the plot): the headless-browser test
// reads them back.

#include <string>
#include <vector>

#include "renderer/film.h"
#include "renderer/io/png_memory.h"

namespace raylab {

/// Text safe inside HTML elements and attribute values.
std::string escapeHtml(const std::string& text);

/// RFC 4648 base64 of `bytes`.
std::string base64(const std::vector<unsigned char>& bytes);

/// "data:image/png;base64,..." of the image.
std::string pngDataUri(const Rgb8Image& image);

/// \brief A false-colour map of how far `image` is from `reference`: the
///   largest linear-RGB channel difference of each pixel on a log scale from
///   1e-4 (dark blue) to 1 (yellow-white); identical pixels are black.
/// \throws std::invalid_argument when the sizes differ.
Rgb8Image errorMap(const Film& image, const Film& reference);

/// The colour bar of errorMap, `width` × `height` pixels, 1e-4 on the left.
Rgb8Image errorMapLegend(int width, int height);

/// One image the viewer can show.
struct ViewerImage {
    std::string label;   ///< shown in the menus and under the thumbnail
    std::string group;   ///< "image", "error map", ...: thumbnails are grouped by it
    std::string caption;  ///< a line under the thumbnail (may be empty)
    Rgb8Image image;
};

/// \brief The comparison viewer and a thumbnail gallery of `images`: two
///   menus choose the left and right image (initially the first two),
///   a zoom slider magnifies both by integer factors with visible pixels, a
///   mode switch puts them side by side or wipes one over the other.
std::string comparisonViewer(const std::vector<ViewerImage>& images);

/// \brief A complete page: `title` as <title> and heading, `body` (HTML) below,
///   the page's style and the scripts of the viewer and the self-check.
std::string htmlDocument(const std::string& title, const std::string& body);

/// Refuses (UsageError naming `flag`) a report directory that cannot be
/// one: an existing file that is not a directory. Checked before long runs.
void checkReportDir(const std::string& dir, const std::string& flag);

/// Writes `html` to DIR/index.html atomically, creating DIR when missing;
/// returns the path. Throws InputError on failure.
std::string writeHtmlReport(const std::string& dir, const std::string& html);

}  // namespace raylab

// raylab accuracy: what accuracy costs in time (tools/accuracy/ does the work).

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "apps/arg_parser.h"
#include "apps/commands.h"
#include "apps/progress_bar.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"
#include "tools/accuracy/accuracy_html.h"
#include "tools/accuracy/accuracy_report.h"
#include "tools/accuracy/accuracy_sweep.h"
#include "tools/report/html_page.h"
#include "tools/report/svg_plot.h"
#include "tools/report/table_format.h"

namespace raylab {

namespace {

const char* const kAccuracyHelp =
    "usage: raylab accuracy SCENE [options]\n"
    "\n"
    "What accuracy costs in time. Renders a reference of SCENE (64 stratified jittered samples\n"
    "per pixel, depth 12, double-precision intersectors, robust Embree traversal, robust\n"
    "self-intersection offset, point-sampled textures), then sweeps each accuracy knob alone from the renderer's\n"
    "defaults (1 spp, depth 5, double, robust offset, medium BVH), plus a few combinations:\n"
    "  spp         4, 16 samples per pixel\n"
    "  adaptive    Whitted adaptive supersampling, thresholds 0.1, 0.03, 0.01 (2 levels; 0.01 with "
    "3)\n"
    "  depth       ray-tree depth 1, 2, 3, 4, 6, 8, 12\n"
    "  min-weight  Hall-Greenberg pruning 0.01, 0.05, 0.1, 0.3 at depth 12\n"
    "  precision   float instead of double analytic intersectors\n"
    "  offset      fixed epsilon 1e-2, 1e-4, 1e-6 instead of the robust offset\n"
    "  bvh         Embree build quality low, high; fast traversal (--no-robust)\n"
    "  shadows     opaque shadow feelers (the classic Whitted shadow) instead of filtered\n"
    "  texture     (scenes with textures) every --texture-filter with every --texture-footprint\n"
    "  alpha-cutoff  (scenes with cut-outs) --alpha-cutoff 0.1, 0.25, 0.5, 0.75, 0.9; the reference\n"
    "              is then the mean over 16 cut-offs spread over (0, 1): alpha as coverage\n"
    "  combo       preview, spp 4 + depth 3, adaptive + pruning, spp 16 + depth 8 + robust\n"
    "For each setting: build and render time (wall clock, and CPU time of all threads; medians\n"
    "of interleaved runs), rays traced, RMSE, PSNR and largest channel error in linear RGB\n"
    "against the reference, pixels visibly off (more than 2/255 in 8-bit sRGB), the same two\n"
    "errors against the reference settings rendered at the setting's own sampling (\"ss\": the\n"
    "non-sampling knobs alone), and NaN/Inf samples (must be 0). The Pareto front uses CPU time,\n"
    "which other processes on a shared machine do not inflate. The scene file's own image and\n"
    "render settings are not used.\n"
    "\n"
    "options:\n"
    "  --width W, --height H   image size (default 160x120; 80x60 with --quick)\n"
    "  --runs N                timed runs per setting, median reported (default 3; 1 with "
    "--quick)\n"
    "  --threads N             worker threads (default: all cores)\n"
    "  --reference-spp N       samples per pixel of the reference (default 64; 16 with --quick)\n"
    "  --knobs LIST            comma-separated knob groups to sweep (default: all); the default\n"
    "                          setting is always included\n"
    "  --visible L             visible-difference threshold in 8-bit sRGB levels (default 2)\n"
    "  --quick                 a smoke run of seconds: 11 settings, 80x60, one run\n"
    "  --out FILE              results as CSV (.csv) or JSON (.json)\n"
    "  --plot FILE             SVG plot of RMSE against CPU time per frame, Pareto front marked\n"
    "  --html DIR              DIR/index.html: a self-contained page with the reference, every\n"
    "                          setting's image and false-colour error map, the plot with its\n"
    "                          Pareto front, the table, and a side-by-side/zoom viewer\n"
    "  -q, --quiet             no progress bar and no table (the bar is drawn only when stderr\n"
    "                          is a terminal)\n"
    "\n"
    "Flags take their value as '--flag value' or '--flag=value'.\n"
    "Exit status 1 when any rendered sample was NaN or Inf (after writing the outputs).\n";

}  // namespace

const CommandFlags kAccuracyFlags{"accuracy", kAccuracyHelp,
                                  {{"--width", "", true},
                                   {"--height", "", true},
                                   {"--runs", "", true},
                                   {"--threads", "", true},
                                   {"--reference-spp", "", true},
                                   {"--visible", "", true},
                                   {"--knobs", "", true},
                                   {"--quick", "", false},
                                   {"--quiet", "-q", false},
                                   {"--out", "", true},
                                   {"--plot", "", true},
                                   {"--html", "", true}}};

namespace {

struct AccuracyCli {
    std::string scene, out, plot, html;
    bool quick = false, quiet = false;
    std::optional<int> width, height, runs, referenceSpp;
    int threads = 0;
    int visible = 2;
    std::vector<std::string> knobs;
};

std::vector<std::string> splitList(const std::string& flag, const std::string& text) {
    std::vector<std::string> items;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = text.find(',', start);
        const std::string item =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty()) throw UsageError(flag + ": empty item in '" + text + "'");
        items.push_back(item);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return items;
}

AccuracyCli parseAccuracyArgs(const std::vector<std::string>& args) {
    AccuracyCli cli;
    ArgParser p(args, kAccuracyFlags);
    while (!p.done()) {
        const std::string a = p.next();
        if (a == "--width")
            cli.width = int(p.integer(a, 1, 8192));
        else if (a == "--height")
            cli.height = int(p.integer(a, 1, 8192));
        else if (a == "--runs")
            cli.runs = int(p.integer(a, 1, 1000));
        else if (a == "--threads")
            cli.threads = int(p.integer(a, 1, 4096));
        else if (a == "--reference-spp")
            cli.referenceSpp = int(p.integer(a, 1, 65536));
        else if (a == "--visible")
            cli.visible = int(p.integer(a, 0, 254));
        else if (a == "--knobs")
            cli.knobs = splitList(a, p.value(a));
        else if (a == "--quick")
            cli.quick = true;
        else if (a == "--quiet" || a == "-q")
            cli.quiet = true;
        else if (a == "--out")
            cli.out = p.value(a);
        else if (a == "--plot")
            cli.plot = p.value(a);
        else if (a == "--html")
            cli.html = p.value(a);
        else if (cli.scene.empty())
            cli.scene = a;
        else
            throw UsageError("unexpected argument '" + a + "' (one scene per sweep)");
    }
    if (cli.scene.empty())
        throw UsageError("accuracy: missing SCENE (see 'raylab accuracy --help')");
    if (!cli.out.empty()) tableFormatOf(cli.out, "--out");  // reject a bad extension up front
    if (!cli.html.empty()) checkReportDir(cli.html, "--html");
    const std::vector<std::string> known = accuracyKnobNames();
    for (const std::string& k : cli.knobs) {
        if (std::find(known.begin(), known.end(), k) == known.end()) {
            std::string list;
            for (const std::string& n : known) list += (list.empty() ? "" : ",") + n;
            throw UsageError("--knobs: unknown knob '" + k + "' (expected " + list + ")");
        }
    }
    return cli;
}

}  // namespace

int accuracyCommand(const std::vector<std::string>& args) {
    const AccuracyCli cli = parseAccuracyArgs(args);
    Scene scene = loadScene(cli.scene);

    AccuracySweepOptions options;
    options.width = cli.width.value_or(cli.quick ? 80 : 160);
    options.height = cli.height.value_or(cli.quick ? 60 : 120);
    options.runs = cli.runs.value_or(cli.quick ? 1 : 3);
    options.referenceSpp = cli.referenceSpp.value_or(cli.quick ? 16 : 64);
    options.threads = cli.threads;
    options.visibleLevels = cli.visible;
    options.keepImages = !cli.html.empty();
    for (AccuracySetting& s :
         accuracySweepSettings(cli.quick, hasTextures(scene), hasCutOuts(scene))) {
        const bool wanted =
            cli.knobs.empty() || s.knob == "default" ||
            std::find(cli.knobs.begin(), cli.knobs.end(), s.knob) != cli.knobs.end();
        if (wanted) options.settings.push_back(std::move(s));
    }

    ProgressBar bar("accuracy", !cli.quiet && isatty(STDERR_FILENO));
    const AccuracyReport report = runAccuracySweep(
        scene, cli.scene, options,
        [&](int done, int total, const std::string&) { bar.update(double(done) / total); },
        &g_interrupted);
    bar.finish();
    if (report.cancelled) {
        std::fprintf(stderr, "raylab: interrupted: no output written\n");
        return 130;
    }

    if (!cli.quiet) std::fputs(accuracyTable(report).c_str(), stdout);
    if (!cli.out.empty()) {
        const bool csv = tableFormatOf(cli.out, "--out") == TableFormat::Csv;
        writeFileAtomically(cli.out, csv ? accuracyCsv(report) : accuracyJson(report));
    }
    if (!cli.plot.empty()) writeSvgPlot(cli.plot, accuracyPlot(report));
    if (!cli.html.empty()) {
        const std::string page = writeHtmlReport(cli.html, accuracyHtml(report));
        if (!cli.quiet) std::printf("report: %s\n", page.c_str());
    }

    uint64_t nonFinite = report.reference.nonFiniteSamples + report.reference.nonFinitePixels;
    std::string firstBad = nonFinite ? report.reference.setting.name : "";
    for (const AccuracyResult& r : report.results) {
        const uint64_t n = r.nonFiniteSamples + r.nonFinitePixels;
        if (n && firstBad.empty()) firstBad = r.setting.name;
        nonFinite += n;
    }
    if (nonFinite) {
        throw InputError(
            cli.scene, 0,
            std::to_string(nonFinite) + " NaN/Inf samples (first in setting '" + firstBad + "')");
    }
    return 0;
}

}  // namespace raylab

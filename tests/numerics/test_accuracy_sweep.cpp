// The accuracy sweep engine (tools/accuracy/) and the `raylab accuracy`
// front end: visible-difference counting, the Pareto front, the settings
// table, a tiny end-to-end sweep and the outputs.

#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <set>
#include <tuple>
#include <string>

#include "cli/cli_helpers.h"
#include "io/io_test_helpers.h"
#include "numerics/numerics_helpers.h"
#include "renderer/io/scene_loader.h"
#include "renderer/io/errors.h"
#include "renderer/io/json.h"
#include "tools/accuracy/accuracy_report.h"
#include "tools/accuracy/accuracy_sweep.h"

using namespace raylab;
using namespace raylab::numerics_test;

namespace {

/// Linear value that the sRGB preview maps to exactly `k` of 255 levels, for
/// k <= 10: below 0.0031308 the transfer is 12.92·v, so v = k / (12.92·255).
float levels(int k) { return float(k / (12.92 * 255.0)); }

Film film(int w, int h) { return Film(w, h); }

void setRgb(Film& f, int i, float r, float g, float b) {
    f.rgba[4 * i + 0] = r;
    f.rgba[4 * i + 1] = g;
    f.rgba[4 * i + 2] = b;
    f.rgba[4 * i + 3] = 1;
}

AccuracyResult result(const std::string& name, double cpuSeconds, double rmse) {
    AccuracyResult r;
    r.setting.name = name;
    r.renderCpuSeconds = cpuSeconds;
    r.renderSeconds = 10 - cpuSeconds;  // wall clock is not what the front ranks
    r.rmse = rmse;
    return r;
}

/// A unit sphere (mirror) on a matte plane, one light: small but with every
/// ray type the sweep measures.
Scene tinyScene() {
    Scene s;
    s.camera = Camera::perspective({0, 1.5, 5}, {0, 0.5, 0}, {0, 1, 0}, 40);
    s.background = Color(0.2, 0.3, 0.4);
    s.ambient = Color(0.1);
    Light l;
    l.position = {-3, 5, 4};
    s.lights.push_back(l);
    s.materials.push_back(material(Color(0.7), Color(0.7)));
    s.materials.push_back(material(Color(0.1), Color(0.0), Color(0.8)));
    s.objects.push_back(shapeObject("floor", makePlane({0, 0, 0}, {0, 1, 0}, 20), 0));
    s.objects.push_back(shapeObject("ball", makeSphere({0, 1, 0}, 1), 1));
    return s;
}

}  // namespace

TEST_CASE("accuracy: visible differences count pixels more than L levels off in 8-bit sRGB") {
    Film a = film(4, 1), b = film(4, 1);
    for (int i = 0; i < 4; ++i) setRgb(a, i, 0, 0, 0);
    setRgb(b, 0, levels(2), 0, 0);  // 2 levels: not more than 2
    setRgb(b, 1, 0, levels(3), 0);  // 3 levels: visible
    setRgb(b, 2, 0, 0, 0);          // identical
    setRgb(a, 3, 5, 5, 5);          // both clamp to 255
    setRgb(b, 3, 7, 9, 1.5f);
    CHECK(countVisibleDifferences(a, b, 2) == 1);
    CHECK(countVisibleDifferences(a, b, 1) == 2);
    CHECK(countVisibleDifferences(a, b, 3) == 0);
    CHECK_THROWS_AS(countVisibleDifferences(a, film(2, 2), 2), InputError);
}

TEST_CASE("accuracy: the Pareto front keeps the settings nothing beats on time and error") {
    // (CPU time, RMSE): A (1, 0.5), B (2, 0.3), C (3, 0.4) beaten by B, D = B
    // (ties do not beat each other), E (0.5, NaN) never on the front and
    // never beating anything, F (0.5, 0.6) the fastest finite one.
    std::vector<AccuracyResult> r = {result("A", 1, 0.5),
                                     result("B", 2, 0.3),
                                     result("C", 3, 0.4),
                                     result("D", 2, 0.3),
                                     result("E", 0.5, std::nan("")),
                                     result("F", 0.5, 0.6)};
    markParetoFront(r);
    CHECK(r[0].pareto);
    CHECK(r[1].pareto);
    CHECK_FALSE(r[2].pareto);
    CHECK(r[3].pareto);
    CHECK_FALSE(r[4].pareto);
    CHECK(r[5].pareto);
    // Build CPU time counts: A at 1 + 1.5 s with RMSE 0.5 is beaten by B (2 s, 0.3).
    r[0].buildCpuSeconds = 1.5;
    markParetoFront(r);
    CHECK_FALSE(r[0].pareto);
}

TEST_CASE("accuracy: the sweep varies one knob at a time from the default") {
    const AccuracySetting d = defaultAccuracySetting();
    CHECK(d.flags() ==
          "--spp 1 --depth 5 --precision double --bvh-quality medium --robust --shadows filtered");
    CHECK(referenceAccuracySetting(64).flags() ==
          "--spp 64 --depth 12 --precision double --bvh-quality medium --robust --shadows filtered "
          "--texture-filter point --texture-footprint differentials");
    for (const auto& [quick, textured, cutOuts] :
         {std::tuple{false, false, false}, std::tuple{true, false, false},
          std::tuple{false, true, false}, std::tuple{false, false, true},
          std::tuple{true, false, true}}) {
        const auto settings = accuracySweepSettings(quick, textured, cutOuts);
        const auto knobs = accuracyKnobNames();
        std::set<std::string> names;
        for (const AccuracySetting& s : settings) {
            CAPTURE(s.name);
            CHECK(names.insert(s.name).second);  // unique row labels
            CHECK(std::find(knobs.begin(), knobs.end(), s.knob) != knobs.end());
            // Which knob groups differ from the default.
            std::set<std::string> diff;
            if (s.spp != d.spp) diff.insert("spp");
            if (s.adaptiveThreshold != d.adaptiveThreshold || s.adaptiveLevels != d.adaptiveLevels)
                diff.insert("adaptive");
            if (s.maxDepth != d.maxDepth) diff.insert("depth");
            if (s.minWeight != d.minWeight) diff.insert("min-weight");
            if (s.precision != d.precision) diff.insert("precision");
            if (s.offset != d.offset || s.epsilon != d.epsilon) diff.insert("offset");
            if (s.quality != d.quality || s.robust != d.robust) diff.insert("bvh");
            if (s.shadows != d.shadows) diff.insert("shadows");
            if (s.textures.filter != d.textures.filter ||
                s.textures.footprint != d.textures.footprint)
                diff.insert("texture");
            if (s.alphaCutoff != d.alphaCutoff) diff.insert("alpha-cutoff");
            CHECK(s.coverageCutoffs == 0);  // only the reference averages cut-offs
            CHECK((s.knob == "texture") <= textured);
            CHECK((s.knob == "alpha-cutoff") <= cutOuts);
            if (s.knob == "default")
                CHECK(diff.empty());
            else if (s.knob == "combo")
                CHECK(diff.size() >= 2);
            else if (s.knob == "min-weight")  // swept at the reference depth 12
                CHECK(diff == std::set<std::string>{"depth", "min-weight"});
            else
                CHECK(diff == std::set<std::string>{s.knob});
        }
        CHECK(settings.front().knob == "default");
        CHECK(settings.size() >= (quick ? 10u : 25u));
        // Point, bilinear, and the two footprints of the other filter than
        // the default's, plus the default filter's other footprint: 5 rows.
        const auto textureRows = std::count_if(settings.begin(), settings.end(),
                                               [](const AccuracySetting& s) { return s.knob == "texture"; });
        CHECK(textureRows == (textured ? 5 : 0));
        const auto cutoffRows = std::count_if(settings.begin(), settings.end(),
                                              [](const AccuracySetting& s) { return s.knob == "alpha-cutoff"; });
        CHECK(cutoffRows == (cutOuts ? (quick ? 2 : 5) : 0));
    }
}

TEST_CASE("accuracy: a tiny sweep end to end") {
    // 12x9, reference 4 spp, two runs. The reference settings swept as a
    // setting reproduce the reference exactly (RMSE 0, PSNR inf); depth 1
    // traces only camera and shadow rays and loses the mirror's reflection
    // even against the reference settings at its own 1 spp; the default
    // (1 spp) differs from the 4-spp reference at edges.
    Scene scene = tinyScene();
    AccuracySweepOptions o;
    o.width = 12;
    o.height = 9;
    o.runs = 2;
    o.referenceSpp = 4;
    AccuracySetting again = referenceAccuracySetting(4);
    again.name = "reference again";
    again.knob = "combo";
    AccuracySetting depth1 = defaultAccuracySetting();
    depth1.name = "depth 1";
    depth1.knob = "depth";
    depth1.maxDepth = 1;
    AccuracySetting flt = defaultAccuracySetting();
    flt.name = "float";
    flt.knob = "precision";
    flt.precision = Precision::Float;
    o.settings = {defaultAccuracySetting(), again, depth1, flt};
    int calls = 0, lastDone = -1, lastTotal = 0;
    const AccuracyReport rep =
        runAccuracySweep(scene, "tiny", o, [&](int done, int total, const std::string&) {
            ++calls;
            CHECK(done > lastDone);
            lastDone = done;
            lastTotal = total;
        });
    // 1 reference + 1 matched (spp 1) + 2 runs x 4 settings, then the final call.
    CHECK(lastTotal == 1 + 1 + 2 * 4);
    CHECK(lastDone == lastTotal);
    CHECK(calls == lastTotal + 1);
    REQUIRE(rep.results.size() == 4);
    CHECK_FALSE(rep.cancelled);
    CHECK(rep.width == 12);
    CHECK(rep.reference.rays > 0);
    for (const AccuracyResult& r : rep.results) {
        CAPTURE(r.setting.name);
        CHECK(r.deterministic);
        CHECK(r.nonFiniteSamples == 0);
        CHECK(r.nonFinitePixels == 0);
        CHECK(r.renderSeconds > 0);
        CHECK(r.renderMinSeconds <= r.renderSeconds);
        CHECK(r.renderSeconds <= r.renderMaxSeconds);
    }
    const AccuracyResult& def = rep.results[0];
    const AccuracyResult& ref = rep.results[1];
    const AccuracyResult& d1 = rep.results[2];
    CHECK(ref.rmse == 0);
    CHECK(std::isinf(ref.psnr));
    CHECK(ref.visiblePixels == 0);
    CHECK(ref.knobRmse == 0);
    CHECK(ref.rays == rep.reference.rays);
    CHECK(def.rmse > 0);
    // Depth 1: 12 x 9 camera rays and at most one shadow ray each (one light).
    CHECK(d1.rays >= 108);
    CHECK(d1.rays <= 2 * 108);
    CHECK(d1.rays < def.rays);
    CHECK(d1.knobRmse > 0);  // no mirror reflection at depth 1
    // Outputs: CSV (header + reference + 4 rows), valid JSON, a plot.
    const std::string csv = accuracyCsv(rep);
    CHECK(cli::lineCount(csv) == 6);
    CHECK(csv.rfind("setting,knob,flags,", 0) == 0);
    const JsonValue json = parseJson(accuracyJson(rep), "sweep.json");
    REQUIRE(json.find("settings"));
    CHECK(json.find("settings")->size() == 4);
    CHECK(json.find("reference")->find("rays")->asNumber() == double(rep.reference.rays));
    const std::string svg = renderSvgPlot(accuracyPlot(rep));
    CHECK(svg.find("Pareto front") != std::string::npos);
    const std::string table = accuracyTable(rep);
    CHECK(table.find("depth 1") != std::string::npos);

    // The scene file's own "render" block must not leak into the sweep
    // (an epsilon there would replace the robust offset of every setting),
    // and it is put back afterwards.
    scene.settings.epsilon = 0.3;
    scene.settings.maxDepth = 1;
    const AccuracyReport withBlock = runAccuracySweep(scene, "tiny", o);
    REQUIRE(withBlock.results.size() == rep.results.size());
    for (size_t i = 0; i < rep.results.size(); ++i) {
        CHECK(withBlock.results[i].rmse == rep.results[i].rmse);
        CHECK(withBlock.results[i].rays == rep.results[i].rays);
    }
    REQUIRE(scene.settings.epsilon);
    CHECK(*scene.settings.epsilon == 0.3);
    scene.settings = RenderOverrides{};

    std::atomic<bool> cancel{true};
    const AccuracyReport stopped = runAccuracySweep(scene, "tiny", o, {}, &cancel);
    CHECK(stopped.cancelled);
    CHECK(stopped.results.empty());
}

TEST_CASE("accuracy: the command line") {
    const cli::Result help = cli::run("accuracy --help");
    CHECK(help.exitCode == 0);
    CHECK(help.out.find("usage: raylab accuracy SCENE") != std::string::npos);
    CHECK(cli::run("accuracy").exitCode == 2);
    const std::string scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/primitives.json";
    CHECK(cli::run("accuracy " + scene + " --knobs bogus").exitCode == 2);
    CHECK(cli::run("accuracy " + scene + " --out results.txt").exitCode == 2);
    CHECK(cli::run("accuracy /no/such/scene.json --quick").exitCode == 1);

    cli::TempDir dir;
    const cli::Result r =
        cli::run("accuracy " + scene + " --quick --width 16 --height 12 " + "--knobs depth --out " +
                 dir.file("r.csv") + " --plot " + dir.file("p.svg"));
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("depth 3") != std::string::npos);
    // Quick depth settings: 1 and 3, plus the default, the reference and the header.
    CHECK(cli::lineCount(cli::readFile(dir.file("r.csv"))) == 5);
    CHECK(cli::readFile(dir.file("p.svg")).rfind("<svg", 0) == 0);
}

TEST_CASE("accuracy: with cut-outs the reference reads alpha as coverage (the mean over cut-offs)") {
    // A white card of uniform alpha 0.3 fills the view, lit by ambient 1 only,
    // over a black background. Of the 16 cut-offs (k + 0.5)/16 five are <= 0.3
    // (0.03125 ... 0.28125), so the reference is 5/16 white everywhere; a
    // cut-off of 0.25 keeps the card (error 11/16 in every channel), 0.5
    // makes it a hole (error 5/16).
    test::TempDir dir;
    Scene scene = loadScene(dir.write("card.json", R"({
        "camera": {"type": "orthographic", "eye": [0, 0, 5], "direction": [0, 0, -1], "width": 2},
        "ambient": [1, 1, 1],
        "materials": {"card": {"ka": [1, 1, 1], "kd": 0, "alpha": 0.3}},
        "objects": [{"type": "polygon", "material": "card",
                     "vertices": [[-4, -4, 0], [4, -4, 0], [4, 4, 0], [-4, 4, 0]]}]})"));
    REQUIRE(hasCutOuts(scene));
    AccuracySweepOptions o;
    o.width = 8;
    o.height = 6;
    o.runs = 1;
    o.referenceSpp = 2;
    for (const AccuracySetting& s : accuracySweepSettings(true, false, true))
        if (s.knob == "alpha-cutoff") o.settings.push_back(s);
    REQUIRE(o.settings.size() == 2);
    REQUIRE(*o.settings[0].alphaCutoff == 0.25);
    REQUIRE(*o.settings[1].alphaCutoff == 0.75);
    const AccuracyReport rep = runAccuracySweep(scene, "card", o);
    REQUIRE(rep.results.size() == 2);
    CHECK(rep.reference.setting.coverageCutoffs == kCoverageCutoffs);
    CHECK(rep.results[0].rmse == doctest::Approx(11.0 / 16).epsilon(1e-6));
    CHECK(rep.results[1].rmse == doctest::Approx(5.0 / 16).epsilon(1e-6));
    CHECK(rep.results[0].setting.flags().find("--alpha-cutoff 0.25") != std::string::npos);
    // A scene without cut-outs keeps the one-render reference.
    Scene plain = tinyScene();
    CHECK_FALSE(hasCutOuts(plain));
}

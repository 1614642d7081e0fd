// The self-contained HTML reports of `raylab accuracy --html` and `raylab
// bench accel --html`, loaded in a real browser: headless Chromium (skipped
// when it is not installed: scripts/install-deps.sh --optional) opens the
// page, whose own script records on <body> how many images decoded and how
// many plot markers were drawn; the test reads the DOM Chromium dumps.

#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "support/run_command.h"
#include "support/temp_dir.h"
#include "tools/report/html_page.h"

using raylab::test::CommandResult;
using raylab::test::runCommand;
using raylab::test::TempDir;

namespace {

const std::string kScene = R"({
  "camera": {"type": "perspective", "eye": [0, 1.5, 6], "look_at": [0, 0.3, 0], "up": [0, 1, 0], "fov": 45},
  "ambient": [0.1, 0.1, 0.1],
  "lights": [{"type": "point", "position": [3, 5, 4], "color": [1, 1, 1], "intensity": 1}],
  "materials": {"mirror": {"kd": [0.2, 0.2, 0.2], "ks": [0.6, 0.6, 0.6], "km": [0.5, 0.5, 0.5], "shininess": 40},
                "glass": {"kd": [0.05, 0.05, 0.05], "kt": [0.8, 0.8, 0.8], "ior": 1.5},
                "floor": {"kd": [0.7, 0.7, 0.5]}},
  "objects": [{"type": "sphere", "center": [-0.8, 0.5, 0], "radius": 0.7, "material": "mirror"},
              {"type": "sphere", "center": [0.9, 0.5, 0.5], "radius": 0.6, "material": "glass"},
              {"type": "polygon", "vertices": [[-4, -0.2, -4], [4, -0.2, -4], [4, -0.2, 4], [-4, -0.2, 4]],
               "material": "floor"}]
})";

std::string chromium() {
    for (const char* name : {"chromium", "chromium-browser", "google-chrome"})
        if (std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0)
            return name;
    return "";
}

/// The value of the first `name="..."` in `html` ("" when there is none).
std::string attribute(const std::string& html, const std::string& name) {
    const std::string open = name + "=\"";
    const size_t at = html.find(open);
    if (at == std::string::npos) return "";
    const size_t from = at + open.size(), to = html.find('"', from);
    return to == std::string::npos ? "" : html.substr(from, to - from);
}

size_t countOf(const std::string& s, const std::string& what) {
    size_t n = 0;
    for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
}

/// Loads `page` in headless Chromium and checks what the page's script found.
void checkInBrowser(const std::string& page, int expectedImages) {
    const std::string browser = chromium();
    if (browser.empty()) {
        MESSAGE("raylab-test-skipped: Chromium is not installed (scripts/install-deps.sh --optional)");
        return;
    }
    const TempDir profile;
    // --no-sandbox: the tests may run as root (CI), where Chromium refuses its sandbox.
    const CommandResult r = runCommand(
        "timeout 180 " + browser + " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage "
        "--no-first-run --user-data-dir=" + profile.path().string() +
        " --virtual-time-budget=10000 --dump-dom file://" + page);
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    const std::string images = attribute(r.out, "data-images");
    CAPTURE(images);
    REQUIRE_FALSE(images.empty());  // the script ran
    CHECK(images == std::to_string(expectedImages) + "/" + std::to_string(expectedImages));
    const std::string points = attribute(r.out, "data-plot-points");
    const std::string expected = attribute(r.out, "data-expected-points");
    CAPTURE(points);
    CAPTURE(expected);
    CHECK(std::atoi(expected.c_str()) > 0);
    CHECK(points == expected);
}

}  // namespace

TEST_CASE("html report: raylab accuracy --html writes a page a browser shows whole") {
    const TempDir dir;
    const std::string scene = dir.write("s.json", kScene);
    const std::string out = dir.file("report");
    const CommandResult r =
        runCommand(std::string(RAYLAB_BINARY) + " accuracy " + scene + " --quick --width 32 --height=24 "
                   "--knobs spp,depth --threads 2 -q --html=" + out);
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    const std::string page = raylab::test::readFile(out + "/index.html");
    CHECK(page.find("src=\"http") == std::string::npos);  // nothing fetched from elsewhere
    CHECK(page.find("href=\"http") == std::string::npos);
    CHECK(page.find("<script src") == std::string::npos);
    CHECK(page.find("<link") == std::string::npos);
    CHECK(page.rfind("<!DOCTYPE html>", 0) == 0);
    // Settings: default + the quick sweep's spp and depth settings.
    const size_t settings = countOf(page, "<tr") - 2;  // header and reference rows
    CHECK(settings >= 3);
    // Images: reference + each setting's image + each error map + the colour bar.
    const int expectedImages = int(1 + 2 * settings + 1);
    CHECK(countOf(page, "<img ") == size_t(expectedImages) + 3);  // + the viewer's three panes
    CHECK(countOf(page, "src=\"data:image/png;base64,") == size_t(expectedImages));
    CHECK(page.find("class=\"viewer\"") != std::string::npos);
    CHECK(page.find("Pareto") != std::string::npos);
    checkInBrowser(out + "/index.html", expectedImages);
}

TEST_CASE("html report: raylab bench accel --html, and a report path that is a file") {
    const TempDir dir;
    const std::string scene = dir.write("s.json", kScene);
    const std::string out = dir.file("bench");
    const CommandResult r =
        runCommand(std::string(RAYLAB_BINARY) + " bench accel " + scene +
                   " --quick --width 16 --height 16 --runs 1 --naive-budget 0.05 --html " + out);
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    CHECK(r.out.find("report: " + out + "/index.html") != std::string::npos);
    const std::string page = raylab::test::readFile(out + "/index.html");
    CHECK(page.find("<script src") == std::string::npos);
    CHECK(page.find(">file</td><td class=\"text\">s.json</td>") != std::string::npos);
    const int images = int(countOf(page, "src=\"data:image/png;base64,"));
    CHECK(images > 3);
    checkInBrowser(out + "/index.html", images);

    const std::string file = dir.write("taken", "x");
    const CommandResult bad = runCommand(std::string(RAYLAB_BINARY) + " bench accel --html " + file);
    CHECK(bad.exitCode == 2);
    CHECK(bad.err == "raylab: error: --html: '" + file + "' exists and is not a directory\n");
}

TEST_CASE("html page: base64 and escaping") {
    CHECK(raylab::base64({}) == "");
    CHECK(raylab::base64({'f'}) == "Zg==");
    CHECK(raylab::base64({'f', 'o'}) == "Zm8=");
    CHECK(raylab::base64({'f', 'o', 'o', 'b', 'a', 'r'}) == "Zm9vYmFy");
    CHECK(raylab::escapeHtml("<a href=\"x\">&'") == "&lt;a href=&quot;x&quot;&gt;&amp;&#39;");
}

// MTL map_d as an alpha cut-out mask (issue 19): an RGBA PNG's alpha, or a
// grey PNG's level, gives the same holes as the JSON checker mask whose
// pixels tests/renderer/test_cut_outs.cpp checks by hand.
#include <doctest/doctest.h>

#include <string>

#include "io/io_test_helpers.h"
#include "renderer/io/scene_loader.h"
#include "textures/image_files.h"

using namespace raylab;
using raylab::test::TempDir;

namespace {

/// A floor, a unit quad at z = 1 (uv = (x, y)) with material `quadMaterial`
/// (or the OBJ's own when empty), one directional light, no ambient.
std::string scene(const std::string& quadMaterial) {
    return R"({"camera": {"type": "orthographic", "eye": [0, 0.5, 5], "direction": [0, 0, -1], "width": 2},
        "lights": [{"type": "directional", "direction": [-1, 0, -1]}],
        "materials": {"floor": {"kd": [0.5, 0.5, 0.5]},
          "checker": {"kd": [1, 1, 1], "alpha": {"checker": [[0, 0, 0], [1, 1, 1]], "scale": [2, 2]}}},
        "objects": [{"type": "polygon", "vertices": [[-4, -4, 0], [4, -4, 0], [4, 4, 0], [-4, 4, 0]], "material": "floor"},
                    {"type": "mesh", "file": "q.obj")" +
           (quadMaterial.empty() ? "" : R"(, "material": ")" + quadMaterial + "\"") + "}]}";
}

}  // namespace

TEST_CASE("mtl: map_d cuts holes where the mask's alpha (or grey) is below 0.5") {
    TempDir dir;
    dir.write("q.obj",
              "mtllib q.mtl\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
              "usemtl leaf\nf 1/1 2/2 3/3 4/4\n");
    // 2 x 2 texels, row 0 at the top (v > 0.5): holes at (u < 0.5, v < 0.5)
    // and (u > 0.5, v > 0.5), as the checker's even squares. Clamped, so the
    // bilinear lookup at a pixel centre is on the nearest texel's side of 0.5.
    testing::writeImage(dir.file("rgba.png"), 2, 2, 4,
                        {0, 1, 0, 1, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 1}, OIIO::TypeDesc::UINT8);
    testing::writeImage(dir.file("grey.png"), 2, 2, 1, {1, 0, 0, 1}, OIIO::TypeDesc::UINT8);
    const Scene reference = loadScene(dir.write("ref.json", scene("checker")));
    for (const char* mask : {"rgba.png", "grey.png"}) {
        CAPTURE(mask);
        dir.write("q.mtl", std::string("newmtl leaf\nKa 0 0 0\nKd 1 1 1\nmap_d -clamp on ") +
                               mask + "\n");
        const Scene s = loadScene(dir.write("s.json", scene("")));
        for (const char* accel : {"embree", "naive"}) {
            CAPTURE(accel);
            const Film want = test::renderFilm(reference, accel, 16, 8);
            const Film got = test::renderFilm(s, accel, 16, 8);
            CHECK(got.rgba == want.rgba);
        }
    }
}

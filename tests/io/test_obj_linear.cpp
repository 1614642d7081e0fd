// OBJ and MTL loading is linear in the input (issue 22): 10^5 distinct
// undefined material names, 10^5 mtllib statements and 10^5 materials are
// each read once. The checks are counts (lines read, libraries opened,
// warnings kept), not timings; the quadratic reader these replace rescanned
// the whole file for every warning and re-read a library per mtllib line.
#include <doctest/doctest.h>

#include <string>

#include "io/io_test_helpers.h"
#include "renderer/io/obj_loader.h"

using namespace raylab;
using raylab::test::quiet;
using raylab::test::contains;
using raylab::test::TempDir;

namespace {

constexpr int kN = 100000;

const char* const kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("linear input: 10^5 distinct undefined usemtl names") {
    TempDir dir;
    dir.write("m.mtl", "newmtl defined\nKd 1 0 0\n");
    std::string obj = std::string("mtllib m.mtl\n") + kTriangle;
    for (int i = 0; i < kN; ++i) obj += "usemtl undefined " + std::to_string(i) + "\nf 1 2 3\n";
    const ObjModel m = loadObj(dir.write("names.obj", obj), quiet());
    CHECK(m.counts.objLines == 4 + 2 * kN);  // every line read once
    CHECK(m.counts.mtlLibraries == 1);
    CHECK(m.triangleCount() == size_t(kN));
    // Five named, the rest counted in one line: the terminal is not flooded.
    REQUIRE(m.warnings.size() == LoadWarnings::kListedPerKind + 1);
    CHECK(contains(m.warnings[0], "names.obj:5: material 'undefined 0' is not defined"));
    CHECK(contains(m.warnings.back(), "and " + std::to_string(kN - 5) +
                                          " more warnings about undefined materials"));
}

TEST_CASE("linear input: 10^5 mtllib statements naming one library read it once") {
    TempDir dir;
    dir.write("m.mtl", "newmtl red\nKd 1 0 0\n");
    std::string obj;
    for (int i = 0; i < kN; ++i) obj += "mtllib m.mtl\n";
    obj += std::string("usemtl red\n") + kTriangle + "f 1 2 3\n";
    const ObjModel m = loadObj(dir.write("libs.obj", obj), quiet());
    CHECK(m.counts.objLines == kN + 5);
    CHECK(m.counts.mtlLibraries == 1);
    CHECK(m.counts.mtlLines == 2);
    CHECK(m.warnings.empty());
    REQUIRE(m.materials.size() == 1);
    CHECK(m.parts[0].faceMaterials[0] == 0);
}

TEST_CASE("linear input: 10^5 materials in one library, each used once") {
    TempDir dir;
    std::string mtl, obj = std::string("mtllib big.mtl\n") + kTriangle;
    for (int i = 0; i < kN; ++i) {
        mtl += "newmtl m" + std::to_string(i) + "\nKd 0.5 0.5 0.5\n";
        obj += "usemtl m" + std::to_string(kN - 1 - i) + "\nf 1 2 3\n";
    }
    dir.write("big.mtl", mtl);
    const ObjModel m = loadObj(dir.write("many.obj", obj), quiet());
    CHECK(m.counts.mtlLibraries == 1);
    CHECK(m.counts.mtlLines == 2 * kN);
    CHECK(m.counts.objLines == 4 + 2 * kN);
    CHECK(m.materials.size() == size_t(kN));
    CHECK(m.warnings.empty());
    // The last face uses the first material: names resolved, not positions.
    CHECK(m.parts[0].faceMaterials.back() == 0);
    CHECK(m.parts[0].faceMaterials.front() == uint32_t(kN - 1));
}

TEST_CASE("linear input: 10^5 mtllib statements naming missing libraries") {
    TempDir dir;
    std::string obj;
    for (int i = 0; i < kN; ++i) obj += "mtllib gone" + std::to_string(i) + ".mtl\n";
    obj += std::string(kTriangle) + "f 1 2 3\n";
    const ObjModel m = loadObj(dir.write("gone.obj", obj), quiet());
    CHECK(m.counts.mtlLibraries == 0);
    REQUIRE(m.warnings.size() == LoadWarnings::kListedPerKind + 1);
    CHECK(contains(m.warnings.back(), "and " + std::to_string(kN - 5) +
                                          " more warnings about missing material libraries"));
}

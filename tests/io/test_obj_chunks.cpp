// The parallel OBJ parse (renderer/io/obj_parser.cpp): a text cut into chunks
// reads exactly as in one piece, for any chunk size and thread count, with the
// usemtl and s state carried across chunks, warnings in file order and the
// first error of the file reported. (Every OBJ text of the suites is also
// parsed in 13-byte chunks by the differential test.)
#include <doctest/doctest.h>

#include <tbb/global_control.h>

#include <string>

#include "io/io_test_helpers.h"
#include "renderer/io/obj_parser.h"
#include "support/obj_differential.h"

using namespace raylab;
using raylab::test::compareObjParsers;
using raylab::test::obj_differential_detail::sameObjData;

namespace {

/// About 3.5 MB: a strip of quads in bands of 9973 faces, each band another
/// material and smoothing group; only the last vertex has a colour; a few
/// unknown statements spread through the file.
std::string bigText() {
    std::string t = "mtllib a.mtl\n";
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        t += "v " + std::to_string(i) + " 0 " + std::to_string(i % 7) + ".25\n";
        t += "v " + std::to_string(i) + " 1 0.5\n";
        if (i % 30011 == 0) t += "bogus " + std::to_string(i) + "\n";
    }
    t += "v 0 0 0 0.5 0.25 1\n";
    for (int i = 0; i + 1 < n; ++i) {
        if (i % 9973 == 0) {
            t += "usemtl band " + std::to_string(i / 9973 % 3) + "\n";
            t += i % 2 ? "s off\n" : "s " + std::to_string(i + 1) + "\n";
        }
        const int a = 2 * i + 1;
        t += "f " + std::to_string(a) + " " + std::to_string(a + 2) + " " +
             std::to_string(a + 3) + " " + std::to_string(a + 1) + "\n";
    }
    return t;
}

}  // namespace

TEST_CASE("obj chunks: a 3.5 MB text reads the same in every chunk size, and as tinyobj reads it") {
    const std::string text = bigText();
    REQUIRE(text.size() > 3 * kObjChunkBytes);
    const auto d = compareObjParsers(text);
    CHECK(d.mismatch == "");
    CHECK(!d.raylabRefused);
    CHECK(d.facesCompared == 99999);

    LoadWarnings w1("a.obj"), w2("a.obj");
    const ObjData whole = parseObj(text, "a.obj", w1, text.size());
    const ObjData chunked = parseObj(text, "a.obj", w2);
    CHECK(sameObjData(whole, chunked));
    CHECK(w1.lines() == w2.lines());
    REQUIRE(whole.materialNames.size() == 3);
    CHECK(whole.materialNames[0].uses == 4);
    CHECK(whole.colors.size() == whole.positions.size());
    CHECK(whole.colors.front().x == 1.0f);
    CHECK(whole.colors.back().y == 0.25f);
    // Faces after "s off" have group 0, the others their band's number.
    CHECK(whole.faces[9973].smoothingGroup == 0);
    CHECK(whole.faces[2 * 9973].smoothingGroup == 2 * 9973 + 1);
    CHECK(whole.faces[2 * 9973 - 1].smoothingGroup == 0);
}

TEST_CASE("obj chunks: the same data with 1 thread and with all cores") {
    const std::string text = bigText();
    LoadWarnings w1("a.obj"), w2("a.obj");
    ObjData one;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = parseObj(text, "a.obj", w1);
    }
    const ObjData all = parseObj(text, "a.obj", w2);
    CHECK(sameObjData(one, all));
    CHECK(w1.lines() == w2.lines());
}

TEST_CASE("obj chunks: the first error of the file is reported, wherever the chunks fall") {
    std::string text;
    for (int i = 0; i < 200000; ++i) text += "v 1 2 3\n";
    text += "f 1 2 3\n";
    const int firstBad = 200000 + 2;
    text += "v 1 2 x\n";  // line 200002
    for (int i = 0; i < 200000; ++i) text += "v 1 2 3\n";
    text += "f 1 2 999999\n";  // a later error
    for (const size_t chunk : {size_t(64), size_t(4096), kObjChunkBytes, text.size()}) {
        CAPTURE(chunk);
        LoadWarnings w("e.obj");
        const auto f = raylab::test::failureOf([&] { parseObj(text, "e.obj", w, chunk); });
        CHECK(f.line == firstBad);
        CHECK(raylab::test::contains(f.message, "'x' is not a finite number"));
    }
}

TEST_CASE("obj indices: plain digits (the fast path) and every other form read alike") {
    // Each face names vertices 1, 2, 3 (or 3, 2, 1) in another spelling:
    // leading zeros, ten digits (past the fast path), relative, '/' forms.
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
    for (const char* face : {"f 1 2 3", "f 001 02 0003", "f 0000000001 2 0000000003",
                             "f -3 -2 -1", "f 1/1 2/1 3/1", "f 3 2 1"})
        text += std::string(face) + "\n";
    LoadWarnings w("i.obj");
    const ObjData d = parseObj(text, "i.obj", w);
    REQUIRE(d.faces.size() == 6);
    REQUIRE(d.cornerV.size() == 18);
    for (size_t f = 0; f < 5; ++f)
        for (size_t k = 0; k < 3; ++k) {
            CAPTURE(f);
            CHECK(d.cornerV[3 * f + k] == k);
        }
    CHECK(d.cornerV[15] == 2);
    CHECK(d.cornerV[17] == 0);
    // Out of range and zero still fail with the general path's message.
    for (const char* bad : {"f 1 2 4", "f 0 1 2", "f 1 2 999999999"}) {
        CAPTURE(bad);
        LoadWarnings wb("b.obj");
        const auto failure = raylab::test::failureOf(
            [&] { parseObj(std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + bad + "\n", "b.obj", wb); });
        CHECK(failure.line == 4);
        CHECK(raylab::test::contains(failure.message, "face refers to vertex"));
    }
}

// Bad OBJ/MTL input through the real binary (`raylab render mesh.obj`):
// refused with one "raylab: error: FILE:LINE: ..." line and exit 1, nothing
// written; a missing MTL or texture is only a warning. Renders are 8x8.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <cmath>
#include <string>

#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

/// Refused at `errorFile` (in the scratch folder), `line` (0: no line).
void refused(const std::string& obj, int line, const std::string& fragment,
             const std::vector<std::pair<std::string, std::string>>& files = {},
             const std::string& errorFile = "mesh.obj") {
    TempDir dir;
    std::vector<std::string> inputs{"mesh.obj"};
    for (const auto& [name, body] : files) {
        dir.write(name, body);
        inputs.push_back(name);
    }
    const std::string path = dir.write("mesh.obj", obj);
    checkRefused(runRaylab(tinyRender(dir, path)), dir, inputs, 1,
                 dir.file(errorFile) + ":" + (line > 0 ? std::to_string(line) + ":" : ""),
                 fragment);
}

/// Rendered or refused, whichever the reader decides, within `seconds`.
void handled(const std::string& obj, double seconds = 60,
             const std::vector<std::pair<std::string, std::string>>& files = {}) {
    TempDir dir;
    std::vector<std::string> inputs{"mesh.obj"};
    for (const auto& [name, body] : files) {
        dir.write(name, body);
        inputs.push_back(name);
    }
    const std::string path = dir.write("mesh.obj", obj);
    const RunResult r = runRaylab(tinyRender(dir, path), seconds);
    CAPTURE(r.seconds);
    checkHandled(r, dir, inputs, path + ":");
}

/// Renders; returns stderr (the warnings) for further checks.
std::string rendered(const std::string& obj,
                     const std::vector<std::pair<std::string, std::string>>& files = {}) {
    TempDir dir;
    std::vector<std::string> inputs{"mesh.obj"};
    for (const auto& [name, body] : files) {
        dir.write(name, body);
        inputs.push_back(name);
    }
    const std::string path = dir.write("mesh.obj", obj);
    const RunResult r = runRaylab(tinyRender(dir, path));
    checkRendered(r, dir, inputs);
    return r.err;
}

}  // namespace

TEST_CASE("obj: empty files, binary garbage and files without faces are refused") {
    refused("", 0, "no faces");
    refused("# nothing but a comment\n\n", 0, "no faces");
    refused(std::string("\x7f" "ELF\x02\x01\x01\x00\x00\x00\x00\xff\xfe", 14), 0, "");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\n", 0, "no faces");
    refused("v 0 0 0\nv 0 0 0\nv 0 0 0\nf 1 2 3\n", 4, "zero area");  // zero area only
}

TEST_CASE("obj: a file truncated in the middle of a face is refused or stops cleanly") {
    // "f 1 2" is a face with two corners: it has no triangle.
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2", 4, "fewer than 3 corners");
    // Cut inside an index: "f 1 2 3" becomes "f 1 2 " (trailing blank).
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 ", 4, "fewer than 3 corners");
}

TEST_CASE("obj: face indices out of range are refused at the face's line") {
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, "vertex 4");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", 4, "vertex 0");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", 4, "vertex -4");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483648\n", 4, "vertex");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -99999999999999999999\n", 4, "vertex");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n", 5, "normal 2");
    // A relative index that is fine for the whole file but not at its line.
    refused("v 0 0 0\nf -1 -2 -3\nv 1 0 0\nv 0 1 0\n", 2, "vertex -2");
    // A huge polygon whose last corner is out of range.
    std::string big = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf";
    for (int i = 0; i < 100000; ++i) big += " " + std::to_string(i % 3 + 1);
    refused(big + " 5\n", 4, "");  // the index, or the corner count
}

TEST_CASE("obj: NaN, infinite and overflowing vertices are refused") {
    refused("v 0 0 0\nv 1 0 1e400\nv 0 1 0\nf 1 2 3\n", 2, "finite");
    // tinyobjloader reads a coordinate it cannot parse as 0, without a word:
    // "nan" and "inf" must still be refused at their line, not turned into a
    // different mesh ("no triangles") or a silently wrong one.
    refused("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", 2, "");
    refused("v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n", 2, "");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 nan\nf 1//1 2//1 3//1\n", 4, "");
    // Beyond float range (tinyobjloader reads floats): refused or rendered,
    // never a crash.
    handled("v 0 0 0\nv 1e308 0 0\nv 1e308 1e-300 0\nf 1 2 3\n");
    handled("v -1.7e308 0 0\nv 1.7e308 0 0\nv 0 1e300 0\nf 1 2 3\n");
    // Within float range, but the auto-framed camera lands ~1e39 away, beyond
    // float: the accelerator cannot take the mesh. The refusal must still
    // name the file ("raylab: error: FILE: ..."), as every input error does.
    refused("v 0 0 0\nv 3e38 0 0\nv 0 3e38 0\nf 1 2 3\n", 0, "");
}

TEST_CASE("obj: words, missing values, NUL bytes and floats out of range are refused at their line") {
    // tinyobjloader reads each of these as 0 (or as the end of the line)
    // without a word: a different mesh than the file says.
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf a b c\n", 4, "'a' where a vertex index belongs");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//x 2 3\n", 4, "'x' where a normal index belongs");
    // A huge index is shown as written, not clamped.
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999\n", 4,
            "vertex 99999999999999999999999 but the file has 3 vertices");
    refused("v 0 0 0\nv 1\nv 0 1 0\nf 1 2 3\n", 2, "'v' needs 3 numbers, found 1");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0\nf 1//1 2//1 3//1\n", 4, "'vn' needs 3");
    refused("v 0 0 0\nv 1e300 0 0\nv 0 1 0\nf 1 2 3\n", 2, "'1e300' is beyond float range");
    refused(std::string("v 0 0 0\nv 1 0 0\nv 0 \0 1 0\nf 1 2 3\n", 34), 3, "NUL byte");
    refused("mtllib m.mtl\nusemtl a\n" + kTriangle, 2, "NUL byte",
            {{"m.mtl", std::string("newmtl a\nKd 1 \0 0 0\n", 20)}}, "m.mtl");
    // Vertex colours (v x y z r g b) and a 1-component vt are fine.
    rendered("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nvt 0.5\nf 1 2 3\n");
}

TEST_CASE("obj: texture-coordinate indices are checked like the others") {
    // tinyobjloader only warns, at the file's last line.
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/5 2/5 3/5\n\n\n", 5,
            "texture coordinate 5 but the file has 1 texture coordinate");
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1/9 2/1/9 3/1/9\n", 5, "normal 9");
    rendered("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2/-1/1 3/1/-1\n");
}

TEST_CASE("obj: MTL warnings are reported at the MTL's own line") {
    const std::string err = rendered(
        "mtllib m.mtl\nusemtl a\n" + kTriangle,
        {{"m.mtl", "newmtl a\nKd 1 0 0\nd 0.5\nTr 0.5\nmap_Kd wood.png\nTf 1 1 1\n"}});
    CHECK(contains(err, "m.mtl:4: Both `d` and `Tr` parameters defined"));
    CHECK(contains(err, "m.mtl:6: 'Tf' (transmission filter) is only used with illum 6 or 7"));
    CHECK(contains(err, "m.mtl:5: material 'a': map_Kd: texture not read ("));
}

TEST_CASE("obj: MTL statements tinyobjloader misreads are read as the MTL format means them") {
    // "Kd 0.5" is grey (g = b = r), "d -halo 0.25" a dissolve of 0.25: with a
    // glass-like illum 4, Kd 0.5 grey and kt = 1 - 0.25 load without error,
    // where "Kd 1 1" (two values) and a dissolve above 1 are refused.
    rendered("mtllib m.mtl\nusemtl a\n" + kTriangle,
             {{"m.mtl", "newmtl a\nillum 4\nKd 0.5\nd -halo 0.25\nKa xyz 1 1 1\n"}});
    refused("mtllib m.mtl\nusemtl a\n" + kTriangle, 2, "'Kd' needs 3 numbers, found 2",
            {{"m.mtl", "newmtl a\nKd 1 1\n"}}, "m.mtl");
    refused("mtllib m.mtl\nusemtl a\n" + kTriangle, 3, "dissolve",
            {{"m.mtl", "newmtl a\nillum 4\nd 1.5\n"}}, "m.mtl");
    // A material whose name has a blank: located all the same.
    refused("mtllib m.mtl\nusemtl a\n" + kTriangle, 3, "material 'two words': Kd",
            {{"m.mtl", "newmtl two words\nKs 1 1 1\nKd -1 0 0\n"}}, "m.mtl");
}

TEST_CASE("obj: a trailing comment on a vertex line is not a bad coordinate") {
    // tinyobjloader reads "v 0 0 0 # origin" as the origin; a check for
    // non-numeric coordinates must stop at the comment.
    rendered("v 0 0 0 # origin\nv 1 0 0\t# x\nv 0 1 0\nvn 0 0 1 # up\nf 1//1 2//1 3//1\n");
}

TEST_CASE("obj: broken MTL files are refused at the MTL's line, naming the material") {
    const std::string obj = "mtllib m.mtl\nusemtl a\n" + kTriangle;
    // tinyobjloader would read "nan" as 0 without a word.
    refused(obj, 2, "'nan' is not a finite number", {{"m.mtl", "newmtl a\nKd nan 0 0\n"}},
            "m.mtl");
    refused(obj, 3, "'inf' is not a finite number", {{"m.mtl", "newmtl a\nKd 1 1 1\nNs inf\n"}},
            "m.mtl");
    refused(obj, 2, "material 'a': Kd", {{"m.mtl", "newmtl a\nKd -1 0 0\n"}}, "m.mtl");
    refused(obj, 3, "material 'a': Ns", {{"m.mtl", "newmtl a\nKd 1 1 1\nNs -5\n"}}, "m.mtl");
    // The second of two materials: the line inside its own block.
    refused("mtllib m.mtl\nusemtl b\n" + kTriangle, 5, "material 'b': Ns",
            {{"m.mtl", "newmtl a\nNs 5\n\nnewmtl b\nNs -5\n"}}, "m.mtl");
    // The same library found through a second OBJ folder level.
    refused("mtllib lib/m.mtl\nusemtl a\n" + kTriangle, 2, "Kd",
            {{"lib/m.mtl", "newmtl a\nKd 0 -2 0\n"}}, "lib/m.mtl");
}

TEST_CASE("obj: an MTL library that is a device or FIFO is refused, not read without end") {
    TempDir dir;
    const std::string obj = dir.write("mesh.obj", "mtllib zero.mtl\nusemtl a\n" + kTriangle);
    std::filesystem::create_symlink("/dev/zero", dir.file("zero.mtl"));
    RunResult r = runRaylab(tinyRender(dir, obj), 20);
    checkRefused(r, dir, {"mesh.obj"}, 1, dir.file("zero.mtl") + ":", "not a regular file");
    CHECK(r.seconds < 10);
    std::filesystem::remove(dir.file("zero.mtl"));
    REQUIRE(::mkfifo(dir.file("zero.mtl").c_str(), 0644) == 0);
    r = runRaylab(tinyRender(dir, obj), 20);
    checkRefused(r, dir, {"mesh.obj"}, 1, dir.file("zero.mtl") + ":", "not a regular file");
    CHECK(r.seconds < 10);
}

TEST_CASE("obj: a missing MTL library or texture is a warning and the render goes on") {
    const std::string noMtl = rendered("mtllib missing.mtl\nusemtl red\n" + kTriangle);
    CHECK(contains(noMtl, "raylab: warning: "));
    const std::string noTexture = rendered(
        "mtllib m.mtl\nusemtl red\n" + kTriangle,
        {{"m.mtl", "newmtl red\nKd 1 0 0\nmap_Kd missing.png\nmap_Ks also_missing.png\n"}});
    CHECK(contains(noTexture, "texture"));
    // An unknown material name without any library: warning only.
    rendered("usemtl nothing_defines_me\n" + kTriangle);
}

TEST_CASE("obj: UTF-16 files are refused, CRLF line ends are accepted") {
    std::string le = "\xff\xfe";
    for (char c : kTriangle) {
        le += c;
        le += '\0';
    }
    refused(le, 1, "UTF-16");
    // UTF-16 without a byte-order mark: its NUL bytes give it away on line 1.
    refused(le.substr(2), 1, "NUL byte");
    std::string crlf;
    for (char c : "o tri\n" + kTriangle) {
        if (c == '\n') crlf += '\r';
        crlf += c;
    }
    rendered(crlf);
    // Line numbers with CRLF: the bad face is on line 4.
    std::string crlfBad;
    for (char c : std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")) {
        if (c == '\n') crlfBad += '\r';
        crlfBad += c;
    }
    refused(crlfBad, 4, "vertex 9");
}

TEST_CASE("obj: very long lines and huge faces neither hang nor crash") {
    // A 4 MB comment line, then a triangle.
    rendered("# " + std::string(4 << 20, 'c') + "\n" + kTriangle);
    // A 200000-corner polygon (3.6 MB): tinyobjloader's ear clipping is
    // quadratic (20000 corners take 1 s, 40000 take 4.5 s), so the whole
    // face would take minutes. It must be refused at its line or rendered
    // within 30 s.
    std::string ngon;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double a = 6.283185307179586 * i / n;
        ngon += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    ngon += "f";
    for (int i = 1; i <= n; ++i) ngon += " " + std::to_string(i);
    handled(ngon + "\n", 30);
    // A 1 MB token on a vertex line.
    handled("v 0 0 0\nv 1 0 " + std::string(1 << 20, '9') + "\nv 0 1 0\nf 1 2 3\n");
}

TEST_CASE("obj: corners with an empty index are refused in raylab's words (issue 22)") {
    // Before: tinyobjloader's "Failed parse `f' line(e.g. zero value for face index".
    refused("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2/ 3/\n", 4,
            "face corner '1/' has nothing after '/' (a corner is v, v/vt, v//vn or v/vt/vn)");
    refused(kTriangle.substr(0, 24) + "vt 0 0\nf 1/1/ 2/1/ 3/1/\n", 5,
            "has nothing after its second '/'");
    refused(kTriangle.substr(0, 24) + "f /1 2 3\n", 4, "has no vertex index before '/'");
    refused(kTriangle.substr(0, 24) + "f 1/1/1/1 2 3\n", 4, "has more than two '/'");
}

TEST_CASE("obj: a model too large to frame is refused by its size, not by a vertex at the origin "
          "(issue 22)") {
    // Before: "embree: object 'mesh.obj' (triangle mesh): vertex 0 is not finite or too far from
    // the origin", vertex 0 being (0, 0, 0).
    refused("v 0 0 0\nv 1e30 0 0\nv 0 1e30 0\nf 1 2 3\n", 0,
            "the model is 1e+30 units across; framed whole, it would lie");
}

TEST_CASE("obj: MTL dissolve and transparency outside [0, 1] are refused in every spelling "
          "(issue 22)") {
    const std::string obj = "mtllib m.mtl\nusemtl a\n" + kTriangle;
    for (const char* statement : {"d -1", "d -0.5", "d 1.5", "Tr 2", "Tr -1", "d -halo -1"}) {
        CAPTURE(statement);
        refused(obj, 3, "must be in [0, 1]",
                {{"m.mtl", std::string("newmtl a\nillum 4\n") + statement + "\n"}}, "m.mtl");
    }
    // With an illum that ignores transparency too: one range, whatever the illum.
    refused(obj, 3, "material 'a': Tr (transparency, 1 - dissolve) must be in [0, 1] (got 2)",
            {{"m.mtl", "newmtl a\nillum 2\nTr 2\n"}}, "m.mtl");
}

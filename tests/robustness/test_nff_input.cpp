// Bad NFF input through the real binary: every malformed file is refused with
// one "raylab: error: FILE:LINE: ..." line and exit 1, and nothing is written;
// odd but valid files render. Renders are 8x8.
#include <doctest/doctest.h>

#include <string>

#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

const std::string kView =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 8 8\n";

/// Renders `text` saved as scene.nff; checks the refusal contract.
void refused(const std::string& text, int line, const std::string& fragment,
             const std::vector<std::string>& extra = {}) {
    TempDir dir;
    const std::string scene = dir.write("scene.nff", text);
    const RunResult r = runRaylab(tinyRender(dir, scene, extra));
    const std::string location = scene + ":" + (line > 0 ? std::to_string(line) + ":" : "");
    checkRefused(r, dir, {"scene.nff"}, 1, location, fragment);
}

void rendered(const std::string& text, const std::vector<std::string>& extra = {}) {
    TempDir dir;
    const std::string scene = dir.write("scene.nff", text);
    checkRendered(runRaylab(tinyRender(dir, scene, extra)), dir, {"scene.nff"});
}

}  // namespace

TEST_CASE("nff: empty and whitespace-only files are refused") {
    refused("", 0, "viewpoint incomplete");
    refused("\n\n   \n# only a comment\n", 0, "viewpoint incomplete");
}

TEST_CASE("nff: binary garbage is refused on its first line") {
    // No NUL byte: the tokenizer sees an unknown entity on line 1.
    refused(std::string("\x89\xfe\x01garbage\x7f\xc3\x28 s 1 2 3", 20) + "\n", 1, "unknown entity");
    // With NUL bytes: recognised as binary up front.
    refused(std::string("\x7f" "ELF\x02\x01\x01\x00\x00\x00 v from", 18), 1, "not a text file");
    // A NUL further down is reported at its own line (8), not at line 1.
    refused(kView + std::string("s 0 0 \0 0 1\n", 12), 8, "NUL byte");
}

TEST_CASE("nff: a file truncated in the middle of an entity names the last line") {
    // Line 8 is "s 0 0"; the radius never comes.
    refused(kView + "s 0 0", 8, "unexpected end of file");
    // A polygon announcing 4 vertices with only 2: "p 4" on line 8, cut on line 10.
    refused(kView + "p 4\n0 0 0\n1 0 0\n", 8, "exceeds what the file holds");
    // Cut in the third vertex (line 11): the message points there and names
    // the line where the polygon started.
    refused(kView + "p 3\n0 0 0\n1 0 0\n0 1", 11, "line 8");
    refused(kView + "f 1 0 0 1", 8, "unexpected end of file");
}

TEST_CASE("nff: NaN, infinities and out-of-range numbers are refused with their line") {
    refused(kView + "s 0 0 0 nan\n", 8, "finite");
    refused(kView + "s 0 inf 0 1\n", 8, "finite");
    refused(kView + "s 0 0 0 1e400\n", 8, "out of range");
    refused(kView + "s -1e400 0 0 1\n", 8, "out of range");
    refused(kView + "f 1 1 1 1e999 0 0 0 1\n", 8, "out of range");
    refused("v\nfrom 0 0 nan\nat 0 0 0\nup 0 1 0\nangle 40\n", 2, "finite");
    // A negative background would put negative radiance in every missed pixel.
    refused(kView + "b -1 0 0\ns 0 0 0 1\n", 8, "background colour must be >= 0");
}

TEST_CASE("nff: zero, negative and absurd counts and resolutions are refused") {
    const std::string head = "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\n";
    refused(head + "resolution 0 0\n", 6, "resolution");
    refused(head + "resolution -8 8\n", 6, "resolution");
    refused(head + "resolution 8.5 8\n", 6, "integer");
    refused(head + "resolution 100000 8\n", 6, "resolution");
    refused(kView + "p -3\n", 8, "below 3");
    refused(kView + "p 0\n", 8, "below 3");
    refused(kView + "p 2\n0 0 0\n1 0 0\n", 8, "below 3");
    // Two billion vertices cannot follow in a 60-byte file: refused before any allocation.
    refused(kView + "p 2000000000\n0 0 0\n1 0 0\n0 1 0\n", 8, "exceeds");
    refused(kView + "pp 99999999999\n", 8, "exceeds");
    refused(kView + "p 1e300\n", 8, "integer");
}

TEST_CASE("nff: impossible primitives are refused at their line") {
    refused(kView + "s 0 0 0 0\n", 8, "");               // zero radius
    refused(kView + "c\n0 0 0 1\n0 0 0 1\n", 8, "");      // cone with base == apex
    refused(kView + "c\n0 0 0 0\n0 1 0 0\n", 8, "");      // cone with both radii 0
    // ior 0 is SPD's "opaque"; with T > 0 it is an error.
    refused(kView + "f 1 1 1 1 0 0 0.5 0\n", 8, "index of refraction");
    refused(kView + "hither -1\n", 8, "hither");
    refused(kView + "sphere 0 0 0 1\n", 8, "unknown entity 'sphere'");
}

TEST_CASE("nff: a degenerate camera is refused at the line that makes it so") {
    // "from" equal to "at" (line 3), zero "up" (line 4), "up" along the view
    // direction (line 4), angles outside (0, 180) (line 5). The camera is only
    // built once the file is read, but the message must still point at a line.
    refused("v\nfrom 1 2 3\nat 1 2 3\nup 0 1 0\nangle 40\n", 3, "coincide");
    refused("v\nfrom 0 0 5\nat 0 0 0\nup 0 0 0\nangle 40\n", 4, "zero length");
    refused("v\nfrom 0 0 5\nat 0 0 0\nup 0 0 -2\nangle 40\n", 4, "parallel");
    refused("v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 180\n", 5, "field of view");
    refused("v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 0\n", 5, "field of view");
    refused("v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\n", 0, "viewpoint incomplete");
}

TEST_CASE("nff: a patch with a zero-length vertex normal is refused") {
    // A zero normal has no direction: refused at the vertex's line, for
    // triangles (one mesh) and larger patches (the polygon primitive) alike.
    refused(kView + "pp 3\n0 0 0 0 0 0\n1 0 0 0 0 1\n0 1 0 0 0 1\n", 9, "normal");
    refused(kView + "pp 4\n0 0 0 0 0 1\n1 0 0 0 0 1\n1 1 0 0 0 0\n0 1 0 0 0 1\n", 11,
            "normal");
}

TEST_CASE("nff: UTF-16 files are refused, a UTF-8 BOM and CRLF line ends are accepted") {
    std::string utf16 = "\xff\xfe";
    for (char c : kView + "s 0 0 0 1\n") {
        utf16 += c;
        utf16 += '\0';
    }
    refused(utf16, 1, "UTF-16");
    std::string utf16be = "\xfe\xff";
    for (char c : kView) {
        utf16be += '\0';
        utf16be += c;
    }
    refused(utf16be, 1, "UTF-16");

    std::string crlf;
    for (char c : kView + "l 1 2 3\ns 0 0 0 1\n") {
        if (c == '\n') crlf += '\r';
        crlf += c;
    }
    rendered(crlf);
    rendered("\xEF\xBB\xBF" + kView + "s 0 0 0 1\n");
    // With CRLF the reported line is still the physical line: "s" on line 9.
    std::string crlfBad;
    for (char c : kView + "l 1 2 3\ns 0 0 0 -0\n") {
        if (c == '\n') crlfBad += '\r';
        crlfBad += c;
    }
    refused(crlfBad, 9, "");
}

TEST_CASE("nff: very long lines neither hang nor flood the terminal") {
    // 200000 spheres on one 4 MB line: valid, renders.
    std::string line;
    for (int i = 0; i < 200000; ++i) line += "s " + std::to_string(i % 100) + " 0 -5 0.1 ";
    rendered(kView + line + "\n");
    // A 1 MB token where a number belongs: refused, and the message stays short.
    refused(kView + "s 0 0 0 " + std::string(1 << 20, '7') + "x\n", 8, "'7777");
    refused(kView + std::string(1 << 20, 'q') + "\n", 8, "unknown entity");
}

TEST_CASE("nff: lights inside objects and other odd but valid scenes render") {
    // A light inside a closed sphere, and one inside a glass sphere.
    rendered(kView + "l 0 0 0\nf 1 1 1 1 0 0 0 1\ns 0 0 0 1\n");
    rendered(kView + "l 0 0 0 1 1 1\nf 1 1 1 0.2 0.5 50 0.9 1.5\ns 0 0 0 1\n");
    // No lights, no objects: background only.
    rendered(kView);
    // Extreme but finite magnitudes: no crash, no hang, whatever the pixels.
    rendered(kView + "s 0 0 -1e300 1e299\ns 1e-300 0 0 1e-300\n");
    rendered(kView + "p 3\n0 0 0\n1e-200 0 0\n0 1e-200 0\n");  // zero-area after squaring: dropped
}

TEST_CASE("nff: a light without colour followed by an unknown entity names the entity (issue 22)") {
    // Before: "l: expected a number for light colour, got 'frobnicate'".
    refused(kView + "l 1 2 3\nfrobnicate 1\n", 9, "unknown entity 'frobnicate'");
    // A light colour that is not finite is still a light-colour error.
    refused(kView + "l 1 2 3 nan 1 1\n", 8, "light colour must be a finite number");
    rendered(kView + "l 1 2 3\ns 0 0 0 1\n");
}

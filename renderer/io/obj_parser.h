#pragma once
// The parsing stage of OBJ reading: the file's text into plain arrays (every
// statement read once, in linear time), with each face's line for messages.
// Nothing here triangulates, looks up materials or opens other files: the
// mesh builder (obj_loader.cpp) does that with what this returns.
// tests/io/test_obj_differential.cpp reads every test OBJ with this parser and
// with tinyobjloader and compares (so does the fuzz target fuzz_obj).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/vec.h"
#include "geometry/vec2.h"
#include "renderer/io/load_warnings.h"

namespace raylab {

/// A face corner: 0-based indices, relative (negative) ones already resolved.
struct ObjCorner {
    uint32_t v = 0;
    int32_t vt = -1;  ///< texture coordinate, -1 when the corner has none
    int32_t vn = -1;  ///< normal, -1 when the corner has none
};

struct ObjFace {
    uint32_t firstCorner = 0;  ///< ObjData::corner(firstCorner + k), k < cornerCount
    uint32_t cornerCount = 0;  ///< as written; fewer than 3 is kept (and reported) here
    uint32_t material = 0;     ///< into ObjData::materialNames, or kNoObjMaterial
    uint32_t smoothingGroup = 0;  ///< `s N`; 0 is "off"
    int line = 0;
};

constexpr uint32_t kNoObjMaterial = UINT32_MAX;

/// A name the file gives with its first line: a `usemtl` material or an `mtllib` argument.
struct ObjName {
    std::string name;
    int line = 0;
    int uses = 1;  ///< statements naming it
};

struct ObjData {
    /// Coordinates are read at float precision, as tinyobjloader (raylab's
    /// OBJ reader before this one) read them: meshes rendered before keep
    /// their pictures bit for bit.
    std::vector<Vec3f> positions;
    std::vector<Vec3f> colors;  ///< `v x y z r g b`: one per position, or empty
    std::vector<Vec3f> normals;
    std::vector<Vec2f> texcoords;
    /// Face corners, one entry per corner in file order, stored by field: the
    /// texture-coordinate and normal indices only when some face corner of
    /// the file has a '/' (a mesh of `f 1 2 3` faces stores 4 bytes a corner).
    std::vector<uint32_t> cornerV;
    std::vector<int32_t> cornerVt;  ///< empty, or one per corner (-1: none)
    std::vector<int32_t> cornerVn;  ///< empty, or one per corner (-1: none)
    std::vector<ObjFace> faces;  ///< in file order
    /// Distinct `usemtl` names (blanks around the name trimmed, inner ones
    /// kept), in the order of first use.
    std::vector<ObjName> materialNames;
    /// `mtllib` arguments, '\' read as '/', one per statement: the whole
    /// argument text (it may name one file with blanks or several files).
    std::vector<ObjName> libraries;
    int linesRead = 0;  ///< physical lines visited: each exactly once

    size_t cornerCount() const { return cornerV.size(); }
    ObjCorner corner(size_t i) const {
        return {cornerV[i], cornerVt.empty() ? -1 : cornerVt[i], cornerVn.empty() ? -1 : cornerVn[i]};
    }
};

/// Parses an OBJ file's text. The text is cut into chunks of about 1 MiB at
/// line ends (the cut depends only on the text) and parsed in parallel: a
/// first pass counts each chunk's lines, elements and face corners, a second
/// fills the arrays in place; `usemtl` and `s` carry from chunk to chunk, and
/// warnings and the first error come out as a serial reading gives them, for
/// any thread count. Throws InputError(path, line, ...) for a
/// statement raylab cannot read: numbers that are missing, not finite or
/// beyond float, face corners that are not v, v/vt, v//vn or v/vt/vn, indices
/// out of range (the index shown as written), faces beyond
/// kMaxTriangulatedVertices corners. Statements it does not render (lines,
/// points, free-form geometry, unknown keywords) are one warning per keyword.
ObjData parseObj(std::string_view text, const std::string& path, LoadWarnings& warn);

/// Chunk size of the parallel parse: large enough that the per-chunk merge
/// is negligible, small enough that 2 cores share a 60 MB file evenly.
constexpr size_t kObjChunkBytes = size_t(1) << 20;

/// parseObj with another chunk size: the same result for any size (the tests
/// and the fuzz target cut small texts into many chunks to check that).
ObjData parseObj(std::string_view text, const std::string& path, LoadWarnings& warn,
                 size_t chunkBytes);

}  // namespace raylab

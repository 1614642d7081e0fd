#pragma once
// The parsing stage of OBJ reading: the file's text into plain arrays (every
// statement read once, in linear time), with each face's line for messages.
// Nothing here triangulates, looks up materials or opens other files: the
// mesh builder (obj_loader.cpp) does that with what this returns, so a faster
// parser can replace this one behind parseObj.

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
    uint32_t firstCorner = 0;  ///< into ObjData::corners
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
    std::vector<ObjCorner> corners;
    std::vector<ObjFace> faces;  ///< in file order
    /// Distinct `usemtl` names (blanks around the name trimmed, inner ones
    /// kept), in the order of first use.
    std::vector<ObjName> materialNames;
    /// `mtllib` arguments, '\' read as '/', one per statement: the whole
    /// argument text (it may name one file with blanks or several files).
    std::vector<ObjName> libraries;
    int linesRead = 0;  ///< physical lines visited: each exactly once
};

/// Parses an OBJ file's text. Throws InputError(path, line, ...) for a
/// statement raylab cannot read: numbers that are missing, not finite or
/// beyond float, face corners that are not v, v/vt, v//vn or v/vt/vn, indices
/// out of range (the index shown as written), faces beyond
/// kMaxTriangulatedVertices corners. Statements it does not render (lines,
/// points, free-form geometry, unknown keywords) are one warning per keyword.
ObjData parseObj(std::string_view text, const std::string& path, LoadWarnings& warn);

}  // namespace raylab

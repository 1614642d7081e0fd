#pragma once
// raylab's OBJ parser (renderer/io/obj_parser.h) against tinyobjloader's
// tinyobj::LoadObj(triangulate = false), the parser raylab used before issue
// 17, on one OBJ text (issue 20 bar 4). Shared by the io suite
// (tests/io/test_obj_differential.cpp) and the fuzz target (fuzz_obj.cpp).
//
// The rule: where tinyobjloader refuses a file, raylab refuses it too; where
// both read it, they read the same positions, normals, texture coordinates,
// vertex colours, face corners and counts, smoothing groups and material name
// per face. raylab may refuse more (it checks numbers, index ranges and
// colours, which tinyobjloader lets through). The deliberate differences,
// each from issue 17 or from tinyobjloader's own limits, are recognised in the
// text and listed by name in ObjDifferential::expected:
//   names-with-blanks   `usemtl Hard Shiny` is one name in raylab; tinyobj
//                       keeps its first word (issue 17 item 3), so material
//                       names are compared as raylab's name's first word.
//   trailing-comment    `f 1 2 3 # note`: raylab ends the statement at '#'
//                       (exporters write such comments); tinyobj reads '#'
//                       as an index, atoi gives 0 and it refuses the file.
//   glued-comment       `f 1# 2 3`, `v 0 0 0 0.5# 0.25 1`: a '#' right after a
//                       number. raylab ends the statement there; tinyobj takes
//                       the number before the '#' (atoi, its greedy decimal
//                       reader) and reads on, so it sees more corners or a
//                       colour. Such a text is compared for refusals only.
//   unread-statement    an `l`, `p` (lines, points: not rendered) or `vw`
//                       (a tinyobj extension) with index 0 or a negative
//                       joint: tinyobj refuses; raylab warns once per keyword
//                       and reads no further (they add nothing to a picture).
//   smoothing-spelling  an `s` argument other than a number or `off`
//                       (`s 1.5`, `s #`, `s offset`, `s +1`): raylab warns and
//                       keeps the group; tinyobj takes atoi's prefix (or 0).
//   usemtl-prefix       `usemtlfoo`: tinyobj matches the keyword by prefix and
//                       selects "foo"; raylab reads an unknown statement.
//   lone-cr             a CR not followed by LF: tinyobj ends the line there
//                       (classic Mac line ends), raylab reads it as a blank;
//                       such a text is not compared at all.
//   face-count-byte     a face with 256 or more corners: tinyobj stores the
//                       count in an unsigned char (it wraps); raylab's count
//                       is compared modulo 256, every corner in full.
//   decimal-rounding    tinyobj's decimal conversion is not correctly rounded
//                       (it sums digit times 0.1^k and scales with pow(5, e));
//                       raylab's (std::from_chars) is. A coordinate may differ
//                       by one float ulp, never more.
//   decimal-overflow    tinyobj assembles a number as mantissa · 5^e · 2^e in
//                       doubles, so a zero mantissa with an exponent above 441
//                       (`0e990`) reads as 0 · ∞ = NaN, and a mantissa of more
//                       than 308 digits as ∞ even where the exponent brings the
//                       value back (`1000…0e-400`). raylab reads the value the
//                       text means (0, 1). Where the text has such a spelling
//                       and tinyobj's number is not finite, raylab's finite one
//                       is taken as right.
// raylab keeps faces with fewer than 3 corners in its ObjData (the mesh
// builder drops them with a warning at their line); tinyobj drops them while
// parsing: only faces of 3 or more corners are compared.
//
// raylab's parse is also run in chunks of 13 bytes (4099 for texts of 64 KiB
// and more: many chunks, cut inside every kind of statement sequence): its data, warnings and error must not change.

#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/io/errors.h"
#include "renderer/io/load_warnings.h"
#include "renderer/io/obj_parser.h"
#include "renderer/io/text_file.h"

namespace raylab::test {

struct ObjDifferential {
    bool raylabRefused = false;
    bool tinyRefused = false;
    std::string raylabError;  ///< InputError's located message
    std::string tinyError;    ///< tinyobj's err string
    std::set<std::string> expected;  ///< deliberate differences that applied (names above)
    std::string mismatch;     ///< "" when the two agree (up to `expected`)
    size_t facesCompared = 0;
};

namespace obj_differential_detail {

/// The name of the MTL library prepended to the text tinyobj reads, so that it
/// knows every material name and reports it per face.
constexpr const char* kSyntheticLibrary = "raylab-differential-names.mtl";

/// tinyobj's lines: ends at LF, CRLF or a lone CR.
inline std::vector<std::string_view> tinyLines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '\n' && text[i] != '\r') continue;
        lines.push_back(text.substr(start, i - start));
        if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
        start = i + 1;
    }
    if (start < text.size()) lines.push_back(text.substr(start));
    return lines;
}

inline bool tinyBlank(char c) { return c == ' ' || c == '\t'; }

/// A line after tinyobj's leading-blank skip, cut at a NUL as its c_str() reading is.
inline std::string_view tinyBody(std::string_view line) {
    line = line.substr(0, line.find('\0'));
    size_t a = 0;
    while (a < line.size() && tinyBlank(line[a])) ++a;
    return line.substr(a);
}

/// tinyobj's parseString: skip blanks, take up to a blank or CR.
inline std::string tinyWord(std::string_view s) {
    size_t a = 0;
    while (a < s.size() && tinyBlank(s[a])) ++a;
    size_t b = a;
    while (b < s.size() && !tinyBlank(s[b]) && s[b] != '\r') ++b;
    return std::string(s.substr(a, b - a));
}

/// Every material name tinyobj will look up (its `usemtl` prefix match).
inline std::set<std::string> tinyMaterialNames(std::string_view text) {
    std::set<std::string> names;
    for (std::string_view line : tinyLines(text)) {
        const std::string_view body = tinyBody(line);
        if (body.substr(0, 6) == "usemtl") names.insert(tinyWord(body.substr(6)));
    }
    names.erase("");
    return names;
}

/// Hands tinyobj one material per name when it reads the synthetic library,
/// and nothing for the file's own `mtllib` lines (MTL is not compared here).
class NameOnlyMaterials : public tinyobj::MaterialReader {
public:
    explicit NameOnlyMaterials(std::set<std::string> names) : m_names(std::move(names)) {}
    bool operator()(const std::string& id, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* map, std::string*, std::string*) override {
        if (id != kSyntheticLibrary) return false;
        for (const std::string& n : m_names) {
            tinyobj::material_t m;
            m.name = n;
            (*map)[n] = int(materials->size());
            materials->push_back(m);
        }
        return true;
    }

private:
    std::set<std::string> m_names;
};

/// raylab's statement keyword and arguments of a line (its blanks include CR).
inline bool raylabBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Whether a smoothing argument means the same to both readers: a decimal
/// number up to INT_MAX or "off", alone or followed by a blank.
inline bool plainSmoothingArgument(std::string_view args) {
    size_t end = 0;
    while (end < args.size() && !raylabBlank(args[end]) && args[end] != '#') ++end;
    const std::string_view t = args.substr(0, end);
    if (end < args.size() && args[end] == '#') return false;  // "s 1#": raylab "1", tinyobj 1; "s #": differ
    if (t.empty()) return args.empty();
    if (t == "off") return true;
    if (t.size() > 10) return false;
    for (char c : t)
        if (c < '0' || c > '9') return false;
    return std::strtoll(std::string(t).c_str(), nullptr, 10) <= 2147483647LL;
}

/// The quirks of the file that change what is compared (see the list above).
struct Quirks {
    bool loneCr = false;
    bool gluedComment = false;
    bool smoothingSpelling = false;
    bool usemtlPrefix = false;
    bool hugeDecimal = false;  ///< an exponent of 300 or more, or 300 digits in a row
};

/// Whether the text spells a number tinyobj's double arithmetic overflows on
/// (decimal-overflow): an exponent of magnitude 300 or more after a digit or
/// '.', or a run of 300 digits (a '.' inside the run does not end it).
inline bool hasHugeDecimal(std::string_view text) {
    const auto digit = [](char c) { return c >= '0' && c <= '9'; };
    size_t run = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        run = digit(c) ? run + 1 : (c == '.' ? run : 0);
        if (run >= 300) return true;
        if ((c == 'e' || c == 'E') && i > 0 && (digit(text[i - 1]) || text[i - 1] == '.')) {
            size_t j = i + 1;
            if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
            long exponent = 0;
            for (; j < text.size() && digit(text[j]) && exponent < 300; ++j)
                exponent = exponent * 10 + (text[j] - '0');
            if (exponent >= 300) return true;
        }
    }
    return false;
}

inline Quirks quirksOf(std::string_view text) {
    Quirks q;
    q.hugeDecimal = hasHugeDecimal(text);
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) q.loneCr = true;
    for (std::string_view line : tinyLines(text)) {
        const std::string_view body = tinyBody(line);
        if (body.size() >= 2 && body[0] == 's' && tinyBlank(body[1])) {
            std::string_view args = body.substr(2);
            while (!args.empty() && raylabBlank(args.front())) args.remove_prefix(1);
            while (!args.empty() && raylabBlank(args.back())) args.remove_suffix(1);
            if (!plainSmoothingArgument(args)) q.smoothingSpelling = true;
        }
        if (body.substr(0, 6) == "usemtl" && body.size() > 6 && !raylabBlank(body[6]))
            q.usemtlPrefix = true;
        const bool geometry = (body.size() >= 2 && (body[0] == 'v' || body[0] == 'f') &&
                               tinyBlank(body[1])) ||
                              (body.size() >= 3 && body[0] == 'v' &&
                               (body[1] == 't' || body[1] == 'n') && tinyBlank(body[2]));
        for (size_t i = 2; geometry && i < body.size(); ++i)
            if (body[i] == '#' && !raylabBlank(body[i - 1])) q.gluedComment = true;
    }
    return q;
}

/// The 1-based line tinyobj names in "... line N.)" (its count includes the
/// synthetic first line), or 0.
inline int tinyErrorLine(const std::string& err) {
    const size_t at = err.rfind("line ");
    if (at == std::string::npos) return 0;
    return std::atoi(err.c_str() + at + 5) - 1;
}

/// Whether two floats are equal or one ulp apart (decimal-rounding).
inline bool withinUlp(float a, float b, bool* rounded) {
    if (a == b) return true;
    if (std::nextafter(a, b) == b) {
        *rounded = true;
        return true;
    }
    return false;
}

inline std::string describe(float a, float b) {
    std::ostringstream s;
    s.precision(9);
    s << "raylab " << a << ", tinyobj " << b;
    return s.str();
}

/// The small chunk size a text is also parsed in: 13 bytes (a cut inside
/// nearly every line), coarser for large texts so the check stays fast.
inline size_t smallChunks(std::string_view text) { return text.size() < 65536 ? 13 : 4099; }

/// Whether two parses gave identical data, bit for bit.
inline bool sameObjData(const ObjData& a, const ObjData& b) {
    const auto same = [](const auto& x, const auto& y) {
        // memcmp must not see the null data() of an empty vector (UBSan).
        return x.size() == y.size() &&
               (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
    };
    if (!same(a.positions, b.positions) || !same(a.colors, b.colors) ||
        !same(a.normals, b.normals) || !same(a.texcoords, b.texcoords) ||
        !same(a.cornerV, b.cornerV) || !same(a.cornerVt, b.cornerVt) ||
        !same(a.cornerVn, b.cornerVn) || a.faces.size() != b.faces.size() ||
        a.linesRead != b.linesRead || a.materialNames.size() != b.materialNames.size() ||
        a.libraries.size() != b.libraries.size())
        return false;
    for (size_t i = 0; i < a.faces.size(); ++i) {
        const ObjFace &f = a.faces[i], &g = b.faces[i];
        if (f.firstCorner != g.firstCorner || f.cornerCount != g.cornerCount ||
            f.material != g.material || f.smoothingGroup != g.smoothingGroup || f.line != g.line)
            return false;
    }
    const auto sameNames = [](const std::vector<ObjName>& x, const std::vector<ObjName>& y) {
        for (size_t i = 0; i < x.size(); ++i)
            if (x[i].name != y[i].name || x[i].line != y[i].line || x[i].uses != y[i].uses)
                return false;
        return true;
    };
    return sameNames(a.materialNames, b.materialNames) && sameNames(a.libraries, b.libraries);
}

}  // namespace obj_differential_detail

/// Reads `text` with both parsers and compares (see the file comment).
inline ObjDifferential compareObjParsers(std::string_view text) {
    using namespace obj_differential_detail;
    ObjDifferential out;

    const Quirks quirks = quirksOf(text);
    if (quirks.loneCr) {
        // Lines differ, so no statement is comparable.
        out.expected.insert("lone-cr");
        return out;
    }

    // raylab: the text checks of loadObj, then the parser; once in the
    // parser's own chunks and once cut into chunks of a few bytes, which must
    // give the same data, warnings and error (the parallel parse's merge).
    ObjData ours;
    std::vector<std::string> ourWarnings;
    const std::string path = "differential.obj";
    if (const auto [line, message] = findNonText(text, "OBJ"); line > 0) {
        out.raylabRefused = true;
        out.raylabError = InputError(path, line, message).located();
    } else {
        for (const size_t chunkBytes : {kObjChunkBytes, smallChunks(text)}) {
            ObjData data;
            std::string error;
            LoadWarnings warn(path);
            try {
                data = parseObj(text, path, warn, chunkBytes);
            } catch (const InputError& e) {
                error = e.located();
            }
            if (chunkBytes == kObjChunkBytes) {
                ours = std::move(data);
                ourWarnings = warn.lines();
                out.raylabRefused = !error.empty();
                out.raylabError = error;
            } else if (error != out.raylabError) {
                out.mismatch = "in small chunks raylab says '" + error + "', in one chunk '" +
                               out.raylabError + "'";
                return out;
            } else if (!sameObjData(ours, data) || warn.lines() != ourWarnings) {
                out.mismatch = "in small chunks raylab reads other data or warnings";
                return out;
            }
        }
    }

    // tinyobj, with a first line that names the synthetic library.
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    std::istringstream stream(std::string("mtllib ") + kSyntheticLibrary + "\n" +
                              std::string(text));
    NameOnlyMaterials reader(tinyMaterialNames(text));
    out.tinyRefused = !tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &stream,
                                        &reader, /*triangulate=*/false,
                                        /*default_vcols_fallback=*/true);
    out.tinyError = err;

    if (out.tinyRefused && !out.raylabRefused) {
        const bool unread = err.find("`l'") != std::string::npos ||
                            err.find("`p'") != std::string::npos ||
                            err.find("`vw'") != std::string::npos;
        if (unread) {
            out.expected.insert("unread-statement");
            return out;
        }
        const int line = tinyErrorLine(err);
        const std::vector<std::string_view> lines = tinyLines(text);
        if (err.find("`f'") != std::string::npos && line >= 1 && size_t(line) <= lines.size() &&
            lines[size_t(line - 1)].find('#') != std::string_view::npos) {
            out.expected.insert("trailing-comment");
            return out;
        }
        out.mismatch = "tinyobjloader refuses the file (" + err.substr(0, 200) +
                       ") but raylab reads it";
        return out;
    }
    if (out.raylabRefused || out.tinyRefused) return out;  // raylab refuses more: allowed
    if (quirks.gluedComment) {
        out.expected.insert("glued-comment");
        return out;
    }

    std::ostringstream why;
    bool rounded = false;
    const auto compareFloats = [&](const char* what, const std::vector<float>& a,
                                   const std::vector<tinyobj::real_t>& b) {
        if (a.size() != b.size()) {
            why << what << ": raylab has " << a.size() << " numbers, tinyobj " << b.size();
            return false;
        }
        for (size_t i = 0; i < a.size(); ++i) {
            if (quirks.hugeDecimal && std::isfinite(a[i]) && !std::isfinite(b[i])) {
                out.expected.insert("decimal-overflow");
                continue;
            }
            if (!withinUlp(a[i], b[i], &rounded)) {
                why << what << " number " << i << ": " << describe(a[i], b[i]);
                return false;
            }
        }
        return true;
    };
    std::vector<float> flat;
    const auto flat3 = [&](const std::vector<Vec3f>& v) {
        flat.clear();
        for (const Vec3f& p : v) flat.insert(flat.end(), {p.x, p.y, p.z});
        return flat;
    };
    const auto flat2 = [&](const std::vector<Vec2f>& v) {
        flat.clear();
        for (const Vec2f& p : v) flat.insert(flat.end(), {p.x, p.y});
        return flat;
    };
    std::vector<Vec3f> colors = ours.colors;
    // raylab keeps no colours when no vertex has one; tinyobj's fallback is white.
    if (colors.empty()) colors.assign(ours.positions.size(), Vec3f(1, 1, 1));
    if (!compareFloats("positions", flat3(ours.positions), attrib.vertices) ||
        !compareFloats("normals", flat3(ours.normals), attrib.normals) ||
        !compareFloats("texture coordinates", flat2(ours.texcoords), attrib.texcoords) ||
        !compareFloats("vertex colours", flat3(colors), attrib.colors)) {
        out.mismatch = why.str();
        return out;
    }

    // Faces: tinyobj's shapes in order are the file's faces in order.
    struct TinyFace {
        size_t firstIndex;
        unsigned count;
        int material;
        unsigned smoothing;
        const tinyobj::shape_t* shape;
    };
    std::vector<TinyFace> theirs;
    for (const tinyobj::shape_t& s : shapes) {
        size_t index = 0;
        for (size_t f = 0; f < s.mesh.num_face_vertices.size(); ++f) {
            theirs.push_back({index, s.mesh.num_face_vertices[f], s.mesh.material_ids[f],
                              s.mesh.smoothing_group_ids[f], &s});
            // The stored count may have wrapped (face-count-byte): the next
            // face's start comes from raylab's count below.
            index += s.mesh.num_face_vertices[f];
        }
    }
    std::vector<const ObjFace*> compared;
    for (const ObjFace& f : ours.faces)
        if (f.cornerCount >= 3) compared.push_back(&f);
    if (compared.size() != theirs.size()) {
        out.mismatch = "raylab has " + std::to_string(compared.size()) +
                       " faces of 3 or more corners, tinyobj " + std::to_string(theirs.size());
        return out;
    }
    const tinyobj::shape_t* shape = nullptr;
    size_t next = 0;  // the current face's first index in its shape
    for (size_t i = 0; i < compared.size(); ++i) {
        const ObjFace& f = *compared[i];
        const TinyFace& t = theirs[i];
        if (t.shape != shape) {
            shape = t.shape;
            next = 0;
        }
        const std::string at = "face at line " + std::to_string(f.line) + ": ";
        if (f.cornerCount >= 256) out.expected.insert("face-count-byte");
        if (t.count != f.cornerCount % 256) {
            out.mismatch = at + "raylab has " + std::to_string(f.cornerCount) +
                           " corners, tinyobj " + std::to_string(t.count);
            return out;
        }
        if (next + f.cornerCount > shape->mesh.indices.size()) {
            out.mismatch = at + "tinyobj has fewer corner indices than raylab";
            return out;
        }
        for (uint32_t k = 0; k < f.cornerCount; ++k) {
            const ObjCorner c = ours.corner(f.firstCorner + k);
            const tinyobj::index_t& x = shape->mesh.indices[next + k];
            if (int64_t(c.v) != x.vertex_index || c.vt != x.texcoord_index ||
                c.vn != x.normal_index) {
                out.mismatch = at + "corner " + std::to_string(k + 1) + " is " +
                               std::to_string(c.v) + "/" + std::to_string(c.vt) + "/" +
                               std::to_string(c.vn) + " in raylab, " +
                               std::to_string(x.vertex_index) + "/" +
                               std::to_string(x.texcoord_index) + "/" +
                               std::to_string(x.normal_index) + " in tinyobj (0-based)";
                return out;
            }
        }
        next += f.cornerCount;
        if (quirks.smoothingSpelling) {
            out.expected.insert("smoothing-spelling");
        } else if (f.smoothingGroup != t.smoothing) {
            out.mismatch = at + "smoothing group " + std::to_string(f.smoothingGroup) +
                           " in raylab, " + std::to_string(t.smoothing) + " in tinyobj";
            return out;
        }
        if (quirks.usemtlPrefix) {
            out.expected.insert("usemtl-prefix");
            continue;
        }
        const std::string ourName =
            f.material == kNoObjMaterial ? "" : ours.materialNames[f.material].name;
        const std::string ourFirstWord = tinyWord(ourName);
        if (ourFirstWord != ourName) out.expected.insert("names-with-blanks");
        const std::string theirName =
            t.material >= 0 && size_t(t.material) < materials.size()
                ? materials[size_t(t.material)].name
                : "";
        if (ourFirstWord != theirName) {
            out.mismatch = at + "material '" + ourName + "' in raylab, '" + theirName +
                           "' in tinyobj";
            return out;
        }
    }
    if (rounded) out.expected.insert("decimal-rounding");
    out.facesCompared = compared.size();
    return out;
}

}  // namespace raylab::test

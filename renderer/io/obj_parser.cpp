#include "renderer/io/obj_parser.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include "geometry/primitives.h"
#include "renderer/io/errors.h"
#include "renderer/io/wavefront_text.h"

namespace raylab {

namespace {

/// How many v, vt and vn statements the file has: a positive face index may
/// refer to an element defined later in the file (as tinyobjloader allowed).
struct ElementCounts {
    long long v = 0, vt = 0, vn = 0;
};

ElementCounts countElements(std::string_view text) {
    ElementCounts n;
    StatementReader reader(text);
    while (const auto s = reader.next()) {
        if (s->keyword == "v") ++n.v;
        else if (s->keyword == "vt") ++n.vt;
        else if (s->keyword == "vn") ++n.vn;
    }
    return n;
}

/// Keywords of the OBJ format that describe no surface raylab renders.
bool isUnrenderedKeyword(std::string_view k) {
    static const std::unordered_set<std::string_view> kKeywords = {
        "l", "p", "vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm",
        "trim", "hole", "scrv", "sp", "end", "con", "mg", "bevel", "c_interp", "d_interp",
        "lod", "usemap", "maplib", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh"};
    return kKeywords.count(k) > 0;
}

class ObjParser {
public:
    ObjParser(std::string_view text, const std::string& path, LoadWarnings& warn)
        : m_text(text), m_path(path), m_warn(warn), m_totals(countElements(text)) {}

    ObjData parse() {
        StatementReader reader(m_text);
        while (const auto s = reader.next()) statement(*s);
        m_data.linesRead = reader.linesRead();
        return std::move(m_data);
    }

private:
    [[noreturn]] void fail(int line, const std::string& message) const {
        throw InputError(m_path, line, message);
    }

    void statement(const Statement& s) {
        const std::string_view k = s.keyword;
        if (k == "v") return vertex(s);
        if (k == "vn") return normal(s);
        if (k == "vt") return texcoord(s);
        if (k == "f") return face(s);
        if (k == "usemtl") return useMaterial(s);
        if (k == "mtllib") {
            // Several files, or one whose name has blanks: the loader decides.
            m_data.libraries.push_back({slashPath(s.args), s.line, 1});
            return;
        }
        if (k == "s") return smoothingGroup(s);
        if (k == "g" || k == "o") return;  // names: one mesh per file
        if (isUnrenderedKeyword(k))
            m_warn.add("'" + std::string(k) +
                           "' statements (lines, points, free-form geometry) are not rendered",
                       s.line);
        else
            m_warn.add("unknown statement '" + terminalSafe(std::string(k.substr(0, 40))) +
                           "' is ignored",
                       s.line);
    }

    /// The numbers of a v/vn/vt statement; errors name the keyword and token.
    int numbers(const Statement& s, double* out, int maxCount) {
        std::string_view rest = withoutComment(s.args);
        int count = 0;
        for (std::string_view t = nextToken(rest); !t.empty(); t = nextToken(rest)) {
            const std::optional<double> x = parseNumber(t);
            if (!x)
                fail(s.line, "'" + std::string(s.keyword) + "': " + quotedToken(t) +
                                 " is not a finite number");
            // tinyobjloader's float: a larger value would become infinite.
            if (std::fabs(*x) > double(std::numeric_limits<float>::max()))
                fail(s.line, "'" + std::string(s.keyword) + "': " + quotedToken(t) +
                                 " is beyond float range (about 3.4e38)");
            if (count == maxCount)
                fail(s.line, "'" + std::string(s.keyword) + "' has more than " +
                                 std::to_string(maxCount) + " numbers");
            out[count++] = *x;
        }
        return count;
    }

    void vertex(const Statement& s) {
        double x[7];
        const int n = numbers(s, x, 7);
        if (n < 3)
            fail(s.line, "'v' needs 3 numbers, found " + std::to_string(n));
        // x y z, x y z w (a rational weight, ignored), or x y z r g b.
        if (n != 3 && n != 4 && n != 6)
            fail(s.line, "'v' takes x y z, x y z w or x y z r g b; found " + std::to_string(n) +
                             " numbers");
        m_data.positions.push_back(Vec3f(float(x[0]), float(x[1]), float(x[2])));
        if (n == 6) {
            if (x[3] < 0 || x[4] < 0 || x[5] < 0)
                fail(s.line, "'v': a vertex colour must be >= 0");
            // Vertices before the first coloured one are white (no tint).
            m_data.colors.resize(m_data.positions.size() - 1, Vec3f(1, 1, 1));
            m_data.colors.push_back(Vec3f(float(x[3]), float(x[4]), float(x[5])));
        } else if (!m_data.colors.empty()) {
            m_data.colors.push_back(Vec3f(1, 1, 1));
        }
    }

    void normal(const Statement& s) {
        double x[3];
        const int n = numbers(s, x, 3);
        if (n < 3) fail(s.line, "'vn' needs 3 numbers, found " + std::to_string(n));
        m_data.normals.push_back(Vec3f(float(x[0]), float(x[1]), float(x[2])));
    }

    void texcoord(const Statement& s) {
        double x[3] = {0, 0, 0};
        const int n = numbers(s, x, 3);
        if (n < 1) fail(s.line, "'vt' needs 1 to 3 numbers, found none");
        m_data.texcoords.push_back(Vec2f(float(x[0]), float(x[1])));
    }

    /// One index of a corner, resolved to 0-based; `soFar` elements precede
    /// the face, `total` are in the file.
    uint32_t index(int line, std::string_view text, long long soFar, long long total,
                   const char* what, const char* plural) const {
        long long idx = 0;
        const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), idx);
        const bool number = ptr == text.data() + text.size() && !text.empty() &&
                            (ec == std::errc() || ec == std::errc::result_out_of_range);
        if (!number)
            fail(line, "face corner has " + quotedToken(text) + " where a " + what +
                           " index belongs");
        const std::string shown = std::string(text.substr(0, 24));
        const auto count = [&](long long n) {
            return std::to_string(n) + " " + (n == 1 ? what : plural);
        };
        if (ec == std::errc() && idx < 0) {
            // Relative: -1 is the last element defined before this face.
            if (-idx > soFar)
                fail(line, std::string("face refers to ") + what + " " + shown +
                               " (relative) but only " + count(soFar) + " precede it");
            return uint32_t(soFar + idx);
        }
        if (ec != std::errc() || idx == 0 || idx > total)
            fail(line, std::string("face refers to ") + what + " " + shown +
                           " but the file has " + count(total));
        return uint32_t(idx - 1);
    }

    void face(const Statement& s) {
        ObjFace f;
        f.firstCorner = uint32_t(m_data.corners.size());
        f.material = m_material;
        f.smoothingGroup = m_smoothingGroup;
        f.line = s.line;
        std::string_view rest = withoutComment(s.args);
        for (std::string_view c = nextToken(rest); !c.empty(); c = nextToken(rest)) {
            // Ear clipping is quadratic in the corners: a 200000-corner face
            // would take many minutes.
            if (++f.cornerCount > kMaxTriangulatedVertices)
                fail(s.line, "face has more than " + std::to_string(kMaxTriangulatedVertices) +
                                 " corners (the triangulation limit)");
            m_data.corners.push_back(corner(s.line, c));
        }
        m_data.faces.push_back(f);
    }

    /// v, v/vt, v//vn or v/vt/vn.
    ObjCorner corner(int line, std::string_view c) const {
        const size_t s1 = c.find('/');
        const size_t s2 = s1 == std::string_view::npos ? s1 : c.find('/', s1 + 1);
        const auto malformed = [&](const char* what) {
            fail(line, "face corner " + quotedToken(c) + " " + what +
                           " (a corner is v, v/vt, v//vn or v/vt/vn)");
        };
        if (s2 != std::string_view::npos && c.find('/', s2 + 1) != std::string_view::npos)
            malformed("has more than two '/'");
        ObjCorner out;
        const std::string_view v = c.substr(0, s1);
        if (v.empty()) malformed("has no vertex index before '/'");
        out.v = index(line, v, long(m_data.positions.size()), m_totals.v, "vertex", "vertices");
        if (s1 == std::string_view::npos) return out;
        const std::string_view vt =
            c.substr(s1 + 1, (s2 == std::string_view::npos ? c.size() : s2) - s1 - 1);
        if (s2 == std::string_view::npos && vt.empty())
            malformed("has nothing after '/'");
        if (!vt.empty())
            out.vt = int32_t(index(line, vt, long(m_data.texcoords.size()), m_totals.vt,
                                   "texture coordinate", "texture coordinates"));
        if (s2 == std::string_view::npos) return out;
        const std::string_view vn = c.substr(s2 + 1);
        if (vn.empty()) malformed("has nothing after its second '/'");
        out.vn = int32_t(
            index(line, vn, long(m_data.normals.size()), m_totals.vn, "normal", "normals"));
        return out;
    }

    void useMaterial(const Statement& s) {
        const std::string name(s.args);  // trimmed; inner blanks are part of the name
        if (name.empty()) {
            m_material = kNoObjMaterial;
            m_warn.add("'usemtl' without a name: the default material is used", s.line);
            return;
        }
        const auto [it, added] =
            m_materialSlots.emplace(name, uint32_t(m_data.materialNames.size()));
        if (added)
            m_data.materialNames.push_back({name, s.line, 0});
        ++m_data.materialNames[it->second].uses;
        m_material = it->second;
    }

    void smoothingGroup(const Statement& s) {
        std::string_view rest = withoutComment(s.args);
        const std::string_view t = nextToken(rest);
        unsigned long group = 0;
        const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), group);
        if (t == "off") {
            m_smoothingGroup = 0;
        } else if (!t.empty() && ptr == t.data() + t.size() && ec == std::errc() &&
                   group <= UINT32_MAX) {
            m_smoothingGroup = uint32_t(group);
        } else {
            m_warn.add("'s' takes a group number or 'off'; " + quotedToken(t) + " is ignored",
                       s.line);
        }
    }

    std::string_view m_text;
    const std::string& m_path;
    LoadWarnings& m_warn;
    ElementCounts m_totals;
    ObjData m_data;
    uint32_t m_material = kNoObjMaterial;
    uint32_t m_smoothingGroup = 0;
    std::unordered_map<std::string, uint32_t> m_materialSlots;
};

}  // namespace

ObjData parseObj(std::string_view text, const std::string& path, LoadWarnings& warn) {
    return ObjParser(text, path, warn).parse();
}

}  // namespace raylab

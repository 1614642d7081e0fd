#include "renderer/io/obj_parser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <unordered_map>
#include <unordered_set>

#include "geometry/primitives.h"
#include "renderer/huge_pages.h"
#include "renderer/io/errors.h"
#include "renderer/io/wavefront_text.h"

namespace raylab {

namespace {

/// Where each chunk starts: at 0 and after the first '\n' at least
/// `chunkBytes` after the previous start (so a chunk holds whole lines).
std::vector<size_t> chunkStarts(std::string_view text, size_t chunkBytes) {
    std::vector<size_t> starts{0};
    size_t next = chunkBytes;
    while (next < text.size()) {
        const size_t nl = text.find('\n', std::max(next, starts.back()));
        if (nl == std::string_view::npos || nl + 1 >= text.size()) break;
        starts.push_back(nl + 1);
        next = nl + 1 + chunkBytes;
    }
    return starts;
}

/// What the first pass finds in a chunk; prefix sums of these place each
/// chunk's elements, faces, corners and lines in the whole file.
struct ChunkCounts {
    long long lines = 0, v = 0, vt = 0, vn = 0, f = 0, corners = 0;
    bool slashes = false;  ///< some face corner has a '/'
};

ChunkCounts countChunk(std::string_view chunk) {
    ChunkCounts n;
    StatementReader reader(chunk);
    while (const auto s = reader.next()) {
        const std::string_view k = s->keyword;
        if (k.size() > 2 || k.empty()) continue;
        if (k == "v") {
            ++n.v;
        } else if (k == "vt") {
            ++n.vt;
        } else if (k == "vn") {
            ++n.vn;
        } else if (k == "f") {
            ++n.f;
            std::string_view rest = withoutComment(s->args);
            for (std::string_view c = nextToken(rest); !c.empty(); c = nextToken(rest)) {
                ++n.corners;
                if (!n.slashes && c.find('/') != std::string_view::npos) n.slashes = true;
            }
        }
    }
    n.lines = reader.linesRead();
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

/// Warnings of one chunk, each message once with its first line and count,
/// replayed into LoadWarnings in chunk order: the same list a serial pass gives.
class ChunkWarnings {
public:
    void add(std::string message, int line) {
        const auto [it, added] = m_index.emplace(message, m_entries.size());
        if (added) m_entries.push_back({std::move(message), line, 0});
        ++m_entries[it->second].count;
    }
    void replay(LoadWarnings& warn) const {
        for (const Entry& e : m_entries)
            for (int i = 0; i < e.count; ++i) warn.add(e.message, e.line);
    }

private:
    struct Entry {
        std::string message;
        int line;
        int count;
    };
    std::vector<Entry> m_entries;
    std::unordered_map<std::string, size_t> m_index;
};

/// Where a chunk's elements go in the whole file's arrays.
struct ChunkPlace {
    long long line = 0, v = 0, vt = 0, vn = 0, f = 0, corners = 0;
};

/// The second pass over one chunk: fills its slices of `data` and keeps what
/// depends on the chunks before it (materials, smoothing group) to be settled
/// in the merge.
class ChunkParser {
public:
    ChunkParser(std::string_view chunk, const ChunkPlace& place, const ChunkCounts& totals,
                const std::string& path, ObjData& data)
        : m_chunk(chunk), m_place(place), m_totals(totals), m_path(path), m_data(data) {}

    /// Parses the chunk; an error is kept (the merge throws the first one).
    void run() {
        try {
            StatementReader reader(m_chunk);
            while (const auto s = reader.next()) statement(*s, int(m_place.line) + s->line);
        } catch (...) {
            error = std::current_exception();
        }
    }

    std::exception_ptr error;
    ChunkWarnings warnings;
    /// `usemtl` names in the order this chunk first uses them (views into the text).
    struct LocalName {
        std::string_view name;
        int line;
        int uses;
    };
    std::vector<LocalName> names;
    std::vector<ObjName> libraries;
    std::vector<Vec3f> colors;       ///< empty, or one per vertex of this chunk
    long long facesBeforeUsemtl = -1;  ///< faces before the first usemtl (-1: none)
    long long facesBeforeS = -1;       ///< faces before the first valid `s` (-1: none)
    uint32_t material = kNoObjMaterial;  ///< local index after the last usemtl
    uint32_t smoothingGroup = 0;         ///< after the last valid `s`

private:
    [[noreturn]] void fail(int line, const std::string& message) const {
        throw InputError(m_path, line, message);
    }

    void statement(const Statement& s, int line) {
        const std::string_view k = s.keyword;
        if (k == "v") return vertex(s, line);
        if (k == "f") return face(s, line);
        if (k == "vn") return normal(s, line);
        if (k == "vt") return texcoord(s, line);
        if (k == "usemtl") return useMaterial(s, line);
        if (k == "mtllib") {
            // Several files, or one whose name has blanks: the loader decides.
            libraries.push_back({slashPath(s.args), line, 1});
            return;
        }
        if (k == "s") return setSmoothingGroup(s, line);
        if (k == "g" || k == "o") return;  // names: one mesh per file
        if (isUnrenderedKeyword(k))
            warnings.add("'" + std::string(k) +
                             "' statements (lines, points, free-form geometry) are not rendered",
                         line);
        else
            warnings.add("unknown statement '" + terminalSafe(std::string(k.substr(0, 40))) +
                             "' is ignored",
                         line);
    }

    /// The numbers of a v/vn/vt statement; errors name the keyword and token.
    int numbers(const Statement& s, int line, double* out, int maxCount) const {
        std::string_view rest = withoutComment(s.args);
        int count = 0;
        for (std::string_view t = nextToken(rest); !t.empty(); t = nextToken(rest)) {
            const std::optional<double> x = parseNumber(t);
            if (!x)
                fail(line, "'" + std::string(s.keyword) + "': " + quotedToken(t) +
                               " is not a finite number");
            // tinyobjloader's float: a larger value would become infinite.
            if (std::fabs(*x) > double(std::numeric_limits<float>::max()))
                fail(line, "'" + std::string(s.keyword) + "': " + quotedToken(t) +
                               " is beyond float range (about 3.4e38)");
            if (count == maxCount)
                fail(line, "'" + std::string(s.keyword) + "' has more than " +
                               std::to_string(maxCount) + " numbers");
            out[count++] = *x;
        }
        return count;
    }

    void vertex(const Statement& s, int line) {
        double x[7];
        const int n = numbers(s, line, x, 7);
        if (n < 3) fail(line, "'v' needs 3 numbers, found " + std::to_string(n));
        // x y z, x y z w (a rational weight, ignored), or x y z r g b.
        if (n != 3 && n != 4 && n != 6)
            fail(line, "'v' takes x y z, x y z w or x y z r g b; found " + std::to_string(n) +
                           " numbers");
        const size_t i = size_t(m_place.v + m_v);
        m_data.positions[i] = Vec3f(float(x[0]), float(x[1]), float(x[2]));
        if (n == 6) {
            if (x[3] < 0 || x[4] < 0 || x[5] < 0) fail(line, "'v': a vertex colour must be >= 0");
            // Vertices without a colour are white (no tint).
            if (colors.empty()) colors.assign(size_t(m_count.v), Vec3f(1, 1, 1));
            colors[size_t(m_v)] = Vec3f(float(x[3]), float(x[4]), float(x[5]));
        }
        ++m_v;
    }

    void normal(const Statement& s, int line) {
        double x[3];
        const int n = numbers(s, line, x, 3);
        if (n < 3) fail(line, "'vn' needs 3 numbers, found " + std::to_string(n));
        m_data.normals[size_t(m_place.vn + m_vn++)] =
            Vec3f(float(x[0]), float(x[1]), float(x[2]));
    }

    void texcoord(const Statement& s, int line) {
        double x[3] = {0, 0, 0};
        const int n = numbers(s, line, x, 3);
        if (n < 1) fail(line, "'vt' needs 1 to 3 numbers, found none");
        m_data.texcoords[size_t(m_place.vt + m_vt++)] = Vec2f(float(x[0]), float(x[1]));
    }

    /// One index of a corner, resolved to 0-based; `soFar` elements precede
    /// the face, `total` are in the file.
    uint32_t index(int line, std::string_view text, long long soFar, long long total,
                   const char* what, const char* plural) const {
        // Nearly every index is a few plain digits naming an element in the
        // file: read without from_chars (~100 instructions an index), the
        // same value; anything else takes the general path below.
        if (!text.empty() && text.size() <= 9) {
            long long plain = 0;
            size_t k = 0;
            for (; k < text.size() && text[k] >= '0' && text[k] <= '9'; ++k)
                plain = plain * 10 + (text[k] - '0');
            if (k == text.size() && plain > 0 && plain <= total) return uint32_t(plain - 1);
        }
        long long idx = 0;
        const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), idx);
        const bool number = ptr == text.data() + text.size() && !text.empty() &&
                            (ec == std::errc() || ec == std::errc::result_out_of_range);
        if (!number)
            fail(line, "face corner has " + quotedToken(text) + " where a " + what +
                           " index belongs");
        if (ec == std::errc() && idx > 0 && idx <= total) return uint32_t(idx - 1);  // the usual case
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
        fail(line, std::string("face refers to ") + what + " " + shown + " but the file has " +
                       count(total));
    }

    void face(const Statement& s, int line) {
        ObjFace f;
        f.firstCorner = uint32_t(m_place.corners + m_corners);
        f.material = material;
        f.smoothingGroup = smoothingGroup;
        f.line = line;
        std::string_view rest = withoutComment(s.args);
        for (std::string_view c = nextToken(rest); !c.empty(); c = nextToken(rest)) {
            // Ear clipping is quadratic in the corners: a 200000-corner face
            // would take many minutes.
            if (++f.cornerCount > kMaxTriangulatedVertices)
                fail(line, "face has more than " + std::to_string(kMaxTriangulatedVertices) +
                               " corners (the triangulation limit)");
            corner(line, c, size_t(m_place.corners + m_corners++));
        }
        m_data.faces[size_t(m_place.f + m_f++)] = f;
    }

    /// v, v/vt, v//vn or v/vt/vn, stored at corner `at`. The checks run in
    /// the order the messages promise: slashes, then each index in turn.
    void corner(int line, std::string_view c, size_t at) const {
        const size_t s1 = c.find('/');
        const size_t s2 = s1 == std::string_view::npos ? s1 : c.find('/', s1 + 1);
        const auto malformed = [&](const char* what) {
            fail(line, "face corner " + quotedToken(c) + " " + what +
                           " (a corner is v, v/vt, v//vn or v/vt/vn)");
        };
        if (s2 != std::string_view::npos && c.find('/', s2 + 1) != std::string_view::npos)
            malformed("has more than two '/'");
        const std::string_view v = c.substr(0, s1);
        if (v.empty()) malformed("has no vertex index before '/'");
        m_data.cornerV[at] = index(line, v, m_place.v + m_v, m_totals.v, "vertex", "vertices");
        int32_t vti = -1, vni = -1;
        if (s1 != std::string_view::npos) {
            const std::string_view vt =
                c.substr(s1 + 1, (s2 == std::string_view::npos ? c.size() : s2) - s1 - 1);
            if (s2 == std::string_view::npos && vt.empty()) malformed("has nothing after '/'");
            if (!vt.empty())
                vti = int32_t(index(line, vt, m_place.vt + m_vt, m_totals.vt,
                                    "texture coordinate", "texture coordinates"));
            if (s2 != std::string_view::npos) {
                const std::string_view vn = c.substr(s2 + 1);
                if (vn.empty()) malformed("has nothing after its second '/'");
                vni = int32_t(
                    index(line, vn, m_place.vn + m_vn, m_totals.vn, "normal", "normals"));
            }
        }
        if (!m_data.cornerVt.empty()) {
            m_data.cornerVt[at] = vti;
            m_data.cornerVn[at] = vni;
        }
    }

    void useMaterial(const Statement& s, int line) {
        if (facesBeforeUsemtl < 0) facesBeforeUsemtl = m_f;
        const std::string_view name = s.args;  // trimmed; inner blanks are part of the name
        if (name.empty()) {
            material = kNoObjMaterial;
            warnings.add("'usemtl' without a name: the default material is used", line);
            return;
        }
        const auto [it, added] = m_slots.emplace(name, uint32_t(names.size()));
        if (added) names.push_back({name, line, 0});
        ++names[it->second].uses;
        material = it->second;
    }

    void setSmoothingGroup(const Statement& s, int line) {
        std::string_view rest = withoutComment(s.args);
        const std::string_view t = nextToken(rest);
        unsigned long group = 0;
        const auto [ptr, ec] = std::from_chars(t.data(), t.data() + t.size(), group);
        if (t == "off") {
            group = 0;
        } else if (!(!t.empty() && ptr == t.data() + t.size() && ec == std::errc() &&
                     group <= UINT32_MAX)) {
            warnings.add("'s' takes a group number or 'off'; " + quotedToken(t) + " is ignored",
                         line);
            return;
        }
        if (facesBeforeS < 0) facesBeforeS = m_f;
        smoothingGroup = uint32_t(group);
    }

public:
    /// This chunk's counts (set before run()).
    ChunkCounts m_count;

private:
    std::string_view m_chunk;
    ChunkPlace m_place;
    const ChunkCounts& m_totals;
    const std::string& m_path;
    ObjData& m_data;
    long long m_v = 0, m_vt = 0, m_vn = 0, m_f = 0, m_corners = 0;
    std::unordered_map<std::string_view, uint32_t> m_slots;
};

}  // namespace

ObjData parseObj(std::string_view text, const std::string& path, LoadWarnings& warn) {
    return parseObj(text, path, warn, kObjChunkBytes);
}

ObjData parseObj(std::string_view text, const std::string& path, LoadWarnings& warn,
                 size_t chunkBytes) {
    const std::vector<size_t> starts = chunkStarts(text, std::max<size_t>(chunkBytes, 1));
    const size_t chunkCount = starts.size();
    const auto chunkText = [&](size_t c) {
        const size_t end = c + 1 < chunkCount ? starts[c + 1] : text.size();
        return text.substr(starts[c], end - starts[c]);
    };

    // Pass 1: counts per chunk, then where each chunk's share goes.
    std::vector<ChunkCounts> counts(chunkCount);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, chunkCount, 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t c = r.begin(); c != r.end(); ++c)
                              counts[c] = countChunk(chunkText(c));
                      });
    ChunkCounts totals;
    std::vector<ChunkPlace> places(chunkCount);
    for (size_t c = 0; c < chunkCount; ++c) {
        places[c] = {totals.lines, totals.v, totals.vt, totals.vn, totals.f, totals.corners};
        totals.lines += counts[c].lines;
        totals.v += counts[c].v;
        totals.vt += counts[c].vt;
        totals.vn += counts[c].vn;
        totals.f += counts[c].f;
        totals.corners += counts[c].corners;
        totals.slashes = totals.slashes || counts[c].slashes;
    }
    if (totals.corners > (long long)UINT32_MAX || totals.v > (long long)UINT32_MAX)
        throw InputError(path, 0, "the OBJ file has more than 2^32 vertices or face corners");

    // Pass 2: every chunk fills its slices of the arrays, sized exactly once.
    ObjData data;
    resizeHugePages(data.positions, size_t(totals.v));
    resizeHugePages(data.normals, size_t(totals.vn));
    resizeHugePages(data.texcoords, size_t(totals.vt));
    resizeHugePages(data.faces, size_t(totals.f));
    resizeHugePages(data.cornerV, size_t(totals.corners));
    if (totals.slashes) {
        resizeHugePages(data.cornerVt, size_t(totals.corners));
        resizeHugePages(data.cornerVn, size_t(totals.corners));
    }
    std::vector<std::unique_ptr<ChunkParser>> parsers(chunkCount);
    for (size_t c = 0; c < chunkCount; ++c) {
        parsers[c] = std::make_unique<ChunkParser>(chunkText(c), places[c], totals, path, data);
        parsers[c]->m_count = counts[c];
    }
    tbb::parallel_for(tbb::blocked_range<size_t>(0, chunkCount, 1),
                      [&](const tbb::blocked_range<size_t>& r) {
                          for (size_t c = r.begin(); c != r.end(); ++c) parsers[c]->run();
                      });

    // The first error in the file: chunks before the first failing one read cleanly.
    for (const auto& p : parsers)
        if (p->error) std::rethrow_exception(p->error);

    // Merge in file order: warnings, library names, material names, colours,
    // and the usemtl / s state each chunk starts with.
    std::unordered_map<std::string_view, uint32_t> globalSlot;
    std::vector<std::vector<uint32_t>> remap(chunkCount);
    std::vector<uint32_t> startMaterial(chunkCount), startGroup(chunkCount);
    uint32_t material = kNoObjMaterial, group = 0;
    bool anyColors = false;
    for (size_t c = 0; c < chunkCount; ++c) {
        ChunkParser& p = *parsers[c];
        p.warnings.replay(warn);
        for (ObjName& l : p.libraries) data.libraries.push_back(std::move(l));
        for (const ChunkParser::LocalName& n : p.names) {
            const auto [it, added] =
                globalSlot.emplace(n.name, uint32_t(data.materialNames.size()));
            if (added) data.materialNames.push_back({std::string(n.name), n.line, 0});
            data.materialNames[it->second].uses += n.uses;
            remap[c].push_back(it->second);
        }
        startMaterial[c] = material;
        startGroup[c] = group;
        if (p.facesBeforeUsemtl >= 0)
            material = p.material == kNoObjMaterial ? kNoObjMaterial : remap[c][p.material];
        if (p.facesBeforeS >= 0) group = p.smoothingGroup;
        anyColors = anyColors || !p.colors.empty();
    }
    if (anyColors) data.colors.assign(data.positions.size(), Vec3f(1, 1, 1));
    tbb::parallel_for(tbb::blocked_range<size_t>(0, chunkCount, 1),
                      [&](const tbb::blocked_range<size_t>& r) {
        for (size_t c = r.begin(); c != r.end(); ++c) {
            const ChunkParser& p = *parsers[c];
            ObjFace* faces = data.faces.data() + places[c].f;
            const long long n = counts[c].f;
            const long long inheritM = p.facesBeforeUsemtl < 0 ? n : p.facesBeforeUsemtl;
            const long long inheritS = p.facesBeforeS < 0 ? n : p.facesBeforeS;
            for (long long i = 0; i < n; ++i) {
                ObjFace& f = faces[i];
                if (i < inheritM) f.material = startMaterial[c];
                else if (f.material != kNoObjMaterial) f.material = remap[c][f.material];
                if (i < inheritS) f.smoothingGroup = startGroup[c];
            }
            if (!p.colors.empty())
                std::copy(p.colors.begin(), p.colors.end(),
                          data.colors.begin() + long(places[c].v));
        }
    });
    data.linesRead = int(totals.lines);
    return data;
}

}  // namespace raylab

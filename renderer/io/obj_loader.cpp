#include "renderer/io/obj_loader.h"

#include "geometry/primitives.h"

#include <tiny_obj_loader.h>

#include <sys/stat.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>

#include "renderer/io/errors.h"
#include "renderer/io/text_file.h"
#include "renderer/scene.h"

namespace raylab {

// ---------------------------------------------------------------------------
// MeshTransform

namespace {
constexpr double kPi = 3.14159265358979323846;
}

MeshTransform MeshTransform::translate(const Vec3& offset) {
    MeshTransform t;
    t.translation = offset;
    return t;
}

MeshTransform MeshTransform::scale(const Vec3& factors) {
    MeshTransform t;
    t.linear = {{{factors.x, 0, 0}, {0, factors.y, 0}, {0, 0, factors.z}}};
    return t;
}

MeshTransform MeshTransform::rotate(const Vec3& axis, double degrees) {
    // Rodrigues: R = cos θ I + sin θ [k]x + (1 - cos θ) k kᵀ, k the unit axis.
    const Vec3 k = normalize(axis);
    const double theta = degrees * kPi / 180.0;
    const double c = std::cos(theta), s = std::sin(theta), C = 1 - c;
    MeshTransform t;
    t.linear = {{{c + k.x * k.x * C, k.x * k.y * C - k.z * s, k.x * k.z * C + k.y * s},
                 {k.y * k.x * C + k.z * s, c + k.y * k.y * C, k.y * k.z * C - k.x * s},
                 {k.z * k.x * C - k.y * s, k.z * k.y * C + k.x * s, c + k.z * k.z * C}}};
    return t;
}

MeshTransform MeshTransform::then(const MeshTransform& next) const {
    // next(this(p)) = N (L p + t) + n = (N L) p + (N t + n)
    MeshTransform r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double sum = 0;
            for (int k = 0; k < 3; ++k) sum += next.linear[i][k] * linear[k][j];
            r.linear[i][j] = sum;
        }
    r.translation = next.applyPoint(translation);
    return r;
}

Vec3 MeshTransform::applyPoint(const Vec3& p) const {
    const auto& m = linear;
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + translation.x,
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + translation.y,
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + translation.z};
}

Vec3 MeshTransform::applyNormal(const Vec3& n) const {
    // The inverse transpose equals cofactor(L) / det(L); the positive factor
    // 1/|det| drops out under normalisation, but the sign of det must stay so
    // a mirroring transform keeps normals on the side the winding says is outside.
    const auto& m = linear;
    const Vec3 r0{m[0][0], m[0][1], m[0][2]}, r1{m[1][0], m[1][1], m[1][2]},
        r2{m[2][0], m[2][1], m[2][2]};
    // Row i of the cofactor matrix is the cross product of the other two rows.
    const Vec3 c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
    const Vec3 out{dot(c0, n), dot(c1, n), dot(c2, n)};
    return normalize(determinant() < 0 ? -out : out);
}

double MeshTransform::determinant() const {
    const auto& m = linear;
    return dot(Vec3{m[0][0], m[0][1], m[0][2]},
               cross(Vec3{m[1][0], m[1][1], m[1][2]}, Vec3{m[2][0], m[2][1], m[2][2]}));
}

bool MeshTransform::isIdentity() const {
    const MeshTransform id;
    return linear == id.linear && translation == id.translation;
}

size_t ObjModel::triangleCount() const {
    size_t n = 0;
    for (const ObjMeshPart& p : parts) n += p.mesh->triangleCount();
    return n;
}

// ---------------------------------------------------------------------------
// Reading

namespace {

/// Splits tinyobjloader's newline-separated messages into trimmed lines.
std::vector<std::string> splitMessages(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const size_t a = line.find_first_not_of(" \t\r.");
        if (a == std::string::npos) continue;
        const size_t b = line.find_last_not_of(" \t\r");
        out.push_back(line.substr(a, b - a + 1));
    }
    return out;
}

/// The line a tinyobjloader message refers to, and the message without that
/// reference. Its formats vary ("... (line 12.)", "... line 12.)", "line: 12",
/// "(line 4 in .mtl.)"); the last "line" followed by a number is the one (a
/// material name quoted earlier in the message may contain the word).
/// Returns {0, message} when there is none.
std::pair<int, std::string> splitLineReference(const std::string& message) {
    for (size_t at = message.rfind("line"); at != std::string::npos;
         at = at == 0 ? std::string::npos : message.rfind("line", at - 1)) {
        size_t q = at + 4;
        while (q < message.size() && (message[q] == ':' || message[q] == ' ')) ++q;
        if (q >= message.size() || !std::isdigit(static_cast<unsigned char>(message[q])))
            continue;
        const int line = std::atoi(message.c_str() + q);
        size_t cut = at;
        while (cut > 0 && (message[cut - 1] == ' ' || message[cut - 1] == '(' ||
                           message[cut - 1] == '.'))
            --cut;
        return {line, message.substr(0, cut)};
    }
    return {0, message};
}

/// Collects warnings once each, counting repeats (an OBJ whose MTL lacks a
/// material repeats "material not found" for every usemtl), and formats them
/// as "FILE:LINE: message" (or "FILE: message" when no line applies).
class Warnings {
public:
    explicit Warnings(std::string path) : m_path(std::move(path)) {}
    /// `file` names another file than the OBJ (an MTL library).
    void add(const std::string& message, int line = 0, const std::string& file = "") {
        const std::string where = file.empty() ? m_path : file;
        auto [it, inserted] = m_counts.emplace(where + "\n" + message, Entry{where, message, line, 0});
        if (inserted) m_order.push_back(it->first);
        ++it->second.count;
    }
    std::vector<std::string> lines() const {
        std::vector<std::string> out;
        for (const std::string& key : m_order) {
            const Entry& e = m_counts.at(key);
            out.push_back(e.file + (e.line > 0 ? ":" + std::to_string(e.line) : "") + ": " +
                          e.message +
                          (e.count > 1 ? " (" + std::to_string(e.count) + " times)" : ""));
        }
        return out;
    }

private:
    struct Entry {
        std::string file, message;
        int line;
        int count;
    };
    std::string m_path;
    std::map<std::string, Entry> m_counts;
    std::vector<std::string> m_order;
};

/// Calls `fn(keyword, rest, lineNo)` for every statement line of an OBJ text;
/// `keyword` and `rest` are [begin, end) pointer pairs within the line.
template <class Fn>
void forEachStatement(const std::string& text, Fn fn) {
    const char* p = text.data();
    const char* const end = p + text.size();
    int lineNo = 0;
    while (p < end) {
        const char* eol = p;
        while (eol < end && *eol != '\n') ++eol;
        ++lineNo;
        const char* k = p;
        while (k < eol && (*k == ' ' || *k == '\t')) ++k;
        const char* ke = k;
        while (ke < eol && *ke != ' ' && *ke != '\t' && *ke != '\r') ++ke;
        if (ke > k) fn(std::string(k, ke), ke, eol, lineNo);
        p = eol + 1;
    }
}

/// Finds the first face line with a vertex or normal index out of range.
/// Relative (negative) indices resolve against the elements read so far and
/// positive ones against the whole file, as in tinyobjloader. This runs
/// before tinyobjloader, whose triangulation reads vertices by index unchecked.
/// Returns {line, message} or {0, ""}.
std::pair<int, std::string> findBadFaceIndex(const std::string& text) {
    long vTotal = 0, vtTotal = 0, vnTotal = 0;
    forEachStatement(text, [&](const std::string& kw, const char*, const char*, int) {
        if (kw == "v") ++vTotal;
        if (kw == "vt") ++vtTotal;
        if (kw == "vn") ++vnTotal;
    });
    // `text` is one index as written (up to the next '/' or the corner's end).
    auto check = [](const std::string& text, long soFar, long total, const char* what,
                    const char* plural) -> std::string {
        errno = 0;
        char* end = nullptr;
        const long idx = std::strtol(text.c_str(), &end, 10);
        if (end == text.c_str() || *end != '\0')
            return std::string("face corner has '") + text.substr(0, 24) + "' where a " + what +
                   " index belongs";
        const long resolved = idx > 0 ? idx - 1 : soFar + idx;
        if (errno == ERANGE || idx == 0 || resolved < 0 || resolved >= total)
            return std::string("face refers to ") + what + " " + text.substr(0, 24) +
                   " but the file has " + std::to_string(total) + " " +
                   (total == 1 ? what : plural);
        return "";
    };
    long vSoFar = 0, vtSoFar = 0, vnSoFar = 0;
    std::pair<int, std::string> bad{0, ""};
    forEachStatement(text, [&](const std::string& kw, const char* q, const char* eol, int line) {
        if (kw == "v") ++vSoFar;
        if (kw == "vt") ++vtSoFar;
        if (kw == "vn") ++vnSoFar;
        if (kw != "f" || bad.first > 0) return;
        for (const char* c = q; c < eol; ++c)  // a '#' starts a trailing comment
            if (*c == '#') {
                eol = c;
                break;
            }
        size_t corners = 0;
        while (true) {
            while (q < eol && (*q == ' ' || *q == '\t' || *q == '\r')) ++q;
            if (q >= eol) break;
            // One corner: v, v/vt, v//vn or v/vt/vn.
            const char* ce = q;
            while (ce < eol && *ce != ' ' && *ce != '\t' && *ce != '\r') ++ce;
            const std::string corner(q, ce);
            q = ce;
            // tinyobjloader's ear clipping is quadratic: a 200000-corner face
            // would take many minutes, so faces beyond the limit are refused.
            if (++corners > kMaxTriangulatedVertices) {
                bad = {line, "face has more than " + std::to_string(kMaxTriangulatedVertices) +
                                 " corners (the triangulation limit)"};
                return;
            }
            const size_t s1 = corner.find('/');
            const size_t s2 = s1 == std::string::npos ? s1 : corner.find('/', s1 + 1);
            std::string message =
                check(corner.substr(0, s1), vSoFar, vTotal, "vertex", "vertices");
            // v/vt and v/vt/vn: raylab does not use texture coordinates, but
            // one out of range is a broken file all the same.
            const size_t vtEnd = s2 == std::string::npos ? corner.size() : s2;
            if (message.empty() && s1 != std::string::npos && vtEnd > s1 + 1)
                message = check(corner.substr(s1 + 1, vtEnd - s1 - 1), vtSoFar, vtTotal,
                                "texture coordinate", "texture coordinates");
            if (message.empty() && s2 != std::string::npos && s2 + 1 < corner.size())
                message = check(corner.substr(s2 + 1), vnSoFar, vnTotal, "normal", "normals");
            if (!message.empty()) {
                bad = {line, message};
                return;
            }
        }
    });
    return bad;
}

/// A statement whose arguments are all numbers.
struct NumericStatement {
    const char* keyword;
    int minArgs;  ///< fewer is an error (tinyobjloader would read the rest as 0)
};

/// Finds the first of `statements` with an argument that is not a finite
/// number, or with too few. tinyobjloader reads "nan", "inf", words it cannot
/// parse and missing values as 0 without a word, which would silently make a
/// different mesh or material. With `floatRange`, finite values beyond float
/// (tinyobjloader's type) are refused too instead of becoming infinities.
/// `skipWords` are allowed first arguments that introduce a non-numeric form
/// (MTL "Kd spectral file.rfl", "Kd xyz 1 1 1").
/// Returns {line, message} or {0, ""}.
std::pair<int, std::string> findBadNumber(const std::string& text,
                                          std::initializer_list<NumericStatement> statements,
                                          bool floatRange,
                                          std::initializer_list<const char*> skipWords = {}) {
    std::pair<int, std::string> bad{0, ""};
    forEachStatement(text, [&](const std::string& kw, const char* q, const char* eol, int line) {
        if (bad.first > 0) return;
        int minArgs = -1;
        for (const NumericStatement& st : statements)
            if (kw == st.keyword) minArgs = st.minArgs;
        if (minArgs < 0) return;
        // A '#' starts a comment, also after the numbers.
        for (const char* c = q; c < eol; ++c)
            if (*c == '#') {
                eol = c;
                break;
            }
        int count = 0;
        while (true) {
            while (q < eol && (*q == ' ' || *q == '\t' || *q == '\r')) ++q;
            if (q >= eol) break;
            const char* te = q;
            while (te < eol && *te != ' ' && *te != '\t' && *te != '\r') ++te;
            const std::string token(q, te);
            q = te;
            if (count == 0)
                for (const char* w : skipWords)
                    if (token == w) return;
            ++count;
            char* end = nullptr;
            const double x = std::strtod(token.c_str(), &end);
            // Every v/vn/vt of a mesh passes here: the message is only built for a bad one.
            const auto shown = [&] { return "'" + kw + "': '" + token.substr(0, 40) + "'"; };
            if (end != token.c_str() + token.size() || !std::isfinite(x)) {
                bad = {line, shown() + " is not a finite number"};
                return;
            }
            if (floatRange && std::fabs(x) > double(std::numeric_limits<float>::max())) {
                bad = {line, shown() + " is beyond float range (about 3.4e38)"};
                return;
            }
        }
        if (count < minArgs)
            bad = {line, "'" + kw + "' needs " + std::to_string(minArgs) + " numbers, found " +
                             std::to_string(count)};
    });
    return bad;
}

/// Line of the `index`-th (0-based) statement with keyword `kw`, or 0.
int lineOfStatement(const std::string& text, const std::string& kw, size_t index) {
    int found = 0;
    size_t seen = 0;
    forEachStatement(text, [&](const std::string& k, const char*, const char*, int line) {
        if (found == 0 && k == kw && seen++ == index) found = line;
    });
    return found;
}

/// Line of the first statement `kw` with `arg` among its blank-separated
/// arguments, or 0.
int lineOfStatementWith(const std::string& text, const std::string& kw, const std::string& arg) {
    int found = 0;
    forEachStatement(text, [&](const std::string& k, const char* rest, const char* eol, int line) {
        if (found != 0 || k != kw) return;
        std::istringstream args(std::string(rest, eol));
        for (std::string token; args >> token;)
            if (token == arg) found = line;
    });
    return found;
}

/// The text between the first `open` and the following `close` in s, trimmed
/// of blanks and quotes ("" when absent).
std::string between(const std::string& s, const std::string& open, const std::string& close) {
    const size_t a = s.find(open);
    if (a == std::string::npos) return "";
    const size_t b = s.find(close, a + open.size());
    if (b == std::string::npos) return "";
    std::string v = s.substr(a + open.size(), b - a - open.size());
    const auto keep = [](char c) { return c != ' ' && c != '\''; };
    while (!v.empty() && !keep(v.front())) v.erase(v.begin());
    while (!v.empty() && !keep(v.back())) v.pop_back();
    return v;
}

/// tinyobjloader's warnings, reworded with the line they are about. When no
/// library loads it reports that three ways ("Material file [ x ] not found",
/// "Failed to load material file(s)", then "material [ 'm' ] not found" for
/// every usemtl); the user gets one line per missing library, at its mtllib
/// statement. When another library did load, undefined names are still
/// reported.
void addTinyObjWarnings(const std::vector<std::string>& messages, const std::string& text,
                        Warnings& warn) {
    bool noLibraryLoaded = false;
    for (const std::string& m : messages) {
        if (m.rfind("Material file [", 0) == 0) {
            const std::string name = between(m, "[", "]");
            warn.add("material library '" + name +
                         "' not found beside the OBJ; its materials get the default material",
                     lineOfStatementWith(text, "mtllib", name));
        }
        if (m.rfind("Failed to load material file", 0) == 0) noLibraryLoaded = true;
    }
    for (const std::string& m : messages) {
        if (m.rfind("Material file [", 0) == 0 || m.rfind("Failed to load material file", 0) == 0)
            continue;
        if (m.rfind("material [", 0) == 0 && m.find("not found") != std::string::npos) {
            if (noLibraryLoaded) continue;  // a consequence of the missing library
            const std::string name = between(m, "[", "]");
            warn.add("material '" + name + "' is not defined in the MTL libraries; the default "
                     "material is used", lineOfStatementWith(text, "usemtl", name));
            continue;
        }
        // Anything else is passed on, at the line tinyobjloader names in it.
        const auto [line, message] = splitLineReference(m);
        warn.add(message, line);
    }
}

/// The MTL text with the statements tinyobjloader misreads rewritten, line
/// for line (line numbers stay valid): "d -halo X" becomes "d X" (it would
/// read the dissolve as 0), and a colour with one value, "Kd 0.5", becomes
/// "Kd 0.5 0.5 0.5" (the MTL rule: g = b = r; it would read 0.5 0 0, red).
std::string normalizeMtl(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    size_t p = 0;
    while (p <= text.size()) {
        size_t eol = text.find('\n', p);
        if (eol == std::string::npos) eol = text.size();
        std::string line = text.substr(p, eol - p);
        const size_t hash = line.find('#');  // a trailing comment is kept as it is
        const std::string comment = hash == std::string::npos ? "" : " " + line.substr(hash);
        std::istringstream in(line.substr(0, hash));
        std::vector<std::string> tokens;
        for (std::string t; in >> t;) tokens.push_back(t);
        const bool colour = !tokens.empty() && (tokens[0] == "Ka" || tokens[0] == "Kd" ||
                                                tokens[0] == "Ks" || tokens[0] == "Ke" ||
                                                tokens[0] == "Tf" || tokens[0] == "Kt");
        if (tokens.size() == 3 && tokens[0] == "d" && tokens[1] == "-halo")
            line = "d " + tokens[2] + comment;
        else if (colour && tokens.size() == 2)
            line = tokens[0] + " " + tokens[1] + " " + tokens[1] + " " + tokens[1] + comment;
        out += line;
        if (eol < text.size()) out += '\n';
        p = eol + 1;
    }
    return out;
}

/// Reads the MTL libraries an OBJ names, in place of tinyobjloader's
/// MaterialFileReader: through readTextFile, so a device, FIFO or huge file
/// is refused instead of read without end; relative to the OBJ's directory
/// (absolute names stay absolute); with NaN/Inf values refused at their line;
/// and keeping each library's text so a bad material, and each warning, is
/// reported at the MTL's own line.
class MtlLibraryReader : public tinyobj::MaterialReader {
public:
    struct Library {
        std::string path, text;
        size_t firstMaterial = 0, endMaterial = 0;  ///< [first, end) in the material list
    };
    struct Warning {
        std::string path;
        int line;
        std::string message;
    };

    explicit MtlLibraryReader(std::string objPath) : m_objPath(std::move(objPath)) {}

    bool operator()(const std::string& matId, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* matMap, std::string* warn,
                    std::string*) override {
        const std::string path = resolveRelativeTo(m_objPath, matId);
        struct stat st {};
        // Only a library that is not there is a warning (the render goes on
        // with the default material); one that is there but cannot be read
        // is an error naming it.
        if (::stat(path.c_str(), &st) != 0 && (errno == ENOENT || errno == ENOTDIR)) {
            if (warn) *warn += "Material file [ " + matId + " ] not found\n";
            return false;
        }
        Library lib;
        lib.path = path;
        lib.text = readTextFile(path);
        if (const auto [line, message] = findNonText(lib.text, "MTL"); line > 0)
            throw InputError(path, line, message);
        const std::string normalized = normalizeMtl(lib.text);
        if (const auto [line, message] = findBadNumber(
                normalized,
                {{"Ka", 3}, {"Kd", 3}, {"Ks", 3}, {"Ke", 3}, {"Tf", 3}, {"Kt", 3}, {"Ns", 1},
                 {"Ni", 1}, {"d", 1}, {"Tr", 1}, {"illum", 1}},
                false, {"spectral", "xyz"});
            line > 0)
            throw InputError(path, line, message);
        lib.firstMaterial = materials->size();
        std::istringstream in(normalized);
        std::string mtlWarnings, mtlErrors;
        tinyobj::LoadMtl(matMap, materials, &in, &mtlWarnings, &mtlErrors);
        for (const std::string* text : {&mtlErrors, &mtlWarnings})
            for (const std::string& m : splitMessages(*text)) {
                const auto [line, message] = splitLineReference(m);
                m_warnings.push_back({path, line, message});
            }
        lib.endMaterial = materials->size();
        m_libraries.push_back(std::move(lib));
        return true;
    }

    /// What tinyobjloader said about the libraries, each at its MTL line.
    const std::vector<Warning>& warnings() const { return m_warnings; }

    /// FILE and LINE of the first of `keywords` inside material `index`'s
    /// block (the `newmtl` line when the block has none), for errors about it.
    std::pair<std::string, int> locate(size_t index, const std::string& name,
                                       std::initializer_list<const char*> keywords) const {
        for (const Library& lib : m_libraries) {
            if (index < lib.firstMaterial || index >= lib.endMaterial) continue;
            int newmtl = 0, found = 0;
            bool ended = false;
            forEachStatement(lib.text, [&](const std::string& k, const char* rest,
                                           const char* eol, int line) {
                if (found || ended) return;
                if (k == "newmtl") {
                    if (newmtl) {
                        ended = true;  // the block ended without any of `keywords`
                        return;
                    }
                    // The name as tinyobjloader takes it: the rest of the
                    // line after one blank, without trailing blanks.
                    std::string n(rest < eol ? rest + 1 : eol, eol);
                    while (!n.empty() && (n.back() == ' ' || n.back() == '\t' || n.back() == '\r'))
                        n.pop_back();
                    if (n == name) newmtl = line;
                    return;
                }
                if (newmtl)
                    for (const char* kw : keywords)
                        if (k == kw) found = line;
            });
            return {lib.path, found ? found : newmtl};
        }
        return {m_objPath, 0};
    }

private:
    std::string m_objPath;
    std::vector<Library> m_libraries;
    std::vector<Warning> m_warnings;
};

Color colorOf(const tinyobj::real_t c[3]) { return Color(c[0], c[1], c[2]); }

/// The MTL -> Whitted mapping documented in obj_loader.h.
Material materialFromMtl(const tinyobj::material_t& m, size_t index,
                         const MtlLibraryReader& libraries, Warnings& warn) {
    // Warnings and errors point at the MTL statement they are about.
    const auto note = [&](std::initializer_list<const char*> keywords, const std::string& what) {
        const auto [file, line] = libraries.locate(index, m.name, keywords);
        warn.add("material '" + m.name + "': " + what, line, file);
    };
    Material out;
    out.name = m.name;
    out.ka = colorOf(m.ambient);
    out.kd = colorOf(m.diffuse);
    out.ks = colorOf(m.specular);
    out.shininess = m.shininess;
    int illum = m.illum;
    if (illum < 0 || illum > 10) {
        note({"illum"}, "illum " + std::to_string(illum) + " is unknown; read as illum 2");
        illum = 2;
    }
    if (illum == 0) out.ka = Color(0);
    if (illum <= 1) out.ks = Color(0);
    if (illum >= 3 && illum <= 7) out.km = colorOf(m.specular);
    if (illum == 4 || illum == 6 || illum == 7) {
        const Color tf = colorOf(m.transmittance);
        out.kt = !tf.isBlack() ? tf : Color(1.0 - double(m.dissolve));
    } else if (m.dissolve < 1) {
        note({"d", "Tr"}, "dissolve d < 1 is ignored with illum " + std::to_string(illum) +
                              " (transparency needs illum 4, 6 or 7)");
    }
    out.ior = m.ior > 0 ? m.ior : 1.0;
    if (!m.diffuse_texname.empty() || !m.specular_texname.empty() || !m.bump_texname.empty() ||
        !m.ambient_texname.empty() || !m.alpha_texname.empty())
        note({"map_Kd", "map_Ks", "map_Ka", "map_d", "bump", "map_bump"},
             "texture maps are not supported and are ignored");

    const auto refuse = [&](std::initializer_list<const char*> keywords,
                            const std::string& what) {
        const auto [file, line] = libraries.locate(index, m.name, keywords);
        return InputError(file, line, "material '" + m.name + "': " + what);
    };
    const auto bad = [](const Color& c) { return !c.isFinite() || c.r < 0 || c.g < 0 || c.b < 0; };
    const char* const colourRule = ": colours must be finite and >= 0";
    if (bad(out.ka)) throw refuse({"Ka"}, std::string("Ka") + colourRule);
    if (bad(out.kd)) throw refuse({"Kd"}, std::string("Kd") + colourRule);
    if (bad(out.ks) || bad(out.km)) throw refuse({"Ks"}, std::string("Ks") + colourRule);
    // The transmission comes from Tf (or Kt), else from 1 - dissolve (d, Tr).
    if (bad(out.kt)) {
        if (!colorOf(m.transmittance).isBlack())
            throw refuse({"Tf", "Kt"}, std::string("Tf") + colourRule);
        throw refuse({"d", "Tr"}, "the dissolve d (or 1 - Tr) must be in [0, 1]");
    }
    if (!(out.shininess >= 0 && std::isfinite(out.shininess)))
        throw refuse({"Ns"}, "Ns must be finite and >= 0");
    if (!std::isfinite(out.ior)) throw refuse({"Ni"}, "Ni must be finite");
    return out;
}

/// Builds one mesh part, sharing vertices between triangles that use the same
/// (position, normal) index pair.
struct PartBuilder {
    ObjMeshPart part;
    std::unordered_map<uint64_t, uint32_t> vertexOf;
    bool smooth = false;

    uint32_t vertex(int v, int vn, const tinyobj::attrib_t& a, const MeshTransform& xf) {
        const uint64_t key = (uint64_t(uint32_t(v)) << 32) | uint32_t(smooth ? vn + 1 : 0);
        const auto [it, inserted] = vertexOf.emplace(key, uint32_t(part.mesh->positions.size()));
        if (inserted) {
            const auto& p = a.vertices;
            part.mesh->positions.push_back(
                xf.applyPoint(Vec3(p[3 * v], p[3 * v + 1], p[3 * v + 2])));
            if (smooth) {
                const auto& n = a.normals;
                part.mesh->normals.push_back(
                    xf.applyNormal(Vec3(n[3 * vn], n[3 * vn + 1], n[3 * vn + 2])));
            }
        }
        return it->second;
    }
};

}  // namespace

ObjModel loadObj(const std::string& path, const ObjLoadOptions& options) {
    const std::string text = readTextFile(path);
    // tinyobjloader reads a NUL as the end of a line and UTF-16 as no statements.
    if (const auto [line, message] = findNonText(text, "OBJ"); line > 0)
        throw InputError(path, line, message);
    // tinyobjloader only warns about bad indices (reporting the file's last
    // line) and may read out of bounds first; check them here with the real line.
    if (const auto [line, message] = findBadFaceIndex(text); line > 0)
        throw InputError(path, line, message);
    if (const auto [line, message] = findBadNumber(text, {{"v", 3}, {"vn", 3}, {"vt", 1}}, true);
        line > 0)
        throw InputError(path, line, message);

    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> mtls;
    std::string warnText, errText;
    std::istringstream stream(text);
    // MTL libraries are looked up beside the OBJ ("" = current directory).
    MtlLibraryReader mtlReader(path);
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &mtls, &warnText, &errText, &stream,
                                     &mtlReader, /*triangulate=*/true,
                                     /*default_vcols_fallback=*/false);
    Warnings warn(path);
    const std::vector<std::string> errors = splitMessages(errText);
    if (!ok) {
        const std::string first = errors.empty() ? "cannot parse the OBJ file" : errors.front();
        const auto [line, message] = splitLineReference(first);
        throw InputError(path, line, message);
    }
    for (const std::string& e : errors) warn.add(e);

    const size_t vertexCount = attrib.vertices.size() / 3;
    const size_t normalCount = attrib.normals.size() / 3;

    // findBadFaceIndex checked the text already; this guards against our scan
    // and tinyobjloader's parser disagreeing, never against a crash.
    for (const auto& sh : shapes)
        for (const auto& idx : sh.mesh.indices)
            if (idx.vertex_index < 0 || size_t(idx.vertex_index) >= vertexCount ||
                idx.normal_index < -1 ||
                (idx.normal_index >= 0 && size_t(idx.normal_index) >= normalCount))
                throw InputError(path, 0, "face index out of range");
    addTinyObjWarnings(splitMessages(warnText), text, warn);

    for (size_t i = 0; i < vertexCount; ++i)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(attrib.vertices[3 * i + k]))
                throw InputError(path, lineOfStatement(text, "v", i),
                                 "vertex " + std::to_string(i + 1) + " is not finite");

    ObjModel model;
    for (const MtlLibraryReader::Warning& w : mtlReader.warnings())
        warn.add(w.message, w.line, w.path);
    for (size_t i = 0; i < mtls.size(); ++i)
        model.materials.push_back(materialFromMtl(mtls[i], i, mtlReader, warn));
    const uint32_t mtlCount = uint32_t(model.materials.size());
    bool needDefault = false;

    PartBuilder smooth, flat;
    smooth.smooth = true;
    smooth.part.mesh = std::make_shared<TriangleMesh>();
    flat.part.mesh = std::make_shared<TriangleMesh>();
    const MeshTransform& xf = options.transform;
    const bool mirrored = xf.determinant() < 0;
    size_t degenerate = 0;

    auto validNormal = [&](int vn) {
        if (vn < 0) return false;
        const Vec3 n(attrib.normals[3 * vn], attrib.normals[3 * vn + 1],
                     attrib.normals[3 * vn + 2]);
        return isFinite(n) && lengthSquared(n) > 0;
    };

    for (const tinyobj::shape_t& s : shapes) {
        size_t offset = 0;
        for (size_t f = 0; f < s.mesh.num_face_vertices.size(); ++f) {
            const size_t n = s.mesh.num_face_vertices[f];
            const int mid = f < s.mesh.material_ids.size() ? s.mesh.material_ids[f] : -1;
            uint32_t material = mtlCount;  // the default material, appended below
            if (mid >= 0 && uint32_t(mid) < mtlCount)
                material = uint32_t(mid);
            else
                needDefault = true;
            // tinyobjloader triangulates; fan anything it left as a polygon.
            for (size_t k = 1; k + 1 < n; ++k) {
                const tinyobj::index_t c[3] = {s.mesh.indices[offset], s.mesh.indices[offset + k],
                                               s.mesh.indices[offset + k + 1]};
                const bool hasNormals = validNormal(c[0].normal_index) &&
                                        validNormal(c[1].normal_index) &&
                                        validNormal(c[2].normal_index);
                PartBuilder& b = hasNormals ? smooth : flat;
                std::array<uint32_t, 3> tri;
                for (int j = 0; j < 3; ++j)
                    tri[j] = b.vertex(c[j].vertex_index, c[j].normal_index, attrib, xf);
                // A mirroring transform reverses the winding; swap to keep the front side.
                if (mirrored) std::swap(tri[1], tri[2]);
                const auto& P = b.part.mesh->positions;
                const Vec3 area = cross(P[tri[1]] - P[tri[0]], P[tri[2]] - P[tri[0]]);
                // Zero-area triangles have no normal; Embree would never report them.
                if (!(lengthSquared(area) > 0) || !isFinite(area)) {
                    ++degenerate;
                    continue;
                }
                b.part.mesh->triangles.push_back(tri);
                b.part.faceMaterials.push_back(material);
            }
            offset += n;
        }
    }
    if (degenerate > 0)
        warn.add("dropped " + std::to_string(degenerate) + " degenerate (zero-area) triangle" +
                 (degenerate > 1 ? "s" : ""));
    if (needDefault) {
        // Grey, lit by the ambient term too, so a bare OBJ is readable.
        Material def;
        def.name = "default";
        def.ka = def.kd;
        model.materials.push_back(def);
    }
    for (PartBuilder* b : {&smooth, &flat})
        if (b->part.mesh->triangleCount() > 0) model.parts.push_back(std::move(b->part));
    if (model.parts.empty()) {
        if (const int firstFace = lineOfStatement(text, "f", 0))
            throw InputError(path, firstFace,
                             xf.isIdentity()
                                 ? "the OBJ file has no triangles: every face has zero area or "
                                   "fewer than 3 corners"
                                 : "no triangles left: every face has zero area or fewer than 3 "
                                   "corners once the scene's transform (scale, rotate) is "
                                   "applied");
        throw InputError(path, 0, "the OBJ file has no faces");
    }

    model.warnings = warn.lines();
    if (options.printWarnings)
        for (const std::string& w : model.warnings)
            std::fprintf(stderr, "raylab: warning: %s\n", terminalSafe(w).c_str());
    return model;
}

void appendObjModel(Scene& scene, const ObjModel& model, const std::string& baseName,
                    std::optional<uint32_t> overrideMaterial) {
    const uint32_t firstMaterial = uint32_t(scene.materials.size());
    if (!overrideMaterial) {
        for (const Material& m : model.materials) {
            scene.materials.push_back(m);
            scene.materials.back().name = baseName + "/" + m.name;
        }
    }
    for (size_t i = 0; i < model.parts.size(); ++i) {
        const ObjMeshPart& part = model.parts[i];
        Object obj;
        obj.name = baseName;
        if (model.parts.size() > 1 && !part.mesh->hasNormals()) obj.name += " (flat)";
        obj.shape = part.mesh;
        if (overrideMaterial) {
            obj.material = *overrideMaterial;
        } else {
            // One material for the whole part needs no per-face table.
            bool uniform = true;
            for (uint32_t m : part.faceMaterials) uniform = uniform && m == part.faceMaterials[0];
            obj.material = firstMaterial + part.faceMaterials[0];
            if (!uniform)
                for (uint32_t m : part.faceMaterials)
                    obj.faceMaterials.push_back(firstMaterial + m);
        }
        scene.objects.push_back(std::move(obj));
    }
}

}  // namespace raylab

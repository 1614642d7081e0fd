// Eric Haines' Neutral File Format (NFF), the format of the Standard
// Procedural Databases. NFF is read as a stream of whitespace-separated tokens
// (the format document puts a cone's end points on two lines, SPD's generators
// on one), with '#' comments to the end of a line.
//
// Mapping to raylab's model (SPD conventions, see docs/spd.md):
//   v from/at/up/angle/hither/resolution -> camera (angle = full vertical field
//                                  of view between the outermost sample rows),
//                                  cameraNear, image size (flags override it).
//   f R G B Kd Ks Shine T ior  ->  kd = ka = colour·Kd, ks = Ks (white),
//                                  shininess = Shine with Phong highlights
//                                  (SPD's model), km = Ks (a reflective
//                                  surface spawns mirror rays), kt = T, ior
//                                  (only read when T > 0: SPD writes ior 0 for
//                                  opaque surfaces).
//   l X Y Z [R G B]            ->  point light; without a colour its intensity is
//                                  sqrt(L)/(2L) for L lights, as is the ambient Ia.
//   s, c (cone/cylinder, no caps), p (polygon), pp (patch with vertex normals):
//   one-sided (outside visible), two-sided for transmitters, inside-visible for
//   negative radii. Triangles (p 3, pp 3) go to Embree triangle meshes; larger
//   polygons to the analytic polygon primitive. Zero-area polygons are dropped
//   (they can never be hit; tessellators emit them at poles).
//
// Polygons with 4 or more vertices are built (normal, planarity, the inside
// test's grid) by tasks while the rest of the file is read, in batches handed
// over as they fill; errors keep the file's order: the first bad polygon is
// reported, unless the text broke before it.
//
// Error locations: a malformed token (not a number, NaN/Inf, out of range) is
// reported on its own line; a wrong count of numbers or a truncated polygon on
// the line where the entity starts, since in a token stream the mistake is only
// noticed at the next entity's keyword.

#include <tbb/task_group.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "renderer/io/errors.h"
#include "renderer/io/plain_decimal.h"
#include "renderer/io/scene_loader.h"
#include "renderer/io/shape_factory.h"
#include "renderer/io/text_file.h"
#include "renderer/render_options.h"

namespace raylab {

namespace {

/// Hard cap on vertices per polygon: SPD's largest have 144; anything near the
/// cap is corrupt input. Counts are also checked against the bytes left in the
/// file before anything is reserved, so "p 2000000000" allocates nothing.
constexpr long long kMaxPolygonVertices = 1 << 20;

/// Same collinearity tolerance as Polygon::create: zero-area polygons are
/// dropped here instead of being rejected there.
constexpr double kCollinearTolerance = 1e-12;

bool isKeyword(std::string_view t) {
    // Sorted by frequency in the SPD files: s and p dominate.
    return t == "s" || t == "p" || t == "pp" || t == "c" || t == "f" || t == "l" || t == "b" ||
           t == "v" || t == "from" || t == "at" || t == "up" || t == "angle" || t == "hither" ||
           t == "resolution";
}

/// A token for a message: at most 40 bytes, and anything but printable ASCII
/// as \xNN, so a binary blob or an escape sequence cannot garble the terminal.
std::string quoted(std::string_view t) {
    static const char* const kHex = "0123456789ABCDEF";
    std::string s = "'";
    for (const char c : t.substr(0, 40)) {
        const unsigned char u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u < 0x7f) {
            s += c;
        } else {
            s += "\\x";
            s += kHex[u >> 4];
            s += kHex[u & 15];
        }
    }
    return s + (t.size() > 40 ? "...'" : "'");
}

/// Token stream over the whole file text, tracking line numbers.
class Tokenizer {
public:
    explicit Tokenizer(std::string_view text) : m_p(text.data()), m_end(text.data() + text.size()) {}

    /// Next token (its line in tokenLine()), or an empty view at the end of the input.
    std::string_view next() {
        skipSpace();
        const char* start = m_p;
        while (m_p < m_end && !endsToken(*m_p)) ++m_p;
        m_tokenLine = m_line;
        return {start, size_t(m_p - start)};
    }

    /// The next token without consuming it.
    std::string_view peek() {
        const char* p = m_p;
        const int line = m_line, tokenLine = m_tokenLine;
        const std::string_view t = next();
        m_p = p;
        m_line = line;
        m_tokenLine = tokenLine;
        return t;
    }

    /// The next token read in the same pass as its value when it is a plain
    /// decimal (plainDecimalPrefix's form) ended by whitespace, '#' or the end: true,
    /// with the value and the token's line, as next() + plainDecimal() give.
    /// Any other token is left unread (false) for next(). Nearly every
    /// number of an SPD file takes this path (number() was a quarter of
    /// gears' parse when each token was scanned twice).
    bool nextPlainDecimal(double& value) {
        skipSpace();
        const char* stop = m_p;
        const std::optional<double> v = plainDecimalPrefix(m_p, m_end, stop);
        if (!v || (stop < m_end && !endsToken(*stop))) return false;
        value = *v;
        m_p = stop;
        m_tokenLine = m_line;
        return true;
    }

    int tokenLine() const { return m_tokenLine; }
    /// Bytes not yet read: bounds how many numbers can still follow.
    size_t remaining() const { return size_t(m_end - m_p); }

private:
    /// Whitespace (' ', \n, \t, \r, \f, \v) or '#': one bit test, the hot
    /// loop of every token (a third of gears' parse was this loop and the number's).
    static bool endsToken(char c) {
        const unsigned u = static_cast<unsigned char>(c);
        constexpr uint64_t kEnds = (uint64_t(1) << ' ') | (uint64_t(1) << '\n') |
                                   (uint64_t(1) << '\t') | (uint64_t(1) << '\r') |
                                   (uint64_t(1) << '\f') | (uint64_t(1) << '\v') |
                                   (uint64_t(1) << '#');
        return u <= '#' && ((kEnds >> u) & 1u) != 0;
    }

    void skipSpace() {
        while (m_p < m_end) {
            const char c = *m_p;
            if (c == '\n') {
                ++m_line;
                ++m_p;
            } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
                ++m_p;
            } else if (c == '#') {
                const void* nl = std::memchr(m_p, '\n', size_t(m_end - m_p));
                m_p = nl ? static_cast<const char*>(nl) : m_end;
            } else {
                break;
            }
        }
    }

    const char* m_p;
    const char* m_end;
    int m_line = 1;
    int m_tokenLine = 1;
};

struct NffLight {
    Vec3 position;
    bool hasColor = false;
    Color color;
};

class NffReader {
public:
    NffReader(std::string_view text, const std::string& path) : m_tok(text), m_path(path) {
        checkEncoding(text);
        // Every object starts a line of its own and takes at least 9 bytes
        // ("s 0 0 0 1"): both bound the objects, so the vector need not
        // reallocate (SPD gears: 9,345 objects of 80 bytes, 14 reallocations
        // moving them and faulting in each new buffer). Reserved, not touched:
        // the unused tail costs no page, only address space, hence the cap
        // (80 MB; `ulimit -v` counts it) beyond which the vector grows as usual.
        const size_t lines = size_t(std::count(text.begin(), text.end(), '\n')) + 1;
        m_objects.reserve(std::min({lines, text.size() / 9 + 1, size_t(1) << 20}));
    }

    // The builder tasks read m_path and write their batches: they must be
    // done before either goes (they catch every error themselves).
    ~NffReader() {
        try {
            m_builders.wait();
        } catch (...) {
        }
    }
    NffReader(const NffReader&) = delete;
    NffReader& operator=(const NffReader&) = delete;

    Scene read() {
        try {
            for (std::string_view t = m_tok.next(); !t.empty(); t = m_tok.next()) entity(t);
        } catch (...) {
            // A polygon read before the broken text may be bad too, and its
            // line comes first: its error wins, as when each was built in
            // turn. Anything else going wrong in that build (memory, threads)
            // leaves the text's own error to be reported.
            try {
                buildPolygons();
            } catch (const InputError&) {
                throw;
            } catch (...) {
            }
            throw;
        }
        buildPolygons();
        return finish();
    }

private:
    /// NFF is ASCII: UTF-16 (a byte-order mark or NUL bytes) is refused with
    /// a clear message, at the line of the first NUL, instead of a confusing
    /// token error.
    void checkEncoding(std::string_view text) const {
        if (const auto [line, message] = findNonText(text, "NFF"); line > 0)
            throw InputError(m_path, line, "not a text file: " + message);
    }

    [[noreturn]] void failAt(int line, const std::string& message) const {
        throw InputError(m_path, line, message);
    }

    /// Error about the entity being read, located at its first line.
    [[noreturn]] void failEntity(const std::string& message) const {
        failAt(m_entityLine, entityName() + ": " + message);
    }

    std::string entityName() const { return std::string(m_entity); }

    /// What the current entity takes, for count errors (built only on failure).
    std::string expectedText() const {
        if (m_polygonCount > 0)
            return "truncated polygon: expected " + std::to_string(m_polygonCount) +
                   (m_polygonPatch ? " vertices of 6 numbers (x y z nx ny nz)"
                                   : " vertices of 3 numbers (x y z)");
        return std::string("expected ") + m_expected;
    }

    void entity(std::string_view t) {
        const std::string_view previous = m_entity;
        const int previousLine = m_entityLine;
        m_entity = t;
        m_entityLine = m_tok.tokenLine();
        m_numbersRead = 0;
        m_lastNumberLine = m_entityLine;
        m_polygonCount = 0;
        m_splitVertex = -1;
        if (t == "s") return sphere();
        if (t == "p") return polygon(false);
        if (t == "pp") return polygon(true);
        if (t == "c") return cone();
        if (t == "f") return material();
        if (t == "l") return light();
        if (t == "b") {
            m_expected = "3 numbers (R G B)";
            m_background = color("background colour");
            // Negative radiance would reach the pixels of every ray that misses.
            if (m_background.r < 0 || m_background.g < 0 || m_background.b < 0)
                failEntity("background colour must be >= 0");
            return;
        }
        if (t == "v") {
            m_viewLine = m_entityLine;
            return;  // the viewpoint keywords follow as their own entities
        }
        if (t == "from" || t == "at" || t == "up") {
            m_expected = "3 numbers (x y z)";
            const Vec3 p = vec3("x", "y", "z");
            if (t == "from") {
                m_from = p;
                m_seen |= kFrom;
                m_fromLine = m_entityLine;
            } else if (t == "at") {
                m_at = p;
                m_seen |= kAt;
                m_atLine = m_entityLine;
            } else {
                m_up = p;
                m_seen |= kUp;
                m_upLine = m_entityLine;
            }
            return;
        }
        if (t == "angle") {
            m_expected = "1 number (degrees)";
            m_angle = number("field of view");
            if (!(m_angle > 0 && m_angle < 180))
                failEntity("field of view must be in (0, 180) degrees (got " +
                           formatNumber(m_angle) + ")");
            m_seen |= kAngle;
            return;
        }
        if (t == "hither") {
            m_expected = "1 number (distance)";
            m_hither = number("distance");
            if (m_hither < 0) failEntity("distance must be >= 0 (got " + formatNumber(m_hither) + ")");
            return;
        }
        if (t == "resolution") {
            m_expected = "2 integers (width height)";
            const long long w = integer("width"), h = integer("height");
            if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
                failEntity("expected two integers in [1, " + std::to_string(kMaxImageSide) + "], got " + std::to_string(w) + " " +
                           std::to_string(h));
            m_width = int(w);
            m_height = int(h);
            m_sizeLine = m_entityLine;
            return;
        }
        if (looksNumeric(t)) {
            // A number where an entity should start: the previous entity had
            // more numbers than it takes.
            if (previous.empty())
                failAt(m_tok.tokenLine(), "unexpected number " + quoted(t) + " before any entity");
            const int line = m_tok.tokenLine();
            failAt(line, "unexpected number " + quoted(t) + ": too many numbers for '" +
                             std::string(previous) + "'" +
                             (previousLine == line
                                  ? std::string()
                                  : " ('" + std::string(previous) + "' starts on line " +
                                        std::to_string(previousLine) + ")"));
        }
        failAt(m_tok.tokenLine(), "unknown entity " + quoted(t));
    }

    static bool looksNumeric(std::string_view t) {
        const char c = t[0];
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
    }

    /// "nan", "inf", "infinity" in any case: numbers, but not finite ones.
    static bool looksNonFinite(std::string_view t) {
        std::string lower;
        for (char c : t.substr(0, 8)) lower += char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
        return lower == "nan" || lower == "inf" || lower == "infinity";
    }

    static std::string formatNumber(double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return buf;
    }

    /// The next number of the current entity; `what` names it in messages.
    double number(const char* what) {
        if (double v; m_tok.nextPlainDecimal(v)) {
            ++m_numbersRead;  // counted with its line for a later count error
            m_lastNumberLine = m_tok.tokenLine();
            return v;
        }
        const std::string_view t = m_tok.next();
        // Keywords start with a letter, numbers never do: the keyword test
        // stays off the hot path.
        if (t.empty() || (!looksNumeric(t) && isKeyword(t))) {
            // The entity ended early: a count problem, reported where it starts.
            // Reported on the line of the entity's last number, where it
            // stops short; the message names the line it starts on.
            const std::string got = ", got " + std::to_string(m_numbersRead) + " number" +
                                    (m_numbersRead == 1 ? "" : "s");
            const std::string start = m_lastNumberLine == m_entityLine
                                          ? std::string()
                                          : " ('" + entityName() + "' starts on line " +
                                                std::to_string(m_entityLine) + ")";
            if (t.empty())
                failAt(m_lastNumberLine, entityName() + ": unexpected end of file: " +
                                             expectedText() + got + start + extraHint());
            failAt(m_lastNumberLine, entityName() + ": " + expectedText() + got + " before '" +
                                         std::string(t) + "' on line " +
                                         std::to_string(m_tok.tokenLine()) + start + extraHint());
        }
        const char* first = t.data();
        const char* last = t.data() + t.size();
        if (*first == '+' && t.size() > 1 && first[1] != '-') ++first;  // from_chars rejects '+'
        const int line = m_tok.tokenLine();
        // Every number read is counted, with its line, for a later count error.
        const auto accepted = [&](double v) {
            ++m_numbersRead;
            m_lastNumberLine = line;
            return v;
        };
        if (const std::optional<double> plain = plainDecimal(first, last)) return accepted(*plain);
        double v = 0;
        const auto [ptr, ec] = std::from_chars(first, last, v);
        if (ptr != last || (ec != std::errc() && ec != std::errc::result_out_of_range))
            failAt(line, entityName() + ": expected a number for " + what + ", got " + quoted(t));
        if (ec == std::errc::result_out_of_range) {
            // Underflow towards zero is harmless; overflow is not representable.
            // (Rare path: strtod tells the two apart.)
            const double approx = std::strtod(std::string(t).c_str(), nullptr);
            if (!(std::abs(approx) < 1.0))
                failAt(line, entityName() + ": " + what + " is out of range: " + quoted(t));
            v = approx;
        }
        if (!std::isfinite(v))
            failAt(line, entityName() + ": " + what + " must be a finite number, got " + quoted(t));
        return accepted(v);
    }

    Vec3 vec3(const char* x, const char* y, const char* z) {
        const double a = number(x), b = number(y), c = number(z);
        return {a, b, c};
    }

    Color color(const char* what) {
        const double r = number(what), g = number(what), b = number(what);
        return {r, g, b};
    }

    long long integer(const char* what) {
        const double v = number(what);
        if (v != std::floor(v) || std::abs(v) > 9e15)
            failAt(m_tok.tokenLine(),
                   entityName() + ": " + what + " must be an integer, got " + formatNumber(v));
        return (long long)v;
    }

    /// Polygons: names the first vertex whose numbers span two lines, the
    /// likely place of a missing number when the polygon comes up short.
    std::string extraHint() const {
        if (m_splitVertex < 0) return "";
        return " (vertex " + std::to_string(m_splitVertex + 1) + " starts on line " +
               std::to_string(m_splitLine) + " and continues on the next line: a number missing there?)";
    }

    void light() {
        m_expected = "3 or 6 numbers (x y z [R G B])";
        NffLight l;
        l.position = vec3("light x", "light y", "light z");
        // A colour starts with a number (or NaN/Inf, refused as a colour);
        // anything else is the next entity, reported as such when it is not
        // one rather than as a bad light colour.
        const std::string_view t = m_tok.peek();
        if (!t.empty() && (looksNumeric(t) || looksNonFinite(t))) {
            l.hasColor = true;
            l.color = color("light colour");
            if (l.color.r < 0 || l.color.g < 0 || l.color.b < 0)
                failEntity("light colour must be >= 0");
        }
        m_lights.push_back(l);
    }

    void material() {
        m_expected = "8 numbers (R G B Kd Ks Shine T ior)";
        const Color c = color("colour");
        const double kd = number("Kd"), ks = number("Ks");
        const double shine = number("Shine"), t = number("T");
        const double ior = number("index of refraction");
        if (c.r < 0 || c.g < 0 || c.b < 0) failEntity("colour must be >= 0");
        if (kd < 0 || ks < 0 || t < 0) failEntity("Kd, Ks and T must be >= 0");
        if (shine < 0) failEntity("Shine must be >= 0 (got " + formatNumber(shine) + ")");
        // SPD writes ior 0 for opaque materials: the index only matters when T > 0.
        if (t > 0 && !(ior > 0))
            failEntity("index of refraction must be > 0 when T > 0 (got " + formatNumber(ior) + ")");
        Material m;
        m.name = "nff_f" + std::to_string(m_materials.size()) + "_line" +
                 std::to_string(m_entityLine);
        m.kd = c * kd;
        m.ka = c * kd;
        if (!m.kd.isFinite())  // each factor is finite, their product need not be
            failEntity("colour x Kd overflows a double (" + formatNumber(c.maxComponent()) + " x " +
                       formatNumber(kd) + "); the product must stay below 1.8e308");
        m.ks = Color(ks);
        m.shininess = shine;
        m.highlight = Highlight::Phong;  // NFF's Shine is a Phong cosine power
        m.km = Color(ks);
        m.kt = Color(t);
        m.ior = t > 0 ? ior : 1.0;
        m_materials.push_back(m);
    }

    uint32_t currentMaterial() {
        if (m_materials.empty()) {
            // Objects before any 'f' get a plain white diffuse surface.
            Material m;
            m.name = "nff_default";
            m.kd = m.ka = Color(1.0);
            m_materials.push_back(m);
        }
        return uint32_t(m_materials.size() - 1);
    }

    /// Transmitters are two-sided (rays leave them from the inside); other
    /// objects show their outside, or their inside for negative radii.
    Sidedness sides(bool insideVisible) {
        const uint32_t m = currentMaterial();
        if (m_materials[m].transmissive()) return Sidedness::Both;
        return insideVisible ? Sidedness::Inside : Sidedness::Outside;
    }

    /// Runs a geometry factory; its complaint is reported at the entity's line.
    template <class F>
    std::unique_ptr<Shape> make(F&& f) {
        return callFactory(m_path, m_entityLine, "", std::forward<F>(f));
    }

    void addShape(std::unique_ptr<Shape> shape, Sidedness s, const char* kind) {
        shape->setSidedness(s);
        addObject(kind).shape = std::move(shape);
    }

    /// An object of the current material named after the entity's line.
    Object& addObject(const char* kind) {
        Object o;
        o.material = currentMaterial();
        o.name = std::string(kind) + "@" + std::to_string(m_entityLine);
        return m_objects.emplace_back(std::move(o));
    }

    void sphere() {
        m_expected = "4 numbers (x y z radius)";
        const Vec3 c = vec3("centre x", "centre y", "centre z");
        const double r = number("radius");
        const Sidedness s = sides(r < 0);
        addShape(make([&] { return makeSphere(c, std::abs(r)); }), s, "sphere");
    }

    void cone() {
        m_expected = "8 numbers (base x y z radius, apex x y z radius)";
        ConeParams p;
        p.base = vec3("base x", "base y", "base z");
        p.baseRadius = number("base radius");
        p.apex = vec3("apex x", "apex y", "apex z");
        p.apexRadius = number("apex radius");
        // Negative radii mark an inside-visible cone; a radius of 0 (a pointed
        // cone) goes with either sign, a negative and a positive one do not.
        if ((p.baseRadius < 0 && p.apexRadius > 0) || (p.baseRadius > 0 && p.apexRadius < 0))
            failEntity("radii must not have opposite signs (got " + formatNumber(p.baseRadius) +
                       " and " + formatNumber(p.apexRadius) + ")");
        const bool inside = p.baseRadius < 0 || p.apexRadius < 0;
        p.baseRadius = std::abs(p.baseRadius);
        p.apexRadius = std::abs(p.apexRadius);
        p.capped = false;  // NFF cones have no end caps
        const Sidedness s = sides(inside);
        addShape(make([&] { return makeCone(p); }), s, "cone");
    }

    void polygon(bool patch) {
        const char* name = patch ? "pp" : "p";
        m_expected = "a vertex count";
        const long long n = integer("vertex count");
        if (n < 3) failEntity("vertex count " + std::to_string(n) + " is below 3");
        // Each vertex needs at least 3 (or 6) one-digit numbers and their
        // separators: a count the rest of the file cannot hold is refused
        // before anything is reserved.
        // (One byte of slack: the check only guards the allocation, the
        // vertex reader reports any real shortfall.)
        const unsigned long long minBytes = (unsigned long long)n * (patch ? 12 : 6) - 1;
        if (n > kMaxPolygonVertices)
            failEntity("vertex count " + std::to_string(n) + " exceeds the limit of " +
                       std::to_string(kMaxPolygonVertices));
        if (minBytes > m_tok.remaining() + 1)
            failEntity("truncated polygon: vertex count " + std::to_string(n) +
                       " exceeds what the file holds (" + std::to_string(n) +
                       " vertices need at least " + std::to_string(minBytes) +
                       " more bytes, the file ends after " + std::to_string(m_tok.remaining()) +
                       ")");
        m_polygonCount = n;
        m_polygonPatch = patch;
        m_vertices.clear();
        m_normals.clear();
        m_numbersRead = 0;
        m_splitVertex = -1;
        for (long long i = 0; i < n; ++i) {
            const double x = number("vertex x");
            const int firstLine = m_tok.tokenLine();
            const double y = number("vertex y"), z = number("vertex z");
            m_vertices.push_back({x, y, z});
            if (patch) {
                const Vec3 nv = vec3("normal x", "normal y", "normal z");
                if (!(lengthSquared(nv) > 0))
                    failAt(m_tok.tokenLine(), std::string(name) + ": normal of vertex " +
                                                  std::to_string(i + 1) + " is zero");
                m_normals.push_back(nv);
            }
            if (m_splitVertex < 0 && m_tok.tokenLine() != firstLine) {
                m_splitVertex = int(i);
                m_splitLine = firstLine;
            }
        }
        m_splitVertex = -1;
        const uint32_t mat = currentMaterial();
        if (isDegenerate(m_vertices)) return;
        if (n == 3) {
            addTriangle(mat, patch);
            return;
        }
        // Built by a task (handOver), its shape given by buildPolygons: the
        // object is added now, without it, so that the polygon names one that exists.
        addObject(patch ? "patch" : "polygon");
        // Made whole before it joins a batch: a failed copy (memory) must
        // not leave a polygon without vertices for the build to report.
        PendingPolygon pending;
        pending.object = m_objects.size() - 1;
        pending.line = m_entityLine;
        pending.sides = sides(false);
        pending.params.vertices = m_vertices;
        pending.params.normals = m_normals;
        if (!m_filling) m_filling = std::make_unique<PolygonBatch>();
        m_filling->polygons.push_back(std::move(pending));
        m_filling->vertices += m_vertices.size();
        if (m_filling->vertices >= kBatchVertices) handOver();
    }

    /// A polygon read, to be built by a task into `shape` (or `error`), then
    /// moved by buildPolygons into objects[object].
    struct PendingPolygon {
        size_t object = 0;
        int line = 0;  ///< where its entity starts, for errors
        Sidedness sides = Sidedness::Outside;
        PolygonParams params;
        std::unique_ptr<Shape> shape;
        std::exception_ptr error;
    };

    /// Polygons handed to one task. A batch does not move once handed over
    /// (the reader keeps only a pointer to it), so the task writes into it
    /// while the reader goes on.
    struct PolygonBatch {
        std::vector<PendingPolygon> polygons;
        size_t vertices = 0;
    };

    /// About this many vertices per task: SPD gears (9,217 quads and 128
    /// 144-gons) makes ~50 tasks, each far longer than its hand-over.
    static constexpr size_t kBatchVertices = 1024;

    /// Starts a task that builds the filling batch.
    void handOver() {
        PolygonBatch* batch = m_filling.get();
        m_batches.push_back(std::move(m_filling));
        m_builders.run([this, batch] { build(*batch); });
    }

    /// Builds the batch's polygons; each keeps its shape or its error.
    void build(PolygonBatch& batch) const {
        for (PendingPolygon& p : batch.polygons) {
            try {
                std::unique_ptr<Shape> shape =
                    callFactory(m_path, p.line, "", [&] { return makePolygon(p.params); });
                shape->setSidedness(p.sides);
                p.shape = std::move(shape);
            } catch (...) {
                p.error = std::current_exception();
            }
            p.params = {};  // its vertices are the polygon's now
        }
    }

    /// Waits for every polygon read (the last batch too) to be built, then
    /// gives each its object; rethrows the error of the first in file order.
    void buildPolygons() {
        if (m_filling && !m_filling->polygons.empty()) handOver();
        m_builders.wait();
        std::exception_ptr first;
        for (const std::unique_ptr<PolygonBatch>& batch : m_batches) {
            for (PendingPolygon& p : batch->polygons) {
                if (p.error && !first) first = p.error;
                if (p.shape) m_objects[p.object].shape = std::move(p.shape);
            }
        }
        m_batches.clear();
        if (first) std::rethrow_exception(first);
    }

    /// Zero-area polygons (collinear or repeated vertices) can never be hit;
    /// the test mirrors Polygon::create's, which would reject them.
    static bool isDegenerate(const std::vector<Vec3>& v) {
        Bounds3 box;
        Vec3 centroid{};
        for (const Vec3& p : v) {
            box.expand(p);
            centroid += p;
        }
        centroid = centroid / double(v.size());
        const double diagonal = length(box.extent());
        const double tolerance = kCollinearTolerance * diagonal * diagonal;
        if (!(diagonal > 0)) return true;
        if (length(newellNormal(v)) > tolerance) return false;
        for (size_t i = 0; i < v.size(); ++i) {
            const Vec3 c = cross(v[i] - centroid, v[(i + 1) % v.size()] - centroid);
            if (length(c) > tolerance) return false;
        }
        return true;
    }

    /// Triangles gather into one mesh per kind (flat or smooth) and per
    /// sidedness: one-sided like every NFF object, two-sided for transmitters.
    void addTriangle(uint32_t material, bool patch) {
        const bool twoSided = m_materials[material].transmissive();
        TriangleMesh& m = m_meshes[patch][twoSided];
        std::vector<uint32_t>& mats = m_meshMaterials[patch][twoSided];
        const uint32_t base = uint32_t(m.positions.size());
        for (int i = 0; i < 3; ++i) {
            m.positions.push_back(m_vertices[i]);
            if (patch) m.normals.push_back(normalize(m_normals[i]));
        }
        m.triangles.push_back({base, base + 1, base + 2});
        mats.push_back(material);
    }

    void addMesh(TriangleMesh& mesh, std::vector<uint32_t>& materials, const char* name,
                 Sidedness sides) {
        if (mesh.triangles.empty()) return;
        Object o;
        o.name = name;
        o.material = materials.front();
        // One material for all faces needs no per-face table.
        bool uniform = true;
        for (uint32_t m : materials) uniform = uniform && m == o.material;
        if (!uniform) o.faceMaterials = std::move(materials);
        o.shape = std::make_shared<TriangleMesh>(std::move(mesh));
        o.shape->setSidedness(sides);
        m_objects.push_back(std::move(o));
    }

    /// The line that makes the camera degenerate: the later of from/at when
    /// they coincide, else the up line (zero or along the view direction).
    int cameraErrorLine() const {
        if (!(length(m_at - m_from) > 0)) return std::max(m_fromLine, m_atLine);
        if (!(length(m_up) > 0)) return m_upLine;
        if (!(length(cross(normalize(m_up), normalize(m_at - m_from))) > 1e-9)) return m_upLine;
        return m_viewLine;
    }

    Scene finish() {
        if ((m_seen & kAll) != kAll) {
            std::string missing;
            const char* names[] = {"from", "at", "up", "angle"};
            for (int i = 0; i < 4; ++i)
                if (!(m_seen & (1u << i))) missing += std::string(missing.empty() ? "" : ", ") + names[i];
            // Nothing is on a line: a file-level error.
            failAt(0, "viewpoint incomplete: missing " + missing);
        }
        Scene s;
        s.sourcePath = m_path;
        s.camera = callFactory(m_path, cameraErrorLine(), "",
                               [&] { return Camera::perspective(m_from, m_at, m_up, m_angle); });
        s.cameraNear = m_hither;
        s.image.width = m_width;
        s.image.sizeLine = m_sizeLine;
        s.image.height = m_height;
        s.image.maxDepth = 5;
        s.background = m_background;
        // SPD: each of the L lights, and the ambient term, has relative
        // intensity sqrt(L) / (2L), so total illumination stays comparable.
        const double L = double(std::max<size_t>(1, m_lights.size()));
        const double intensity = std::sqrt(L) / (2.0 * L);
        s.ambient = Color(intensity);
        for (const NffLight& l : m_lights) {
            Light light;
            light.type = Light::Type::Point;
            light.position = l.position;
            light.intensity = l.hasColor ? l.color : Color(intensity);
            s.lights.push_back(light);
        }
        addMesh(m_meshes[0][0], m_meshMaterials[0][0], "triangles", Sidedness::Outside);
        addMesh(m_meshes[0][1], m_meshMaterials[0][1], "transmissive triangles", Sidedness::Both);
        addMesh(m_meshes[1][0], m_meshMaterials[1][0], "patches", Sidedness::Outside);
        addMesh(m_meshes[1][1], m_meshMaterials[1][1], "transmissive patches", Sidedness::Both);
        s.materials = std::move(m_materials);
        s.objects = std::move(m_objects);
        return s;
    }

    static constexpr unsigned kFrom = 1, kAt = 2, kUp = 4, kAngle = 8, kAll = 15;

    Tokenizer m_tok;
    std::string m_path;
    std::string_view m_entity;    ///< keyword of the entity being read (points into the text)
    int m_entityLine = 0;         ///< line where it starts
    const char* m_expected = "";  ///< what it takes, for count errors
    long long m_polygonCount = 0; ///< polygons: vertices announced (0 otherwise)
    bool m_polygonPatch = false;
    size_t m_numbersRead = 0;     ///< numbers read for it so far
    int m_lastNumberLine = 0;     ///< line of its last number (its start line before any)
    int m_splitVertex = -1, m_splitLine = 0;
    int m_viewLine = 0, m_fromLine = 0, m_atLine = 0, m_upLine = 0;
    Vec3 m_from{0, 0, 0}, m_at{0, 0, -1}, m_up{0, 1, 0};
    double m_angle = 45, m_hither = 0;
    unsigned m_seen = 0;
    int m_width = 512, m_height = 512;
    int m_sizeLine = 0;  ///< line of `resolution`
    Color m_background{0, 0, 0};
    std::vector<NffLight> m_lights;
    std::vector<Material> m_materials;
    std::vector<Object> m_objects;
    std::unique_ptr<PolygonBatch> m_filling;               ///< polygons read, not handed over
    std::vector<std::unique_ptr<PolygonBatch>> m_batches;  ///< handed over, in file order
    tbb::task_group m_builders;                            ///< the tasks building them
    std::vector<Vec3> m_vertices, m_normals;  ///< reused per polygon
    TriangleMesh m_meshes[2][2];                  ///< [patch][two-sided]
    std::vector<uint32_t> m_meshMaterials[2][2];  ///< per-face materials of each
};

}  // namespace

Scene loadNffScene(const std::string& text, const std::string& path) {
    std::string_view body(text);
    // A UTF-8 byte-order mark is harmless: skip it.
    if (body.size() >= 3 && body.compare(0, 3, "\xEF\xBB\xBF") == 0) body.remove_prefix(3);
    return NffReader(body, path).read();
}

}  // namespace raylab

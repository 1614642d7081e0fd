// Eric Haines' Neutral File Format (NFF), the format of the Standard
// Procedural Databases. NFF is read as a stream of whitespace-separated tokens
// (the format document puts a cone's end points on two lines, SPD's generators
// on one), with '#' comments to the end of a line.
//
// Mapping to raylab's model (SPD conventions, see docs/spd.md):
//   f R G B Kd Ks Shine T ior  ->  kd = colour·Kd, ka = colour·Kd, ks = Ks (white),
//                                  shininess = Shine, km = Ks (a reflective
//                                  surface spawns mirror rays), kt = T, ior.
//   l X Y Z [R G B]            ->  point light; without a colour its intensity is
//                                  sqrt(L)/(2L) for L lights, as is the ambient Ia.
//   s, c (cone/cylinder, no caps), p (polygon), pp (patch with vertex normals):
//   one-sided (outside visible), two-sided for transmitters, inside-visible for
//   negative radii. Triangles (p 3, pp 3) go to one Embree triangle mesh;
//   larger polygons to the analytic polygon primitive.

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/primitives.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"

namespace raylab {

namespace {

/// Hard cap on vertices per polygon: SPD's largest have 144; anything near the
/// cap is corrupt input, and the count is never used to preallocate.
constexpr long long kMaxPolygonVertices = 1 << 20;

class Tokenizer {
public:
    Tokenizer(const std::string& text, std::string path)
        : m_p(text.data()), m_end(text.data() + text.size()), m_path(std::move(path)) {}

    /// Next token, or an empty view at the end of the input.
    std::string_view next() {
        skipSpace();
        const char* start = m_p;
        while (m_p < m_end && !isSpace(*m_p) && *m_p != '#') ++m_p;
        m_tokenLine = m_line;
        return {start, size_t(m_p - start)};
    }

    /// True when the next token starts like a number (without consuming it).
    bool peekNumber() {
        skipSpace();
        if (m_p >= m_end) return false;
        const char c = *m_p;
        return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
    }

    double number(const char* what) {
        const std::string_view t = next();
        if (t.empty()) fail(std::string("unexpected end of file, expected ") + what);
        double v = 0;
        const char* first = t.data();
        if (*first == '+') ++first;  // from_chars rejects a leading '+'
        const auto [ptr, ec] = std::from_chars(first, t.data() + t.size(), v);
        if (ec == std::errc::result_out_of_range)
            fail(std::string(what) + ": number out of range '" + std::string(t) + "'");
        if (ec != std::errc() || ptr != t.data() + t.size())
            fail(std::string("expected a number for ") + what + ", got '" + std::string(t) + "'");
        if (!std::isfinite(v)) fail(std::string(what) + ": number must be finite, got '" + std::string(t) + "'");
        return v;
    }

    Vec3 vec3(const char* what) {
        const double x = number(what), y = number(what), z = number(what);
        return {x, y, z};
    }

    long long integer(const char* what) {
        const double v = number(what);
        if (v != std::floor(v) || std::abs(v) > 9e15)
            fail(std::string(what) + ": expected an integer");
        return (long long)v;
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(m_path, m_tokenLine, message);
    }

    int line() const { return m_tokenLine; }
    /// Bytes not yet read: bounds how many numbers can still follow.
    size_t remaining() const { return size_t(m_end - m_p); }

private:
    static bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

    void skipSpace() {
        while (m_p < m_end) {
            if (*m_p == '\n') {
                ++m_line;
                ++m_p;
            } else if (isSpace(*m_p)) {
                ++m_p;
            } else if (*m_p == '#') {
                while (m_p < m_end && *m_p != '\n') ++m_p;
            } else {
                break;
            }
        }
    }

    const char* m_p;
    const char* m_end;
    std::string m_path;
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
    NffReader(const std::string& text, const std::string& path) : m_tok(text, path), m_path(path) {}

    Scene read(const std::string& text) {
        checkEncoding(text);
        for (std::string_view t = m_tok.next(); !t.empty(); t = m_tok.next()) entity(t);
        return finish();
    }

private:
    /// NFF is ASCII: UTF-16 (a byte-order mark or NUL bytes) is refused with
    /// a clear message instead of a confusing token error.
    void checkEncoding(const std::string& text) const {
        const bool bom16 = text.size() >= 2 && ((uint8_t(text[0]) == 0xFF && uint8_t(text[1]) == 0xFE) ||
                                                (uint8_t(text[0]) == 0xFE && uint8_t(text[1]) == 0xFF));
        if (bom16 || text.find('\0') != std::string::npos)
            throw InputError(m_path, 1, "not a text file (UTF-16 or binary data); NFF must be ASCII");
    }

    void entity(std::string_view t) {
        if (t == "v") return;  // the viewpoint keywords follow as their own entities
        if (t == "from") { m_from = m_tok.vec3("from"); m_seen |= 1; return; }
        if (t == "at") { m_at = m_tok.vec3("at"); m_seen |= 2; return; }
        if (t == "up") { m_up = m_tok.vec3("up"); m_seen |= 4; return; }
        if (t == "angle") { m_angle = m_tok.number("angle"); m_seen |= 8; return; }
        if (t == "hither") {
            m_hither = m_tok.number("hither");
            if (m_hither < 0) m_tok.fail("hither: must be >= 0");
            return;
        }
        if (t == "resolution") {
            const long long w = m_tok.integer("resolution"), h = m_tok.integer("resolution");
            if (w < 1 || h < 1 || w > 65536 || h > 65536)
                m_tok.fail("resolution: expected two integers in [1, 65536], got " +
                           std::to_string(w) + " " + std::to_string(h));
            m_width = int(w);
            m_height = int(h);
            return;
        }
        if (t == "b") { m_background = color("background"); return; }
        if (t == "l") { light(); return; }
        if (t == "f") { material(); return; }
        if (t == "s") { sphere(); return; }
        if (t == "c") { cone(); return; }
        if (t == "p") { polygon(false); return; }
        if (t == "pp") { polygon(true); return; }
        m_tok.fail("unknown entity '" + std::string(t.substr(0, 40)) + "'");
    }

    Color color(const char* what) {
        const double r = m_tok.number(what), g = m_tok.number(what), b = m_tok.number(what);
        return {r, g, b};
    }

    void light() {
        NffLight l;
        l.position = m_tok.vec3("light position");
        if (m_tok.peekNumber()) {
            l.hasColor = true;
            l.color = color("light colour");
        }
        m_lights.push_back(l);
    }

    void material() {
        Material m;
        const Color c = color("material colour");
        const double kd = m_tok.number("Kd"), ks = m_tok.number("Ks");
        const double shine = m_tok.number("Shine"), t = m_tok.number("T");
        const double ior = m_tok.number("index of refraction");
        if (ior <= 0) m_tok.fail("index of refraction must be > 0");
        m.name = "nff_f" + std::to_string(m_materials.size()) + "_line" + std::to_string(m_tok.line());
        m.kd = c * kd;
        m.ka = c * kd;
        m.ks = Color(ks);
        m.shininess = shine;
        m.km = Color(ks);
        m.kt = Color(t);
        m.ior = ior;
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

    Sidedness sides(bool negativeRadius) {
        if (m_materials.empty() ? false : m_materials.back().transmissive()) return Sidedness::Both;
        return negativeRadius ? Sidedness::Inside : Sidedness::Outside;
    }

    void addShape(std::unique_ptr<Shape> shape, Sidedness s, const char* kind, int line) {
        Object o;
        shape->setSidedness(s);
        o.shape = std::move(shape);
        o.material = currentMaterial();
        o.name = std::string(kind) + "@" + std::to_string(line);
        m_objects.push_back(std::move(o));
    }

    template <class F>
    auto make(F&& f, int line) {
        try {
            return f();
        } catch (const std::invalid_argument& e) {
            throw InputError(m_path, line, e.what());
        }
    }

    void sphere() {
        const int line = m_tok.line();
        const Vec3 c = m_tok.vec3("sphere centre");
        const double r = m_tok.number("sphere radius");
        const Sidedness s = sides(r < 0);
        currentMaterial();
        addShape(make([&] { return makeSphere(c, std::abs(r)); }, line), s, "sphere", line);
    }

    void cone() {
        const int line = m_tok.line();
        ConeParams p;
        p.base = m_tok.vec3("cone base");
        p.baseRadius = m_tok.number("cone base radius");
        p.apex = m_tok.vec3("cone apex");
        p.apexRadius = m_tok.number("cone apex radius");
        const bool inside = p.baseRadius < 0 || p.apexRadius < 0;
        p.baseRadius = std::abs(p.baseRadius);
        p.apexRadius = std::abs(p.apexRadius);
        p.capped = false;  // NFF cones have no end caps
        const Sidedness s = sides(inside);
        currentMaterial();
        addShape(make([&] { return makeCone(p); }, line), s, "cone", line);
    }

    void polygon(bool patch) {
        const int line = m_tok.line();
        const char* what = patch ? "pp vertex count" : "p vertex count";
        const long long n = m_tok.integer(what);
        // Each vertex needs at least 3 (or 6) numbers of 2 bytes: a count the
        // rest of the file cannot hold is refused before anything is stored.
        const long long minBytes = n * (patch ? 12 : 6) - 1;
        if (n < 3 || n > kMaxPolygonVertices || size_t(minBytes) > m_tok.remaining() + 1)
            m_tok.fail(std::string(patch ? "pp" : "p") + ": vertex count " + std::to_string(n) +
                       (n < 3 ? " is below 3" : " exceeds what the file holds"));
        std::vector<Vec3> v, nrm;
        v.reserve(size_t(n));
        if (patch) nrm.reserve(size_t(n));
        for (long long i = 0; i < n; ++i) {
            v.push_back(m_tok.vec3(patch ? "pp vertex" : "p vertex"));
            if (patch) nrm.push_back(m_tok.vec3("pp vertex normal"));
        }
        const uint32_t mat = currentMaterial();
        if (n == 3) {
            addTriangle(v, nrm, mat);
            return;
        }
        PolygonParams p;
        p.vertices = std::move(v);
        p.normals = std::move(nrm);
        addShape(make([&] { return makePolygon(p); }, line), sides(false),
                 patch ? "patch" : "polygon", line);
    }

    /// Triangles gather into one mesh (Embree's native triangles); zero-area
    /// ones are dropped, as they can never be hit.
    void addTriangle(const std::vector<Vec3>& v, const std::vector<Vec3>& n, uint32_t material) {
        if (!(lengthSquared(cross(v[1] - v[0], v[2] - v[0])) > 0)) return;
        TriangleMesh& m = n.empty() ? m_flat : m_smooth;
        std::vector<uint32_t>& mats = n.empty() ? m_flatMaterials : m_smoothMaterials;
        const uint32_t base = uint32_t(m.positions.size());
        for (int i = 0; i < 3; ++i) {
            m.positions.push_back(v[i]);
            if (!n.empty()) m.normals.push_back(normalize(n[i]));
        }
        m.triangles.push_back({base, base + 1, base + 2});
        mats.push_back(material);
    }

    void addMesh(TriangleMesh& mesh, std::vector<uint32_t>& materials, const char* name) {
        if (mesh.triangles.empty()) return;
        Object o;
        o.name = name;
        o.material = materials.front();
        o.faceMaterials = std::move(materials);
        o.mesh = std::make_shared<TriangleMesh>(std::move(mesh));
        m_objects.push_back(std::move(o));
    }

    Scene finish() {
        if ((m_seen & 15) != 15)
            throw InputError(m_path, 0,
                             "viewpoint incomplete: 'v' needs from, at, up and angle");
        Scene s;
        s.sourcePath = m_path;
        try {
            s.camera = Camera::perspective(m_from, m_at, m_up, m_angle);
        } catch (const std::invalid_argument& e) {
            throw InputError(m_path, 0, e.what());
        }
        s.cameraNear = m_hither;
        s.image.width = m_width;
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
        addMesh(m_flat, m_flatMaterials, "triangles");
        addMesh(m_smooth, m_smoothMaterials, "patches");
        s.materials = std::move(m_materials);
        s.objects = std::move(m_objects);
        return s;
    }

    Tokenizer m_tok;
    std::string m_path;
    Vec3 m_from{0, 0, 0}, m_at{0, 0, -1}, m_up{0, 1, 0};
    double m_angle = 45, m_hither = 0;
    unsigned m_seen = 0;
    int m_width = 512, m_height = 512;
    Color m_background{0, 0, 0};
    std::vector<NffLight> m_lights;
    std::vector<Material> m_materials;
    std::vector<Object> m_objects;
    TriangleMesh m_flat, m_smooth;
    std::vector<uint32_t> m_flatMaterials, m_smoothMaterials;
};

}  // namespace

Scene loadNffScene(const std::string& text, const std::string& path) {
    // A UTF-8 byte-order mark is harmless: skip it.
    if (text.size() >= 3 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) {
        const std::string body = text.substr(3);  // the tokenizer points into it
        return NffReader(body, path).read(body);
    }
    return NffReader(text, path).read(text);
}

}  // namespace raylab

#include "renderer/io/mtl_reader.h"

#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>

#include "renderer/io/errors.h"
#include "renderer/io/text_file.h"
#include "renderer/io/wavefront_text.h"

namespace raylab {

namespace {

std::string lowerCase(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return out;
}

/// Keywords of texture maps (MTL spec, plus the common bump/normal/PBR maps).
bool isTextureKeyword(const std::string& k) {
    static const std::unordered_set<std::string> kMaps = {
        "map_ka", "map_kd", "map_ks", "map_ke", "map_ns", "map_d", "map_tr", "map_bump",
        "bump", "disp", "decal", "refl", "norm", "map_pr", "map_pm", "map_ps", "map_rma",
        "map_orm"};
    return kMaps.count(k) > 0;
}

/// Options a texture statement may give before its file name, with their
/// argument counts (-o, -s, -t take one to three numbers).
int textureOptionArgs(std::string_view option) {
    static const std::unordered_map<std::string_view, int> kArgs = {
        {"-blendu", 1}, {"-blendv", 1}, {"-boost", 1},  {"-mm", 2},   {"-o", 3},
        {"-s", 3},      {"-t", 3},      {"-texres", 1}, {"-clamp", 1}, {"-bm", 1},
        {"-imfchan", 1}, {"-type", 1},  {"-cc", 1}};
    const auto it = kArgs.find(option);
    return it == kArgs.end() ? -1 : it->second;
}

/// Keywords raylab reads but does not simulate (physically based extensions,
/// emission, sharpness, ...): one warning per keyword and file.
const char* unsimulated(const std::string& k) {
    static const std::unordered_map<std::string, const char*> kKeys = {
        {"pr", "roughness (PBR)"},       {"pm", "metallic (PBR)"},
        {"ps", "sheen (PBR)"},           {"pc", "clearcoat (PBR)"},
        {"pcr", "clearcoat roughness (PBR)"}, {"aniso", "anisotropy (PBR)"},
        {"anisor", "anisotropy rotation (PBR)"}, {"sharpness", "reflection sharpness"},
        {"km", "bump multiplier"}};
    const auto it = kKeys.find(k);
    return it == kKeys.end() ? nullptr : it->second;
}

class MtlParser {
public:
    MtlParser(std::string_view text, const std::string& path, LoadWarnings& warn)
        : m_text(text), m_path(path), m_warn(warn) {}

    MtlLibrary parse() {
        m_library.path = m_path;
        StatementReader reader(m_text);
        while (const auto s = reader.next()) statement(*s);
        m_library.linesRead = reader.linesRead();
        return std::move(m_library);
    }

private:
    [[noreturn]] void fail(int line, const std::string& message) const {
        throw InputError(m_path, line, message);
    }
    /// An error about the current material's value.
    [[noreturn]] void failValue(int line, const std::string& message) const {
        fail(line, "material '" + current().name + "': " + message);
    }
    /// A warning that holds for the whole file: reported once, at its first line.
    void warnOnce(int line, const std::string& message) { m_warn.add(message, line, m_path); }

    MtlMaterial& current() { return m_library.materials.back(); }
    const MtlMaterial& current() const { return m_library.materials.back(); }

    void statement(const Statement& s) {
        const std::string k = lowerCase(s.keyword);
        if (k == "newmtl") return newMaterial(s);
        if (m_library.materials.empty()) {
            warnOnce(s.line, "statements before the first 'newmtl' belong to no material; ignored");
            return;
        }
        if (k == "ka") return color(s, current().ka);
        if (k == "kd") return color(s, current().kd);
        if (k == "ks") return color(s, current().ks);
        if (k == "ke") return color(s, current().ke);
        if (k == "tf" || k == "kt") return color(s, current().tf);
        if (k == "ns") {
            const double ns = number(s);
            if (ns < 0) failValue(s.line, "Ns must be >= 0 (got " + shown(ns) + ")");
            current().ns = {ns, s.line};
            return;
        }
        if (k == "ni") {
            current().ni = {number(s), s.line};
            return;
        }
        if (k == "d" || k == "tr") return dissolve(s, k == "d");
        if (k == "illum") return illum(s);
        if (isTextureKeyword(k)) return texture(s);
        if (const char* what = unsimulated(k)) {
            warnOnce(s.line, "'" + std::string(s.keyword) + "' (" + what +
                                 ") is not simulated by raylab; ignored");
            return;
        }
        warnOnce(s.line, "unknown MTL statement '" +
                             terminalSafe(std::string(s.keyword.substr(0, 40))) + "' is ignored");
    }

    void newMaterial(const Statement& s) {
        const std::string name(s.args);  // trimmed; inner blanks are part of the name
        if (name.empty()) fail(s.line, "'newmtl' needs a material name");
        MtlMaterial m;
        m.name = name;
        m.file = m_path;
        m.line = s.line;
        m_library.materials.push_back(std::move(m));
    }

    static std::string shown(double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return buf;
    }

    /// Values are read at float precision, as tinyobjloader read them: the
    /// pictures of files rendered before stay bit-identical.
    static double asFloat(double v) { return double(float(v)); }

    /// The numbers of a statement (at most `maxCount`), each finite.
    int numbers(const Statement& s, std::string_view rest, double* out, int maxCount) {
        int count = 0;
        for (std::string_view t = nextToken(rest); !t.empty(); t = nextToken(rest)) {
            const std::optional<double> x = parseNumber(t);
            if (!x)
                fail(s.line, "'" + std::string(s.keyword) + "': " + quotedToken(t) +
                                 " is not a finite number");
            if (count == maxCount)
                fail(s.line, "'" + std::string(s.keyword) + "' takes at most " +
                                 std::to_string(maxCount) + " numbers");
            // A finite double beyond the float range would become Inf here.
            if (!std::isfinite(asFloat(*x)))
                fail(s.line, "'" + std::string(s.keyword) + "': " + quotedToken(t) +
                                 " is beyond float range (about 3.4e38)");
            out[count++] = asFloat(*x);
        }
        return count;
    }

    /// A statement with exactly one number.
    double number(const Statement& s) {
        double x = 0;
        const int n = numbers(s, withoutComment(s.args), &x, 1);
        if (n != 1) fail(s.line, "'" + std::string(s.keyword) + "' needs 1 number, found none");
        return x;
    }

    /// "K r g b", or "K r" for a grey (the MTL rule: g = b = r).
    void color(const Statement& s, MtlValue<Color>& out) {
        std::string_view rest = withoutComment(s.args);
        std::string_view probe = rest;
        const std::string_view first = nextToken(probe);
        if (first == "spectral" || first == "xyz") {
            warnOnce(s.line, "'" + std::string(s.keyword) + " " + std::string(first) +
                                 "' colours are not supported; the statement is ignored");
            return;
        }
        double x[3];
        const int n = numbers(s, rest, x, 3);
        if (n == 1) x[1] = x[2] = x[0];
        else if (n != 3)
            fail(s.line, "'" + std::string(s.keyword) + "' needs 3 numbers, found " +
                             std::to_string(n));
        if (x[0] < 0 || x[1] < 0 || x[2] < 0)
            failValue(s.line, std::string(s.keyword) + ": colours must be finite and >= 0 (got " +
                                  shown(x[0]) + " " + shown(x[1]) + " " + shown(x[2]) + ")");
        out = {Color(x[0], x[1], x[2]), s.line};
    }

    /// d X, d -halo X, Tr X: one range, [0, 1], however it is spelt.
    void dissolve(const Statement& s, bool isD) {
        std::string_view rest = withoutComment(s.args);
        std::string spelling = isD ? "d" : "Tr";
        std::string_view probe = rest;
        if (isD && nextToken(probe) == "-halo") {
            // The halo form fades with the view angle; raylab reads its plain value.
            rest = probe;
            spelling = "d -halo";
        }
        double x = 0;
        if (numbers(s, rest, &x, 1) != 1)
            fail(s.line, "'" + spelling + "' needs 1 number, found none");
        if (!(x >= 0 && x <= 1))
            failValue(s.line, spelling + (isD ? " (dissolve)" : " (transparency, 1 - dissolve)") +
                                  " must be in [0, 1] (got " + shown(x) + ")");
        MtlMaterial& m = current();
        if (m.dissolve.given() && (m.dissolveKeyword == "Tr") == isD) {
            // Exporters that write both mean the same thing; d is the standard one.
            warnOnce(s.line, "Both `d` and `Tr` parameters defined; the value of `d` is used");
            if (!isD) return;
        }
        m.dissolve = {isD ? x : asFloat(1.0 - x), s.line};
        m.dissolveKeyword = spelling;
    }

    void illum(const Statement& s) {
        const double x = number(s);
        if (x != std::floor(x) || std::fabs(x) > 1e9)
            failValue(s.line, "illum takes an integer (got " + shown(x) + ")");
        current().illum = {int(x), s.line};
    }

    /// map_Kd [-options ...] file: the options are kept as written; the file
    /// name is the rest of the line (it may contain blanks).
    void texture(const Statement& s) {
        MtlTexture t;
        t.keyword = std::string(s.keyword);
        t.line = s.line;
        std::string_view rest = s.args;
        while (true) {
            std::string_view probe = rest;
            const std::string_view option = nextToken(probe);
            const int args = textureOptionArgs(option);
            if (args < 0) break;
            // -o/-s/-t take one to three numbers; the others a fixed count.
            for (int i = 0; i < args; ++i) {
                std::string_view next = probe;
                const std::string_view a = nextToken(next);
                if (a.empty() || (i > 0 && (option == "-o" || option == "-s" || option == "-t") &&
                                  !parseNumber(a)))
                    break;
                probe = next;
            }
            rest = probe;
        }
        const size_t optionsLength = size_t(rest.data() - s.args.data());
        t.options = std::string(trimBlanks(s.args.substr(0, optionsLength)));
        t.file = slashPath(trimBlanks(rest));
        if (t.file.empty()) fail(s.line, "'" + t.keyword + "' needs a file name");
        current().textures.push_back(std::move(t));
    }

    std::string_view m_text;
    const std::string& m_path;
    LoadWarnings& m_warn;
    MtlLibrary m_library;
};

}  // namespace

MtlLibrary parseMtl(std::string_view text, const std::string& path, LoadWarnings& warn) {
    return MtlParser(text, path, warn).parse();
}

MtlLibrary readMtl(const std::string& path, LoadWarnings& warn) {
    const std::string text = readTextFile(path);
    if (const auto [line, message] = findNonText(text, "MTL"); line > 0)
        throw InputError(path, line, message);
    return parseMtl(text, path, warn);
}

}  // namespace raylab

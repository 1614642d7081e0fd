#include "renderer/io/obj_scan.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "geometry/primitives.h"

namespace raylab {

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
            std::string message = check(corner.substr(0, s1), vSoFar, vTotal, "vertex", "vertices");
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

std::pair<int, std::string> findBadNumber(const std::string& text,
                                          std::initializer_list<NumericStatement> statements,
                                          bool floatRange,
                                          std::initializer_list<const char*> skipWords) {
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

int lineOfStatement(const std::string& text, const std::string& kw, size_t index) {
    int found = 0;
    size_t seen = 0;
    forEachStatement(text, [&](const std::string& k, const char*, const char*, int line) {
        if (found == 0 && k == kw && seen++ == index) found = line;
    });
    return found;
}

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

}  // namespace raylab

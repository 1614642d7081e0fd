#include "renderer/io/wavefront_text.h"

#include "renderer/io/plain_decimal.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace raylab {

std::optional<Statement> StatementReader::next() {
    while (m_pos < m_text.size()) {
        const char* begin = m_text.data() + m_pos;
        const size_t left = m_text.size() - m_pos;
        const void* nl = std::memchr(begin, '\n', left);
        const size_t length = nl ? size_t(static_cast<const char*>(nl) - begin) : left;
        m_pos += length + 1;
        ++m_line;
        std::string_view line(begin, length);
        const std::string_view body = trimBlanks(line);
        if (body.empty() || body[0] == '#') continue;
        size_t k = 0;
        while (k < body.size() && !isBlank(body[k])) ++k;
        return Statement{body.substr(0, k), trimBlanks(body.substr(k)), m_line};
    }
    return std::nullopt;
}

std::string_view withoutComment(std::string_view args) {
    const size_t hash = args.find('#');
    return hash == std::string_view::npos ? args : trimBlanks(args.substr(0, hash));
}

std::string_view nextToken(std::string_view& rest) {
    const char* p = rest.data();
    const char* const end = p + rest.size();
    while (p < end && isBlank(*p)) ++p;
    const char* q = p;
    while (q < end && !isBlank(*q)) ++q;
    rest = std::string_view(q, size_t(end - q));
    return std::string_view(p, size_t(q - p));
}

std::string_view trimBlanks(std::string_view s) {
    size_t a = 0, b = s.size();
    while (a < b && isBlank(s[a])) ++a;
    while (b > a && isBlank(s[b - 1])) --b;
    return s.substr(a, b - a);
}

std::string slashPath(std::string_view path) {
    std::string out(path);
    for (char& c : out)
        if (c == '\\') c = '/';
    return out;
}

std::string quotedToken(std::string_view token) {
    return "'" + std::string(token.substr(0, 40)) + (token.size() > 40 ? "...'" : "'");
}

std::optional<double> parseNumber(std::string_view token) {
    const char* first = token.data();
    const char* last = first + token.size();
    // from_chars takes no '+' (and reads "nan" and "inf", refused below).
    if (first < last && *first == '+' && first + 1 < last && first[1] != '-') ++first;
    if (const std::optional<double> plain = plainDecimal(first, last)) return plain;
    double v = 0;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ptr != last || token.empty()) return std::nullopt;
    if (ec == std::errc::result_out_of_range) {
        // Underflow towards zero is harmless; overflow is not a number raylab
        // can use. (Rare path: strtod tells the two apart.)
        const double approx = std::strtod(std::string(token).c_str(), nullptr);
        if (!(std::fabs(approx) < 1.0)) return std::nullopt;
        return approx;
    }
    if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace raylab

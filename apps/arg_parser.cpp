#include "apps/arg_parser.h"

#include <cerrno>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "renderer/io/errors.h"

namespace raylab {

namespace {

/// strtoll and strtod skip leading blanks; a value that starts with one is
/// almost always a quoting mistake, so it is refused rather than guessed.
bool startsWithSpace(const std::string& v) {
    return !v.empty() && std::isspace(static_cast<unsigned char>(v[0]));
}

/// A range bound as a person writes it: 1e+30, 0.5, 64 (not 1000000000000000019884624838656.000000).
std::string formatBound(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
}

}  // namespace

std::string ArgParser::next() { return m_args.at(m_pos++); }

bool ArgParser::peekFlag() const {
    return !done() && m_args[m_pos].size() > 1 && m_args[m_pos][0] == '-';
}

std::string ArgParser::value(const std::string& flag) {
    if (done()) throw UsageError(flag + ": missing value");
    // A flag given twice is almost always a script that appends to a command
    // line: which value wins would be a guess, so neither does.
    const std::string name = flag == "-o" ? "--output" : flag;  // the one short alias
    for (const std::string& seen : m_seen)
        if (seen == name) throw UsageError(flag + ": given more than once");
    m_seen.push_back(name);
    return next();
}

std::string ArgParser::repeatableValue(const std::string& flag) {
    if (done()) throw UsageError(flag + ": missing value");
    return next();
}

long long ArgParser::integer(const std::string& flag, long long lo, long long hi) {
    const std::string v = value(flag);
    errno = 0;
    char* end = nullptr;
    const long long x = std::strtoll(v.c_str(), &end, 10);
    if (v.empty() || startsWithSpace(v) || *end != '\0' || errno == ERANGE || x < lo || x > hi)
        throw UsageError(flag + ": expected an integer in [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "] (got '" + v + "')");
    return x;
}

double ArgParser::number(const std::string& flag, double lo, double hi) {
    const std::string v = value(flag);
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || startsWithSpace(v) || *end != '\0' || !std::isfinite(x) || x < lo || x > hi)
        throw UsageError(flag + ": expected a number in [" + formatBound(lo) + ", " +
                         formatBound(hi) + "] (got '" + v + "')");
    return x;
}

std::array<double, 3> ArgParser::triple(const std::string& flag) {
    const std::string v = value(flag);
    std::array<double, 3> out{};
    size_t start = 0;
    for (size_t i = 0; i < 3; ++i) {
        const size_t comma = v.find(',', start);
        const bool last = i == 2;
        const std::string part =
            v.substr(start, (last || comma == std::string::npos) ? std::string::npos : comma - start);
        char* end = nullptr;
        out[i] = std::strtod(part.c_str(), &end);
        if (part.empty() || startsWithSpace(part) || *end != '\0' || !std::isfinite(out[i]) ||
            (!last && comma == std::string::npos))
            throw UsageError(flag + ": expected three numbers X,Y,Z (got '" + v + "')");
        start = comma + 1;
    }
    return out;
}

size_t ArgParser::choiceIndex(const std::string& flag, const std::vector<std::string>& words) {
    const std::string v = value(flag);
    std::string list;
    for (size_t i = 0; i < words.size(); ++i) {
        if (words[i] == v) return i;
        list += (list.empty() ? "" : "|") + words[i];
    }
    throw UsageError(flag + ": expected " + list + " (got '" + v + "')");
}

}  // namespace raylab

#include "apps/arg_parser.h"

#include <cerrno>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "renderer/io/did_you_mean.h"
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

std::vector<std::string> CommandFlags::names() const {
    std::vector<std::string> out{"--help"};
    for (const FlagSpec& f : flags) {
        out.push_back(f.name);
        if (!f.shortName.empty()) out.push_back(f.shortName);
    }
    return out;
}

const FlagSpec* CommandFlags::find(const std::string& name) const {
    for (const FlagSpec& f : flags)
        if (f.name == name || (!f.shortName.empty() && f.shortName == name)) return &f;
    return nullptr;
}

std::string ArgParser::next() {
    // A value after "=" that the command did not read would be silently lost.
    if (m_inlineValue) throw std::logic_error("ArgParser: value of '=' form not read");
    std::string a = m_args.at(m_pos++);
    if (a.size() < 2 || a[0] != '-') return a;  // a positional argument ("-" included)
    std::optional<std::string> inlineValue;
    if (a.compare(0, 2, "--") == 0) {
        const size_t eq = a.find('=');
        if (eq != std::string::npos) {
            inlineValue = a.substr(eq + 1);
            a.resize(eq);
        }
    }
    if (a == "-h" || a == "--help") {
        std::fputs(m_flags.help, stdout);
        std::exit(0);
    }
    const FlagSpec* spec = m_flags.find(a);
    if (!spec)
        throw UsageError(m_flags.command + ": unknown option '" + a + "'" +
                         didYouMean(a, m_flags.names()) + " (see 'raylab " + m_flags.command +
                         " --help')");
    if (inlineValue && !spec->takesValue)
        throw UsageError(a + ": takes no value (got '" + a + "=" + *inlineValue + "')");
    m_inlineValue = std::move(inlineValue);
    return a;
}

bool ArgParser::peekFlag() const {
    return !done() && m_args[m_pos].size() > 1 && m_args[m_pos][0] == '-';
}

std::string ArgParser::value(const std::string& flag) {
    // A flag given twice is almost always a script that appends to a command
    // line: which value wins would be a guess, so neither does.
    const FlagSpec* spec = m_flags.find(flag);
    const std::string name = spec ? spec->name : flag;
    for (const std::string& seen : m_seen)
        if (seen == name) throw UsageError(flag + ": given more than once");
    m_seen.push_back(name);
    if (m_inlineValue) {
        std::string v = std::move(*m_inlineValue);
        m_inlineValue.reset();
        return v;
    }
    if (done()) throw UsageError(flag + ": missing value");
    return m_args.at(m_pos++);
}

std::string ArgParser::repeatableValue(const std::string& flag) {
    if (m_inlineValue) {  // "-o=a.exr" style: "--output=a.exr"
        std::string v = std::move(*m_inlineValue);
        m_inlineValue.reset();
        return v;
    }
    if (done()) throw UsageError(flag + ": missing value");
    return m_args.at(m_pos++);
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

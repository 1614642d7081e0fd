#include "tools/report/table_format.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "renderer/io/errors.h"

namespace raylab {

TableFormat tableFormatOf(const std::string& path, const std::string& what) {
    std::string lower = path;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    const auto endsWith = [&](const char* ext) {
        const std::string e = ext;
        return lower.size() > e.size() && lower.compare(lower.size() - e.size(), e.size(), e) == 0;
    };
    if (endsWith(".csv")) return TableFormat::Csv;
    if (endsWith(".json")) return TableFormat::Json;
    throw UsageError(what + ": '" + path + "' must end in .csv or .json");
}

std::string jsonNumber(double v) {
    if (!std::isfinite(v)) return "null";
    // The shortest precision that reads back to the same double.
    char buf[40];
    for (int precision = 6; precision <= 17; ++precision) {
        std::snprintf(buf, sizeof buf, "%.*g", precision, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

std::string fileName(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace raylab

#include "renderer/io/json_string.h"

#include <cstdio>

namespace raylab {

namespace {

/// The escape of byte c, or null when it passes through unchanged.
const char* shortEscape(unsigned char c) {
    switch (c) {
        case '"': return "\\\"";
        case '\\': return "\\\\";
        case '\n': return "\\n";
        case '\r': return "\\r";
        case '\t': return "\\t";
        case '\b': return "\\b";
        case '\f': return "\\f";
        default: return nullptr;
    }
}

bool needsEscape(unsigned char c) { return c < 0x20 || c == '"' || c == '\\'; }

}  // namespace

void appendJsonString(std::string& out, std::string_view s) {
    out += '"';
    size_t plain = 0;  // start of the run not yet copied
    for (size_t i = 0; i < s.size(); ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (!needsEscape(c)) continue;  // UTF-8 bytes pass through unchanged
        out.append(s, plain, i - plain);
        plain = i + 1;
        if (const char* e = shortEscape(c)) {
            out += e;
        } else {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        }
    }
    out.append(s, plain, s.size() - plain);
    out += '"';
}

std::string jsonString(std::string_view s) {
    std::string out;
    out.reserve(s.size() + 2);
    appendJsonString(out, s);
    return out;
}

}  // namespace raylab

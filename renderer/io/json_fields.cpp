#include "renderer/io/json_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "renderer/io/did_you_mean.h"
#include "renderer/io/errors.h"

namespace raylab {

std::string formatJsonNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string memberPath(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

std::string indexPath(const std::string& parent, size_t i) {
    return parent + "[" + std::to_string(i) + "]";
}

std::string quotedList(const std::vector<std::string>& items) {
    std::string s;
    for (size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + ("'" + items[i] + "'");
    return s;
}

// ---------------------------------------------------------------------------
// Typed values

void JsonFieldReader::fail(int line, const std::string& path, const std::string& message) const {
    throw InputError(m_file, line, path.empty() ? message : path + ": " + message);
}

void JsonFieldReader::expectType(const JsonValue& v, const std::string& path, JsonValue::Type type,
                                 const char* expected) const {
    if (v.type() != type)
        fail(v, path, std::string("expected ") + expected + ", got " + v.typeName());
}

double JsonFieldReader::number(const JsonValue& v, const std::string& path) const {
    expectType(v, path, JsonValue::Type::Number, "a number");
    return v.asNumber();
}

double JsonFieldReader::positive(const JsonValue& v, const std::string& path) const {
    const double x = number(v, path);
    if (!(x > 0)) fail(v, path, "must be > 0 (got " + formatJsonNumber(x) + ")");
    return x;
}

double JsonFieldReader::nonNegative(const JsonValue& v, const std::string& path) const {
    const double x = number(v, path);
    if (!(x >= 0)) fail(v, path, "must be >= 0 (got " + formatJsonNumber(x) + ")");
    return x;
}

long long JsonFieldReader::integer(const JsonValue& v, const std::string& path, long long lo,
                                   long long hi) const {
    const double x = number(v, path);
    if (x != std::floor(x)) fail(v, path, "must be an integer (got " + formatJsonNumber(x) + ")");
    if (x < lo || x > hi)
        fail(v, path,
             "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " +
                 formatJsonNumber(x) + ")");
    return static_cast<long long>(x);
}

bool JsonFieldReader::boolean(const JsonValue& v, const std::string& path) const {
    expectType(v, path, JsonValue::Type::Bool, "true or false");
    return v.asBool();
}

const std::string& JsonFieldReader::string(const JsonValue& v, const std::string& path) const {
    expectType(v, path, JsonValue::Type::String, "a string");
    return v.asString();
}

const JsonValue& JsonFieldReader::array(const JsonValue& v, const std::string& path) const {
    expectType(v, path, JsonValue::Type::Array, "an array");
    return v;
}

Vec3 JsonFieldReader::vec3(const JsonValue& v, const std::string& path) const {
    if (!v.isArray()) fail(v, path, std::string("expected [x, y, z], got ") + v.typeName());
    if (v.size() != 3)
        fail(v, path,
             "expected [x, y, z] (3 numbers), got " + std::to_string(v.size()) +
                 (v.size() == 1 ? " element" : " elements"));
    Vec3 out;
    for (int i = 0; i < 3; ++i) out[i] = number(v.at(size_t(i)), indexPath(path, size_t(i)));
    return out;
}

Vec3 JsonFieldReader::direction(const JsonValue& v, const std::string& path) const {
    const Vec3 d = vec3(v, path);
    if (!(length(d) > 0)) fail(v, path, "must not be the zero vector");
    return d;
}

Color JsonFieldReader::color(const JsonValue& v, const std::string& path) const {
    if (v.isNumber()) return Color(nonNegative(v, path));
    if (!v.isArray() || v.size() != 3)
        fail(v, path,
             std::string("expected [r, g, b] or a number, got ") +
                 (v.isArray() ? "an array of " + std::to_string(v.size()) : v.typeName()));
    Color c;
    c.r = nonNegative(v.at(0), indexPath(path, 0));
    c.g = nonNegative(v.at(1), indexPath(path, 1));
    c.b = nonNegative(v.at(2), indexPath(path, 2));
    return c;
}

// ---------------------------------------------------------------------------
// Object members

JsonFields::JsonFields(const JsonFieldReader& reader, const JsonValue& value, std::string path,
                       std::string what, const std::vector<std::string>& allowed)
    : m_reader(reader), m_value(value), m_path(std::move(path)), m_what(std::move(what)) {
    if (!value.isObject())
        reader.fail(value, m_path,
                    "expected an object ({...}) for " + m_what + ", got " + value.typeName());
    for (size_t i = 0; i < value.size(); ++i) {
        const std::string& key = value.key(i);
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        // Suggest the closest allowed key within two edits, else list them all.
        std::string hint = didYouMean(key, allowed);
        if (hint.empty()) hint = " (expected " + quotedList(allowed) + ")";
        reader.fail(value.keyLine(i), memberPath(m_path, key), "unknown key for " + m_what + hint);
    }
}

const JsonValue& JsonFields::need(const std::string& key) const {
    const JsonValue* v = get(key);
    if (!v) m_reader.fail(m_value, m_path, "missing required key '" + key + "' for " + m_what);
    return *v;
}

}  // namespace raylab

#pragma once
// Typed reading of JSON scene values with located errors: every failure is an
// InputError naming the file, the value's line and its key path
// ("scene.json:14: objects[3].radius: must be > 0 (got -1)").

#include <string>
#include <utility>
#include <vector>

#include "geometry/vec.h"
#include "renderer/io/json.h"
#include "shading/color.h"

namespace raylab {

/// Numbers in messages: short, exact for the values people type.
std::string formatJsonNumber(double v);
/// Key paths: "objects[3].radius".
std::string memberPath(const std::string& parent, const std::string& key);
std::string indexPath(const std::string& parent, size_t i);
/// "'a', 'b', 'c'".
std::string quotedList(const std::vector<std::string>& items);

/// Reads the values of one JSON file as the types the scene format names
/// (docs/scene-format.md, "Value types").
class JsonFieldReader {
public:
    explicit JsonFieldReader(std::string file) : m_file(std::move(file)) {}

    const std::string& file() const { return m_file; }

    [[noreturn]] void fail(int line, const std::string& path, const std::string& message) const;
    [[noreturn]] void fail(const JsonValue& v, const std::string& path,
                           const std::string& message) const {
        fail(v.line(), path, message);
    }

    void expectType(const JsonValue& v, const std::string& path, JsonValue::Type type,
                    const char* expected) const;
    double number(const JsonValue& v, const std::string& path) const;
    double positive(const JsonValue& v, const std::string& path) const;
    double nonNegative(const JsonValue& v, const std::string& path) const;
    long long integer(const JsonValue& v, const std::string& path, long long lo,
                      long long hi) const;
    bool boolean(const JsonValue& v, const std::string& path) const;
    const std::string& string(const JsonValue& v, const std::string& path) const;
    const JsonValue& array(const JsonValue& v, const std::string& path) const;
    Vec3 vec3(const JsonValue& v, const std::string& path) const;
    /// A vector that must not be zero (directions, normals, axes).
    Vec3 direction(const JsonValue& v, const std::string& path) const;
    /// [r, g, b] or one number for a grey; every component >= 0.
    Color color(const JsonValue& v, const std::string& path) const;

    /// One of the named `options`.
    template <class E>
    E choice(const JsonValue& v, const std::string& path,
             const std::vector<std::pair<std::string, E>>& options) const {
        const std::string& s = string(v, path);
        std::vector<std::string> names;
        for (const auto& [name, e] : options) {
            if (name == s) return e;
            names.push_back(name);
        }
        fail(v, path, "must be one of " + quotedList(names) + " (got '" + s + "')");
    }

private:
    std::string m_file;
};

/// The members of one JSON object: rejects keys outside the allowed set up
/// front (before any value is read, so a misspelt key is the first error
/// reported, with a "did you mean" hint) and reports missing required keys.
class JsonFields {
public:
    /// `what` names the object in messages ("a sphere").
    JsonFields(const JsonFieldReader& reader, const JsonValue& value, std::string path,
               std::string what, const std::vector<std::string>& allowed);

    const JsonValue* get(const std::string& key) const { return m_value.find(key); }
    const JsonValue& need(const std::string& key) const;
    bool has(const std::string& key) const { return get(key) != nullptr; }
    std::string path(const std::string& key) const { return memberPath(m_path, key); }
    const JsonValue& value() const { return m_value; }
    const std::string& objectPath() const { return m_path; }

private:
    const JsonFieldReader& m_reader;
    const JsonValue& m_value;
    std::string m_path;
    std::string m_what;
};

}  // namespace raylab

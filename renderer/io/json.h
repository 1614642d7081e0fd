#pragma once
// A small strict JSON reader for scene files. Every value remembers the line
// it starts on, so loaders can report "scene.json:14: objects[3].radius: ...".
//
// Accepted: RFC 8259 JSON in UTF-8 (an optional UTF-8 byte-order mark is
// skipped), plus // line comments and /* block */ comments. Rejected with an
// InputError(file, line, message): trailing commas, duplicate object keys,
// numbers that overflow a double ("number out of range"), NaN/Infinity,
// invalid UTF-8 in strings, lone UTF-16 surrogates in \u escapes, NUL bytes,
// UTF-16/UTF-32 input, nesting deeper than kMaxJsonDepth, and anything after
// the top-level value.

#include <cstddef>
#include <string>
#include <vector>

namespace raylab {

/// Maximum nesting of arrays and objects; deeper input is an error rather
/// than a stack overflow in the recursive-descent parser.
constexpr int kMaxJsonDepth = 256;

class JsonValue {
public:
    enum class Type { Null, Bool, Number, String, Array, Object };

    /// A null value with no source line.
    JsonValue() = default;

    Type type() const { return m_type; }
    /// 1-based line on which the value starts (0 for a default-constructed value).
    int line() const { return m_line; }

    bool isNull() const { return m_type == Type::Null; }
    bool isBool() const { return m_type == Type::Bool; }
    bool isNumber() const { return m_type == Type::Number; }
    bool isString() const { return m_type == Type::String; }
    bool isArray() const { return m_type == Type::Array; }
    bool isObject() const { return m_type == Type::Object; }

    /// The payload; each throws std::logic_error when the type does not match
    /// (callers check the type first and report a located InputError).
    bool asBool() const;
    double asNumber() const;
    const std::string& asString() const;

    /// Number of array elements or object members (0 for scalars).
    size_t size() const { return m_items.size(); }
    /// Array element or object member value `i`, in source order.
    const JsonValue& at(size_t i) const { return m_items.at(i); }
    /// Object member key `i`, in source order.
    const std::string& key(size_t i) const { return m_keys.at(i); }
    /// Line of object member key `i`.
    int keyLine(size_t i) const { return m_keyLines.at(i); }
    /// The member named `key`, or null when absent or when this is not an object.
    const JsonValue* find(const std::string& key) const;

    /// "null", "boolean", "number", "string", "array" or "object".
    static const char* typeName(Type type);
    const char* typeName() const { return typeName(m_type); }

private:
    friend class JsonParser;

    Type m_type = Type::Null;
    int m_line = 0;
    bool m_bool = false;
    double m_number = 0;
    std::string m_string;
    std::vector<JsonValue> m_items;   ///< array elements or object member values
    std::vector<std::string> m_keys;  ///< object keys, parallel to m_items
    std::vector<int> m_keyLines;      ///< object key lines, parallel to m_items
};

/// Parses a whole JSON document. `file` is only used in error messages.
/// Throws InputError(file, line, message) on any syntax or encoding error.
JsonValue parseJson(const std::string& text, const std::string& file);

}  // namespace raylab

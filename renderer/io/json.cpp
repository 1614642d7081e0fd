#include "renderer/io/json.h"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <unordered_map>

#include "renderer/io/errors.h"
#include "renderer/io/text_file.h"

namespace raylab {

bool JsonValue::asBool() const {
    if (m_type != Type::Bool) throw std::logic_error("JsonValue: not a boolean");
    return m_bool;
}

double JsonValue::asNumber() const {
    if (m_type != Type::Number) throw std::logic_error("JsonValue: not a number");
    return m_number;
}

const std::string& JsonValue::asString() const {
    if (m_type != Type::String) throw std::logic_error("JsonValue: not a string");
    return m_string;
}

const JsonValue* JsonValue::find(const std::string& key) const {
    if (m_type != Type::Object) return nullptr;
    for (size_t i = 0; i < m_keys.size(); ++i)
        if (m_keys[i] == key) return &m_items[i];
    return nullptr;
}

const char* JsonValue::typeName(Type type) {
    switch (type) {
        case Type::Null:
            return "null";
        case Type::Bool:
            return "boolean";
        case Type::Number:
            return "number";
        case Type::String:
            return "string";
        case Type::Array:
            return "array";
        case Type::Object:
            return "object";
    }
    return "?";
}

/// Recursive-descent parser over the raw bytes; tracks the current line.
class JsonParser {
public:
    JsonParser(const std::string& text, const std::string& file) : m_s(text), m_file(file) {}

    JsonValue parseDocument() {
        checkEncoding();
        skipSpace();
        if (atEnd()) fail("empty file (expected a JSON value)");
        JsonValue root = parseValue(0);
        skipSpace();
        if (!atEnd()) fail("unexpected " + describeHere() + " after the end of the JSON value");
        return root;
    }

private:
    const std::string& m_s;
    const std::string& m_file;
    size_t m_pos = 0;
    int m_line = 1;

    [[noreturn]] void fail(const std::string& message) const { fail(m_line, message); }
    [[noreturn]] void fail(int line, const std::string& message) const {
        throw InputError(m_file, line, message);
    }

    bool atEnd() const { return m_pos >= m_s.size(); }
    unsigned char peek(size_t ahead = 0) const {
        return m_pos + ahead < m_s.size() ? static_cast<unsigned char>(m_s[m_pos + ahead]) : 0;
    }

    /// The character at the cursor, for messages: "'x'", "byte 0xC3" or "end of input".
    std::string describeHere() const {
        if (atEnd()) return "end of input";
        const unsigned char c = peek();
        if (c >= 0x21 && c < 0x7f) return std::string("'") + char(c) + "'";
        char buf[32];
        std::snprintf(buf, sizeof buf, "byte 0x%02X", unsigned(c));
        return buf;
    }

    /// Rejects encodings we cannot read before the grammar sees them; skips a UTF-8 BOM.
    void checkEncoding() {
        if (const auto [line, message] = findNonText(m_s, "JSON"); line > 0) fail(line, message);
        auto byte = [&](size_t i) { return static_cast<unsigned char>(m_s[i]); };
        if (m_s.size() >= 3 && byte(0) == 0xEF && byte(1) == 0xBB && byte(2) == 0xBF) m_pos = 3;
    }

    /// Advances over one character, counting "\n", "\r\n" and a lone "\r" as one line break.
    void advance() {
        const char c = m_s[m_pos++];
        if (c == '\n' || (c == '\r' && peek() != '\n')) ++m_line;
    }

    /// Skips whitespace and comments.
    void skipSpace() {
        while (!atEnd()) {
            const unsigned char c = peek();
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                while (!atEnd() && peek() != '\n' && peek() != '\r') advance();
            } else if (c == '/' && peek(1) == '*') {
                const int startLine = m_line;
                advance();
                advance();
                while (!(peek() == '*' && peek(1) == '/')) {
                    if (atEnd()) fail(startLine, "unterminated /* comment");
                    advance();
                }
                advance();
                advance();
            } else {
                return;
            }
        }
    }

    JsonValue parseValue(int depth) {
        JsonValue v;
        v.m_line = m_line;
        if (atEnd()) fail("unexpected end of input (expected a value)");
        const unsigned char c = peek();
        if (c == '{' || c == '[') {
            if (depth + 1 > kMaxJsonDepth)
                fail("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
            if (c == '{')
                parseObject(v, depth + 1);
            else
                parseArray(v, depth + 1);
        } else if (c == '"') {
            v.m_type = JsonValue::Type::String;
            v.m_string = parseString();
        } else if (c == '-' || (c >= '0' && c <= '9')) {
            v.m_type = JsonValue::Type::Number;
            v.m_number = parseNumber();
        } else if (std::isalpha(c) || c == '_') {
            parseLiteral(v);
        } else if (c == '\'') {
            fail("strings must use double quotes, not single quotes");
        } else if (c == '.' || c == '+') {
            fail("invalid number: JSON numbers start with '-' or a digit");
        } else {
            fail("unexpected " + describeHere() + " (expected a value)");
        }
        return v;
    }

    void parseLiteral(JsonValue& v) {
        size_t end = m_pos;
        while (end < m_s.size() &&
               (std::isalnum(static_cast<unsigned char>(m_s[end])) || m_s[end] == '_'))
            ++end;
        const std::string word = m_s.substr(m_pos, end - m_pos);
        if (word == "true" || word == "false") {
            v.m_type = JsonValue::Type::Bool;
            v.m_bool = word == "true";
        } else if (word == "null") {
            v.m_type = JsonValue::Type::Null;
        } else if (word == "NaN" || word == "Infinity" || word == "inf" || word == "nan") {
            fail("invalid value '" + word + "' (JSON has no NaN or infinity)");
        } else {
            fail("invalid literal '" + word +
                 "' (expected true, false, null, a number, a string, an array or an object)");
        }
        m_pos = end;
    }

    void parseObject(JsonValue& v, int depth) {
        v.m_type = JsonValue::Type::Object;
        std::unordered_map<std::string, int> seen;  // key -> line of first definition
        advance();                                  // '{'
        skipSpace();
        if (peek() == '}' && !atEnd()) {
            advance();
            return;
        }
        while (true) {
            skipSpace();
            if (atEnd()) fail("unexpected end of input inside an object");
            if (peek() != '"') {
                if (peek() == '}') fail("trailing comma before '}'");
                fail("expected a string key in double quotes, got " + describeHere());
            }
            const int keyLine = m_line;
            std::string key = parseString();
            const auto [it, inserted] = seen.emplace(key, keyLine);
            if (!inserted)
                fail(keyLine, "duplicate key '" + key + "' (first defined on line " +
                                  std::to_string(it->second) + ")");
            skipSpace();
            if (peek() != ':' || atEnd())
                fail("expected ':' after key '" + key + "', got " + describeHere());
            advance();
            skipSpace();
            JsonValue member = parseValue(depth);
            v.m_keys.push_back(std::move(key));
            v.m_keyLines.push_back(keyLine);
            v.m_items.push_back(std::move(member));
            skipSpace();
            if (atEnd()) fail("unexpected end of input inside an object (missing '}')");
            if (peek() == ',') {
                advance();
                continue;
            }
            if (peek() == '}') {
                advance();
                return;
            }
            fail("expected ',' or '}' after an object member, got " + describeHere());
        }
    }

    void parseArray(JsonValue& v, int depth) {
        v.m_type = JsonValue::Type::Array;
        advance();  // '['
        skipSpace();
        if (peek() == ']' && !atEnd()) {
            advance();
            return;
        }
        while (true) {
            skipSpace();
            if (peek() == ']' && !atEnd()) fail("trailing comma before ']'");
            v.m_items.push_back(parseValue(depth));
            skipSpace();
            if (atEnd()) fail("unexpected end of input inside an array (missing ']')");
            if (peek() == ',') {
                advance();
                continue;
            }
            if (peek() == ']') {
                advance();
                return;
            }
            fail("expected ',' or ']' after an array element, got " + describeHere());
        }
    }

    /// JSON number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
    double parseNumber() {
        size_t end = m_pos;
        // The token is the longest run of number-like characters, so "1.2.3"
        // and "01" are reported whole.
        while (end < m_s.size() && (std::isalnum(static_cast<unsigned char>(m_s[end])) ||
                                    m_s[end] == '.' || m_s[end] == '-' || m_s[end] == '+'))
            ++end;
        const std::string token = m_s.substr(m_pos, end - m_pos);
        if (!validNumber(token)) fail("invalid number '" + token + "'");
        // strtod is locale-dependent; the process never calls setlocale, so it
        // runs in the "C" locale where '.' is the decimal point.
        const double value = std::strtod(token.c_str(), nullptr);
        if (!std::isfinite(value)) fail("number out of range (" + token + ")");
        m_pos = end;
        return value;
    }

    static bool validNumber(const std::string& t) {
        size_t i = 0;
        auto digit = [&](size_t k) { return k < t.size() && t[k] >= '0' && t[k] <= '9'; };
        if (i < t.size() && t[i] == '-') ++i;
        if (!digit(i)) return false;
        if (t[i] == '0') {
            ++i;
            if (digit(i)) return false;  // leading zero
        } else {
            while (digit(i)) ++i;
        }
        if (i < t.size() && t[i] == '.') {
            ++i;
            if (!digit(i)) return false;
            while (digit(i)) ++i;
        }
        if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
            ++i;
            if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
            if (!digit(i)) return false;
            while (digit(i)) ++i;
        }
        return i == t.size();
    }

    static void appendUtf8(std::string& out, uint32_t cp) {
        if (cp < 0x80) {
            out += char(cp);
        } else if (cp < 0x800) {
            out += char(0xC0 | (cp >> 6));
            out += char(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += char(0xE0 | (cp >> 12));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        } else {
            out += char(0xF0 | (cp >> 18));
            out += char(0x80 | ((cp >> 12) & 0x3F));
            out += char(0x80 | ((cp >> 6) & 0x3F));
            out += char(0x80 | (cp & 0x3F));
        }
    }

    uint32_t parseHex4() {
        uint32_t cp = 0;
        for (int k = 0; k < 4; ++k) {
            const unsigned char h = peek();
            uint32_t d;
            if (h >= '0' && h <= '9')
                d = h - '0';
            else if (h >= 'a' && h <= 'f')
                d = h - 'a' + 10;
            else if (h >= 'A' && h <= 'F')
                d = h - 'A' + 10;
            else
                fail("invalid \\u escape: expected 4 hex digits");
            cp = cp * 16 + d;
            advance();
        }
        return cp;
    }

    /// Validates one UTF-8 sequence starting at the cursor and copies it to `out`.
    void copyUtf8Sequence(std::string& out) {
        const unsigned char c = peek();
        int len;
        uint32_t cp;
        if (c >= 0xC2 && c <= 0xDF) {
            len = 2;
            cp = c & 0x1F;
        } else if (c >= 0xE0 && c <= 0xEF) {
            len = 3;
            cp = c & 0x0F;
        } else if (c >= 0xF0 && c <= 0xF4) {
            len = 4;
            cp = c & 0x07;
        } else {
            fail("invalid UTF-8 in string");
        }
        for (int k = 1; k < len; ++k) {
            const unsigned char cc = peek(k);
            if ((cc & 0xC0) != 0x80) fail("invalid UTF-8 in string");
            cp = (cp << 6) | (cc & 0x3F);
        }
        // Overlong forms, UTF-16 surrogates and code points above U+10FFFF.
        const uint32_t minimum = len == 2 ? 0x80 : (len == 3 ? 0x800 : 0x10000);
        if (cp < minimum || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF)
            fail("invalid UTF-8 in string");
        out.append(m_s, m_pos, size_t(len));
        m_pos += size_t(len);
    }

    std::string parseString() {
        const int startLine = m_line;
        advance();  // opening quote
        std::string out;
        while (true) {
            if (atEnd()) fail(startLine, "unterminated string");
            const unsigned char c = peek();
            if (c == '"') {
                advance();
                return out;
            }
            if (c < 0x20) {
                if (c == '\n' || c == '\r')
                    fail(startLine, "unterminated string (line break inside)");
                fail("control character in string (write it as an escape such as \\t)");
            }
            if (c == '\\') {
                advance();
                if (atEnd()) fail(startLine, "unterminated string");
                const char e = char(peek());
                advance();
                switch (e) {
                    case '"':
                        out += '"';
                        break;
                    case '\\':
                        out += '\\';
                        break;
                    case '/':
                        out += '/';
                        break;
                    case 'b':
                        out += '\b';
                        break;
                    case 'f':
                        out += '\f';
                        break;
                    case 'n':
                        out += '\n';
                        break;
                    case 'r':
                        out += '\r';
                        break;
                    case 't':
                        out += '\t';
                        break;
                    case 'u': {
                        uint32_t cp = parseHex4();
                        if (cp >= 0xDC00 && cp <= 0xDFFF)
                            fail("lone UTF-16 low surrogate in \\u escape");
                        if (cp >= 0xD800 && cp <= 0xDBFF) {
                            // A high surrogate must be followed by an escaped low surrogate.
                            if (!(peek() == '\\' && peek(1) == 'u'))
                                fail("lone UTF-16 high surrogate in \\u escape");
                            advance();
                            advance();
                            const uint32_t low = parseHex4();
                            if (low < 0xDC00 || low > 0xDFFF)
                                fail("lone UTF-16 high surrogate in \\u escape");
                            cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                        }
                        appendUtf8(out, cp);
                        break;
                    }
                    default:
                        fail(std::string("invalid escape '\\") + e + "' in string");
                }
                continue;
            }
            if (c >= 0x80) {
                copyUtf8Sequence(out);
                continue;
            }
            out += char(c);
            advance();
        }
    }
};

JsonValue parseJson(const std::string& text, const std::string& file) {
    return JsonParser(text, file).parseDocument();
}

}  // namespace raylab

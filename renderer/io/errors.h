#pragma once
// Errors that reach the user as one line: "raylab: error: FILE:LINE: message".

#include <algorithm>
#include <stdexcept>
#include <string>

namespace raylab {

/// Bad input (a scene file, a mesh, a value): exit code 1.
class InputError : public std::runtime_error {
public:
    InputError(std::string file, int line, const std::string& message)
        : std::runtime_error(message), m_file(std::move(file)), m_line(line), m_message(message) {}
    explicit InputError(const std::string& message) : InputError("", 0, message) {}

    const std::string& file() const { return m_file; }
    int line() const { return m_line; }  ///< 0 when no line applies
    /// The whole message: what() is a C string and ends at a NUL byte that
    /// the input put there (a JSON "\u0000"), this does not.
    const std::string& message() const { return m_message; }

    /// "FILE:LINE: message", "FILE: message" or "message".
    std::string located() const {
        std::string s;
        if (!m_file.empty()) s += m_file + ":";
        if (m_line > 0) s += std::to_string(m_line) + ":";
        if (!s.empty()) s += " ";
        return s + m_message;
    }

private:
    std::string m_file;
    int m_line = 0;
    std::string m_message;
};

/// Makes text that may quote user input safe for a one-line terminal message:
/// control bytes (including newlines and escape sequences) become \xNN, and a
/// message longer than maxLength is cut, marked with "...".
inline std::string terminalSafe(const std::string& text, size_t maxLength = 300) {
    static const char* const kHex = "0123456789abcdef";
    std::string out;
    out.reserve(std::min(text.size(), maxLength) + 8);
    for (const char ch : text) {
        const unsigned char c = static_cast<unsigned char>(ch);
        if (c < 0x20 || c == 0x7f) {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        } else {
            out += ch;
        }
        if (out.size() >= maxLength) {
            out += "...";
            break;
        }
    }
    return out;
}

/// Bad command-line usage: exit code 2.
class UsageError : public std::runtime_error {
public:
    explicit UsageError(const std::string& message)
        : std::runtime_error(message), m_message(message) {}
    /// The whole message, NUL bytes included (see InputError::message).
    const std::string& message() const { return m_message; }

private:
    std::string m_message;
};

}  // namespace raylab

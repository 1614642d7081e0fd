#pragma once
// The statement syntax OBJ and MTL share: one statement per line, a keyword,
// blank-separated arguments, '#' comments. Readers walk the text once with
// StatementReader and take arguments with the helpers below; every error they
// build names the statement the way the file spells it.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace raylab {

/// One statement: its keyword, the rest of its line (leading and trailing
/// blanks and the '\r' of CRLF removed, comments kept) and its 1-based line.
struct Statement {
    std::string_view keyword;
    std::string_view args;
    int line = 0;
};

/// Walks a text statement by statement, skipping blank lines and lines whose
/// first non-blank character is '#'.
class StatementReader {
public:
    explicit StatementReader(std::string_view text) : m_text(text) {}
    /// The next statement, or nothing at the end of the text.
    std::optional<Statement> next();
    /// Physical lines visited so far (the whole file once next() returned nothing).
    int linesRead() const { return m_line; }

private:
    std::string_view m_text;
    size_t m_pos = 0;
    int m_line = 0;
};

/// Whether c separates arguments (blank, tab, CR): one bit test for the
/// characters up to ' ', the hot loop of every statement's tokens.
inline bool isBlank(char c) {
    const unsigned u = static_cast<unsigned char>(c);
    constexpr uint64_t kBlanks = (uint64_t(1) << ' ') | (uint64_t(1) << '\t') | (uint64_t(1) << '\r');
    return u <= ' ' && ((kBlanks >> u) & 1u) != 0;
}

/// `args` up to its first '#' (a trailing comment), trailing blanks removed.
std::string_view withoutComment(std::string_view args);

/// The next blank-separated token of `rest` (consumed from it), or "" at the end.
std::string_view nextToken(std::string_view& rest);

/// `s` without leading and trailing blanks. Names (newmtl, usemtl) keep inner spaces.
std::string_view trimBlanks(std::string_view s);

/// A file name as written in an OBJ or MTL file, with Windows separators
/// ('\\') read as '/' (exporters on Windows write "mats\\wood.png").
std::string slashPath(std::string_view path);

/// A token for a message: quoted, at most 40 bytes ("'1e400'", "'abc...'").
std::string quotedToken(std::string_view token);

/// Reads `token` as a number. Returns nothing when it is not one (a word,
/// "nan", "inf", trailing junk) or when it is beyond the double range; a
/// value too small for a double reads as 0.
std::optional<double> parseNumber(std::string_view token);

}  // namespace raylab

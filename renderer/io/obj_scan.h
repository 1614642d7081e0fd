#pragma once
// Checks of OBJ and MTL text made before tinyobjloader reads it, each with the
// line it is about: tinyobjloader reports bad indices at the file's last line
// (after reading out of bounds), and reads NaN, words and missing numbers as 0.
// OBJ and MTL share the statement syntax: a keyword, blank-separated
// arguments, '#' comments.

#include <initializer_list>
#include <string>
#include <utility>

namespace raylab {

/// Calls `fn(keyword, rest, eol, lineNo)` for every statement line of an OBJ
/// or MTL text; `rest` and `eol` bound the arguments within the line.
template <class Fn>
void forEachStatement(const std::string& text, Fn fn) {
    const char* p = text.data();
    const char* const end = p + text.size();
    int lineNo = 0;
    while (p < end) {
        const char* eol = p;
        while (eol < end && *eol != '\n') ++eol;
        ++lineNo;
        const char* k = p;
        while (k < eol && (*k == ' ' || *k == '\t')) ++k;
        const char* ke = k;
        while (ke < eol && *ke != ' ' && *ke != '\t' && *ke != '\r') ++ke;
        if (ke > k) fn(std::string(k, ke), ke, eol, lineNo);
        p = eol + 1;
    }
}

/// Finds the first face line with a vertex or normal index out of range.
/// Relative (negative) indices resolve against the elements read so far and
/// positive ones against the whole file, as in tinyobjloader. This runs
/// before tinyobjloader, whose triangulation reads vertices by index unchecked.
/// Returns {line, message} or {0, ""}.
std::pair<int, std::string> findBadFaceIndex(const std::string& text);

/// A statement whose arguments are all numbers.
struct NumericStatement {
    const char* keyword;
    int minArgs;  ///< fewer is an error (tinyobjloader would read the rest as 0)
};

/// Finds the first of `statements` with an argument that is not a finite
/// number, or with too few. tinyobjloader reads "nan", "inf", words it cannot
/// parse and missing values as 0 without a word, which would silently make a
/// different mesh or material. With `floatRange`, finite values beyond float
/// (tinyobjloader's type) are refused too instead of becoming infinities.
/// `skipWords` are allowed first arguments that introduce a non-numeric form
/// (MTL "Kd spectral file.rfl", "Kd xyz 1 1 1").
/// Returns {line, message} or {0, ""}.
std::pair<int, std::string> findBadNumber(const std::string& text,
                                          std::initializer_list<NumericStatement> statements,
                                          bool floatRange,
                                          std::initializer_list<const char*> skipWords = {});

/// Line of the `index`-th (0-based) statement with keyword `kw`, or 0.
int lineOfStatement(const std::string& text, const std::string& kw, size_t index);

/// Line of the first statement `kw` with `arg` among its blank-separated
/// arguments, or 0.
int lineOfStatementWith(const std::string& text, const std::string& kw, const std::string& arg);

}  // namespace raylab

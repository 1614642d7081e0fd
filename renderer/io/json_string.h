#pragma once
// Writing a JSON string literal: the one escaper behind every JSON document
// raylab writes (--stats, the benchmark and accuracy tables).

#include <string>
#include <string_view>

namespace raylab {

/// \brief Appends `s` to `out` as a JSON string literal, quotes included.
/// \details '"' and '\' are escaped, control characters become \n, \r, \t,
///   \b, \f or \u00XX, and every other byte (UTF-8 included) passes through
///   unchanged, so any string gives valid JSON text for valid UTF-8. Runs
///   without such a character are copied whole (object names, keys: all of
///   them, in practice).
void appendJsonString(std::string& out, std::string_view s);

/// \brief `s` as a JSON string literal (appendJsonString to an empty string).
std::string jsonString(std::string_view s);

}  // namespace raylab

#pragma once
// Writing a JSON string literal: the one escaper behind every JSON document
// raylab writes (--stats, the benchmark and accuracy tables).

#include <string>

namespace raylab {

/// \brief `s` as a JSON string literal, quotes included.
/// \details '"' and '\' are escaped, control characters become \n, \r, \t,
///   \b, \f or \u00XX, and every other byte (UTF-8 included) passes through
///   unchanged, so any std::string gives valid JSON text for valid UTF-8.
std::string jsonString(const std::string& s);

}  // namespace raylab

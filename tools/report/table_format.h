#pragma once
// The results tables the measurement commands write with --out: the format
// chosen by the file's extension, and how numbers, text and scene names are
// written into CSV and JSON. (JSON strings: jsonString in
// renderer/io/json_string.h, shared with --stats.)

#include <string>

namespace raylab {

enum class TableFormat { Csv, Json };

/// \brief The format chosen by a file name's extension (.csv or .json, any case).
/// \throws UsageError for any other extension, naming `what` (e.g. "--output").
TableFormat tableFormatOf(const std::string& path, const std::string& what);

/// A double for CSV/JSON: shortest round-trip form ("%.17g" trimmed); non-finite -> "null".
std::string jsonNumber(double v);

/// `s` as a CSV field (quoted when it holds a comma, quote or newline).
std::string csvField(const std::string& s);

/// The name a table or plot shows for a scene file: the path's last component.
std::string fileName(const std::string& path);

}  // namespace raylab

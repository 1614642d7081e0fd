#pragma once
// Whole-file reading for the scene readers, with errors that name the file.

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace raylab {

/// The largest scene, mesh or material file raylab reads (1 GiB): bigger
/// files are refused before they are read rather than exhausting memory.
constexpr size_t kMaxTextFileBytes = size_t(1) << 30;

/// Reads the whole file at `path` as bytes (no newline translation).
/// Throws InputError(path, 0, "cannot open: <reason>") when the file is
/// missing, unreadable, a directory or not a regular file (a device such as
/// /dev/zero, a FIFO, a socket: never opened blocking, never read without
/// end), "file is N MiB, larger than ..." beyond `maxBytes`, and
/// "read error: <reason>" when reading fails midway. The file is recorded as
/// an input of the run (input_files.h); Cancelled is thrown between chunks
/// once a stop was requested (cancel.h).
std::string readTextFile(const std::string& path, size_t maxBytes = kMaxTextFileBytes);

/// Where a file that should be text is not: {1, "..."} for a UTF-16
/// byte-order mark, {line of the first NUL byte, "..."} for binary data or
/// UTF-16 without a mark, {0, ""} for text. `format` names what the file
/// should be ("NFF", "OBJ") in the message.
std::pair<int, std::string> findNonText(std::string_view text, const std::string& format);

/// The directory part of `path` including the trailing '/', or "" when the
/// path has no directory ("scene.json" -> "", "a/b.json" -> "a/").
std::string directoryOf(const std::string& path);

/// `relative` resolved against the directory of `base`; absolute paths are
/// returned unchanged ("scenes/demo.json", "meshes/t.obj" -> "scenes/meshes/t.obj").
std::string resolveRelativeTo(const std::string& base, const std::string& relative);

/// The extension of `path` in lower case, with its dot ("A/B.OBJ" -> ".obj"),
/// or "" when the file name has none.
std::string lowerExtension(const std::string& path);

}  // namespace raylab

#pragma once
// tinyobjloader reports problems as free text, newline-separated, with line
// references in several formats: this turns them into located warnings.

#include <string>
#include <utility>
#include <vector>

#include "renderer/io/load_warnings.h"

namespace raylab {

/// Splits tinyobjloader's newline-separated messages into trimmed lines.
std::vector<std::string> splitMessages(const std::string& text);

/// The line a tinyobjloader message refers to, and the message without that
/// reference. Its formats vary ("... (line 12.)", "... line 12.)", "line: 12",
/// "(line 4 in .mtl.)"); the last "line" followed by a number is the one (a
/// material name quoted earlier in the message may contain the word).
/// Returns {0, message} when there is none.
std::pair<int, std::string> splitLineReference(const std::string& message);

/// tinyobjloader's warnings about the OBJ `text`, reworded with the line they
/// are about. When no library loads it reports that three ways ("Material
/// file [ x ] not found", "Failed to load material file(s)", then "material
/// [ 'm' ] not found" for every usemtl); the user gets one line per missing
/// library, at its mtllib statement. When another library did load,
/// undefined names are still reported.
void addTinyObjWarnings(const std::vector<std::string>& messages, const std::string& text,
                        LoadWarnings& warn);

}  // namespace raylab

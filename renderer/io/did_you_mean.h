#pragma once
// "Did you mean ...?" hints for a mistyped name: one rule for scene keys,
// command-line flags and sub-commands, so every reader suggests alike.

#include <string>
#include <vector>

namespace raylab {

/// Levenshtein distance (insertions, deletions, substitutions).
size_t editDistance(const std::string& a, const std::string& b);

/// The candidate closest to `word` within two edits (the first of equally
/// close ones), or "" when none is that close.
std::string closestName(const std::string& word, const std::vector<std::string>& candidates);

/// " (did you mean 'NAME'?)" for closestName, or "" when nothing is close.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace raylab

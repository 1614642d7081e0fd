#include "renderer/io/file_lookup.h"

#include <algorithm>
#include <filesystem>
#include <system_error>
#include <vector>

namespace raylab {

namespace {

bool sameIgnoringCase(const std::string& a, const std::string& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](char x, char y) {
        const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
        return lower(x) == lower(y);
    });
}

/// The entry of folder `dir` named `name` ignoring case, or "".
std::string entryIgnoringCase(const std::filesystem::path& dir, const std::string& name) {
    std::error_code ec;
    std::vector<std::string> matches;
    for (std::filesystem::directory_iterator it(dir.empty() ? "." : dir, ec), end;
         !ec && it != end; it.increment(ec)) {
        const std::string entry = it->path().filename().string();
        if (sameIgnoringCase(entry, name)) matches.push_back(entry);
    }
    if (matches.empty()) return "";
    return *std::min_element(matches.begin(), matches.end());
}

}  // namespace

std::optional<FoundFile> findFile(const std::string& path) {
    std::error_code ec;
    if (path.empty()) return std::nullopt;
    if (std::filesystem::exists(path, ec)) return FoundFile{path, false};
    // Component by component: keep what exists, look up the rest ignoring case.
    std::filesystem::path resolved;
    for (const std::filesystem::path& part : std::filesystem::path(path)) {
        const std::string name = part.string();
        const std::filesystem::path exact = resolved / part;
        if (name == "/" || name == "." || name == ".." || name.empty() ||
            std::filesystem::exists(exact, ec)) {
            resolved = exact;
            continue;
        }
        const std::string entry = entryIgnoringCase(resolved, name);
        if (entry.empty()) return std::nullopt;
        resolved /= entry;
    }
    return FoundFile{resolved.string(), true};
}

}  // namespace raylab

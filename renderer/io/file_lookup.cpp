#include "renderer/io/file_lookup.h"

#include <filesystem>
#include <system_error>

namespace raylab {

namespace {

std::string lower(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return s;
}

}  // namespace

const std::unordered_map<std::string, std::string>& FileFinder::listing(const std::string& folder) {
    const auto known = m_listings.find(folder);
    if (known != m_listings.end()) return known->second;
    std::unordered_map<std::string, std::string> byLowerName;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folder.empty() ? "." : folder, ec), end;
         !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        auto [entry, added] = byLowerName.emplace(lower(name), name);
        if (!added && name < entry->second) entry->second = name;
    }
    return m_listings.emplace(folder, std::move(byLowerName)).first->second;
}

std::optional<FoundFile> FileFinder::find(const std::string& path) {
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
        const auto& entries = listing(resolved.string());
        const auto match = entries.find(lower(name));
        if (match == entries.end()) return std::nullopt;
        resolved /= match->second;
    }
    return FoundFile{resolved.string(), true};
}

}  // namespace raylab

#pragma once
// Warnings of one mesh load: each reported once, repeats counted (an OBJ whose
// MTL lacks a material repeats "material not found" for every usemtl), and
// warnings of one kind that name different things (10^5 undefined material
// names) cut after the first few, so a broken file cannot flood the terminal.

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace raylab {

class LoadWarnings {
public:
    /// Distinct warnings of one kind that are listed; the rest are counted.
    static constexpr size_t kListedPerKind = 5;

    /// `path` is the file warnings are about unless add() names another.
    explicit LoadWarnings(std::string path) : m_path(std::move(path)) {}

    /// Records `message` about `file` (default: the loaded file) at `line`
    /// (0: none). Messages of the same `kind` (a short plural such as
    /// "undefined materials") beyond kListedPerKind distinct ones are only counted.
    void add(const std::string& message, int line = 0, const std::string& file = "",
             const std::string& kind = "");

    /// "FILE:LINE: message" (or "FILE: message"), with " (N times)" for repeats,
    /// in the order they were first added; then "FILE: and N more warnings about
    /// <kind> ..." for each kind that was cut.
    std::vector<std::string> lines() const;

private:
    struct Entry {
        std::string file, message;
        int line;
        int count;
    };
    struct Kind {
        std::string file;
        size_t listed = 0, more = 0;
    };
    std::string m_path;
    std::map<std::string, Entry> m_counts;
    std::vector<std::string> m_order;
    std::map<std::string, Kind> m_kinds;
    std::vector<std::string> m_kindOrder;
};

}  // namespace raylab

#pragma once
// Warnings of one mesh load: each reported once, repeats counted (an OBJ whose
// MTL lacks a material repeats "material not found" for every usemtl).

#include <map>
#include <string>
#include <vector>

namespace raylab {

class LoadWarnings {
public:
    /// `path` is the file warnings are about unless add() names another.
    explicit LoadWarnings(std::string path) : m_path(std::move(path)) {}

    /// Records `message` about `file` (default: the loaded file) at `line` (0: none).
    void add(const std::string& message, int line = 0, const std::string& file = "");

    /// "FILE:LINE: message" (or "FILE: message"), with " (N times)" for repeats,
    /// in the order they were first added.
    std::vector<std::string> lines() const;

private:
    struct Entry {
        std::string file, message;
        int line;
        int count;
    };
    std::string m_path;
    std::map<std::string, Entry> m_counts;
    std::vector<std::string> m_order;
};

}  // namespace raylab

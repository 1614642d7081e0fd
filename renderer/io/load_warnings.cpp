#include "renderer/io/load_warnings.h"

namespace raylab {

void LoadWarnings::add(const std::string& message, int line, const std::string& file) {
    const std::string where = file.empty() ? m_path : file;
    auto [it, inserted] = m_counts.emplace(where + "\n" + message, Entry{where, message, line, 0});
    if (inserted) m_order.push_back(it->first);
    ++it->second.count;
}

std::vector<std::string> LoadWarnings::lines() const {
    std::vector<std::string> out;
    for (const std::string& key : m_order) {
        const Entry& e = m_counts.at(key);
        out.push_back(e.file + (e.line > 0 ? ":" + std::to_string(e.line) : "") + ": " + e.message +
                      (e.count > 1 ? " (" + std::to_string(e.count) + " times)" : ""));
    }
    return out;
}

}  // namespace raylab

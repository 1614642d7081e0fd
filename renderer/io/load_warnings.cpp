#include "renderer/io/load_warnings.h"

namespace raylab {

void LoadWarnings::add(const std::string& message, int line, const std::string& file,
                       const std::string& kind) {
    const std::string where = file.empty() ? m_path : file;
    const std::string key = where + "\n" + message;
    const auto known = m_counts.find(key);
    if (known != m_counts.end()) {
        ++known->second.count;
        return;
    }
    if (!kind.empty()) {
        auto [k, added] = m_kinds.emplace(kind, Kind{where});
        if (added) m_kindOrder.push_back(kind);
        if (k->second.listed == kListedPerKind) {
            ++k->second.more;
            return;
        }
        ++k->second.listed;
    }
    m_counts.emplace(key, Entry{where, message, line, 1});
    m_order.push_back(key);
}

std::vector<std::string> LoadWarnings::lines() const {
    std::vector<std::string> out;
    for (const std::string& key : m_order) {
        const Entry& e = m_counts.at(key);
        out.push_back(e.file + (e.line > 0 ? ":" + std::to_string(e.line) : "") + ": " +
                      e.message + (e.count > 1 ? " (" + std::to_string(e.count) + " times)" : ""));
    }
    for (const std::string& kind : m_kindOrder) {
        const Kind& k = m_kinds.at(kind);
        if (k.more > 0)
            out.push_back(k.file + ": and " + std::to_string(k.more) + " more warnings about " +
                          kind + " (the first " + std::to_string(kListedPerKind) +
                          " are listed)");
    }
    return out;
}

}  // namespace raylab

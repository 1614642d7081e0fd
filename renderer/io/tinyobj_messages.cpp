#include "renderer/io/tinyobj_messages.h"

#include <cctype>
#include <cstdlib>
#include <sstream>

#include "renderer/io/obj_scan.h"

namespace raylab {

std::vector<std::string> splitMessages(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const size_t a = line.find_first_not_of(" \t\r.");
        if (a == std::string::npos) continue;
        const size_t b = line.find_last_not_of(" \t\r");
        out.push_back(line.substr(a, b - a + 1));
    }
    return out;
}

std::pair<int, std::string> splitLineReference(const std::string& message) {
    for (size_t at = message.rfind("line"); at != std::string::npos;
         at = at == 0 ? std::string::npos : message.rfind("line", at - 1)) {
        size_t q = at + 4;
        while (q < message.size() && (message[q] == ':' || message[q] == ' ')) ++q;
        if (q >= message.size() || !std::isdigit(static_cast<unsigned char>(message[q]))) continue;
        const int line = std::atoi(message.c_str() + q);
        size_t cut = at;
        while (cut > 0 &&
               (message[cut - 1] == ' ' || message[cut - 1] == '(' || message[cut - 1] == '.'))
            --cut;
        return {line, message.substr(0, cut)};
    }
    return {0, message};
}

namespace {

/// The text between the first `open` and the following `close` in s, trimmed
/// of blanks and quotes ("" when absent).
std::string between(const std::string& s, const std::string& open, const std::string& close) {
    const size_t a = s.find(open);
    if (a == std::string::npos) return "";
    const size_t b = s.find(close, a + open.size());
    if (b == std::string::npos) return "";
    std::string v = s.substr(a + open.size(), b - a - open.size());
    const auto keep = [](char c) { return c != ' ' && c != '\''; };
    while (!v.empty() && !keep(v.front())) v.erase(v.begin());
    while (!v.empty() && !keep(v.back())) v.pop_back();
    return v;
}

}  // namespace

void addTinyObjWarnings(const std::vector<std::string>& messages, const std::string& text,
                        LoadWarnings& warn) {
    bool noLibraryLoaded = false;
    for (const std::string& m : messages) {
        if (m.rfind("Material file [", 0) == 0) {
            const std::string name = between(m, "[", "]");
            warn.add("material library '" + name +
                         "' not found beside the OBJ; its materials get the default material",
                     lineOfStatementWith(text, "mtllib", name));
        }
        if (m.rfind("Failed to load material file", 0) == 0) noLibraryLoaded = true;
    }
    for (const std::string& m : messages) {
        if (m.rfind("Material file [", 0) == 0 || m.rfind("Failed to load material file", 0) == 0)
            continue;
        if (m.rfind("material [", 0) == 0 && m.find("not found") != std::string::npos) {
            if (noLibraryLoaded) continue;  // a consequence of the missing library
            const std::string name = between(m, "[", "]");
            warn.add("material '" + name +
                         "' is not defined in the MTL libraries; the default "
                         "material is used",
                     lineOfStatementWith(text, "usemtl", name));
            continue;
        }
        // Anything else is passed on, at the line tinyobjloader names in it.
        const auto [line, message] = splitLineReference(m);
        warn.add(message, line);
    }
}

}  // namespace raylab

#include "renderer/io/mtl_reader.h"

#include <sys/stat.h>

#include <cerrno>
#include <sstream>

#include "renderer/io/errors.h"
#include "renderer/io/obj_scan.h"
#include "renderer/io/text_file.h"
#include "renderer/io/tinyobj_messages.h"

namespace raylab {

namespace {

/// The MTL text with the statements tinyobjloader misreads rewritten, line
/// for line (line numbers stay valid): "d -halo X" becomes "d X" (it would
/// read the dissolve as 0), and a colour with one value, "Kd 0.5", becomes
/// "Kd 0.5 0.5 0.5" (the MTL rule: g = b = r; it would read 0.5 0 0, red).
std::string normalizeMtl(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    size_t p = 0;
    while (p <= text.size()) {
        size_t eol = text.find('\n', p);
        if (eol == std::string::npos) eol = text.size();
        std::string line = text.substr(p, eol - p);
        const size_t hash = line.find('#');  // a trailing comment is kept as it is
        const std::string comment = hash == std::string::npos ? "" : " " + line.substr(hash);
        std::istringstream in(line.substr(0, hash));
        std::vector<std::string> tokens;
        for (std::string t; in >> t;) tokens.push_back(t);
        const bool colour =
            !tokens.empty() && (tokens[0] == "Ka" || tokens[0] == "Kd" || tokens[0] == "Ks" ||
                                tokens[0] == "Ke" || tokens[0] == "Tf" || tokens[0] == "Kt");
        if (tokens.size() == 3 && tokens[0] == "d" && tokens[1] == "-halo")
            line = "d " + tokens[2] + comment;
        else if (colour && tokens.size() == 2)
            line = tokens[0] + " " + tokens[1] + " " + tokens[1] + " " + tokens[1] + comment;
        out += line;
        if (eol < text.size()) out += '\n';
        p = eol + 1;
    }
    return out;
}

}  // namespace

bool MtlLibraryReader::operator()(const std::string& matId,
                                  std::vector<tinyobj::material_t>* materials,
                                  std::map<std::string, int>* matMap, std::string* warn,
                                  std::string*) {
    const std::string path = resolveRelativeTo(m_objPath, matId);
    struct stat st {};
    // Only a library that is not there is a warning (the render goes on
    // with the default material); one that is there but cannot be read
    // is an error naming it.
    if (::stat(path.c_str(), &st) != 0 && (errno == ENOENT || errno == ENOTDIR)) {
        if (warn) *warn += "Material file [ " + matId + " ] not found\n";
        return false;
    }
    Library lib;
    lib.path = path;
    lib.text = readTextFile(path);
    if (const auto [line, message] = findNonText(lib.text, "MTL"); line > 0)
        throw InputError(path, line, message);
    const std::string normalized = normalizeMtl(lib.text);
    if (const auto [line, message] = findBadNumber(normalized,
                                                   {{"Ka", 3},
                                                    {"Kd", 3},
                                                    {"Ks", 3},
                                                    {"Ke", 3},
                                                    {"Tf", 3},
                                                    {"Kt", 3},
                                                    {"Ns", 1},
                                                    {"Ni", 1},
                                                    {"d", 1},
                                                    {"Tr", 1},
                                                    {"illum", 1}},
                                                   false, {"spectral", "xyz"});
        line > 0)
        throw InputError(path, line, message);
    lib.firstMaterial = materials->size();
    std::istringstream in(normalized);
    std::string mtlWarnings, mtlErrors;
    tinyobj::LoadMtl(matMap, materials, &in, &mtlWarnings, &mtlErrors);
    for (const std::string* text : {&mtlErrors, &mtlWarnings})
        for (const std::string& m : splitMessages(*text)) {
            const auto [line, message] = splitLineReference(m);
            m_warnings.push_back({path, line, message});
        }
    lib.endMaterial = materials->size();
    m_libraries.push_back(std::move(lib));
    return true;
}

std::pair<std::string, int> MtlLibraryReader::locate(
    size_t index, const std::string& name, std::initializer_list<const char*> keywords) const {
    for (const Library& lib : m_libraries) {
        if (index < lib.firstMaterial || index >= lib.endMaterial) continue;
        int newmtl = 0, found = 0;
        bool ended = false;
        forEachStatement(
            lib.text, [&](const std::string& k, const char* rest, const char* eol, int line) {
                if (found || ended) return;
                if (k == "newmtl") {
                    if (newmtl) {
                        ended = true;  // the block ended without any of `keywords`
                        return;
                    }
                    // The name as tinyobjloader takes it: the rest of the
                    // line after one blank, without trailing blanks.
                    std::string n(rest < eol ? rest + 1 : eol, eol);
                    while (!n.empty() && (n.back() == ' ' || n.back() == '\t' || n.back() == '\r'))
                        n.pop_back();
                    if (n == name) newmtl = line;
                    return;
                }
                if (newmtl)
                    for (const char* kw : keywords)
                        if (k == kw) found = line;
            });
        return {lib.path, found ? found : newmtl};
    }
    return {m_objPath, 0};
}

}  // namespace raylab

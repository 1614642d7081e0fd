#include "renderer/io/obj_materials.h"

#include <filesystem>
#include <system_error>
#include <unordered_map>
#include <unordered_set>

#include "renderer/io/file_lookup.h"
#include "renderer/io/mtl_material.h"
#include "renderer/io/text_file.h"
#include "renderer/io/wavefront_text.h"

namespace raylab {

namespace {

/// The files an mtllib statement names: the whole argument when a file of
/// that name exists (names with blanks), else each blank-separated word.
std::vector<std::string> libraryNames(const std::string& args, const std::string& objPath,
                                      FileFinder& finder) {
    if (args.find_first_of(" \t") == std::string::npos || finder.find(resolveRelativeTo(objPath, args)))
        return args.empty() ? std::vector<std::string>{} : std::vector<std::string>{args};
    std::vector<std::string> names;
    std::string_view rest = args;
    for (std::string_view t = nextToken(rest); !t.empty(); t = nextToken(rest))
        names.emplace_back(t);
    return names;
}

/// A file's identity for "read once": its canonical path when it has one.
std::string identity(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    return ec ? path : canonical.string();
}

class MaterialLoader {
public:
    MaterialLoader(const std::string& objPath, LoadWarnings& warn)
        : m_objPath(objPath), m_warn(warn) {}

    ObjMaterials load(const ObjData& data) {
        for (const ObjName& lib : data.libraries) {
            // 5000 statements naming one library cost one lookup each, not a read.
            if (!m_statements.insert(lib.name).second) continue;
            const std::vector<std::string> names = libraryNames(lib.name, m_objPath, m_finder);
            if (names.empty())
                m_warn.add("'mtllib' without a file name", lib.line);
            for (const std::string& name : names) library(name, lib.line);
        }
        m_out.byName.reserve(data.materialNames.size());
        for (const ObjName& n : data.materialNames) {
            const auto it = m_index.find(n.name);
            m_out.byName.push_back(it == m_index.end() ? kNoObjMaterial : it->second);
            // Without any library every name is undefined: the missing
            // libraries were reported already.
            if (it == m_index.end() && m_out.librariesRead > 0)
                for (int i = 0; i < n.uses; ++i)
                    m_warn.add("material '" + n.name +
                                   "' is not defined in the MTL libraries; the default "
                                   "material is used",
                               n.line, "", "undefined materials");
        }
        return std::move(m_out);
    }

private:
    void library(const std::string& name, int line) {
        const std::string path = resolveRelativeTo(m_objPath, name);
        const std::optional<FoundFile> found = m_finder.find(path);
        if (!found) {
            m_warn.add("material library '" + name +
                           "' not found beside the OBJ; its materials get the default material",
                       line, "", "missing material libraries");
            return;
        }
        if (found->caseDiffers)
            m_warn.add("material library '" + name + "' found as '" + found->path +
                           "' (the letter case differs)",
                       line, "", "libraries found by ignoring case");
        if (!m_read.insert(identity(found->path)).second) return;  // read already
        MtlLibrary lib = readMtl(found->path, m_warn);
        ++m_out.librariesRead;
        m_out.mtlLinesRead += lib.linesRead;
        m_out.materials.reserve(m_out.materials.size() + lib.materials.size());
        m_out.statements.reserve(m_out.statements.size() + lib.materials.size());
        for (MtlMaterial& m : lib.materials) {
            const auto [it, added] = m_index.emplace(m.name, uint32_t(m_out.materials.size()));
            if (!added) {
                // tinyobjloader kept the first definition too.
                m_warn.add("material '" + m.name + "' is defined again; the first definition (" +
                               m_out.statements[it->second].file + ":" +
                               std::to_string(m_out.statements[it->second].line) + ") is used",
                           m.line, lib.path, "materials defined twice");
                continue;
            }
            findTextures(m, lib.path);
            m_out.materials.push_back(materialFromMtl(m, m_warn));
            m_out.statements.push_back(std::move(m));
        }
    }

    /// Texture files are named relative to their library; mtl_textures.cpp reads them.
    void findTextures(MtlMaterial& m, const std::string& libraryPath) {
        for (MtlTexture& t : m.textures) {
            const std::string path = resolveRelativeTo(libraryPath, t.file);
            const std::optional<FoundFile> found = m_finder.find(path);
            if (!found) {
                // Reported where the map is read (mtl_textures.cpp): one
                // warning per missing file, naming the statement's line.
                t.file = path;
                continue;
            }
            if (found->caseDiffers)
                m_warn.add("texture '" + t.file + "' found as '" + found->path +
                               "' (the letter case differs)",
                           t.line, libraryPath, "textures found by ignoring case");
            t.file = found->path;
        }
    }

    const std::string& m_objPath;
    LoadWarnings& m_warn;
    ObjMaterials m_out;
    std::unordered_map<std::string, uint32_t> m_index;  ///< material name -> index
    std::unordered_set<std::string> m_read;             ///< libraries read
    std::unordered_set<std::string> m_statements;       ///< mtllib arguments handled
    FileFinder m_finder;
};

}  // namespace

ObjMaterials loadObjMaterials(const ObjData& data, const std::string& objPath,
                              LoadWarnings& warn) {
    return MaterialLoader(objPath, warn).load(data);
}

}  // namespace raylab

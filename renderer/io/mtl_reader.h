#pragma once
// Reading the MTL libraries an OBJ names (tinyobjloader parses them; this
// reads the files, rewrites what it misreads and keeps each library's text so
// every warning and error lands on the MTL's own line).

#include <tiny_obj_loader.h>

#include <initializer_list>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

/// Reads the MTL libraries an OBJ names, in place of tinyobjloader's
/// MaterialFileReader: through readTextFile, so a device, FIFO or huge file
/// is refused instead of read without end; relative to the OBJ's directory
/// (absolute names stay absolute); with NaN/Inf values refused at their line;
/// and keeping each library's text so a bad material, and each warning, is
/// reported at the MTL's own line.
class MtlLibraryReader : public tinyobj::MaterialReader {
public:
    struct Library {
        std::string path, text;
        size_t firstMaterial = 0, endMaterial = 0;  ///< [first, end) in the material list
    };
    struct Warning {
        std::string path;
        int line;
        std::string message;
    };

    explicit MtlLibraryReader(std::string objPath) : m_objPath(std::move(objPath)) {}

    bool operator()(const std::string& matId, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* matMap, std::string* warn, std::string*) override;

    /// What tinyobjloader said about the libraries, each at its MTL line.
    const std::vector<Warning>& warnings() const { return m_warnings; }

    /// FILE and LINE of the first of `keywords` inside material `index`'s
    /// block (the `newmtl` line when the block has none), for errors about it.
    std::pair<std::string, int> locate(size_t index, const std::string& name,
                                       std::initializer_list<const char*> keywords) const;

private:
    std::string m_objPath;
    std::vector<Library> m_libraries;
    std::vector<Warning> m_warnings;
};

}  // namespace raylab

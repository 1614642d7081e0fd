#pragma once
// The materials an OBJ file uses: its mtllib libraries found beside it (with
// '\' read as '/' and letter case forgiven, each library read once however
// often it is named) and its usemtl names resolved through one hash map, so
// loading stays linear in the number of statements.

#include <cstdint>
#include <string>
#include <vector>

#include "renderer/io/load_warnings.h"
#include "renderer/io/mtl_reader.h"
#include "renderer/io/obj_parser.h"
#include "shading/material.h"

namespace raylab {

struct ObjMaterials {
    /// Every material of every library, in the order the libraries were read.
    std::vector<Material> materials;
    /// What each material's MTL statements said (parallel to `materials`):
    /// texture maps with their files resolved beside the library.
    std::vector<MtlMaterial> statements;
    /// Per ObjData::materialNames: its index in `materials`, or kNoObjMaterial.
    std::vector<uint32_t> byName;
    int librariesRead = 0;  ///< MTL files opened and parsed
    int mtlLinesRead = 0;   ///< their lines, each read once
};

/// Reads the libraries `data` names (relative to the OBJ's folder) and
/// resolves its material names. A missing library or an undefined name is a
/// warning at the OBJ line that names it; a broken library is an
/// InputError at the library's own line.
ObjMaterials loadObjMaterials(const ObjData& data, const std::string& objPath,
                              LoadWarnings& warn);

}  // namespace raylab

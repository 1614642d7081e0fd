#pragma once
// Reading one MTL material library into what each material states, with the
// line of every statement: the policy that turns those statements into a
// raylab Material is mtl_material.h. The reader checks what a value can be
// (numbers, counts, ranges: "d -1", "Tr 2" and "d -halo -1" are refused
// alike) and warns, once per keyword and file, about statements raylab does
// not simulate.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/io/load_warnings.h"
#include "shading/color.h"

namespace raylab {

/// One statement's value and where it was given (line 0: not given).
template <class T>
struct MtlValue {
    T value{};
    int line = 0;
    bool given() const { return line > 0; }
};

/// A texture map statement (map_Kd, bump, ...): for image textures (issue 18).
struct MtlTexture {
    std::string keyword;  ///< "map_Kd", "bump", ...
    std::string file;     ///< as written, '\' read as '/', relative to the MTL's folder
    std::string options;  ///< the options before the file name ("-s 2 2 -clamp on"), as written
    int line = 0;
};

struct MtlMaterial {
    std::string name;  ///< blanks around it trimmed, inner blanks kept
    std::string file;  ///< the library it comes from
    int line = 0;      ///< its newmtl statement
    MtlValue<Color> ka, kd, ks, ke, tf;
    MtlValue<double> ns, ni;
    /// The dissolve (opacity) in [0, 1], from `d X`, `d -halo X` or `Tr X` (= 1 - X);
    /// `dissolveKeyword` is the spelling it came from.
    MtlValue<double> dissolve;
    std::string dissolveKeyword;
    MtlValue<int> illum;
    std::vector<MtlTexture> textures;
};

struct MtlLibrary {
    std::string path;
    std::vector<MtlMaterial> materials;  ///< in file order
    int linesRead = 0;
};

/// Parses the MTL text of the library at `path`. Throws InputError(path,
/// line, ...) for a statement whose value raylab cannot read: a number that
/// is missing, not finite or out of its range (colours >= 0, Ns >= 0,
/// d and Tr in [0, 1], illum an integer), and names the material.
MtlLibrary parseMtl(std::string_view text, const std::string& path, LoadWarnings& warn);

/// Reads the library file at `path` (through readTextFile: a device, FIFO or
/// huge file is refused) and parses it.
MtlLibrary readMtl(const std::string& path, LoadWarnings& warn);

}  // namespace raylab

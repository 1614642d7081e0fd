#pragma once
// The MTL -> Whitted material policy: what each MTL statement means for
// raylab's Material (Wavefront's illumination models, MTL spec):
//   ka = Ka, kd = Kd, ks = Ks, shininess = Ns, ior = Ni (1 when Ni <= 0).
//   illum 0     colour only: ka = 0, ks = 0
//   illum 1     diffuse only: ks = 0
//   illum 2     diffuse + Blinn-Phong highlight
//   illum 3..7  "reflection: ray trace on": also mirror km = Ks
//   illum 4,6,7 transparency/refraction: kt = Tf when Tf is given and not
//               black, else kt = 1 - d (d = dissolve; "Tr t" means d = 1 - t)
//   other illum values are read as illum 2. Textures are ignored (warning).

#include <tiny_obj_loader.h>

#include <cstddef>

#include "renderer/io/load_warnings.h"
#include "renderer/io/mtl_reader.h"
#include "shading/material.h"

namespace raylab {

/// The material for MTL material `index` (as the libraries read it). Warnings
/// and errors (InputError) point at the MTL statement they are about.
Material materialFromMtl(const tinyobj::material_t& m, size_t index,
                         const MtlLibraryReader& libraries, LoadWarnings& warn);

}  // namespace raylab

#pragma once
// The MTL -> Whitted material policy: what the statements of one MTL material
// mean for raylab's Material. Each rule and its source is in
// docs/scene-format.md ("OBJ and MTL"); in short:
//   kd = Kd (0.8 when absent), ka = Ka (Kd when absent), ks = Ks,
//   shininess = Ns (32 when absent), ior = Ni (1 when absent or <= 0).
//   illum: absent -> 2; 0 colour only (ka = ks = 0); 1 diffuse (ks = 0);
//          2 highlight; 3..7 also mirror km = Ks; 6, 7 (refraction on) also
//          kt = Tf when given and not black, else 1 - d, bent by Ni;
//          other values -> 2.
//   d < 1 in any other model: dissolve, transmission without refraction
//   (ka, kd, ks, km scaled by d, kt = 1 - d, ior 1).
//   Ns < 1: no highlight (ks = 0). Ke, Tf outside illum 6/7 and texture maps
//   other than those mtl_textures.h reads (map_d, disp, refl, ...): warned
//   about (once per library), ignored.
// Texture maps become material data in mtl_textures.h.

#include "renderer/io/load_warnings.h"
#include "renderer/io/mtl_reader.h"
#include "shading/material.h"

namespace raylab {

/// The material `m` means; warnings point at the statement they are about.
Material materialFromMtl(const MtlMaterial& m, LoadWarnings& warn);

}  // namespace raylab

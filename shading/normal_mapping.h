#pragma once
// Shading normals bent by textures: bump maps (Blinn 1978, as pbrt-v4's
// BumpMap: displace the surface along its normal by a height map and take the
// normal of the displaced surface) and tangent-space normal maps.
//
// Normal-map convention (docs/scene-format.md): a texel's RGB in [0, 1] is
// the unit vector 2·rgb - 1 in the frame (T, B, N): N the shading normal, T
// the surface's dp/du orthogonalised against N, B = N × T, flipped where it
// points against dp/dv. So green points towards increasing v (OBJ's up,
// OpenGL's "Y+" maps), red towards increasing u; (0.5, 0.5, 1) leaves N as it is.

#include "geometry/shape.h"
#include "shading/texture.h"

namespace raylab {

/// The shading normal of `sg` displaced by height(u, v) = scale × `height`.
/// Differences are taken over half the footprint in (u, v) (0.0005 without
/// one), through at least a bilinear lookup; the result faces sg.ns's side.
Vec3 bumpedNormal(const SurfaceGeometry& sg, const Texture& height, double scale,
                  const TextureCoords& tc, TextureFilter filter);

/// The shading normal of `sg` replaced by the normal map's vector at `tc`.
Vec3 normalMappedNormal(const SurfaceGeometry& sg, const Texture& map, const TextureCoords& tc,
                        TextureFilter filter);

}  // namespace raylab

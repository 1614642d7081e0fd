#pragma once
// Procedural scenes for the accelerator benchmarks: each generator returns a
// complete Scene (camera framing the content, lights, materials) whose size is
// controlled by one parameter, with a documented, exact primitive count.
//
//   sphereflake(L)       SPD "balls": 1 + 9 + 81 + ... + 9^L spheres on a ground
//                        square, 3 lights, mirror material; L = 4 is balls.nff
//   randomSpheres(N, s)  N seeded random spheres over a ground square
//   heightField(N)       one TriangleMesh terrain of 2·g² triangles, g = round(sqrt(N/2))
//   polygonField(N)      N tilted tiles from makePolygon, alternately hexagons and quads

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/scene.h"

namespace raylab {

/// Number of spheres of a sphereflake of `level`: (9^(level+1) - 1) / 8.
size_t sphereflakeSphereCount(int level);

/// \brief Haines' SPD sphereflake ("balls") at recursion `level` (0..7).
/// \details A sphere of radius 0.5 at the origin with 9 children of 1/3 its
///   radius touching it, recursively (the directions and rotations of SPD's
///   balls.c, so level L reproduces balls_sN.nff's sphere positions), on a
///   24×24 ground square at z = -0.5, seen from (2.1, 1.3, 1.7), 3 point lights
///   and the NFF material mapping (mirror balls: km = ks = 0.5).
///   Primitive count: sphereflakeSphereCount(level) spheres + 1 ground polygon.
/// \throws std::invalid_argument for a level outside 0..7.
Scene makeSphereflakeScene(int level);

/// \brief `count` spheres with seeded uniformly random centres in the cube
///   [-1, 1]³ and radii in [0.5, 1]·r, r = 0.6·count^(-1/3) (constant total
///   volume), over a ground square; 4 materials (one a mirror), 2 lights.
///   Same (count, seed) => bit-identical scene. Primitives: count + 1.
/// \throws std::invalid_argument for count == 0.
Scene makeRandomSpheresScene(size_t count, uint64_t seed = 1);

/// Side g of the height-field grid for about `targetTriangles` triangles:
/// max(1, round(sqrt(targetTriangles / 2))); the mesh has 2·g² triangles.
size_t heightFieldGridSize(size_t targetTriangles);

/// \brief A terrain z = h(x, y) over [-1, 1]² (sum of sines) as ONE TriangleMesh
///   object with per-vertex normals: g×g cells of two triangles each,
///   g = heightFieldGridSize(targetTriangles), slightly reflective; 2 lights.
///   Primitives: 2·g² triangles (nothing else).
Scene makeHeightFieldScene(size_t targetTriangles);

/// \brief `count` planar tiles on a jittered grid over [-1, 1]², each tilted
///   and raised pseudo-randomly; tile i is a hexagon when i is even and a quad
///   when it is odd (makePolygon, two-sided); 2 materials, 2 lights.
///   Primitives: exactly `count` polygons.
/// \throws std::invalid_argument for count == 0.
Scene makePolygonFieldScene(size_t count, uint64_t seed = 1);

/// One benchmark family: a name and a scene builder indexed by size parameter.
struct SceneGenerator {
    std::string name;                 ///< "sphereflake", "spheres", "mesh", "polygons"
    std::string parameterName;        ///< "level", "N", "triangles", "N"
    std::vector<size_t> sizes;        ///< parameters of the default bench run (growing)
    std::vector<size_t> quickSizes;   ///< parameters of the --quick smoke run
    Scene (*make)(size_t parameter);  ///< builds the scene for one parameter
};

/// The four generators above with their default and quick size ladders.
const std::vector<SceneGenerator>& benchSceneGenerators();

}  // namespace raylab

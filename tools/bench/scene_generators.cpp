#include "tools/bench/scene_generators.h"

#include "geometry/triangle_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "geometry/primitives.h"
#include "geometry/random.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;


Object shapeObject(std::string name, std::unique_ptr<Shape> shape, uint32_t material) {
    Object o;
    o.name = std::move(name);
    o.shape = std::move(shape);
    o.material = material;
    return o;
}

Material material(const std::string& name, const Color& kd, double ks, double shininess,
                  double km) {
    Material m;
    m.name = name;
    m.kd = kd;
    m.ka = kd;
    m.ks = Color(ks);
    m.shininess = shininess;
    m.km = Color(km);
    return m;
}

Light pointLight(const Vec3& position, double intensity) {
    Light l;
    l.type = Light::Type::Point;
    l.position = position;
    l.intensity = Color(intensity);
    return l;
}

/// Axis-aligned square of half-size h at height z, counter-clockwise seen
/// from +z (its front side faces up).
std::unique_ptr<Shape> groundSquare(double h, double z) {
    PolygonParams p;
    p.vertices = {{h, h, z}, {-h, h, z}, {-h, -h, z}, {h, -h, z}};
    return makePolygon(p);
}

/// Rodrigues rotation of v about the unit axis k by angle a.
Vec3 rotate(const Vec3& v, const Vec3& k, double a) {
    const double c = std::cos(a), s = std::sin(a);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

/// SPD balls.c's nine child directions of a sphere whose own direction is +z:
/// three trios 120° apart about z; each trio one direction 54.74° above the
/// equator (z = sqrt(2/3)) at azimuth 45°, two on the equator at 15° and 75°.
std::array<Vec3, 9> sphereflakeDirections() {
    std::array<Vec3, 9> dirs;
    const double cosUp = std::sqrt(1.0 / 3.0), sinUp = std::sqrt(2.0 / 3.0);
    for (int set = 0; set < 3; ++set) {
        const double base = set * 120.0;
        const double a0 = (base + 45.0) * kPi / 180.0;
        const double a1 = (base + 15.0) * kPi / 180.0;
        const double a2 = (base + 75.0) * kPi / 180.0;
        dirs[3 * set + 0] = {cosUp * std::cos(a0), cosUp * std::sin(a0), sinUp};
        dirs[3 * set + 1] = {std::cos(a1), std::sin(a1), 0.0};
        dirs[3 * set + 2] = {std::cos(a2), std::sin(a2), 0.0};
    }
    return dirs;
}

/// Emits the sphere, then its nine children depth-first (SPD's output order).
/// The children's directions are the nine base directions rotated so that
/// +z maps onto this sphere's direction; a child touches its parent.
void emitSphereflake(Scene& scene, int depth, const Vec3& centre, double radius,
                     const Vec3& direction, const std::array<Vec3, 9>& base, uint32_t material) {
    scene.objects.push_back(shapeObject("ball " + std::to_string(scene.objects.size()),
                                        makeSphere(centre, radius), material));
    if (depth == 0) return;
    const Vec3 z{0, 0, 1};
    const Vec3 axis = cross(z, direction);
    const double axisLength = length(axis);
    const double angle = std::acos(std::clamp(direction.z, -1.0, 1.0));
    const double distance = radius * (1.0 + 1.0 / 3.0);
    for (const Vec3& b : base) {
        // Directions (anti)parallel to z have no rotation axis: +z needs no
        // rotation; for -z SPD turns 180 degrees about y, (x, y, z) -> (-x, y, -z).
        Vec3 d = b;
        if (axisLength > 1e-12)
            d = rotate(b, axis / axisLength, angle);
        else if (direction.z < 0)
            d = Vec3{-b.x, b.y, -b.z};
        emitSphereflake(scene, depth - 1, centre + d * distance, radius / 3.0, d, base, material);
    }
}

}  // namespace

size_t sphereflakeSphereCount(int level) {
    size_t n = 0, layer = 1;
    for (int i = 0; i <= level; ++i, layer *= 9) n += layer;
    return n;
}

Scene makeSphereflakeScene(int level) {
    // 9^8 = 43 million spheres at level 7 is already far beyond any benchmark.
    if (level < 0 || level > 7)
        throw std::invalid_argument("sphereflake: level must be in 0..7 (got " +
                                    std::to_string(level) + ")");
    Scene scene;
    scene.sourcePath = "sphereflake(" + std::to_string(level) + ")";
    scene.camera = Camera::perspective({2.1, 1.3, 1.7}, {0, 0, 0}, {0, 0, 1}, 45.0);
    scene.cameraNear = 0.01;
    scene.image.width = scene.image.height = 512;
    scene.image.maxDepth = 5;
    scene.background = Color(0.078, 0.361, 0.753);
    // SPD: each of the L = 3 lights and the ambient term has intensity sqrt(L)/(2L).
    const double intensity = std::sqrt(3.0) / 6.0;
    scene.ambient = Color(intensity);
    for (const Vec3& p : {Vec3{4, 3, 2}, Vec3{1, -4, 4}, Vec3{-3, 1, 5}})
        scene.lights.push_back(pointLight(p, intensity));
    // NFF "f 1 0.75 0.33 0.8 0 100000 0 1" and "f 1 0.9 0.7 0.5 0.5 3.0827 0 1"
    // mapped as the NFF reader does: kd = ka = colour·Kd, ks = km = Ks.
    scene.materials.push_back(material("ground", Color(0.8, 0.6, 0.264), 0.0, 100000.0, 0.0));
    scene.materials.push_back(material("ball", Color(0.5, 0.45, 0.35), 0.5, 3.0827, 0.5));

    scene.objects.reserve(sphereflakeSphereCount(level) + 1);
    scene.objects.push_back(shapeObject("ground", groundSquare(12.0, -0.5), 0));
    emitSphereflake(scene, level, {0, 0, 0}, 0.5, {0, 0, 1}, sphereflakeDirections(), 1);
    return scene;
}

Scene makeRandomSpheresScene(size_t count, uint64_t seed) {
    if (count == 0) throw std::invalid_argument("random spheres: count must be > 0");
    Scene scene;
    scene.sourcePath = "spheres(" + std::to_string(count) + ")";
    scene.camera = Camera::perspective({3.2, -4.2, 2.6}, {0, 0, -0.2}, {0, 0, 1}, 40.0);
    scene.image.width = 640;
    scene.image.height = 480;
    scene.image.maxDepth = 5;
    scene.background = Color(0.10, 0.12, 0.18);
    scene.ambient = Color(0.1);
    scene.lights.push_back(pointLight({5, -3, 6}, 0.6));
    scene.lights.push_back(pointLight({-4, -5, 5}, 0.4));
    scene.materials.push_back(material("ground", Color(0.5, 0.5, 0.45), 0.0, 1.0, 0.0));
    scene.materials.push_back(material("red", Color(0.7, 0.2, 0.15), 0.3, 40.0, 0.0));
    scene.materials.push_back(material("green", Color(0.2, 0.6, 0.25), 0.3, 40.0, 0.0));
    scene.materials.push_back(material("blue", Color(0.15, 0.25, 0.7), 0.3, 40.0, 0.0));
    scene.materials.push_back(material("mirror", Color(0.05), 0.6, 200.0, 0.8));

    // Radius ~ count^(-1/3): the spheres fill the same fraction of the cube
    // at every size, so only the primitive count changes.
    const double r = 0.6 / std::cbrt(double(count));
    scene.objects.reserve(count + 1);
    // Spheres reach at most 1 + 0.6 below the cube's centre plane.
    scene.objects.push_back(shapeObject("ground", groundSquare(8.0, -1.7), 0));
    SplitMix64 rng(seed);
    for (size_t i = 0; i < count; ++i) {
        const Vec3 c{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
        const double radius = r * rng.uniform(0.5, 1.0);
        const uint32_t mat = 1 + uint32_t(rng.next() % 4);
        scene.objects.push_back(
            shapeObject("sphere " + std::to_string(i), makeSphere(c, radius), mat));
    }
    return scene;
}

size_t heightFieldGridSize(size_t targetTriangles) {
    const double g = std::round(std::sqrt(double(targetTriangles) / 2.0));
    return g < 1 ? 1 : size_t(g);
}

Scene makeHeightFieldScene(size_t targetTriangles) {
    const size_t g = heightFieldGridSize(targetTriangles);
    Scene scene;
    scene.sourcePath = "mesh(" + std::to_string(targetTriangles) + ")";
    scene.camera = Camera::perspective({0, -2.6, 1.9}, {0, 0, -0.05}, {0, 0, 1}, 45.0);
    scene.image.width = 640;
    scene.image.height = 480;
    scene.image.maxDepth = 5;
    scene.background = Color(0.45, 0.6, 0.85);
    scene.ambient = Color(0.12);
    scene.lights.push_back(pointLight({3, -2, 4}, 0.7));
    scene.lights.push_back(pointLight({-3, -1, 3}, 0.3));
    scene.materials.push_back(material("terrain", Color(0.55, 0.5, 0.4), 0.2, 20.0, 0.15));

    // h(x, y): a few sines of different wavelengths, so finer grids keep
    // adding visible detail; the normal is (-dh/dx, -dh/dy, 1) normalised.
    const auto height = [](double x, double y) {
        return 0.12 * std::sin(3.1 * x + 0.7) * std::cos(2.3 * y) +
               0.06 * std::sin(7.3 * x + 5.1 * y) + 0.03 * std::cos(13.7 * x - 9.1 * y);
    };
    const auto normal = [](double x, double y) {
        const double hx = 0.12 * 3.1 * std::cos(3.1 * x + 0.7) * std::cos(2.3 * y) +
                          0.06 * 7.3 * std::cos(7.3 * x + 5.1 * y) -
                          0.03 * 13.7 * std::sin(13.7 * x - 9.1 * y);
        const double hy = -0.12 * 2.3 * std::sin(3.1 * x + 0.7) * std::sin(2.3 * y) +
                          0.06 * 5.1 * std::cos(7.3 * x + 5.1 * y) +
                          0.03 * 9.1 * std::sin(13.7 * x - 9.1 * y);
        return normalize(Vec3{-hx, -hy, 1.0});
    };

    auto mesh = std::make_shared<TriangleMesh>();
    const size_t n = g + 1;  // vertices per side
    mesh->positions.reserve(n * n);
    mesh->normals.reserve(n * n);
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i < n; ++i) {
            const double x = -1.0 + 2.0 * double(i) / double(g);
            const double y = -1.0 + 2.0 * double(j) / double(g);
            mesh->positions.push_back({x, y, height(x, y)});
            mesh->normals.push_back(normal(x, y));
        }
    }
    mesh->triangles.reserve(2 * g * g);
    for (size_t j = 0; j < g; ++j) {
        for (size_t i = 0; i < g; ++i) {
            const uint32_t v00 = uint32_t(j * n + i), v10 = v00 + 1;
            const uint32_t v01 = uint32_t(v00 + n), v11 = v01 + 1;
            // Counter-clockwise seen from +z: the front faces up.
            mesh->triangles.push_back({v00, v10, v11});
            mesh->triangles.push_back({v00, v11, v01});
        }
    }
    Object o;
    o.name = "terrain";
    o.shape = std::move(mesh);
    o.material = 0;
    scene.objects.push_back(std::move(o));
    return scene;
}

Scene makePolygonFieldScene(size_t count, uint64_t seed) {
    if (count == 0) throw std::invalid_argument("polygon field: count must be > 0");
    Scene scene;
    scene.sourcePath = "polygons(" + std::to_string(count) + ")";
    scene.camera = Camera::perspective({0, -1.75, 1.45}, {0, -0.15, 0.05}, {0, 0, 1}, 45.0);
    scene.image.width = 640;
    scene.image.height = 480;
    scene.image.maxDepth = 5;
    scene.background = Color(0.2, 0.22, 0.25);
    scene.ambient = Color(0.1);
    scene.lights.push_back(pointLight({2, -3, 5}, 0.7));
    scene.lights.push_back(pointLight({-4, 1, 4}, 0.3));
    scene.materials.push_back(material("clay", Color(0.75, 0.45, 0.3), 0.2, 30.0, 0.0));
    scene.materials.push_back(material("slate", Color(0.3, 0.35, 0.45), 0.4, 80.0, 0.35));

    const size_t side = size_t(std::ceil(std::sqrt(double(count))));
    const double cell = 2.0 / double(side);
    SplitMix64 rng(seed);
    scene.objects.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        const double cx = -1.0 + (double(i % side) + 0.5) * cell + rng.uniform(-0.08, 0.08) * cell;
        const double cy = -1.0 + (double(i / side) + 0.5) * cell + rng.uniform(-0.08, 0.08) * cell;
        const double cz = rng.uniform(0.0, 0.3);
        const Vec3 n = normalize(Vec3{rng.uniform(-0.4, 0.4), rng.uniform(-0.4, 0.4), 1.0});
        // Orthonormal tangents with e1 × e2 = n, so increasing angles run
        // counter-clockwise seen from the front.
        const Vec3 e1 = normalize(cross(Vec3{0, 1, 0}, n));
        const Vec3 e2 = cross(n, e1);
        const int sides = (i % 2 == 0) ? 6 : 4;
        // Circumradius a little over half a cell: neighbours may overlap
        // (at different heights), gaps remain where the tilts differ.
        const double radius = 0.55 * cell;
        const double phase = rng.uniform(0, 2 * kPi);
        PolygonParams p;
        for (int k = 0; k < sides; ++k) {
            const double a = phase + 2 * kPi * k / sides;
            p.vertices.push_back(Vec3{cx, cy, cz} + (e1 * std::cos(a) + e2 * std::sin(a)) * radius);
        }
        std::unique_ptr<Shape> tile = makePolygon(p);
        tile->setSidedness(Sidedness::Both);
        scene.objects.push_back(shapeObject("tile " + std::to_string(i), std::move(tile),
                                            uint32_t(rng.next() % 2)));
    }
    return scene;
}

const std::vector<SceneGenerator>& benchSceneGenerators() {
    // Default ladders: a few tiny sizes (where the naive loop may win), then
    // decades up to where the Embree build stays under a second on 2 cores;
    // --quick stops where a naive frame still takes a fraction of a second.
    static const std::vector<SceneGenerator> generators = {
        {"sphereflake", "level", {0, 1, 2, 3, 4, 5}, {0, 1, 2, 3},
         [](size_t p) { return makeSphereflakeScene(int(p)); }},
        {"spheres", "N", {1, 3, 10, 100, 1000, 10000, 100000}, {1, 10, 100, 1000},
         [](size_t p) { return makeRandomSpheresScene(p); }},
        {"mesh", "triangles", {2, 8, 100, 1000, 10000, 100000, 1000000}, {2, 100, 1000, 10000},
         [](size_t p) { return makeHeightFieldScene(p); }},
        {"polygons", "N", {1, 3, 10, 100, 1000, 10000}, {1, 10, 100, 1000},
         [](size_t p) { return makePolygonFieldScene(p); }},
    };
    return generators;
}

}  // namespace raylab

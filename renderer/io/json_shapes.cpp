#include "renderer/io/json_shapes.h"

#include <map>
#include <stdexcept>

#include "geometry/primitives.h"
#include "geometry/triangle_mesh.h"
#include "renderer/io/shape_factory.h"

namespace raylab {

namespace {

/// Runs a geometry factory; its complaint is reported at the object's line and path.
template <class Factory>
auto build(const JsonFieldReader& in, const JsonFields& f, Factory&& factory) {
    return callFactory(in.file(), f.value().line(), f.objectPath(), std::forward<Factory>(factory));
}

std::unique_ptr<Shape> readSphere(const JsonFieldReader& in, const JsonFields& f) {
    const Vec3 centre = in.vec3(f.need("center"), f.path("center"));
    const double radius = in.positive(f.need("radius"), f.path("radius"));
    // The pole orients the sphere's (u, v): +y (the default up) unless given.
    const Vec3 pole = f.has("pole") ? normalize(in.direction(*f.get("pole"), f.path("pole")))
                                    : Vec3{0, 1, 0};
    return build(in, f, [&] { return makeSphere(centre, radius, pole); });
}

std::unique_ptr<Shape> readPlane(const JsonFieldReader& in, const JsonFields& f) {
    const Vec3 point = in.vec3(f.need("point"), f.path("point"));
    const Vec3 normal = in.direction(f.need("normal"), f.path("normal"));
    const double half =
        f.has("half_extent") ? in.positive(*f.get("half_extent"), f.path("half_extent")) : 1e5;
    return build(in, f, [&] { return makePlane(point, normal, half); });
}

std::unique_ptr<Shape> readDisk(const JsonFieldReader& in, const JsonFields& f) {
    const Vec3 centre = in.vec3(f.need("center"), f.path("center"));
    const Vec3 normal = in.direction(f.need("normal"), f.path("normal"));
    const double radius = in.positive(f.need("radius"), f.path("radius"));
    return build(in, f, [&] { return makeDisk(centre, normal, radius); });
}

std::unique_ptr<Shape> readCone(const JsonFieldReader& in, const JsonFields& f, bool cylinder) {
    ConeParams p;
    p.base = in.vec3(f.need("base"), f.path("base"));
    p.apex = in.vec3(f.need("apex"), f.path("apex"));
    if (p.base == p.apex) in.fail(f.need("apex"), f.path("apex"), "must differ from 'base'");
    const JsonValue* r = f.get("radius");
    const JsonValue* rb = f.get("base_radius");
    const JsonValue* ra = f.get("apex_radius");
    if (r && (rb || ra))
        in.fail(rb ? *rb : *ra, f.path(rb ? "base_radius" : "apex_radius"),
                "give either 'radius' or 'base_radius'/'apex_radius', not both");
    if (r) {
        p.baseRadius = p.apexRadius = in.positive(*r, f.path("radius"));
    } else if (cylinder) {
        // A cylinder with two radii is a truncated cone; both must be given.
        if (!rb && !ra)
            in.fail(f.value(), f.objectPath(), "missing required key 'radius' for a cylinder");
        p.baseRadius = in.nonNegative(f.need("base_radius"), f.path("base_radius"));
        p.apexRadius = in.nonNegative(f.need("apex_radius"), f.path("apex_radius"));
    } else {
        if (!rb)
            in.fail(f.value(), f.objectPath(),
                    "missing required key 'base_radius' (or 'radius') for a cone");
        p.baseRadius = in.nonNegative(*rb, f.path("base_radius"));
        p.apexRadius = ra ? in.nonNegative(*ra, f.path("apex_radius")) : 0.0;
    }
    if (!(p.baseRadius > 0 || p.apexRadius > 0))
        in.fail(rb ? *rb : f.value(), rb ? f.path("base_radius") : f.objectPath(),
                "at least one radius must be > 0");
    if (const JsonValue* c = f.get("caps")) p.capped = in.boolean(*c, f.path("caps"));
    return build(in, f, [&] { return makeCone(p); });
}

std::unique_ptr<Shape> readQuadric(const JsonFieldReader& in, const JsonFields& f) {
    QuadricParams q;
    double* coeff[10] = {&q.A, &q.B, &q.C, &q.D, &q.E, &q.F, &q.G, &q.H, &q.I, &q.J};
    static const std::vector<std::string> kLetters = {"A", "B", "C", "D", "E",
                                                      "F", "G", "H", "I", "J"};
    const JsonValue& c = f.need("coefficients");
    const std::string cpath = f.path("coefficients");
    if (c.isArray()) {
        if (c.size() != 10)
            in.fail(c, cpath,
                    "expected 10 numbers [A, B, C, D, E, F, G, H, I, J], got " +
                        std::to_string(c.size()));
        for (size_t i = 0; i < 10; ++i) *coeff[i] = in.number(c.at(i), indexPath(cpath, i));
    } else if (c.isObject()) {
        // Letters not given are 0.
        const JsonFields cf(in, c, cpath, "quadric coefficients", kLetters);
        for (size_t i = 0; i < 10; ++i)
            if (const JsonValue* x = cf.get(kLetters[i]))
                *coeff[i] = in.number(*x, cf.path(kLetters[i]));
    } else {
        in.fail(c, cpath,
                std::string("expected an object {\"A\": ..} or an array of 10 numbers, got ") +
                    c.typeName());
    }
    if (const JsonValue* clip = f.get("clip")) {
        const JsonFields cf(in, *clip, f.path("clip"), "a clipping box", {"min", "max"});
        const Vec3 lo = in.vec3(cf.need("min"), cf.path("min"));
        const Vec3 hi = in.vec3(cf.need("max"), cf.path("max"));
        for (int k = 0; k < 3; ++k)
            if (!(lo[k] <= hi[k]))
                in.fail(cf.need("max"), cf.path("max"), "must be >= 'min' in every component");
        q.clip = Bounds3(lo, hi);
        q.hasClip = true;
    }
    return build(in, f, [&] { return makeQuadric(q); });
}

std::unique_ptr<Shape> readPolygon(const JsonFieldReader& in, const JsonFields& f) {
    PolygonParams p;
    const JsonValue& verts = in.array(f.need("vertices"), f.path("vertices"));
    if (verts.size() < 3)
        in.fail(verts, f.path("vertices"),
                "a polygon needs at least 3 vertices (got " + std::to_string(verts.size()) + ")");
    for (size_t i = 0; i < verts.size(); ++i)
        p.vertices.push_back(in.vec3(verts.at(i), indexPath(f.path("vertices"), i)));
    if (const JsonValue* ns = f.get("normals")) {
        in.array(*ns, f.path("normals"));
        if (ns->size() != verts.size())
            in.fail(*ns, f.path("normals"),
                    "needs one normal per vertex (" + std::to_string(verts.size()) + "), got " +
                        std::to_string(ns->size()));
        for (size_t i = 0; i < ns->size(); ++i)
            p.normals.push_back(
                normalize(in.direction(ns->at(i), indexPath(f.path("normals"), i))));
    }
    const bool triangulate =
        f.has("triangulate") && in.boolean(*f.get("triangulate"), f.path("triangulate"));
    if (triangulate) {
        // Options of the analytic polygon do not apply to its triangles.
        for (const char* key : {"rule", "test"})
            if (const JsonValue* x = f.get(key))
                in.fail(*x, f.path(key), "has no effect with \"triangulate\": true");
        auto mesh = std::make_unique<TriangleMesh>();
        mesh->positions = p.vertices;
        mesh->normals = p.normals;
        mesh->triangles = build(in, f, [&] { return triangulatePolygon(p.vertices); });
        if (mesh->triangles.empty())
            in.fail(f.value(), f.objectPath(), "polygon: triangulation gave no triangles");
        return mesh;
    }
    if (const JsonValue* x = f.get("rule"))
        p.rule = in.choice<FillRule>(
            *x, f.path("rule"), {{"even-odd", FillRule::EvenOdd}, {"nonzero", FillRule::NonZero}});
    if (const JsonValue* x = f.get("test"))
        p.test = in.choice<PolygonTest>(
            *x, f.path("test"),
            {{"watertight", PolygonTest::Watertight}, {"projected", PolygonTest::Projected}});
    return build(in, f, [&] { return makePolygon(p); });
}

}  // namespace

const std::vector<std::string>* analyticShapeKeys(const std::string& type) {
    static const std::map<std::string, std::vector<std::string>> kKeys = {
        {"sphere", {"center", "radius", "pole"}},
        {"plane", {"point", "normal", "half_extent"}},
        {"disk", {"center", "normal", "radius"}},
        {"cylinder", {"base", "apex", "radius", "base_radius", "apex_radius", "caps"}},
        {"cone", {"base", "apex", "radius", "base_radius", "apex_radius", "caps"}},
        {"quadric", {"coefficients", "clip"}},
        {"polygon", {"vertices", "normals", "rule", "test", "triangulate"}},
    };
    const auto it = kKeys.find(type);
    return it == kKeys.end() ? nullptr : &it->second;
}

std::unique_ptr<Shape> readAnalyticShape(const JsonFieldReader& in, const JsonFields& f,
                                         const std::string& type) {
    if (type == "sphere") return readSphere(in, f);
    if (type == "plane") return readPlane(in, f);
    if (type == "disk") return readDisk(in, f);
    if (type == "cylinder" || type == "cone") return readCone(in, f, type == "cylinder");
    if (type == "quadric") return readQuadric(in, f);
    if (type == "polygon") return readPolygon(in, f);
    throw std::logic_error("readAnalyticShape: not an analytic shape type: " + type);
}

}  // namespace raylab

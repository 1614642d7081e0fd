// The native JSON scene format (docs/scene-format.md). Every error names the
// file, the line and the key path: "scene.json:14: objects[3].radius: must be
// > 0 (got -1)". Unknown keys are errors, so typos never pass silently.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "geometry/primitives.h"
#include "renderer/io/errors.h"
#include "renderer/io/json.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/scene_loader.h"
#include "renderer/io/text_file.h"
#include "renderer/render_options.h"

namespace raylab {

namespace {

/// Numbers in messages: short, exact for the values people type.
std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

std::string memberPath(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

std::string indexPath(const std::string& parent, size_t i) {
    return parent + "[" + std::to_string(i) + "]";
}

/// Levenshtein distance, for "did you mean" hints on unknown keys.
size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1])});
            diag = up;
        }
    }
    return row[b.size()];
}

std::string quotedList(const std::vector<std::string>& items) {
    std::string s;
    for (size_t i = 0; i < items.size(); ++i) s += (i ? ", " : "") + ("'" + items[i] + "'");
    return s;
}

class SceneReader;

/// The members of one JSON object: rejects keys outside the allowed set up
/// front (before any value is read, so a misspelt key is the first error
/// reported) and reports missing required keys.
class Fields {
public:
    Fields(const SceneReader& reader, const JsonValue& value, std::string path, std::string what,
           std::vector<std::string> allowed);

    const JsonValue* get(const std::string& key) const { return m_value.find(key); }
    const JsonValue& need(const std::string& key) const;
    bool has(const std::string& key) const { return get(key) != nullptr; }
    std::string path(const std::string& key) const { return memberPath(m_path, key); }
    const JsonValue& value() const { return m_value; }
    const std::string& objectPath() const { return m_path; }

private:
    const SceneReader& m_reader;
    const JsonValue& m_value;
    std::string m_path;
    std::string m_what;
};

/// Reads one scene document into a Scene.
class SceneReader {
public:
    explicit SceneReader(const std::string& file) : m_file(file) {}

    Scene read(const JsonValue& root);

    [[noreturn]] void fail(int line, const std::string& path, const std::string& message) const {
        throw InputError(m_file, line, path.empty() ? message : path + ": " + message);
    }
    [[noreturn]] void fail(const JsonValue& v, const std::string& path,
                           const std::string& message) const {
        fail(v.line(), path, message);
    }

    // ---- Typed values ------------------------------------------------------

    void expectType(const JsonValue& v, const std::string& path, JsonValue::Type type,
                    const char* expected) const {
        if (v.type() != type)
            fail(v, path, std::string("expected ") + expected + ", got " + v.typeName());
    }

    double number(const JsonValue& v, const std::string& path) const {
        expectType(v, path, JsonValue::Type::Number, "a number");
        return v.asNumber();
    }

    double positive(const JsonValue& v, const std::string& path) const {
        const double x = number(v, path);
        if (!(x > 0)) fail(v, path, "must be > 0 (got " + fmt(x) + ")");
        return x;
    }

    double nonNegative(const JsonValue& v, const std::string& path) const {
        const double x = number(v, path);
        if (!(x >= 0)) fail(v, path, "must be >= 0 (got " + fmt(x) + ")");
        return x;
    }

    long long integer(const JsonValue& v, const std::string& path, long long lo,
                      long long hi) const {
        const double x = number(v, path);
        if (x != std::floor(x)) fail(v, path, "must be an integer (got " + fmt(x) + ")");
        if (x < lo || x > hi)
            fail(v, path,
                 "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " +
                     fmt(x) + ")");
        return static_cast<long long>(x);
    }

    bool boolean(const JsonValue& v, const std::string& path) const {
        expectType(v, path, JsonValue::Type::Bool, "true or false");
        return v.asBool();
    }

    const std::string& string(const JsonValue& v, const std::string& path) const {
        expectType(v, path, JsonValue::Type::String, "a string");
        return v.asString();
    }

    const JsonValue& array(const JsonValue& v, const std::string& path) const {
        expectType(v, path, JsonValue::Type::Array, "an array");
        return v;
    }

    Vec3 vec3(const JsonValue& v, const std::string& path) const {
        if (!v.isArray()) fail(v, path, std::string("expected [x, y, z], got ") + v.typeName());
        if (v.size() != 3)
            fail(v, path,
                 "expected [x, y, z] (3 numbers), got " + std::to_string(v.size()) +
                     (v.size() == 1 ? " element" : " elements"));
        Vec3 out;
        for (int i = 0; i < 3; ++i) out[i] = number(v.at(size_t(i)), indexPath(path, size_t(i)));
        return out;
    }

    /// A vector that must not be zero (directions, normals, axes).
    Vec3 direction(const JsonValue& v, const std::string& path) const {
        const Vec3 d = vec3(v, path);
        if (!(length(d) > 0)) fail(v, path, "must not be the zero vector");
        return d;
    }

    /// [r, g, b] or one number for a grey; every component >= 0.
    Color color(const JsonValue& v, const std::string& path) const {
        if (v.isNumber()) return Color(nonNegative(v, path));
        if (!v.isArray() || v.size() != 3)
            fail(v, path,
                 std::string("expected [r, g, b] or a number, got ") +
                     (v.isArray() ? "an array of " + std::to_string(v.size()) : v.typeName()));
        Color c;
        c.r = nonNegative(v.at(0), indexPath(path, 0));
        c.g = nonNegative(v.at(1), indexPath(path, 1));
        c.b = nonNegative(v.at(2), indexPath(path, 2));
        return c;
    }

    template <class E>
    E choice(const JsonValue& v, const std::string& path,
             const std::vector<std::pair<std::string, E>>& options) const {
        const std::string& s = string(v, path);
        std::vector<std::string> names;
        for (const auto& [name, e] : options) {
            if (name == s) return e;
            names.push_back(name);
        }
        fail(v, path, "must be one of " + quotedList(names) + " (got '" + s + "')");
    }

private:
    std::string m_file;
    Scene m_scene;
    std::map<std::string, uint32_t> m_materialIndex;
    std::optional<uint32_t> m_defaultMaterial;

    void readImage(const JsonValue& v, const std::string& path);
    void readRenderSettings(const JsonValue& v, const std::string& path);
    void readCamera(const JsonValue& v, const std::string& path);
    void readLights(const JsonValue& v, const std::string& path);
    Light readLight(const JsonValue& v, const std::string& path);
    void readMaterials(const JsonValue& v, const std::string& path);
    Material readMaterial(const JsonValue& v, const std::string& path);
    uint32_t resolveMaterial(const JsonValue* v, const std::string& path);
    uint32_t defaultMaterial();
    void readObjects(const JsonValue& v, const std::string& path);
    void readObject(const JsonValue& v, const std::string& path);
    MeshTransform readTransform(const JsonValue& v, const std::string& path);
    MeshTransform readRotation(const JsonValue& v, const std::string& path);

    /// The object's "sides" key, or `fallback` without one.
    Sidedness sides(const Fields& f, Sidedness fallback);
    /// "sides" (default both) on every mesh object added since `firstObject`.
    void setMeshSides(const Fields& f, size_t firstObject);
    void addShape(const Fields& f, std::unique_ptr<Shape> shape, uint32_t material,
                  const std::string& name);
    void addMesh(std::shared_ptr<TriangleMesh> mesh, uint32_t material,
                 std::vector<uint32_t> faceMaterials, const std::string& name);

    void readSphere(const Fields& f, uint32_t material, const std::string& name);
    void readPlane(const Fields& f, uint32_t material, const std::string& name);
    void readDisk(const Fields& f, uint32_t material, const std::string& name);
    void readCone(const Fields& f, bool cylinder, uint32_t material, const std::string& name);
    void readQuadric(const Fields& f, uint32_t material, const std::string& name);
    void readPolygon(const Fields& f, uint32_t material, const std::string& name);
    void readMeshFile(const Fields& f, const std::string& name);
    void readCheckerboard(const Fields& f, const std::string& name);

    /// Runs a geometry factory, turning its std::invalid_argument into an
    /// InputError at the object's line and path.
    template <class Factory>
    auto build(const Fields& f, Factory&& factory) -> decltype(factory()) {
        try {
            return factory();
        } catch (const std::invalid_argument& e) {
            fail(f.value(), f.objectPath(), e.what());
        }
    }
};

Fields::Fields(const SceneReader& reader, const JsonValue& value, std::string path,
               std::string what, std::vector<std::string> allowed)
    : m_reader(reader), m_value(value), m_path(std::move(path)), m_what(std::move(what)) {
    if (!value.isObject())
        reader.fail(value, m_path,
                    "expected an object ({...}) for " + m_what + ", got " + value.typeName());
    for (size_t i = 0; i < value.size(); ++i) {
        const std::string& key = value.key(i);
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        // Suggest the closest allowed key within two edits, else list them all.
        std::string hint = " (expected " + quotedList(allowed) + ")";
        size_t best = 3;
        for (const std::string& a : allowed) {
            const size_t d = editDistance(key, a);
            if (d < best) {
                best = d;
                hint = " (did you mean '" + a + "'?)";
            }
        }
        reader.fail(value.keyLine(i), memberPath(m_path, key), "unknown key for " + m_what + hint);
    }
}

const JsonValue& Fields::need(const std::string& key) const {
    const JsonValue* v = get(key);
    if (!v) m_reader.fail(m_value, m_path, "missing required key '" + key + "' for " + m_what);
    return *v;
}

// ---------------------------------------------------------------------------
// Top level

Scene SceneReader::read(const JsonValue& root) {
    m_scene.sourcePath = m_file;
    if (!root.isObject())
        fail(root, "",
             std::string("a scene file must be a JSON object ({...}), got ") + root.typeName());
    const Fields top(
        *this, root, "", "a scene",
        // "camera_path" (--frames sequences) is read by distributed/camera_path.cpp.
        {"image", "render", "camera", "background", "ambient", "lights", "materials", "objects",
         "camera_path"});
    if (const JsonValue* v = top.get("image")) readImage(*v, "image");
    if (const JsonValue* v = top.get("render")) readRenderSettings(*v, "render");
    readCamera(top.need("camera"), "camera");
    if (const JsonValue* v = top.get("background")) m_scene.background = color(*v, "background");
    if (const JsonValue* v = top.get("ambient")) m_scene.ambient = color(*v, "ambient");
    // Materials first: objects refer to them by name wherever they appear in the file.
    if (const JsonValue* v = top.get("materials")) readMaterials(*v, "materials");
    if (const JsonValue* v = top.get("lights")) readLights(*v, "lights");
    readObjects(top.need("objects"), "objects");
    return std::move(m_scene);
}

void SceneReader::readImage(const JsonValue& v, const std::string& path) {
    const Fields f(*this, v, path, "the image settings", {"width", "height", "spp", "depth"});
    ImageSettings& im = m_scene.image;
    if (const JsonValue* x = f.get("width")) im.width = int(integer(*x, f.path("width"), 1, kMaxImageSide));
    if (const JsonValue* x = f.get("height")) im.height = int(integer(*x, f.path("height"), 1, kMaxImageSide));
    if (f.get("width") || f.get("height")) im.sizeLine = v.line();
    if (const JsonValue* x = f.get("spp")) im.spp = int(integer(*x, f.path("spp"), 1, kMaxSpp));
    if (const JsonValue* x = f.get("depth")) im.maxDepth = int(integer(*x, f.path("depth"), 1, kMaxDepth));
}

void SceneReader::readRenderSettings(const JsonValue& v, const std::string& path) {
    const Fields f(*this, v, path, "the render settings",
                   {"adaptive", "adaptive_levels", "min_weight", "seed", "precision", "epsilon",
                    "bvh_quality", "robust", "accel"});
    RenderOverrides& r = m_scene.settings;
    if (const JsonValue* x = f.get("adaptive")) r.adaptiveThreshold = nonNegative(*x, f.path("adaptive"));
    if (const JsonValue* x = f.get("adaptive_levels"))
        r.adaptiveMaxLevel = int(integer(*x, f.path("adaptive_levels"), 1, kMaxAdaptiveLevels));
    if (const JsonValue* x = f.get("min_weight")) {
        r.minWeight = nonNegative(*x, f.path("min_weight"));
        if (*r.minWeight > 1) fail(*x, f.path("min_weight"), "must be in [0, 1] (got " + fmt(*r.minWeight) + ")");
    }
    if (const JsonValue* x = f.get("seed")) r.seed = uint64_t(integer(*x, f.path("seed"), 0, kMaxSeed));
    if (const JsonValue* x = f.get("precision"))
        r.precision = choice<std::string>(*x, f.path("precision"), {{"float", "float"}, {"double", "double"}});
    if (const JsonValue* x = f.get("epsilon")) r.epsilon = nonNegative(*x, f.path("epsilon"));
    if (const JsonValue* x = f.get("bvh_quality"))
        r.bvhQuality = choice<std::string>(*x, f.path("bvh_quality"),
                                           {{"low", "low"}, {"medium", "medium"}, {"high", "high"}});
    if (const JsonValue* x = f.get("robust")) r.robust = boolean(*x, f.path("robust"));
    if (const JsonValue* x = f.get("accel"))
        r.accel = choice<std::string>(*x, f.path("accel"), {{"embree", "embree"}, {"naive", "naive"}});
}

void SceneReader::readCamera(const JsonValue& v, const std::string& path) {
    if (!v.isObject())
        fail(v, path, std::string("expected an object ({...}), got ") + v.typeName());
    enum class Kind { Perspective, Orthographic };
    Kind kind = Kind::Perspective;
    if (const JsonValue* t = v.find("type"))
        kind = choice<Kind>(
            *t, memberPath(path, "type"),
            {{"perspective", Kind::Perspective}, {"orthographic", Kind::Orthographic}});
    try {
        if (kind == Kind::Perspective) {
            const Fields f(*this, v, path, "a perspective camera",
                           {"type", "eye", "look_at", "up", "fov", "near"});
            const Vec3 eye = vec3(f.need("eye"), f.path("eye"));
            const Vec3 lookAt = vec3(f.need("look_at"), f.path("look_at"));
            const Vec3 up = f.has("up") ? direction(*f.get("up"), f.path("up")) : Vec3(0, 1, 0);
            double fov = 45;
            if (const JsonValue* x = f.get("fov")) {
                fov = number(*x, f.path("fov"));
                if (!(fov > 0 && fov < 180))
                    fail(*x, f.path("fov"), "must be in (0, 180) degrees (got " + fmt(fov) + ")");
            }
            m_scene.camera = Camera::perspective(eye, lookAt, up, fov);
        } else {
            const Fields f(*this, v, path, "an orthographic camera",
                           {"type", "eye", "direction", "up", "width", "near"});
            const Vec3 eye = vec3(f.need("eye"), f.path("eye"));
            const Vec3 dir = direction(f.need("direction"), f.path("direction"));
            const Vec3 up = f.has("up") ? direction(*f.get("up"), f.path("up")) : Vec3(0, 1, 0);
            const double width = positive(f.need("width"), f.path("width"));
            m_scene.camera = Camera::orthographic(eye, dir, up, width);
        }
    } catch (const std::invalid_argument& e) {
        // Camera messages already start with "camera: ".
        fail(v, "", e.what());
    }
    // Camera rays start this far from the eye (NFF's "hither").
    if (const JsonValue* n = v.find("near"))
        m_scene.cameraNear = nonNegative(*n, memberPath(path, "near"));
}

// ---------------------------------------------------------------------------
// Lights and materials

void SceneReader::readLights(const JsonValue& v, const std::string& path) {
    array(v, path);
    for (size_t i = 0; i < v.size(); ++i)
        m_scene.lights.push_back(readLight(v.at(i), indexPath(path, i)));
}

Light SceneReader::readLight(const JsonValue& v, const std::string& path) {
    if (!v.isObject())
        fail(v, path, std::string("expected a light object ({...}), got ") + v.typeName());
    const JsonValue* typeValue = v.find("type");
    if (!typeValue) fail(v, path, "missing required key 'type' ('point' or 'directional')");
    const Light::Type type = choice<Light::Type>(
        *typeValue, memberPath(path, "type"),
        {{"point", Light::Type::Point}, {"directional", Light::Type::Directional}});
    Light light;
    light.type = type;
    const bool point = type == Light::Type::Point;
    const Fields f(*this, v, path, point ? "a point light" : "a directional light",
                   {"type", point ? "position" : "direction", "color", "intensity"});
    if (point)
        light.position = vec3(f.need("position"), f.path("position"));
    else
        light.direction = normalize(direction(f.need("direction"), f.path("direction")));
    const Color c = f.has("color") ? color(*f.get("color"), f.path("color")) : Color(1, 1, 1);
    const double s =
        f.has("intensity") ? nonNegative(*f.get("intensity"), f.path("intensity")) : 1.0;
    light.intensity = c * s;
    return light;
}

void SceneReader::readMaterials(const JsonValue& v, const std::string& path) {
    if (!v.isObject())
        fail(v, path,
             std::string("expected an object mapping names to materials, got ") + v.typeName());
    for (size_t i = 0; i < v.size(); ++i) {
        Material m = readMaterial(v.at(i), memberPath(path, v.key(i)));
        m.name = v.key(i);
        m_materialIndex[m.name] = uint32_t(m_scene.materials.size());
        m_scene.materials.push_back(std::move(m));
    }
}

Material SceneReader::readMaterial(const JsonValue& v, const std::string& path) {
    const Fields f(*this, v, path, "a material",
                   {"ka", "kd", "ks", "shininess", "highlight", "km", "kt", "ior"});
    Material m;
    if (const JsonValue* x = f.get("ka")) m.ka = color(*x, f.path("ka"));
    if (const JsonValue* x = f.get("kd")) m.kd = color(*x, f.path("kd"));
    if (const JsonValue* x = f.get("ks")) m.ks = color(*x, f.path("ks"));
    if (const JsonValue* x = f.get("shininess")) m.shininess = nonNegative(*x, f.path("shininess"));
    if (const JsonValue* x = f.get("highlight"))
        m.highlight = choice<Highlight>(
            *x, f.path("highlight"),
            {{"blinn-phong", Highlight::BlinnPhong}, {"phong", Highlight::Phong}});
    if (const JsonValue* x = f.get("km")) m.km = color(*x, f.path("km"));
    if (const JsonValue* x = f.get("kt")) m.kt = color(*x, f.path("kt"));
    if (const JsonValue* x = f.get("ior")) m.ior = positive(*x, f.path("ior"));
    return m;
}

uint32_t SceneReader::defaultMaterial() {
    if (!m_defaultMaterial) {
        // A material the file calls "default" doubles as the default.
        const auto it = m_materialIndex.find("default");
        if (it != m_materialIndex.end()) {
            m_defaultMaterial = it->second;
        } else {
            Material m;
            m.name = "default";
            m_defaultMaterial = uint32_t(m_scene.materials.size());
            m_scene.materials.push_back(m);
        }
    }
    return *m_defaultMaterial;
}

uint32_t SceneReader::resolveMaterial(const JsonValue* v, const std::string& path) {
    if (!v) return defaultMaterial();
    if (v->isString()) {
        const auto it = m_materialIndex.find(v->asString());
        if (it != m_materialIndex.end()) return it->second;
        std::vector<std::string> names;
        for (const auto& [name, index] : m_materialIndex) names.push_back(name);
        fail(*v, path,
             "unknown material '" + v->asString() + "'" +
                 (names.empty() ? " (the scene defines no materials)"
                                : " (defined: " + quotedList(names) + ")"));
    }
    if (v->isObject()) {
        // An inline material, named after where it appears.
        Material m = readMaterial(*v, path);
        m.name = path;
        m_scene.materials.push_back(std::move(m));
        return uint32_t(m_scene.materials.size() - 1);
    }
    fail(*v, path,
         std::string("expected a material name or a material object, got ") + v->typeName());
}

// ---------------------------------------------------------------------------
// Objects

void SceneReader::readObjects(const JsonValue& v, const std::string& path) {
    array(v, path);
    for (size_t i = 0; i < v.size(); ++i) readObject(v.at(i), indexPath(path, i));
}

void SceneReader::readObject(const JsonValue& v, const std::string& path) {
    if (!v.isObject())
        fail(v, path, std::string("expected an object ({...}), got ") + v.typeName());
    const JsonValue* typeValue = v.find("type");
    if (!typeValue) fail(v, path, "missing required key 'type'");
    const std::string& type = string(*typeValue, memberPath(path, "type"));

    // Keys shared by the analytic shapes.
    const std::vector<std::string> shapeKeys = {"type", "name", "material", "sides"};
    auto with = [&](std::vector<std::string> extra) {
        std::vector<std::string> keys = shapeKeys;
        keys.insert(keys.end(), extra.begin(), extra.end());
        return keys;
    };

    std::string name = path;
    if (const JsonValue* n = v.find("name")) name = string(*n, memberPath(path, "name"));

    if (type == "mesh") {
        const Fields f(*this, v, path, "a mesh",
                       {"type", "name", "file", "transform", "material", "sides"});
        const size_t first = m_scene.objects.size();
        readMeshFile(f, v.find("name") ? name : "");
        setMeshSides(f, first);
        return;
    }
    if (type == "checkerboard") {
        const Fields f(*this, v, path, "a checkerboard",
                       {"type", "name", "origin", "edge_u", "edge_v", "divisions", "materials",
                        "sides"});
        const size_t first = m_scene.objects.size();
        readCheckerboard(f, name);
        setMeshSides(f, first);
        return;
    }

    std::vector<std::string> keys;
    const std::string what = "a " + type;
    if (type == "sphere")
        keys = with({"center", "radius"});
    else if (type == "plane")
        keys = with({"point", "normal", "half_extent"});
    else if (type == "disk")
        keys = with({"center", "normal", "radius"});
    else if (type == "cylinder" || type == "cone")
        keys = with({"base", "apex", "radius", "base_radius", "apex_radius", "caps"});
    else if (type == "quadric")
        keys = with({"coefficients", "clip"});
    else if (type == "polygon")
        keys = with({"vertices", "normals", "rule", "test", "triangulate"});
    else
        fail(*typeValue, memberPath(path, "type"),
             "unknown object type '" + type +
                 "' (expected 'sphere', 'plane', 'disk', 'cylinder', 'cone', 'quadric', "
                 "'polygon', 'mesh' or 'checkerboard')");

    const Fields f(*this, v, path, what, keys);
    const uint32_t material = resolveMaterial(f.get("material"), f.path("material"));
    if (type == "sphere") readSphere(f, material, name);
    if (type == "plane") readPlane(f, material, name);
    if (type == "disk") readDisk(f, material, name);
    if (type == "cylinder" || type == "cone") readCone(f, type == "cylinder", material, name);
    if (type == "quadric") readQuadric(f, material, name);
    if (type == "polygon") readPolygon(f, material, name);
}

Sidedness SceneReader::sides(const Fields& f, Sidedness fallback) {
    const JsonValue* s = f.get("sides");
    if (!s) return fallback;
    return choice<Sidedness>(
        *s, f.path("sides"),
        {{"outside", Sidedness::Outside}, {"inside", Sidedness::Inside}, {"both", Sidedness::Both}});
}

void SceneReader::setMeshSides(const Fields& f, size_t firstObject) {
    // Meshes default to both sides: OBJ files from other tools often mix
    // windings, and a one-sided mesh with a flipped face shows a hole.
    const Sidedness s = sides(f, Sidedness::Both);
    for (size_t i = firstObject; i < m_scene.objects.size(); ++i)
        m_scene.objects[i].shape->setSidedness(s);
}

void SceneReader::addShape(const Fields& f, std::unique_ptr<Shape> shape, uint32_t material,
                           const std::string& name) {
    // Transmitters must be hit from inside too, or refracted rays never leave.
    shape->setSidedness(sides(
        f, m_scene.materials[material].transmissive() ? Sidedness::Both : Sidedness::Outside));
    Object obj;
    obj.name = name;
    obj.shape = std::move(shape);
    obj.material = material;
    m_scene.objects.push_back(std::move(obj));
}

void SceneReader::addMesh(std::shared_ptr<TriangleMesh> mesh, uint32_t material,
                          std::vector<uint32_t> faceMaterials, const std::string& name) {
    Object obj;
    obj.name = name;
    obj.shape = std::move(mesh);
    obj.material = material;
    obj.faceMaterials = std::move(faceMaterials);
    m_scene.objects.push_back(std::move(obj));
}

void SceneReader::readSphere(const Fields& f, uint32_t material, const std::string& name) {
    const Vec3 centre = vec3(f.need("center"), f.path("center"));
    const double radius = positive(f.need("radius"), f.path("radius"));
    addShape(f, build(f, [&] { return makeSphere(centre, radius); }), material, name);
}

void SceneReader::readPlane(const Fields& f, uint32_t material, const std::string& name) {
    const Vec3 point = vec3(f.need("point"), f.path("point"));
    const Vec3 normal = direction(f.need("normal"), f.path("normal"));
    const double half =
        f.has("half_extent") ? positive(*f.get("half_extent"), f.path("half_extent")) : 1e5;
    addShape(f, build(f, [&] { return makePlane(point, normal, half); }), material, name);
}

void SceneReader::readDisk(const Fields& f, uint32_t material, const std::string& name) {
    const Vec3 centre = vec3(f.need("center"), f.path("center"));
    const Vec3 normal = direction(f.need("normal"), f.path("normal"));
    const double radius = positive(f.need("radius"), f.path("radius"));
    addShape(f, build(f, [&] { return makeDisk(centre, normal, radius); }), material, name);
}

void SceneReader::readCone(const Fields& f, bool cylinder, uint32_t material,
                           const std::string& name) {
    ConeParams p;
    p.base = vec3(f.need("base"), f.path("base"));
    p.apex = vec3(f.need("apex"), f.path("apex"));
    if (p.base == p.apex) fail(f.need("apex"), f.path("apex"), "must differ from 'base'");
    const JsonValue* r = f.get("radius");
    const JsonValue* rb = f.get("base_radius");
    const JsonValue* ra = f.get("apex_radius");
    if (r && (rb || ra))
        fail(rb ? *rb : *ra, f.path(rb ? "base_radius" : "apex_radius"),
             "give either 'radius' or 'base_radius'/'apex_radius', not both");
    if (r) {
        p.baseRadius = p.apexRadius = positive(*r, f.path("radius"));
    } else if (cylinder) {
        // A cylinder with two radii is a truncated cone; both must be given.
        if (!rb && !ra)
            fail(f.value(), f.objectPath(), "missing required key 'radius' for a cylinder");
        p.baseRadius = nonNegative(f.need("base_radius"), f.path("base_radius"));
        p.apexRadius = nonNegative(f.need("apex_radius"), f.path("apex_radius"));
    } else {
        if (!rb)
            fail(f.value(), f.objectPath(),
                 "missing required key 'base_radius' (or 'radius') for a cone");
        p.baseRadius = nonNegative(*rb, f.path("base_radius"));
        p.apexRadius = ra ? nonNegative(*ra, f.path("apex_radius")) : 0.0;
    }
    if (!(p.baseRadius > 0 || p.apexRadius > 0))
        fail(rb ? *rb : f.value(), rb ? f.path("base_radius") : f.objectPath(),
             "at least one radius must be > 0");
    if (const JsonValue* c = f.get("caps")) p.capped = boolean(*c, f.path("caps"));
    addShape(f, build(f, [&] { return makeCone(p); }), material, name);
}

void SceneReader::readQuadric(const Fields& f, uint32_t material, const std::string& name) {
    QuadricParams q;
    double* coeff[10] = {&q.A, &q.B, &q.C, &q.D, &q.E, &q.F, &q.G, &q.H, &q.I, &q.J};
    static const std::vector<std::string> kLetters = {"A", "B", "C", "D", "E",
                                                      "F", "G", "H", "I", "J"};
    const JsonValue& c = f.need("coefficients");
    const std::string cpath = f.path("coefficients");
    if (c.isArray()) {
        if (c.size() != 10)
            fail(c, cpath,
                 "expected 10 numbers [A, B, C, D, E, F, G, H, I, J], got " +
                     std::to_string(c.size()));
        for (size_t i = 0; i < 10; ++i) *coeff[i] = number(c.at(i), indexPath(cpath, i));
    } else if (c.isObject()) {
        // Letters not given are 0.
        const Fields cf(*this, c, cpath, "quadric coefficients", kLetters);
        for (size_t i = 0; i < 10; ++i)
            if (const JsonValue* x = cf.get(kLetters[i]))
                *coeff[i] = number(*x, cf.path(kLetters[i]));
    } else {
        fail(c, cpath,
             std::string("expected an object {\"A\": ..} or an array of 10 numbers, got ") +
                 c.typeName());
    }
    if (const JsonValue* clip = f.get("clip")) {
        const Fields cf(*this, *clip, f.path("clip"), "a clipping box", {"min", "max"});
        const Vec3 lo = vec3(cf.need("min"), cf.path("min"));
        const Vec3 hi = vec3(cf.need("max"), cf.path("max"));
        for (int k = 0; k < 3; ++k)
            if (!(lo[k] <= hi[k]))
                fail(cf.need("max"), cf.path("max"), "must be >= 'min' in every component");
        q.clip = Bounds3(lo, hi);
        q.hasClip = true;
    }
    addShape(f, build(f, [&] { return makeQuadric(q); }), material, name);
}

void SceneReader::readPolygon(const Fields& f, uint32_t material, const std::string& name) {
    PolygonParams p;
    const JsonValue& verts = array(f.need("vertices"), f.path("vertices"));
    if (verts.size() < 3)
        fail(verts, f.path("vertices"),
             "a polygon needs at least 3 vertices (got " + std::to_string(verts.size()) + ")");
    for (size_t i = 0; i < verts.size(); ++i)
        p.vertices.push_back(vec3(verts.at(i), indexPath(f.path("vertices"), i)));
    if (const JsonValue* ns = f.get("normals")) {
        array(*ns, f.path("normals"));
        if (ns->size() != verts.size())
            fail(*ns, f.path("normals"),
                 "needs one normal per vertex (" + std::to_string(verts.size()) + "), got " +
                     std::to_string(ns->size()));
        for (size_t i = 0; i < ns->size(); ++i)
            p.normals.push_back(normalize(direction(ns->at(i), indexPath(f.path("normals"), i))));
    }
    const bool triangulate =
        f.has("triangulate") && boolean(*f.get("triangulate"), f.path("triangulate"));
    if (triangulate) {
        // Options of the analytic polygon do not apply to its triangles.
        for (const char* key : {"rule", "test"})
            if (const JsonValue* x = f.get(key))
                fail(*x, f.path(key), "has no effect with \"triangulate\": true");
        auto mesh = std::make_shared<TriangleMesh>();
        mesh->positions = p.vertices;
        mesh->normals = p.normals;
        mesh->triangles = build(f, [&] { return triangulatePolygon(p.vertices); });
        if (mesh->triangles.empty())
            fail(f.value(), f.objectPath(), "polygon: triangulation gave no triangles");
        const size_t first = m_scene.objects.size();
        addMesh(mesh, material, {}, name);
        setMeshSides(f, first);
        return;
    }
    if (const JsonValue* x = f.get("rule"))
        p.rule = choice<FillRule>(
            *x, f.path("rule"), {{"even-odd", FillRule::EvenOdd}, {"nonzero", FillRule::NonZero}});
    if (const JsonValue* x = f.get("test"))
        p.test = choice<PolygonTest>(
            *x, f.path("test"),
            {{"watertight", PolygonTest::Watertight}, {"projected", PolygonTest::Projected}});
    addShape(f, build(f, [&] { return makePolygon(p); }), material, name);
}

MeshTransform SceneReader::readRotation(const JsonValue& v, const std::string& path) {
    const Fields f(*this, v, path, "a rotation", {"axis", "degrees"});
    const Vec3 axis = direction(f.need("axis"), f.path("axis"));
    const double degrees = number(f.need("degrees"), f.path("degrees"));
    return MeshTransform::rotate(axis, degrees);
}

MeshTransform SceneReader::readTransform(const JsonValue& v, const std::string& path) {
    // Applied as scale, then rotate (list order), then translate.
    const Fields f(*this, v, path, "a transform", {"translate", "rotate", "scale"});
    MeshTransform xf;
    if (const JsonValue* s = f.get("scale")) {
        Vec3 k;
        if (s->isNumber())
            k = Vec3(1, 1, 1) * number(*s, f.path("scale"));
        else
            k = vec3(*s, f.path("scale"));
        for (int i = 0; i < 3; ++i)
            if (k[i] == 0) fail(*s, f.path("scale"), "scale factors must not be 0");
        xf = xf.then(MeshTransform::scale(k));
    }
    if (const JsonValue* r = f.get("rotate")) {
        if (r->isArray()) {
            for (size_t i = 0; i < r->size(); ++i)
                xf = xf.then(readRotation(r->at(i), indexPath(f.path("rotate"), i)));
        } else {
            xf = xf.then(readRotation(*r, f.path("rotate")));
        }
    }
    if (const JsonValue* t = f.get("translate"))
        xf = xf.then(MeshTransform::translate(vec3(*t, f.path("translate"))));
    return xf;
}

void SceneReader::readMeshFile(const Fields& f, const std::string& name) {
    const JsonValue& fileValue = f.need("file");
    const std::string& file = string(fileValue, f.path("file"));
    if (file.empty()) fail(fileValue, f.path("file"), "must not be empty");
    ObjLoadOptions options;
    if (const JsonValue* t = f.get("transform"))
        options.transform = readTransform(*t, f.path("transform"));
    std::optional<uint32_t> override;
    if (const JsonValue* m = f.get("material")) override = resolveMaterial(m, f.path("material"));

    const std::string objPath = resolveRelativeTo(m_file, file);
    if (lowerExtension(objPath) != ".obj")
        fail(fileValue, f.path("file"), "only .obj meshes are supported (got '" + file + "')");
    ObjModel model;
    try {
        model = loadObj(objPath, options);
    } catch (const InputError& e) {
        // Errors without a line in the OBJ (it is missing, empty, ...) are
        // reported at the scene line that names it.
        if (e.line() == 0) fail(fileValue, f.path("file"), "'" + objPath + "': " + e.what());
        throw;
    }
    appendObjModel(m_scene, model, name.empty() ? file : name, override);
}

void SceneReader::readCheckerboard(const Fields& f, const std::string& name) {
    const Vec3 origin = vec3(f.need("origin"), f.path("origin"));
    const Vec3 eu = direction(f.need("edge_u"), f.path("edge_u"));
    const Vec3 ev = direction(f.need("edge_v"), f.path("edge_v"));
    // sin of the angle between the edges; below ~1e-9 there is no plane.
    if (!(length(cross(normalize(eu), normalize(ev))) > 1e-9))
        fail(f.need("edge_v"), f.path("edge_v"), "must not be parallel to 'edge_u'");
    int nu = 8, nv = 8;
    if (const JsonValue* d = f.get("divisions")) {
        if (d->isArray()) {
            if (d->size() != 2)
                fail(*d, f.path("divisions"),
                     "expected a number or [nu, nv], got " + std::to_string(d->size()) +
                         " elements");
            nu = int(integer(d->at(0), indexPath(f.path("divisions"), 0), 1, 4096));
            nv = int(integer(d->at(1), indexPath(f.path("divisions"), 1), 1, 4096));
        } else {
            nu = nv = int(integer(*d, f.path("divisions"), 1, 4096));
        }
        // Two triangles per square, built before the first pixel and not
        // interruptible: a 300-byte file must not ask for 33 million.
        constexpr long kMaxSquares = 512L * 512L;
        if (long(nu) * nv > kMaxSquares)
            fail(*d, f.path("divisions"),
                 std::to_string(nu) + " x " + std::to_string(nv) + " squares exceed the limit of " +
                     std::to_string(kMaxSquares) + " (512 x 512)");
    }
    const JsonValue& mats = array(f.need("materials"), f.path("materials"));
    if (mats.size() != 2)
        fail(mats, f.path("materials"),
             "expected 2 materials [first, second], got " + std::to_string(mats.size()));
    const uint32_t m0 = resolveMaterial(&mats.at(0), indexPath(f.path("materials"), 0));
    const uint32_t m1 = resolveMaterial(&mats.at(1), indexPath(f.path("materials"), 1));

    // A (nu+1) x (nv+1) grid of shared vertices; square (i, j) becomes two
    // triangles wound so their normal is edge_u x edge_v, and takes the first
    // material when i + j is even (the square at the origin corner is m0).
    auto mesh = std::make_shared<TriangleMesh>();
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i)
            mesh->positions.push_back(origin + eu * (double(i) / nu) + ev * (double(j) / nv));
    std::vector<uint32_t> faceMaterials;
    auto at = [&](int i, int j) { return uint32_t(j * (nu + 1) + i); };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const uint32_t m = (i + j) % 2 == 0 ? m0 : m1;
            mesh->triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh->triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            faceMaterials.push_back(m);
            faceMaterials.push_back(m);
        }
    addMesh(mesh, m0, m0 == m1 ? std::vector<uint32_t>{} : std::move(faceMaterials), name);
}

}  // namespace

Scene loadJsonScene(const std::string& text, const std::string& path) {
    const JsonValue root = parseJson(text, path);
    return SceneReader(path).read(root);
}

}  // namespace raylab

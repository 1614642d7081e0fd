// The native JSON scene format (docs/scene-format.md). Every error names the
// file, the line and the key path: "scene.json:14: objects[3].radius: must be
// > 0 (got -1)". Unknown keys are errors, so typos never pass silently.

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/checkerboard.h"
#include "geometry/transform.h"
#include "geometry/triangle_mesh.h"
#include "renderer/io/errors.h"
#include "renderer/io/json.h"
#include "renderer/io/json_camera_path.h"
#include "renderer/io/json_fields.h"
#include "renderer/io/json_shapes.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/scene_loader.h"
#include "renderer/io/json_textures.h"
#include "renderer/io/shape_factory.h"
#include "renderer/io/text_file.h"
#include "renderer/render_option_names.h"
#include "renderer/render_options.h"

namespace raylab {

namespace {

/// Reads one scene document into a Scene.
class SceneReader : public JsonFieldReader {
public:
    explicit SceneReader(const std::string& file) : JsonFieldReader(file) {}

    Scene read(const JsonValue& root);

private:
    Scene m_scene;
    TextureLibrary m_textureFiles;  ///< every texture file read once, shared with the meshes' MTLs
    std::map<std::string, uint32_t> m_materialIndex;
    std::optional<uint32_t> m_defaultMaterial;

    void readImage(const JsonValue& v, const std::string& path);
    void readRenderSettings(const JsonValue& v, const std::string& path);
    void readCamera(const JsonValue& v, const std::string& path);
    void readCameraPath(const JsonValue& v);
    void readLights(const JsonValue& v, const std::string& path);
    Light readLight(const JsonValue& v, const std::string& path);
    void readMaterials(const JsonValue& v, const std::string& path);
    Material readMaterial(const JsonValue& v, const std::string& path);
    uint32_t resolveMaterial(const JsonValue* v, const std::string& path);
    uint32_t defaultMaterial();
    void readObjects(const JsonValue& v, const std::string& path);
    void readObject(const JsonValue& v, const std::string& path);
    Transform readTransform(const JsonValue& v, const std::string& path);
    Transform readRotation(const JsonValue& v, const std::string& path);

    /// Sets the sidedness of every object added since `firstObject`: the
    /// "sides" key when given, else both for a transmitter (refracted rays
    /// must leave it), else the shape's own default (outside for analytic
    /// shapes, both for meshes: OBJ files from other tools often mix
    /// windings, and a one-sided mesh shows a flipped face as a hole).
    void setSides(const JsonFields& f, size_t firstObject);
    void addObject(std::shared_ptr<Shape> shape, uint32_t material,
                   std::vector<uint32_t> faceMaterials, const std::string& name);

    void readMeshFile(const JsonFields& f, const std::string& name);
    void readCheckerboard(const JsonFields& f, const std::string& name);
};

// ---------------------------------------------------------------------------
// Top level

Scene SceneReader::read(const JsonValue& root) {
    m_scene.sourcePath = file();
    if (!root.isObject())
        fail(root, "",
             std::string("a scene file must be a JSON object ({...}), got ") + root.typeName());
    const JsonFields top(
        *this, root, "", "a scene",
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
    // After everything else: an error elsewhere in the scene is still reported first.
    if (const JsonValue* v = top.get("camera_path")) readCameraPath(*v);
    return std::move(m_scene);
}

void SceneReader::readImage(const JsonValue& v, const std::string& path) {
    const JsonFields f(*this, v, path, "the image settings", {"width", "height", "spp", "depth"});
    ImageSettings& im = m_scene.image;
    if (const JsonValue* x = f.get("width"))
        im.width = int(integer(*x, f.path("width"), 1, kMaxImageSide));
    if (const JsonValue* x = f.get("height"))
        im.height = int(integer(*x, f.path("height"), 1, kMaxImageSide));
    if (f.get("width") || f.get("height")) im.sizeLine = v.line();
    if (const JsonValue* x = f.get("spp")) im.spp = int(integer(*x, f.path("spp"), 1, kMaxSpp));
    if (const JsonValue* x = f.get("depth"))
        im.maxDepth = int(integer(*x, f.path("depth"), 1, kMaxDepth));
}

void SceneReader::readRenderSettings(const JsonValue& v, const std::string& path) {
    const JsonFields f(*this, v, path, "the render settings",
                       {"adaptive", "adaptive_levels", "min_weight", "seed", "max_rays", "precision",
                        "epsilon", "bvh_quality", "robust", "accel", "shadows", "texture_filter",
                        "texture_footprint", "alpha_cutoff"});
    RenderOverrides& r = m_scene.settings;
    if (const JsonValue* x = f.get("adaptive"))
        r.adaptiveThreshold = nonNegative(*x, f.path("adaptive"));
    if (const JsonValue* x = f.get("adaptive_levels"))
        r.adaptiveMaxLevel = int(integer(*x, f.path("adaptive_levels"), 1, kMaxAdaptiveLevels));
    if (const JsonValue* x = f.get("min_weight")) {
        r.minWeight = nonNegative(*x, f.path("min_weight"));
        if (*r.minWeight > 1)
            fail(*x, f.path("min_weight"),
                 "must be in [0, 1] (got " + formatJsonNumber(*r.minWeight) + ")");
    }
    if (const JsonValue* x = f.get("seed"))
        r.seed = uint64_t(integer(*x, f.path("seed"), 0, kMaxSeed));
    if (const JsonValue* x = f.get("max_rays"))
        r.maxRaysPerSample = uint64_t(integer(*x, f.path("max_rays"), 1, kMaxRaysPerSampleLimit));
    if (const JsonValue* x = f.get("precision"))
        r.precision = choice(*x, f.path("precision"), precisionNames());
    if (const JsonValue* x = f.get("epsilon")) r.epsilon = nonNegative(*x, f.path("epsilon"));
    if (const JsonValue* x = f.get("shadows"))
        r.shadows = choice(*x, f.path("shadows"), shadowModeNames());
    if (const JsonValue* x = f.get("alpha_cutoff")) {
        r.alphaCutoff = nonNegative(*x, f.path("alpha_cutoff"));
        if (*r.alphaCutoff > 1)
            fail(*x, f.path("alpha_cutoff"),
                 "must be in [0, 1] (got " + formatJsonNumber(*r.alphaCutoff) + ")");
    }
    if (const JsonValue* x = f.get("bvh_quality"))
        r.bvhQuality = choice(*x, f.path("bvh_quality"), bvhQualityNames());
    if (const JsonValue* x = f.get("robust")) r.robust = boolean(*x, f.path("robust"));
    if (const JsonValue* x = f.get("accel"))
        r.accel = choice(*x, f.path("accel"), acceleratorNames());
    if (const JsonValue* x = f.get("texture_filter"))
        r.textureFilter = choice(*x, f.path("texture_filter"), textureFilterNames());
    if (const JsonValue* x = f.get("texture_footprint"))
        r.textureFootprint = choice(*x, f.path("texture_footprint"), textureFootprintNames());
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
    // Camera messages already start with "camera: ", and are reported at its line.
    const auto make = [&](auto factory) {
        m_scene.camera = callFactory(file(), v.line(), "", factory);
    };
    if (kind == Kind::Perspective) {
        const JsonFields f(*this, v, path, "a perspective camera",
                           {"type", "eye", "look_at", "up", "fov", "near"});
        const Vec3 eye = vec3(f.need("eye"), f.path("eye"));
        const Vec3 lookAt = vec3(f.need("look_at"), f.path("look_at"));
        const Vec3 up = f.has("up") ? direction(*f.get("up"), f.path("up")) : Vec3(0, 1, 0);
        double fov = 45;
        if (const JsonValue* x = f.get("fov")) {
            fov = number(*x, f.path("fov"));
            if (!(fov > 0 && fov < 180))
                fail(*x, f.path("fov"),
                     "must be in (0, 180) degrees (got " + formatJsonNumber(fov) + ")");
        }
        make([&] { return Camera::perspective(eye, lookAt, up, fov); });
    } else {
        const JsonFields f(*this, v, path, "an orthographic camera",
                           {"type", "eye", "direction", "up", "width", "near"});
        const Vec3 eye = vec3(f.need("eye"), f.path("eye"));
        const Vec3 dir = direction(f.need("direction"), f.path("direction"));
        const Vec3 up = f.has("up") ? direction(*f.get("up"), f.path("up")) : Vec3(0, 1, 0);
        const double width = positive(f.need("width"), f.path("width"));
        make([&] { return Camera::orthographic(eye, dir, up, width); });
    }
    // Camera rays start this far from the eye (NFF's "hither").
    if (const JsonValue* n = v.find("near"))
        m_scene.cameraNear = nonNegative(*n, memberPath(path, "near"));
}

void SceneReader::readCameraPath(const JsonValue& v) {
    // Keyframes without "fov" keep the scene camera's.
    const double fov = m_scene.camera.projection() == Camera::Projection::Perspective
                           ? m_scene.camera.vfovDegrees()
                           : 45.0;
    m_scene.cameraPath = parseCameraPath(v, file(), fov);
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
    const JsonFields f(*this, v, path, point ? "a point light" : "a directional light",
                       {"type", point ? "position" : "direction", "color", "intensity"});
    if (point)
        light.position = vec3(f.need("position"), f.path("position"));
    else
        light.direction = normalize(direction(f.need("direction"), f.path("direction")));
    const Color c = f.has("color") ? color(*f.get("color"), f.path("color")) : Color(1, 1, 1);
    const double s =
        f.has("intensity") ? nonNegative(*f.get("intensity"), f.path("intensity")) : 1.0;
    light.intensity = c * s;
    // Each factor is finite, their product need not be: refused here, where
    // it is written, rather than rendered as an infinite light.
    if (!light.intensity.isFinite())
        fail(*f.get("intensity"), f.path("intensity"),
             "color x intensity overflows a double (" + formatJsonNumber(c.maxComponent()) + " x " +
                 formatJsonNumber(s) + "); the product must stay below 1.8e308");
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
    const JsonFields f(*this, v, path, "a material",
                       {"ka", "kd", "ks", "shininess", "highlight", "km", "kt", "ior", "bump",
                        "normal_map", "alpha", "alpha_cutoff"});
    Material m;
    // A colour is a value or a texture ({"texture": ...} or {"checker": ...}),
    // which then stands for the whole colour (its constant is 1).
    const auto colourOrTexture = [&](const char* key, Color& c, uint32_t& map) {
        const JsonValue* x = f.get(key);
        if (!x) return;
        if (!x->isObject()) {
            c = color(*x, f.path(key));
            return;
        }
        const JsonTexture t = readJsonTexture(*this, *x, f.path(key), JsonTextureUse::Colour,
                                              m_textureFiles, m_scene.textures);
        c = Color(1);
        if (t.present) map = t.index;
    };
    colourOrTexture("ka", m.ka, m.maps.ka);
    colourOrTexture("kd", m.kd, m.maps.kd);
    colourOrTexture("ks", m.ks, m.maps.ks);
    if (const JsonValue* x = f.get("shininess")) m.shininess = nonNegative(*x, f.path("shininess"));
    if (const JsonValue* x = f.get("highlight"))
        m.highlight = choice<Highlight>(
            *x, f.path("highlight"),
            {{"blinn-phong", Highlight::BlinnPhong}, {"phong", Highlight::Phong}});
    colourOrTexture("km", m.km, m.maps.km);
    colourOrTexture("kt", m.kt, m.maps.kt);
    if (const JsonValue* x = f.get("ior")) m.ior = positive(*x, f.path("ior"));
    if (const JsonValue* x = f.get("bump")) {
        const JsonTexture t = readJsonTexture(*this, *x, f.path("bump"), JsonTextureUse::Bump,
                                              m_textureFiles, m_scene.textures);
        if (t.present) {
            m.maps.bump = t.index;
            m.maps.bumpScale = t.height;
        }
    }
    if (const JsonValue* x = f.get("normal_map")) {
        const JsonTexture t = readJsonTexture(*this, *x, f.path("normal_map"),
                                              JsonTextureUse::NormalMap, m_textureFiles,
                                              m_scene.textures);
        if (t.present) m.maps.normal = t.index;
    }
    // Cut-outs: "alpha" is a coverage in [0, 1] or a mask texture; where it
    // is below "alpha_cutoff" the surface is a hole.
    const auto unit = [&](const char* key) {
        const JsonValue& x = *f.get(key);
        const double a = number(x, f.path(key));
        if (!(a >= 0 && a <= 1))
            fail(x, f.path(key), "must be in [0, 1] (got " + formatJsonNumber(a) + ")");
        return a;
    };
    if (const JsonValue* x = f.get("alpha")) {
        if (x->isObject()) {
            const JsonTexture t = readJsonTexture(*this, *x, f.path("alpha"), JsonTextureUse::Alpha,
                                                  m_textureFiles, m_scene.textures);
            if (t.present) m.maps.alpha = t.index;
        } else {
            m.alpha = unit("alpha");
        }
    }
    if (f.get("alpha_cutoff")) m.alphaCutoff = unit("alpha_cutoff");
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

    std::string name = path;
    if (const JsonValue* n = v.find("name")) name = string(*n, memberPath(path, "name"));

    const size_t first = m_scene.objects.size();
    if (type == "mesh") {
        const JsonFields f(*this, v, path, "a mesh",
                           {"type", "name", "file", "transform", "material", "sides", "normals"});
        readMeshFile(f, v.find("name") ? name : "");
        setSides(f, first);
        return;
    }
    if (type == "checkerboard") {
        const JsonFields f(
            *this, v, path, "a checkerboard",
            {"type", "name", "origin", "edge_u", "edge_v", "divisions", "materials", "sides"});
        readCheckerboard(f, name);
        setSides(f, first);
        return;
    }
    const std::vector<std::string>* shapeKeys = analyticShapeKeys(type);
    if (!shapeKeys)
        fail(*typeValue, memberPath(path, "type"),
             "unknown object type '" + type +
                 "' (expected 'sphere', 'plane', 'disk', 'cylinder', 'cone', 'quadric', "
                 "'polygon', 'mesh' or 'checkerboard')");
    // Keys shared by the analytic shapes, then the shape's own.
    std::vector<std::string> keys = {"type", "name", "material", "sides"};
    keys.insert(keys.end(), shapeKeys->begin(), shapeKeys->end());
    const JsonFields f(*this, v, path, "a " + type, keys);
    const uint32_t material = resolveMaterial(f.get("material"), f.path("material"));
    addObject(readAnalyticShape(*this, f, type), material, {}, name);
    setSides(f, first);
}

void SceneReader::setSides(const JsonFields& f, size_t firstObject) {
    const JsonValue* given = f.get("sides");
    std::optional<Sidedness> s;
    if (given)
        s = choice<Sidedness>(*given, f.path("sides"),
                              {{"outside", Sidedness::Outside},
                               {"inside", Sidedness::Inside},
                               {"both", Sidedness::Both}});
    for (size_t i = firstObject; i < m_scene.objects.size(); ++i) {
        Object& o = m_scene.objects[i];
        if (s)
            o.shape->setSidedness(*s);
        else if (m_scene.materials[o.material].transmissive())
            o.shape->setSidedness(Sidedness::Both);
    }
}

void SceneReader::addObject(std::shared_ptr<Shape> shape, uint32_t material,
                            std::vector<uint32_t> faceMaterials, const std::string& name) {
    Object obj;
    obj.name = name;
    obj.shape = std::move(shape);
    obj.material = material;
    obj.faceMaterials = std::move(faceMaterials);
    m_scene.objects.push_back(std::move(obj));
}

Transform SceneReader::readRotation(const JsonValue& v, const std::string& path) {
    const JsonFields f(*this, v, path, "a rotation", {"axis", "degrees"});
    const Vec3 axis = direction(f.need("axis"), f.path("axis"));
    const double degrees = number(f.need("degrees"), f.path("degrees"));
    return Transform::rotate(axis, degrees);
}

Transform SceneReader::readTransform(const JsonValue& v, const std::string& path) {
    // Applied as scale, then rotate (list order), then translate.
    const JsonFields f(*this, v, path, "a transform", {"translate", "rotate", "scale"});
    Transform xf;
    if (const JsonValue* s = f.get("scale")) {
        Vec3 k;
        if (s->isNumber())
            k = Vec3(1, 1, 1) * number(*s, f.path("scale"));
        else
            k = vec3(*s, f.path("scale"));
        for (int i = 0; i < 3; ++i)
            if (k[i] == 0) fail(*s, f.path("scale"), "scale factors must not be 0");
        xf = xf.then(Transform::scale(k));
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
        xf = xf.then(Transform::translate(vec3(*t, f.path("translate"))));
    return xf;
}

void SceneReader::readMeshFile(const JsonFields& f, const std::string& name) {
    const JsonValue& fileValue = f.need("file");
    const std::string& file = string(fileValue, f.path("file"));
    if (file.empty()) fail(fileValue, f.path("file"), "must not be empty");
    ObjLoadOptions options;
    options.textureFiles = &m_textureFiles;  // files shared with the JSON materials
    if (const JsonValue* t = f.get("transform"))
        options.transform = readTransform(*t, f.path("transform"));
    if (const JsonValue* n = f.get("normals"))
        options.normals = choice<ObjNormals>(
            *n, f.path("normals"),
            {{"file", ObjNormals::File}, {"flat", ObjNormals::Flat}, {"smooth", ObjNormals::Smooth}});
    std::optional<uint32_t> override;
    if (const JsonValue* m = f.get("material")) override = resolveMaterial(m, f.path("material"));

    const std::string objPath = resolveRelativeTo(this->file(), file);
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

void SceneReader::readCheckerboard(const JsonFields& f, const std::string& name) {
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

    // Square (i, j) takes the first material when i + j is even (the square
    // at the origin corner is m0).
    auto mesh = std::make_shared<TriangleMesh>(makeCheckerboard(origin, eu, ev, nu, nv));
    std::vector<uint32_t> faceMaterials;
    if (m0 != m1)
        for (int j = 0; j < nv; ++j)
            for (int i = 0; i < nu; ++i) {
                const uint32_t m = (i + j) % 2 == 0 ? m0 : m1;
                faceMaterials.push_back(m);
                faceMaterials.push_back(m);
            }
    addObject(mesh, m0, std::move(faceMaterials), name);
}

}  // namespace

Scene loadJsonScene(const std::string& text, const std::string& path) {
    const JsonValue root = parseJson(text, path);
    return SceneReader(path).read(root);
}

}  // namespace raylab

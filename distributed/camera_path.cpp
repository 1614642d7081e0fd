#include "distributed/camera_path.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "renderer/io/errors.h"
#include "renderer/io/text_file.h"

namespace raylab {

namespace {

std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

/// Located errors for one JSON document, in the scene loader's style:
/// "scene.json:12: camera_path.keyframes[1].fov: must be in (0, 180) degrees".
class PathReader {
public:
    explicit PathReader(std::string file) : m_file(std::move(file)) {}

    [[noreturn]] void fail(const JsonValue& v, const std::string& path,
                           const std::string& message) const {
        throw InputError(m_file, v.line(), path + ": " + message);
    }

    /// Rejects members outside `allowed` (typos must not pass silently).
    void checkKeys(const JsonValue& v, const std::string& path, const std::string& what,
                   const std::vector<std::string>& allowed) const {
        if (!v.isObject())
            fail(v, path, "expected an object ({...}) for " + what + ", got " + v.typeName());
        for (size_t i = 0; i < v.size(); ++i) {
            if (std::find(allowed.begin(), allowed.end(), v.key(i)) != allowed.end()) continue;
            std::string list;
            for (const std::string& a : allowed) list += (list.empty() ? "'" : ", '") + a + "'";
            throw InputError(m_file, v.keyLine(i),
                             path + "." + v.key(i) + ": unknown key for " + what + " (expected " +
                                 list + ")");
        }
    }

    const JsonValue& need(const JsonValue& obj, const std::string& path,
                          const std::string& key) const {
        const JsonValue* v = obj.find(key);
        if (!v) fail(obj, path, "missing required key '" + key + "'");
        return *v;
    }

    double number(const JsonValue& v, const std::string& path) const {
        if (!v.isNumber()) fail(v, path, std::string("expected a number, got ") + v.typeName());
        return v.asNumber();
    }

    Vec3 vec3(const JsonValue& v, const std::string& path) const {
        if (!v.isArray() || v.size() != 3)
            fail(v, path,
                 std::string("expected [x, y, z], got ") +
                     (v.isArray() ? "an array of " + std::to_string(v.size()) : v.typeName()));
        Vec3 out;
        for (int i = 0; i < 3; ++i)
            out[i] = number(v.at(size_t(i)), path + "[" + std::to_string(i) + "]");
        return out;
    }

    const std::string& file() const { return m_file; }

private:
    std::string m_file;
};

/// Cubic Hermite basis on [0, 1]: p(t) = h00 p0 + h10 m0 + h01 p1 + h11 m1.
Vec3 hermite(const Vec3& p0, const Vec3& m0, const Vec3& p1, const Vec3& m1, double t) {
    const double t2 = t * t, t3 = t2 * t;
    return p0 * (2 * t3 - 3 * t2 + 1) + m0 * (t3 - 2 * t2 + t) + p1 * (3 * t2 - 2 * t3) +
           m1 * (t3 - t2);
}

Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; }

}  // namespace

CameraPath::CameraPath(std::vector<CameraKeyframe> keys, Interpolation interpolation)
    : m_keys(std::move(keys)), m_interpolation(interpolation) {
    if (m_keys.empty()) throw std::invalid_argument("camera path: no keyframes");
    for (size_t i = 1; i < m_keys.size(); ++i)
        if (!(m_keys[i].frame > m_keys[i - 1].frame))
            throw std::invalid_argument("camera path: keyframe frames must increase");
}

CameraKeyframe CameraPath::at(double frame) const {
    if (frame <= m_keys.front().frame) return m_keys.front();
    if (frame >= m_keys.back().frame) return m_keys.back();
    // Segment i: keys[i].frame <= frame < keys[i+1].frame.
    const auto next = std::upper_bound(
        m_keys.begin(), m_keys.end(), frame,
        [](double f, const CameraKeyframe& k) { return f < double(k.frame); });
    const size_t i = size_t(next - m_keys.begin()) - 1;
    const CameraKeyframe& a = m_keys[i];
    const CameraKeyframe& b = m_keys[i + 1];
    const double h = double(b.frame - a.frame);
    const double t = (frame - a.frame) / h;

    CameraKeyframe k;
    k.frame = int(std::floor(frame));
    k.up = lerp(a.up, b.up, t);
    k.fov = a.fov + (b.fov - a.fov) * t;
    if (m_interpolation == Interpolation::Linear) {
        k.eye = lerp(a.eye, b.eye, t);
        k.lookAt = lerp(a.lookAt, b.lookAt, t);
        return k;
    }
    // Tangents per frame: central differences over the neighbouring keys,
    // one-sided at the ends; scaled by the segment length h for the [0, 1] basis.
    const auto tangent = [&](size_t j, Vec3 CameraKeyframe::*member) {
        const size_t lo = j == 0 ? 0 : j - 1;
        const size_t hi = j + 1 == m_keys.size() ? j : j + 1;
        return (m_keys[hi].*member - m_keys[lo].*member) /
               double(m_keys[hi].frame - m_keys[lo].frame);
    };
    k.eye = hermite(a.eye, tangent(i, &CameraKeyframe::eye) * h, b.eye,
                    tangent(i + 1, &CameraKeyframe::eye) * h, t);
    k.lookAt = hermite(a.lookAt, tangent(i, &CameraKeyframe::lookAt) * h, b.lookAt,
                       tangent(i + 1, &CameraKeyframe::lookAt) * h, t);
    return k;
}

Camera CameraPath::cameraAt(int frame) const {
    const CameraKeyframe k = at(double(frame));
    return Camera::perspective(k.eye, k.lookAt, k.up, k.fov);
}

CameraPath parseCameraPath(const JsonValue& value, const std::string& file, double defaultFov) {
    const PathReader rd(file);
    const std::string path = "camera_path";
    rd.checkKeys(value, path, "a camera path", {"interpolation", "keyframes"});

    CameraPath::Interpolation interpolation = CameraPath::Interpolation::CatmullRom;
    if (const JsonValue* v = value.find("interpolation")) {
        const std::string p = path + ".interpolation";
        if (!v->isString()) rd.fail(*v, p, std::string("expected a string, got ") + v->typeName());
        if (v->asString() == "linear")
            interpolation = CameraPath::Interpolation::Linear;
        else if (v->asString() != "catmull_rom")
            rd.fail(*v, p,
                    "must be one of 'linear', 'catmull_rom' (got '" + terminalSafe(v->asString(), 40) + "')");
    }

    const JsonValue& list = rd.need(value, path, "keyframes");
    const std::string listPath = path + ".keyframes";
    if (!list.isArray() || list.size() == 0)
        rd.fail(list, listPath, "expected a non-empty array of keyframes");
    std::vector<CameraKeyframe> keys;
    for (size_t i = 0; i < list.size(); ++i) {
        const JsonValue& v = list.at(i);
        const std::string kp = listPath + "[" + std::to_string(i) + "]";
        rd.checkKeys(v, kp, "a keyframe", {"frame", "eye", "look_at", "up", "fov"});
        CameraKeyframe k;
        const JsonValue& f = rd.need(v, kp, "frame");
        const double frame = rd.number(f, kp + ".frame");
        if (frame != std::floor(frame) || frame < 0 || frame > kMaxFrame)
            rd.fail(f, kp + ".frame",
                    "must be an integer in [0, " + std::to_string(kMaxFrame) + "] (got " +
                        fmt(frame) + ")");
        k.frame = int(frame);
        if (!keys.empty() && k.frame <= keys.back().frame)
            rd.fail(f, kp + ".frame",
                    "must be greater than the previous keyframe's (" +
                        std::to_string(keys.back().frame) + ")");
        k.eye = rd.vec3(rd.need(v, kp, "eye"), kp + ".eye");
        k.lookAt = rd.vec3(rd.need(v, kp, "look_at"), kp + ".look_at");
        if (const JsonValue* u = v.find("up")) k.up = rd.vec3(*u, kp + ".up");
        k.fov = defaultFov;
        if (const JsonValue* x = v.find("fov")) {
            k.fov = rd.number(*x, kp + ".fov");
            if (!(k.fov > 0 && k.fov < 180))
                rd.fail(*x, kp + ".fov", "must be in (0, 180) degrees (got " + fmt(k.fov) + ")");
        }
        try {
            (void)Camera::perspective(k.eye, k.lookAt, k.up, k.fov);
        } catch (const std::invalid_argument& e) {
            rd.fail(v, kp, e.what());
        }
        keys.push_back(k);
    }
    return CameraPath(std::move(keys), interpolation);
}

std::optional<CameraPath> loadCameraPath(const std::string& scenePath, const Scene& scene) {
    if (lowerExtension(scenePath) != ".json") return std::nullopt;
    const JsonValue root = parseJson(readTextFile(scenePath), scenePath);
    const JsonValue* v = root.find("camera_path");
    if (!v) return std::nullopt;
    const double fov = scene.camera.projection() == Camera::Projection::Perspective
                           ? scene.camera.vfovDegrees()
                           : 45.0;
    return parseCameraPath(*v, scenePath, fov);
}

CameraPath sequenceCameraPath(const std::string& scenePath, const Scene& scene,
                              const FrameRange& frames) {
    std::optional<CameraPath> path = loadCameraPath(scenePath, scene);
    if (!path)
        throw InputError(scenePath, 0,
                         "--frames needs a \"camera_path\" in the scene (a .json scene; see "
                         "docs/distributed.md)");
    // Outside the keyframes the camera holds still: checking the covered
    // frames and one on each side checks them all.
    const int lo = std::max(frames.first, path->keyframes().front().frame - 1);
    const int hi = std::min(frames.last, path->keyframes().back().frame + 1);
    const auto check = [&](int f) {
        try {
            (void)path->cameraAt(f);
        } catch (const std::invalid_argument& e) {
            throw InputError(scenePath, 0,
                             "camera_path: frame " + std::to_string(f) + ": " + e.what());
        }
    };
    check(frames.first);
    check(frames.last);
    for (int f = lo; f <= hi; ++f) check(f);
    return std::move(*path);
}

}  // namespace raylab

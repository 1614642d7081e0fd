#include "renderer/io/json_camera_path.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "renderer/io/errors.h"
#include "renderer/io/json_fields.h"

namespace raylab {

namespace {

/// The scene reader's typed values and located errors, with the wording the
/// camera path's keys and vectors have always had: "scene.json:12:
/// camera_path.keyframes[1].fvo: unknown key for a keyframe (expected ...)".
class PathReader : public JsonFieldReader {
public:
    using JsonFieldReader::JsonFieldReader;

    /// Rejects members outside `allowed` (typos must not pass silently).
    void checkKeys(const JsonValue& v, const std::string& path, const std::string& what,
                   const std::vector<std::string>& allowed) const {
        if (!v.isObject())
            fail(v, path, "expected an object ({...}) for " + what + ", got " + v.typeName());
        for (size_t i = 0; i < v.size(); ++i)
            if (std::find(allowed.begin(), allowed.end(), v.key(i)) == allowed.end())
                fail(v.keyLine(i), memberPath(path, v.key(i)),
                     "unknown key for " + what + " (expected " + quotedList(allowed) + ")");
    }

    const JsonValue& need(const JsonValue& obj, const std::string& path,
                          const std::string& key) const {
        const JsonValue* v = obj.find(key);
        if (!v) fail(obj, path, "missing required key '" + key + "'");
        return *v;
    }

    Vec3 vec3(const JsonValue& v, const std::string& path) const {
        if (!v.isArray() || v.size() != 3)
            fail(v, path,
                 std::string("expected [x, y, z], got ") +
                     (v.isArray() ? "an array of " + std::to_string(v.size()) : v.typeName()));
        Vec3 out;
        for (int i = 0; i < 3; ++i) out[i] = number(v.at(size_t(i)), indexPath(path, size_t(i)));
        return out;
    }
};

}  // namespace

CameraPath parseCameraPath(const JsonValue& value, const std::string& file, double defaultFov) {
    const PathReader rd(file);
    const std::string path = "camera_path";
    rd.checkKeys(value, path, "a camera path", {"interpolation", "keyframes"});

    CameraPath::Interpolation interpolation = CameraPath::Interpolation::CatmullRom;
    if (const JsonValue* v = value.find("interpolation")) {
        const std::string p = memberPath(path, "interpolation");
        const std::string& name = rd.string(*v, p);
        if (name == "linear")
            interpolation = CameraPath::Interpolation::Linear;
        else if (name != "catmull_rom")
            rd.fail(
                *v, p,
                "must be one of 'linear', 'catmull_rom' (got '" + terminalSafe(name, 40) + "')");
    }

    const JsonValue& list = rd.need(value, path, "keyframes");
    const std::string listPath = memberPath(path, "keyframes");
    if (!list.isArray() || list.size() == 0)
        rd.fail(list, listPath, "expected a non-empty array of keyframes");
    std::vector<CameraKeyframe> keys;
    for (size_t i = 0; i < list.size(); ++i) {
        const JsonValue& v = list.at(i);
        const std::string kp = indexPath(listPath, i);
        rd.checkKeys(v, kp, "a keyframe", {"frame", "eye", "look_at", "up", "fov"});
        CameraKeyframe k;
        const JsonValue& f = rd.need(v, kp, "frame");
        const double frame = rd.number(f, kp + ".frame");
        if (frame != std::floor(frame) || frame < 0 || frame > kMaxFrame)
            rd.fail(f, kp + ".frame",
                    "must be an integer in [0, " + std::to_string(kMaxFrame) + "] (got " +
                        formatJsonNumber(frame) + ")");
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
                rd.fail(*x, kp + ".fov",
                        "must be in (0, 180) degrees (got " + formatJsonNumber(k.fov) + ")");
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

}  // namespace raylab

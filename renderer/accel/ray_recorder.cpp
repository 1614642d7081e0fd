#include "renderer/accel/ray_recorder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <tuple>
#include <utility>

#include "geometry/spawn.h"
#include "shading/optics.h"

namespace raylab {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Sub-pixel resolution of the ordering key: 1/1024 pixel.
constexpr double kKeyScale = 1024.0;

/// floor(a / 1024) for negative a too (corner rays can land a hair left of 0).
int64_t floorDiv1024(int64_t a) { return a >= 0 ? a / 1024 : -((-a + 1023) / 1024); }

/// Lexicographic comparison of the bits of two rays: only reached for camera
/// rays that map to the same 1/1024-pixel cell, where it makes the order total.
int compareBits(const RecordedRay& a, const RecordedRay& b) {
    const double ka[7] = {a.ray.o.x, a.ray.o.y, a.ray.o.z, a.ray.d.x, a.ray.d.y, a.ray.d.z, a.tMin};
    const double kb[7] = {b.ray.o.x, b.ray.o.y, b.ray.o.z, b.ray.d.x, b.ray.d.y, b.ray.d.z, b.tMin};
    return std::memcmp(ka, kb, sizeof ka);
}

}  // namespace

RayRecorder::RayRecorder(const Accelerator& inner, const Scene& scene,
                         const RenderOptions& options)
    : m_inner(inner), m_scene(scene), m_options(options) {}

bool RayRecorder::isCameraRay(const Ray& ray) const {
    const CameraFrame& f = m_scene.camera.frame();
    if (m_scene.camera.projection() == Camera::Projection::Perspective) return ray.o == f.eye;
    // Orthographic: direction -w exactly, origin in the eye's image plane (up
    // to the rounding of eye + u·a + v·b).
    const Vec3 rel = ray.o - f.eye;
    return ray.d == -f.w && std::abs(dot(rel, f.w)) <= 1e-9 * (1.0 + length(rel));
}

long RayRecorder::findParent(const std::vector<PathEntry>& path, const Ray& ray, double tMin,
                             const SpawnSettings& spawn) {
    // The integrator spawns every secondary ray with spawnRay(si.p, ng, si.span, dir);
    // recomputing it for each open hit finds the parent exactly (deepest first).
    for (size_t i = path.size(); i-- > 0;) {
        const SpawnedRay s = spawnRay(path[i].p, path[i].ngSide, path[i].span, ray.d, spawn);
        if (s.ray.o == ray.o && s.tMin == tMin) return long(i);
    }
    return -1;
}

void RayRecorder::pushHit(ThreadState& ts, const Ray& ray, const Hit& hit, int depth) const {
    // The same surface data the integrator computes for this hit.
    const SurfaceInteraction si = m_scene.surfaceAt(ray, hit, m_options.accelOptions.intersect);
    const Material& m = m_scene.materials[si.material];
    PathEntry e;
    e.p = si.p;
    e.span = si.span;
    const bool entering = si.frontFace;
    e.ngSide = entering ? si.ng : -si.ng;
    e.nSide = entering ? si.ns : -si.ns;
    e.dirUnit = normalize(ray.d);
    e.etaI = entering ? 1.0 : m.ior;
    e.etaT = entering ? m.ior : 1.0;
    e.depth = depth;
    ts.path.push_back(e);
}

std::optional<Hit> RayRecorder::intersect(const Ray& ray, double tMin, double tMax,
                                          Departure from) const {
    const std::optional<Hit> hit = m_inner.intersect(ray, tMin, tMax, from);
    ThreadState& ts = m_threads.local();
    RecordedRay r;
    r.ray = ray;
    r.tMin = tMin;
    r.tMax = tMax;
    r.hit = hit.has_value();
    r.departed = from.object;
    if (isCameraRay(ray)) {
        ts.path.clear();
        ts.treeStarts.push_back(ts.rays.size());
        r.type = RayType::Camera;
        r.depth = 1;
    } else {
        const long parent = findParent(ts.path, ray, tMin, m_options.spawn);
        if (parent < 0) {
            ++ts.unmatched;
            r.type = RayType::Reflection;
            r.depth = ts.path.empty() ? 2 : ts.path.back().depth + 1;
        } else {
            // Hits above the parent belong to subtrees that are complete.
            ts.path.resize(size_t(parent) + 1);
            PathEntry& p = ts.path.back();
            // Refraction is traced before reflection, so only a first child can be one.
            bool refraction = false;
            if (!p.hadChild) {
                const std::optional<Vec3> t = refract(p.dirUnit, p.nSide, p.etaI, p.etaT);
                refraction = t && *t == ray.d;
            }
            p.hadChild = true;
            r.type = refraction ? RayType::Refraction : RayType::Reflection;
            r.depth = p.depth + 1;
        }
    }
    ts.rays.push_back(r);
    if (hit) pushHit(ts, ray, *hit, r.depth);
    return hit;
}

bool RayRecorder::occluded(const Ray& ray, double tMin, double tMax, Departure from) const {
    const bool result = m_inner.occluded(ray, tMin, tMax, from);
    recordShadowRay(ray, tMin, tMax, from, result);
    return result;
}

Color RayRecorder::transmittance(const Ray& ray, double tMin, double tMax, Departure from) const {
    const Color result = m_inner.transmittance(ray, tMin, tMax, from);
    // Replayed as an occlusion query: bare Embree has no filters.
    recordShadowRay(ray, tMin, tMax, from, result.isBlack());
    return result;
}

void RayRecorder::recordShadowRay(const Ray& ray, double tMin, double tMax, Departure from,
                                  bool result) const {
    ThreadState& ts = m_threads.local();
    RecordedRay r;
    r.ray = ray;
    r.tMin = tMin;
    r.tMax = tMax;
    r.type = RayType::Shadow;
    r.occlusion = true;
    r.hit = result;
    r.departed = from.object;
    // Shadow feelers leave the latest hit, before any of its children.
    const long parent = findParent(ts.path, ray, tMin, m_options.spawn);
    if (parent < 0) {
        ++ts.unmatched;
        r.depth = ts.path.empty() ? 2 : ts.path.back().depth + 1;
    } else {
        r.depth = ts.path[size_t(parent)].depth + 1;
    }
    ts.rays.push_back(r);
}

std::vector<RecordedRay> RayRecorder::takeRays() {
    struct Tree {
        int64_t row, col, qy, qx;  ///< pixel row/column, then position in 1/1024 pixel
        const RecordedRay* begin;
        const RecordedRay* end;
    };
    const Camera& cam = m_scene.camera;
    const CameraFrame& f = cam.frame();
    const double width = m_options.width, height = m_options.height;
    const double aspect = width / height;
    // Inverse of Camera::generateRay: image position (px, py) of a camera ray.
    const auto position = [&](const Ray& ray) {
        double a, b, halfWidth, halfHeight;
        if (cam.projection() == Camera::Projection::Perspective) {
            const double c = -dot(ray.d, f.w);
            a = dot(ray.d, f.u) / c;
            b = dot(ray.d, f.v) / c;
            halfHeight = std::tan(0.5 * cam.vfovDegrees() * kPi / 180.0);
            halfWidth = halfHeight * aspect;
        } else {
            a = dot(ray.o - f.eye, f.u);
            b = dot(ray.o - f.eye, f.v);
            halfWidth = 0.5 * cam.viewWidth();
            halfHeight = halfWidth / aspect;
        }
        return std::make_pair((a / halfWidth + 1.0) * 0.5 * width,
                              (1.0 - b / halfHeight) * 0.5 * height);
    };

    std::vector<Tree> trees;
    size_t total = 0;
    for (ThreadState& ts : m_threads) {
        total += ts.rays.size();
        std::vector<size_t> starts = ts.treeStarts;
        // Rays before the first camera ray (not produced by the integrator)
        // form a tree of their own, keyed by their first ray.
        if (!ts.rays.empty() && (starts.empty() || starts.front() != 0))
            starts.insert(starts.begin(), 0);
        for (size_t k = 0; k < starts.size(); ++k) {
            const size_t b = starts[k];
            const size_t e = k + 1 < starts.size() ? starts[k + 1] : ts.rays.size();
            const auto [px, py] = position(ts.rays[b].ray);
            const auto q = [](double v) {
                return std::isfinite(v) ? int64_t(std::llround(std::clamp(v, -1e12, 1e12) *
                                                               kKeyScale))
                                        : int64_t(0);
            };
            const int64_t qx = q(px), qy = q(py);
            trees.push_back({floorDiv1024(qy), floorDiv1024(qx), qy, qx, ts.rays.data() + b,
                             ts.rays.data() + e});
        }
    }
    // Trees with equal keys start with bit-identical camera rays, so they are
    // identical (the integrator is deterministic): any order among them gives
    // the same output.
    std::sort(trees.begin(), trees.end(), [](const Tree& x, const Tree& y) {
        const auto kx = std::tie(x.row, x.col, x.qy, x.qx);
        const auto ky = std::tie(y.row, y.col, y.qy, y.qx);
        if (kx != ky) return kx < ky;
        return compareBits(*x.begin, *y.begin) < 0;
    });
    std::vector<RecordedRay> out;
    out.reserve(total);
    for (const Tree& t : trees) out.insert(out.end(), t.begin, t.end);
    for (ThreadState& ts : m_threads) {
        ts.rays = {};
        ts.treeStarts = {};
        ts.path.clear();
    }
    return out;
}

uint64_t RayRecorder::unmatchedRays() const {
    uint64_t n = 0;
    for (const ThreadState& ts : m_threads) n += ts.unmatched;
    return n;
}

RayCounters RayRecorder::countRays(const std::vector<RecordedRay>& rays) {
    RayCounters c;
    for (const RecordedRay& r : rays) {
        c.count(r.type, r.depth);
        if (r.type == RayType::Camera && r.hit) ++c.cameraHits;
    }
    return c;
}

}  // namespace raylab

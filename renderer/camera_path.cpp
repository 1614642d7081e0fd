#include "renderer/camera_path.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace raylab {

namespace {

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

}  // namespace raylab

#pragma once
// Whitted material: plain data, no behaviour.

#include <string>

#include "shading/color.h"

namespace raylab {

/// The specular highlight model.
enum class Highlight {
    BlinnPhong,  ///< (N·H)^s: the default
    Phong,       ///< (R·V)^s: NFF/SPD scenes
};

struct Material {
    std::string name;
    Color ka{0, 0, 0};       ///< ambient reflectance (multiplies the scene ambient Ia)
    Color kd{0.8, 0.8, 0.8}; ///< Lambert diffuse reflectance
    Color ks{0, 0, 0};       ///< specular (highlight) reflectance
    double shininess = 32;   ///< specular exponent s
    Highlight highlight = Highlight::BlinnPhong;
    Color km{0, 0, 0};       ///< ideal mirror reflection weight
    Color kt{0, 0, 0};       ///< transmission (refraction) weight
    double ior = 1.0;        ///< index of refraction of the inside medium

    bool reflective() const { return !km.isBlack(); }
    bool transmissive() const { return !kt.isBlack(); }
    bool hasLocalShading() const { return !kd.isBlack() || !ks.isBlack(); }
};

}  // namespace raylab

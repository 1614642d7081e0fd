#pragma once
// Whitted material: plain data, no behaviour.

#include <string>

#include "shading/color.h"

namespace raylab {

struct Material {
    std::string name;
    Color ka{0, 0, 0};       ///< ambient reflectance (multiplies the scene ambient Ia)
    Color kd{0.8, 0.8, 0.8}; ///< Lambert diffuse reflectance
    Color ks{0, 0, 0};       ///< Blinn-Phong specular reflectance
    double shininess = 32;   ///< Blinn-Phong exponent s
    Color km{0, 0, 0};       ///< ideal mirror reflection weight
    Color kt{0, 0, 0};       ///< transmission (refraction) weight
    double ior = 1.0;        ///< index of refraction of the inside medium

    bool reflective() const { return !km.isBlack(); }
    bool transmissive() const { return !kt.isBlack(); }
    bool hasLocalShading() const { return !kd.isBlack() || !ks.isBlack(); }
};

}  // namespace raylab

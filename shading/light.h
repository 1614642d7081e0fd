#pragma once
// Point and directional lights (no attenuation: the classic Whitted model).

#include "geometry/vec.h"
#include "shading/color.h"

namespace raylab {

struct Light {
    enum class Type { Point, Directional };
    Type type = Type::Point;
    Vec3 position{0, 0, 0};   ///< point lights
    Vec3 direction{0, -1, 0}; ///< directional lights: direction the light travels (unit)
    Color intensity{1, 1, 1}; ///< colour × intensity
};

}  // namespace raylab

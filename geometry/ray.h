#pragma once
// A ray o + t·d. The direction need not be unit length: t is measured in units
// of |d| (Embree's convention), and every intersector must honour that.

#include "geometry/vec.h"

namespace raylab {

template <class T>
struct RayT {
    Vec3T<T> o;  ///< origin
    Vec3T<T> d;  ///< direction (not necessarily normalised)

    constexpr Vec3T<T> at(T t) const { return o + d * t; }
};

using Ray = RayT<double>;
using Rayf = RayT<float>;

}  // namespace raylab

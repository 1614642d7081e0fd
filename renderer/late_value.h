#pragma once
// Values built where they are kept, with no copy. LateValue: storage for a
// value built later in a scope, or never, that costs nothing until it is
// built. std::optional would do, but GCC 12's libstdc++ zeroes the whole
// payload of a disengaged optional (a `rep stos` of 120-160 bytes); the
// integrator keeps two such values per hit (a camera ray's footprint, the
// textured optics), which showed in its profile. rebuildInPlace: a value
// rebuilt in the slot that keeps it (see there).

#include <new>
#include <type_traits>
#include <utility>

namespace raylab {

template <class T>
class LateValue {
    static_assert(std::is_trivially_destructible_v<T>, "LateValue never runs a destructor");

public:
    LateValue() {}  // leaves the storage as it is: nothing is read before emplace
    LateValue(const LateValue&) = delete;
    LateValue& operator=(const LateValue&) = delete;

    /// Builds the value from `args` (a prvalue argument is moved in) and returns it.
    template <class... Args>
    T& emplace(Args&&... args) {
        return *::new (static_cast<void*>(&m_value)) T(std::forward<Args>(args)...);
    }

    /// Builds the value as make() returns it, in place: a prvalue result is
    /// constructed directly in this storage (C++17 guaranteed elision), with
    /// no copy of a temporary.
    template <class Make>
    T& emplaceFrom(Make&& make) {
        return *::new (static_cast<void*>(&m_value)) T(std::forward<Make>(make)());
    }

private:
    union {
        T m_value;
    };
};

/// Rebuilds `slot` as make() returns it, in place (C++17 guaranteed
/// elision). `slot = make()` builds the value in a temporary and copies it;
/// the copy reads the temporary right after the call that wrote it, at
/// other widths and offsets than its stores, and such reads wait for the
/// stores to reach the cache (store-to-load forwarding fails). The
/// profile showed these waits on a camera ray and a surface record.
/// For a slot that is a variable, an array element or a member (not a
/// const object, not a base-class part) whose type has no const or
/// reference member: references to the old value then name the new one
/// ([basic.life]). make() must not read the slot.
template <class T, class Make>
T& rebuildInPlace(T& slot, Make&& make) {
    static_assert(std::is_trivially_destructible_v<T>, "the old value is not destroyed");
    static_assert(std::is_trivially_copy_assignable_v<T>,
                  "no const or reference member (old references must name the new value)");
    return *::new (static_cast<void*>(&slot)) T(std::forward<Make>(make)());
}

}  // namespace raylab

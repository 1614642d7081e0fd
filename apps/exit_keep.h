#pragma once
// What a command leaves behind goes back to the kernel with the process.
//
// Why: a render's scene and accelerator are thousands of heap blocks (SPD
// gears: 9,000 polygons with their vertex arrays, grids and chunk boxes, and
// Embree's BVH). Freeing them one by one after the files are committed took
// 3-4 ms of gears' 0.28 s whole process (strace: the last rename to
// exit_group), work whose only result is memory the kernel takes back at exit
// anyway; clang skips it the same way (-disable-free). Only when main() has
// said that the process ends after the command: a test that runs a command
// in-process frees as usual. What is kept stays reachable from a global, so
// leak checkers (valgrind, LeakSanitizer) do not report it.

#include <memory>
#include <type_traits>
#include <utility>

namespace raylab {

/// main() calls this once: the process exits when the command returns.
void setProcessEndsAfterCommand();
bool processEndsAfterCommand();

namespace detail {
void keepUntilExit(std::shared_ptr<void> object);
}

/// Hands `object` over: kept until the process exits when it ends after this
/// command, destroyed here otherwise. Call it only once the command's work is
/// done (the files committed): nothing may use the object afterwards.
template <class T>
void releaseAtExit(T&& object) {
    using Object = std::decay_t<T>;
    if (!processEndsAfterCommand()) {
        Object dropped(std::forward<T>(object));  // destroyed at the end of this scope
        return;
    }
    detail::keepUntilExit(std::make_shared<Object>(std::forward<T>(object)));
}

}  // namespace raylab

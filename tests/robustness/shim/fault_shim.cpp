// LD_PRELOAD shim for the output-commit tests: makes chosen rename(2) calls
// fail, raises a signal just before one, or refuses every link(2), so that
// a test can drive the real raylab binary into the failures a full disk, a
// sticky directory or a file system without hard links would cause.
//
//   RAYLAB_SHIM_FAIL_RENAME=2,3    the 2nd and 3rd rename calls fail with EIO
//   RAYLAB_SHIM_SIGNAL_RENAME=2:15 raise signal 15 just before the 2nd rename
//   RAYLAB_SHIM_FAIL_LINK=1        every link call fails with EPERM
//
// Calls are counted from 1 over the whole process. Built without sanitizers;
// an ASan binary needs ASAN_OPTIONS=verify_asan_link_order=0 to accept it.

#include <dlfcn.h>
#include <signal.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace {

std::atomic<int> g_renames{0};

/// Whether `n` is in the comma-separated list `spec` ("2,3"), before any ':'.
bool listed(const char* spec, int n) {
    if (!spec) return false;
    for (const char* p = spec; *p && *p != ':';) {
        char* end = nullptr;
        const long v = std::strtol(p, &end, 10);
        if (end == p) return false;
        if (v == n) return true;
        p = *end == ',' ? end + 1 : end;
    }
    return false;
}

}  // namespace

extern "C" int rename(const char* from, const char* to) {
    using Rename = int (*)(const char*, const char*);
    static const Rename real = reinterpret_cast<Rename>(dlsym(RTLD_NEXT, "rename"));
    const int n = ++g_renames;
    if (listed(std::getenv("RAYLAB_SHIM_FAIL_RENAME"), n)) {
        errno = EIO;
        return -1;
    }
    const char* sig = std::getenv("RAYLAB_SHIM_SIGNAL_RENAME");
    if (listed(sig, n)) raise(std::atoi(std::strchr(sig, ':') ? std::strchr(sig, ':') + 1 : "15"));
    return real(from, to);
}

extern "C" int link(const char* from, const char* to) {
    using Link = int (*)(const char*, const char*);
    static const Link real = reinterpret_cast<Link>(dlsym(RTLD_NEXT, "link"));
    if (std::getenv("RAYLAB_SHIM_FAIL_LINK")) {
        errno = EPERM;
        return -1;
    }
    return real(from, to);
}

#pragma once
// How much memory this process may still allocate: the tightest of the
// machine's physical memory, the kernel's estimate of what is available, a
// container's cgroup limit and the address-space limit (ulimit -v). The
// memory guard (checkMemoryBudget) compares a render's needs against it, so a
// render that cannot fit is refused up front instead of being OOM-killed or
// failing half-way with bad_alloc.

#include <optional>
#include <string>

namespace raylab {

/// What the system reports; every field is optional (unknown or unlimited).
struct MemoryFacts {
    std::optional<double> physicalBytes;       ///< sysconf(_SC_PHYS_PAGES) x page size
    std::optional<double> availableBytes;      ///< MemAvailable in /proc/meminfo
    std::optional<double> cgroupLimitBytes;    ///< smallest memory.max (v1: limit_in_bytes)
                                               ///< from this process's cgroup up to the root
    std::optional<double> addressSpaceBytes;   ///< RLIMIT_AS soft limit
    double virtualSizeBytes = 0;               ///< this process's address space in use now
};

/// The bound that applies and where it comes from ("physical memory", ...).
struct MemoryLimit {
    double bytes = 0;
    std::string source;  ///< the rest of a sentence: "this machine's memory allows", ...
};

/// Reads the facts of this machine and process (Linux /proc and /sys; a
/// file that cannot be read leaves its field empty).
MemoryFacts readMemoryFacts();

/// The tightest bound: 80% of physical memory, all of MemAvailable, 80% of
/// the cgroup limit, and the address-space limit less what is mapped already
/// and kAddressSpaceReserve. nullopt when nothing is known.
std::optional<MemoryLimit> tightestMemoryLimit(const MemoryFacts& facts);

/// Address space kept back under `ulimit -v` for what the estimate does not
/// count: worker-thread stacks and the allocator's per-thread arenas.
constexpr double kAddressSpaceReserve = 256.0 * (1 << 20);

/// A size in the memory guard's messages: "64 KiB", "2.5 MiB", "393216 MiB"
/// (whole MiB rounded down from 10 MiB on, so a refusal never reads "0 MiB").
std::string describeBytes(double bytes);

/// "MemAvailable:   123456 kB" in a /proc/meminfo text, in bytes.
std::optional<double> parseMemAvailable(const std::string& meminfo);

/// A cgroup memory limit file's value in bytes; nullopt for "max" (v2) or
/// the v1 "unlimited" value (anything at or above 2^62).
std::optional<double> parseCgroupLimit(const std::string& text);

/// This process's cgroup path in a /proc/self/cgroup text: the v2 group
/// ("0::/path") when `controller` is empty, else the v1 hierarchy that holds
/// `controller` ("4:memory:/path"). nullopt when absent or outside this
/// namespace ("/../x").
std::optional<std::string> parseCgroupPath(const std::string& procSelfCgroup,
                                           const std::string& controller);

}  // namespace raylab

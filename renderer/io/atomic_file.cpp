#include "renderer/io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "renderer/io/errors.h"

namespace raylab {

namespace {

// Registry of temporary files that a signal handler may have to delete. A slot
// moves Free -> Filling (owned by one writer, being copied into) -> Ready
// (visible to the handler) -> Free. The handler only reads Ready slots, whose
// bytes are fully written before the release store that publishes them.
enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

static_assert(std::atomic<int>::is_always_lock_free,
              "the signal handler needs lock-free atomics");

struct TempSlot {
    std::atomic<int> state{kFree};
    char path[kMaxTempPathLength];
};

TempSlot g_slots[kMaxInFlightTempFiles];
std::atomic<unsigned> g_counter{0};

/// Records `path`; returns the slot index, or -1 when it cannot be tracked.
int registerTemp(const std::string& path) {
    if (path.size() + 1 > size_t(kMaxTempPathLength)) return -1;
    for (int i = 0; i < kMaxInFlightTempFiles; ++i) {
        int expected = kFree;
        if (g_slots[i].state.compare_exchange_strong(expected, kFilling,
                                                     std::memory_order_acquire)) {
            std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
            g_slots[i].state.store(kReady, std::memory_order_release);
            return i;
        }
    }
    return -1;
}

void unregisterTemp(int slot) {
    if (slot >= 0) g_slots[slot].state.store(kFree, std::memory_order_release);
}

std::string tempNameFor(const std::string& path) {
    // pid keeps concurrent processes apart, the counter concurrent threads.
    return path + ".tmp." + std::to_string(long(::getpid())) + "." +
           std::to_string(g_counter.fetch_add(1, std::memory_order_relaxed));
}

[[noreturn]] void fail(const std::string& path, const std::string& tmp, int slot,
                       const std::string& reason) {
    if (!tmp.empty()) ::unlink(tmp.c_str());
    unregisterTemp(slot);
    throw InputError(path, 0, "cannot write file: " + reason);
}

/// The file that writing `path` must replace. A symbolic link is followed
/// (renaming over the link itself would turn it into a plain file and leave
/// the file it points to stale), relative links against the link's own
/// directory. Anything but a regular file or a new name is refused: renaming
/// over a device such as /dev/full or /dev/null, a FIFO or a socket would
/// replace the node itself, and a directory cannot be replaced.
std::string resolveOutputTarget(const std::string& path) {
    namespace fs = std::filesystem;
    fs::path target = path;
    for (int hops = 0;; ++hops) {
        struct stat st {};
        if (::lstat(target.c_str(), &st) != 0) return target.string();  // a new file
        if (S_ISREG(st.st_mode)) return target.string();
        if (S_ISDIR(st.st_mode)) throw InputError(path, 0, "cannot write file: it is a directory");
        if (!S_ISLNK(st.st_mode))
            throw InputError(path, 0,
                             "cannot write file: not a regular file (a device, FIFO or socket); "
                             "raylab replaces its outputs as a whole");
        if (hops >= 40)  // the kernel's own limit (ELOOP)
            throw InputError(path, 0, "cannot write file: too many levels of symbolic links");
        std::error_code ec;
        const fs::path link = fs::read_symlink(target, ec);
        if (ec) throw InputError(path, 0, "cannot write file: " + ec.message());
        target = link.is_absolute() ? link : target.parent_path() / link;
    }
}

/// Creates the (empty) temporary for `path` and registers it; the caller owns both.
/// The staged path is the resolved target (see resolveOutputTarget).
AtomicFileGroup::Staged createTemp(const std::string& requested) {
    if (requested.empty()) throw InputError("cannot write file: empty output path");
    const std::string path = resolveOutputTarget(requested);
    // A temporary left by a killed run (SIGKILL, OOM) may carry the name this
    // process would pick (same pid in a fresh container, counter from 0): the
    // next name is tried instead of failing after the render.
    for (int attempt = 0;; ++attempt) {
        const std::string tmp = tempNameFor(path);
        // Register before the file exists so there is no window in which an
        // interrupt leaves an unregistered temporary behind.
        const int slot = registerTemp(tmp);
        // Creating the file here (rather than leaving it to the writer) gives a
        // clear error naming the target when its directory is missing or read-only.
        const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            return {path, tmp, slot};
        }
        const int err = errno;
        unregisterTemp(slot);
        if (err != EEXIST || attempt >= 1000)
            throw InputError(requested, 0, std::string("cannot write file: ") + std::strerror(err));
    }
}

}  // namespace

AtomicFileGroup::~AtomicFileGroup() { discard(); }

void AtomicFileGroup::discard() noexcept {
    for (const Staged& s : m_staged) {
        ::unlink(s.tmp.c_str());
        unregisterTemp(s.slot);
    }
    m_staged.clear();
}

void AtomicFileGroup::write(const std::string& path,
                            const std::function<void(const std::string& tmpPath)>& writer) {
    const Staged staged = createTemp(path);
    try {
        writer(staged.tmp);
    } catch (const std::exception& e) {
        fail(path, staged.tmp, staged.slot, e.what());
    } catch (...) {
        fail(path, staged.tmp, staged.slot, "unknown error");
    }
    m_staged.push_back(staged);
}

void AtomicFileGroup::commit() {
    for (size_t i = 0; i < m_staged.size(); ++i) {
        const Staged& s = m_staged[i];
        if (std::rename(s.tmp.c_str(), s.path.c_str()) != 0) {
            const int err = errno;
            const std::string path = s.path;
            m_staged.erase(m_staged.begin(), m_staged.begin() + long(i));  // renamed already
            discard();
            throw InputError(path, 0, std::string("cannot write file: rename failed: ") +
                                          std::strerror(err));
        }
        unregisterTemp(s.slot);
    }
    m_staged.clear();
}

void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writer,
                         AtomicFileGroup* group) {
    if (group) {
        group->write(path, writer);
        return;
    }
    AtomicFileGroup single;
    single.write(path, writer);
    single.commit();
}

void writeFileAtomically(const std::string& path, const std::string& contents,
                         AtomicFileGroup* group) {
    writeFileAtomically(
        path,
        [&](const std::string& tmp) {
            std::FILE* f = std::fopen(tmp.c_str(), "wb");
            if (!f) throw InputError(std::strerror(errno));
            const size_t written = std::fwrite(contents.data(), 1, contents.size(), f);
            const int writeErr = errno;
            // fclose flushes; a full disk may only show up here.
            const bool closed = std::fclose(f) == 0;
            if (written != contents.size())
                throw InputError(std::string("short write: ") + std::strerror(writeErr));
            if (!closed) throw InputError(std::string("close failed: ") + std::strerror(errno));
        },
        group);
}

void checkWritable(const std::string& path) {
    const AtomicFileGroup::Staged probe = createTemp(path);
    ::unlink(probe.tmp.c_str());
    unregisterTemp(probe.slot);
}

void removeInFlightTempFiles() noexcept {
    for (int i = 0; i < kMaxInFlightTempFiles; ++i)
        if (g_slots[i].state.load(std::memory_order_acquire) == kReady)
            ::unlink(g_slots[i].path);
}

int inFlightTempFileCount() noexcept {
    int n = 0;
    for (int i = 0; i < kMaxInFlightTempFiles; ++i)
        if (g_slots[i].state.load(std::memory_order_acquire) == kReady) ++n;
    return n;
}

}  // namespace raylab

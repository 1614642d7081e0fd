#include "renderer/io/atomic_file.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <set>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "renderer/cancel.h"
#include "renderer/io/errors.h"
#include "renderer/io/text_file.h"

namespace raylab {

namespace {

// Registry of temporary files that a signal handler may have to delete. A slot
// moves Free -> Filling (owned by one writer, being copied into) -> Ready
// (visible to the handler) -> Free. The handler only reads Ready slots, whose
// bytes are fully written before the release store that publishes them.
enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

static_assert(std::atomic<int>::is_always_lock_free,
              "the signal handler needs lock-free atomics");

// Every member initialised, so the table is constant-initialised (zero
// bytes in .bss): a constructor run at start-up would touch one page per
// slot, 32 page faults in every process.
struct TempSlot {
    std::atomic<int> state{kFree};
    char path[kMaxTempPathLength]{};
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

/// "<dir>/<name>.<kind>.<pid>.<n>" beside `path`. The name part is cut to
/// kMaxNameStem bytes (at a UTF-8 character boundary) so that a legal
/// 255-byte output name still gets a legal temporary name.
std::string sideName(const std::string& path, const char* kind) {
    constexpr size_t kMaxNameStem = 200;  // + ".tmp." + pid + "." + counter < NAME_MAX
    const std::string dir = directoryOf(path);
    std::string name = path.substr(dir.size());
    if (name.size() > kMaxNameStem) {
        size_t cut = kMaxNameStem;
        while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
        name.resize(cut);
    }
    // pid keeps concurrent processes apart, the counter concurrent threads.
    return dir + name + "." + kind + "." + std::to_string(long(::getpid())) + "." +
           std::to_string(g_counter.fetch_add(1, std::memory_order_relaxed));
}

std::string errnoText(int err) { return std::strerror(err); }

[[noreturn]] void fail(const std::string& path, const std::string& tmp, int slot,
                       const std::string& reason) {
    if (!tmp.empty()) ::unlink(tmp.c_str());
    unregisterTemp(slot);
    throw InputError(path, 0, "cannot write file: " + reason);
}

/// Creates the (empty) temporary for `path` and registers it; the caller owns both.
/// The staged path is the resolved target (see resolveOutputTarget).
AtomicFileGroup::Staged createTemp(const std::string& requested) {
    if (requested.empty()) throw InputError("cannot write file: empty output path");
    throwIfCancelled();  // no new temporary once a stop was requested
    const std::string path = resolveOutputTarget(requested);
    // A temporary left by a killed run (SIGKILL, OOM) may carry the name this
    // process would pick (same pid in a fresh container, counter from 0): the
    // next name is tried instead of failing after the render.
    for (int attempt = 0;; ++attempt) {
        const std::string tmp = sideName(path, "tmp");
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
            throw InputError(requested, 0, "cannot write file: " + errnoText(err));
    }
}

/// Flushes a closed file's data to the disk: a power loss after the rename
/// must not leave a renamed but empty file (the writers close their own streams).
int syncFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return errno;
    const int err = ::fsync(fd) == 0 || errno == EINVAL ? 0 : errno;  // EINVAL: no sync here
    ::close(fd);
    return err;
}

/// A copy of `from` at `to` with `mode`, for file systems without hard links;
/// synced to disk when `sync`.
int copyFile(const std::string& from, const std::string& to, mode_t mode, bool sync) {
    const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
    if (in < 0) return errno;
    const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (out < 0) {
        const int err = errno;
        ::close(in);
        return err;
    }
    int err = 0;
    char buffer[1 << 16];
    while (err == 0) {
        const ssize_t n = ::read(in, buffer, sizeof buffer);
        if (n == 0) break;
        if (n < 0) {
            if (errno != EINTR) err = errno;
            continue;
        }
        for (ssize_t done = 0; done < n && err == 0;) {
            const ssize_t w = ::write(out, buffer + done, size_t(n - done));
            if (w < 0 && errno != EINTR) err = errno;
            if (w > 0) done += w;
        }
    }
    if (sync && err == 0 && ::fsync(out) != 0 && errno != EINVAL) err = errno;
    ::close(in);
    if (::close(out) != 0 && err == 0) err = errno;
    if (err != 0) ::unlink(to.c_str());
    return err;
}

/// Keeps the current content of `target` under a new name beside it, set in
/// `backup`: a hard link (no copy, no data written), or a copy where links
/// are not allowed (synced when `sync`). Returns 0 or the errno of the failure.
int keepAside(const std::string& target, mode_t mode, bool sync, std::string& backup) {
    for (int attempt = 0;; ++attempt) {
        backup = sideName(target, "old");
        if (::link(target.c_str(), backup.c_str()) == 0) return 0;
        int err = errno;
        if (err == EPERM || err == EMLINK || err == EOPNOTSUPP || err == ENOSYS) {
            // No hard links here (FAT, some FUSE) or not for this file
            // (protected_hardlinks: it belongs to someone else): copy instead.
            err = copyFile(target, backup, mode, sync);
            if (err == 0) return 0;
        }
        if (err != EEXIST || attempt >= 1000) {
            backup.clear();
            return err;
        }
    }
}

/// Makes the renames in `dir` ("" for the working directory) durable.
void syncDirectory(const std::string& dir) {
    const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;  // the renames are done; durability is best effort here
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

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
        throwIfCancelled();  // the writer may have run for seconds
    } catch (const Cancelled&) {
        ::unlink(staged.tmp.c_str());
        unregisterTemp(staged.slot);
        throw;
    } catch (const std::exception& e) {
        fail(path, staged.tmp, staged.slot, e.what());
    } catch (...) {
        fail(path, staged.tmp, staged.slot, "unknown error");
    }
    if (m_durability == Durability::PowerLoss)
        if (const int err = syncFile(staged.tmp))
            fail(path, staged.tmp, staged.slot, "cannot flush to disk: " + errnoText(err));
    m_staged.push_back(staged);
}

std::string AtomicFileGroup::rollBack(const std::vector<Replacement>& plan, size_t renamed) noexcept {
    // Newest first; a kept file is renamed back (so it is gone), or removed
    // when its target was never replaced, or kept when the restore failed.
    std::string problems;
    for (size_t i = plan.size(); i-- > 0;) {
        const Replacement& r = plan[i];
        if (i >= renamed) {
            if (!r.backup.empty()) ::unlink(r.backup.c_str());
            continue;
        }
        const bool restored = r.backup.empty() ? ::unlink(r.target.c_str()) == 0
                                               : ::rename(r.backup.c_str(), r.target.c_str()) == 0;
        if (!restored)
            problems += "; " + r.target + " could not be restored (" + errnoText(errno) +
                        (r.backup.empty() ? ")" : "), its old content is in " + r.backup);
    }
    return problems;
}

void AtomicFileGroup::commit() {
    // Nothing is touched yet: a stop requested while the files were written
    // ends here with every target as it was.
    if (cancelRequested()) {
        discard();
        throw Cancelled(cancelSignal());
    }
    // 1. Keep every existing target aside (and copy its mode to the new file),
    //    so that a failed rename can put back the ones already replaced.
    std::vector<Replacement> plan;
    const auto abandon = [&](std::string path, const std::string& reason) {  // a copy: discard() frees it
        rollBack(plan, 0);
        discard();
        throw InputError(path, 0, "cannot write file: " + reason + "; no output was changed");
    };
    for (const Staged& s : m_staged) {
        Replacement r{s.path, ""};
        struct stat st {};
        if (::lstat(s.path.c_str(), &st) == 0) {
            if (!S_ISREG(st.st_mode))
                abandon(s.path, "it is no longer a regular file (it changed during the render)");
            if (::chmod(s.tmp.c_str(), st.st_mode & 07777) != 0)
                abandon(s.path, "cannot give the new file the old one's mode: " + errnoText(errno));
            if (const int err = keepAside(s.path, st.st_mode & 07777,
                                          m_durability == Durability::PowerLoss, r.backup))
                abandon(s.path, "cannot keep the old file aside until the new one is in place: " +
                                    errnoText(err));
        } else if (errno != ENOENT) {
            abandon(s.path, errnoText(errno));
        }
        plan.push_back(r);
    }

    // 2. The renames. A forced exit waits for this section to end (cancel.h).
    {
        const CommitSection section;
        for (size_t i = 0; i < m_staged.size(); ++i) {
            if (::rename(m_staged[i].tmp.c_str(), m_staged[i].path.c_str()) != 0) {
                const int err = errno;
                const std::string path = m_staged[i].path;
                const std::string problems = rollBack(plan, i);
                m_staged.erase(m_staged.begin(), m_staged.begin() + long(i));  // renamed
                discard();
                throw InputError(path, 0,
                                 "cannot write file: rename failed: " + errnoText(err) +
                                     (problems.empty() ? "; no output was changed" : problems));
            }
            unregisterTemp(m_staged[i].slot);
        }
        // A stop that arrived during the renames undoes them: an interrupted
        // run never leaves its outputs replaced.
        if (cancelRequested()) {
            const std::string problems = rollBack(plan, plan.size());
            const std::string path = m_staged.front().path;
            m_staged.clear();
            if (!problems.empty())  // the rare case where "nothing written" would be untrue
                throw InputError(path, 0, "interrupted while replacing the outputs" + problems);
            throw Cancelled(cancelSignal());
        }
        // 3. Every target is in place: make the renames durable if asked, drop
        //    the old files (still in the section: a forced exit leaves no kept file).
        if (m_durability == Durability::PowerLoss) {
            std::set<std::string> directories;
            for (const Staged& s : m_staged) directories.insert(directoryOf(s.path));
            for (const std::string& dir : directories) syncDirectory(dir);
        }
        for (const Replacement& r : plan)
            if (!r.backup.empty()) ::unlink(r.backup.c_str());
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

void writeFileAtomically(const std::string& path, const void* bytes, size_t size,
                         AtomicFileGroup* group) {
    writeFileAtomically(
        path,
        [&](const std::string& tmp) {
            std::FILE* f = std::fopen(tmp.c_str(), "wb");
            if (!f) throw InputError(std::strerror(errno));
            const size_t written = std::fwrite(bytes, 1, size, f);
            const int writeErr = errno;
            // fclose flushes; a full disk may only show up here.
            const bool closed = std::fclose(f) == 0;
            if (written != size)
                throw InputError(std::string("short write: ") + std::strerror(writeErr));
            if (!closed) throw InputError(std::string("close failed: ") + std::strerror(errno));
        },
        group);
}

void writeFileAtomically(const std::string& path, const std::string& contents,
                         AtomicFileGroup* group) {
    writeFileAtomically(path, contents.data(), contents.size(), group);
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

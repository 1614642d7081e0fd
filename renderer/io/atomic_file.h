#pragma once
// Atomic file output: every image and document raylab writes goes to a
// temporary file beside the target and is renamed over it only when complete,
// so an interrupted or failed write never leaves a truncated file behind.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace raylab {

/// \brief Files that replace their targets together: a render's EXR, PNG and
/// statistics either all appear or none is touched.
///
/// write() fills a temporary beside each target (as writeFileAtomically
/// does), and with Durability::PowerLoss flushes it to disk (fsync). commit() then
///  1. stops at once, touching nothing, when a stop was requested (cancel.h);
///  2. keeps every existing target aside under a hard link beside it (a copy
///     where hard links are refused) and gives the new file its permission bits;
///  3. renames the temporaries over the targets, in the order written;
///  4. when a rename fails, or a stop arrives during the renames, puts the
///     targets already replaced back (renames the kept files back, removes
///     the ones that did not exist) and throws;
///  5. otherwise (Durability::PowerLoss: after syncing the directories)
///     removes the kept files.
/// What POSIX does not allow: the group is not one atomic step for an
/// observer (another process can see the first file replaced before the
/// second), a restore can itself fail (the message then names the kept file),
/// and the owner and group of a replaced file become this process's.
/// A group destroyed before commit() removes every temporary.
class AtomicFileGroup {
public:
    /// What the committed files survive. Temp + rename alone is atomic
    /// against a crashed or killed process and against concurrent readers;
    /// only a power loss (or kernel crash) needs the data on the disk, which
    /// costs two fsyncs per output (~0.1 s each on a busy disk).
    enum class Durability {
        ProcessCrash,  ///< no fsync (the default)
        PowerLoss,     ///< fsync each temporary before its rename, each directory after
    };
    explicit AtomicFileGroup(Durability durability = Durability::ProcessCrash)
        : m_durability(durability) {}
    AtomicFileGroup(const AtomicFileGroup&) = delete;
    AtomicFileGroup& operator=(const AtomicFileGroup&) = delete;
    ~AtomicFileGroup();

    /// \throws InputError(path, 0, reason) like writeFileAtomically; files
    ///         written before stay staged until commit() or destruction.
    /// \throws Cancelled when a stop was requested (the temporary is removed).
    void write(const std::string& path,
               const std::function<void(const std::string& tmpPath)>& writer);
    /// \throws InputError(path, 0, reason) when a target cannot be kept aside
    ///         or a rename fails: every target is then as it was (or the
    ///         message says which could not be restored), no temporary is left.
    /// \throws Cancelled when a stop was requested before or during the renames.
    void commit();

    /// One staged file (public for the helpers in atomic_file.cpp).
    struct Staged {
        std::string path, tmp;
        int slot;  ///< removeInFlightTempFiles() registry slot, -1 if untracked
    };

private:
    /// A target and the name its old content was kept under ("" when it was new).
    struct Replacement {
        std::string target, backup;
    };
    /// Undoes the first `renamed` replacements of `plan` and removes the kept
    /// files of the others; returns "" or what could not be undone.
    static std::string rollBack(const std::vector<Replacement>& plan, size_t renamed) noexcept;
    void discard() noexcept;
    Durability m_durability;
    std::vector<Staged> m_staged;
};

/// \brief The file that writing `path` replaces: `path` itself, or the file a
/// symbolic link at `path` points to (followed up to 40 times, relative links
/// against the link's directory; the link stays a link).
/// \throws InputError(path, 0, ...) when it is a directory, a device, FIFO or
///         socket (renaming over it would replace the node itself), or a loop.
std::string resolveOutputTarget(const std::string& path);

/// \brief Writes `path` atomically.
///
/// Creates "<name>.tmp.<pid>.<n>" in the same directory (so the final rename
/// never crosses a file system; a name over 200 bytes is cut there, so the
/// temporary's name stays within NAME_MAX), calls `writer(tmpPath)` to fill it, then
/// renames it over `path` (no fsync: see AtomicFileGroup::Durability). A symbolic link is followed: the file it points to
/// is replaced and the link stays. A `path` that names a directory, device,
/// FIFO or socket is refused before anything is written (renaming over it
/// would replace the node). While the write is in progress the temporary name
/// is recorded so removeInFlightTempFiles() can delete it from a signal handler.
/// \param path   the final file name
/// \param writer fills the file named by its argument (it may reopen and
///               truncate it; the file already exists and is empty)
/// \throws InputError(path, 0, reason) when the temporary file cannot be
///         created, the writer throws, or the rename fails; the temporary file
///         is removed and `path` is left untouched in every case.
/// \param group  when given, the file is staged in it instead: it appears at
///               group->commit(), together with the group's other files
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writer,
                         AtomicFileGroup* group = nullptr);

/// \brief Writes the bytes of `contents` to `path` atomically (see above).
/// \throws InputError(path, 0, reason) on any failure.
void writeFileAtomically(const std::string& path, const std::string& contents,
                         AtomicFileGroup* group = nullptr);
/// The same for `size` bytes at `bytes`.
void writeFileAtomically(const std::string& path, const void* bytes, size_t size,
                         AtomicFileGroup* group = nullptr);

/// \brief Fails early, before a long render, when `path` cannot be written:
/// its directory is missing or read-only, or `path` is a directory, device,
/// FIFO or socket (symbolic links are followed). Creates
/// and removes a temporary beside it; `path` itself is not touched.
/// \throws InputError(path, 0, "cannot write file: reason")
void checkWritable(const std::string& path);

/// \brief Unlinks every temporary file of a write that is still in progress.
///
/// Async-signal-safe (lock-free atomics, fixed buffers and unlink(2) only), so
/// a SIGINT/SIGTERM handler may call it before _exit. At most
/// kMaxInFlightTempFiles concurrent writes with paths shorter than
/// kMaxTempPathLength are tracked; a write beyond that limit still works but is
/// not cleaned up by this function.
void removeInFlightTempFiles() noexcept;

/// \brief Number of temporary files currently registered (for tests).
int inFlightTempFileCount() noexcept;

constexpr int kMaxInFlightTempFiles = 32;
constexpr int kMaxTempPathLength = 4096;

}  // namespace raylab

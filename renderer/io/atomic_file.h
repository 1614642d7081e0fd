#pragma once
// Atomic file output: every image and document raylab writes goes to a
// temporary file beside the target and is renamed over it only when complete,
// so an interrupted or failed write never leaves a truncated file behind.

#include <functional>
#include <string>
#include <vector>

namespace raylab {

/// \brief Files that replace their targets together: a render's EXR, PNG and
/// statistics either all appear or none is touched.
///
/// write() fills a temporary beside each target (as writeFileAtomically
/// does); commit() renames them all, in the order written. A group destroyed
/// before commit() (a later write failed, an exception) removes every
/// temporary and leaves every target as it was. The renames themselves stay
/// within each target's directory, where they do not fail in practice.
class AtomicFileGroup {
public:
    AtomicFileGroup() = default;
    AtomicFileGroup(const AtomicFileGroup&) = delete;
    AtomicFileGroup& operator=(const AtomicFileGroup&) = delete;
    ~AtomicFileGroup();

    /// \throws InputError(path, 0, reason) like writeFileAtomically; files
    ///         written before stay staged until commit() or destruction.
    void write(const std::string& path,
               const std::function<void(const std::string& tmpPath)>& writer);
    /// \throws InputError(path, 0, reason) when a rename fails; the
    ///         temporaries not yet renamed are removed.
    void commit();

    /// One staged file (public for the helpers in atomic_file.cpp).
    struct Staged {
        std::string path, tmp;
        int slot;  ///< removeInFlightTempFiles() registry slot, -1 if untracked
    };

private:
    void discard() noexcept;
    std::vector<Staged> m_staged;
};

/// \brief Writes `path` atomically.
///
/// Creates "<path>.tmp.<pid>.<n>" in the same directory (so the final rename
/// never crosses a file system), calls `writer(tmpPath)` to fill it, then
/// renames it over `path`. A symbolic link is followed: the file it points to
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

#pragma once
// Atomic file output: every image and document raylab writes goes to a
// temporary file beside the target and is renamed over it only when complete,
// so an interrupted or failed write never leaves a truncated file behind.

#include <functional>
#include <string>

namespace raylab {

/// \brief Writes `path` atomically.
///
/// Creates "<path>.tmp.<pid>.<n>" in the same directory (so the final rename
/// never crosses a file system), calls `writer(tmpPath)` to fill it, then
/// renames it over `path`. While the write is in progress the temporary name
/// is recorded so removeInFlightTempFiles() can delete it from a signal handler.
/// \param path   the final file name
/// \param writer fills the file named by its argument (it may reopen and
///               truncate it; the file already exists and is empty)
/// \throws InputError(path, 0, reason) when the temporary file cannot be
///         created, the writer throws, or the rename fails; the temporary file
///         is removed and `path` is left untouched in every case.
void writeFileAtomically(const std::string& path,
                         const std::function<void(const std::string& tmpPath)>& writer);

/// \brief Writes the bytes of `contents` to `path` atomically (see above).
/// \throws InputError(path, 0, reason) on any failure.
void writeFileAtomically(const std::string& path, const std::string& contents);

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

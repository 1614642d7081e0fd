#pragma once
// The process-wide request to stop: set once by a signal handler (SIGINT,
// SIGTERM, SIGHUP), polled by every long-running phase (file reading, the
// Embree build, the per-pixel loop, the output commit). Polling is a relaxed
// atomic load, cheap enough for a per-pixel or per-ray check.

#include <atomic>
#include <exception>

namespace raylab {

/// The flag itself, for APIs that take `const std::atomic<bool>*` (render(),
/// the distributed renderer, the accuracy sweep).
extern std::atomic<bool> g_cancelRequested;

/// Asks every phase to stop. Async-signal-safe; the first signal number wins.
void requestCancel(int signal) noexcept;

/// Whether a stop was requested (relaxed load: a check point may run late by
/// one pixel or one chunk, never miss the request).
inline bool cancelRequested() noexcept {
    return g_cancelRequested.load(std::memory_order_relaxed);
}

/// The signal that asked for the stop (0: none, or a request without one).
int cancelSignal() noexcept;

/// Thrown by check points outside the render loop (reading, building,
/// writing) so the run unwinds, removes its temporaries and exits 128+signal.
class Cancelled : public std::exception {
public:
    explicit Cancelled(int signal) : m_signal(signal) {}
    int signal() const { return m_signal; }
    const char* what() const noexcept override { return "interrupted"; }

private:
    int m_signal;
};

/// Throws Cancelled when a stop was requested.
void throwIfCancelled();

/// \brief Marks the renames of an output commit. While one is alive, a stop
/// must not end the process from outside (a forced exit would leave the
/// output group half replaced): the commit itself checks cancelRequested()
/// once all renames are done and rolls them back.
class CommitSection {
public:
    CommitSection() noexcept;
    ~CommitSection();
    CommitSection(const CommitSection&) = delete;
    CommitSection& operator=(const CommitSection&) = delete;
};

/// Whether a CommitSection is alive (read by the forced-exit path).
bool commitInProgress() noexcept;

}  // namespace raylab

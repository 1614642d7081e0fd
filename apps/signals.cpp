#include "apps/signals.h"

#include <fcntl.h>
#include <pthread.h>
#include <semaphore.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <mutex>
#include <thread>

#include "renderer/cancel.h"
#include "renderer/io/atomic_file.h"

namespace raylab {

namespace {

sem_t g_wake;                         // posted by the handler (sem_post is async-signal-safe)
std::atomic<int> g_signalsSeen{0};
std::atomic<bool> g_exitClaimed{false};
std::atomic<bool> g_watchdogRunning{false};
std::mutex g_outcomeMutex;
std::string g_outcome = "no output written";

extern "C" void onStopSignal(int sig) {
    const int saved = errno;
    requestCancel(sig);
    const int seen = g_signalsSeen.fetch_add(1) + 1;
    ::sem_post(&g_wake);
    // Without a watchdog (no thread could be started), a second signal still
    // ends the process, with async-signal-safe calls only.
    if (seen >= 2 && !g_watchdogRunning.load() && !commitInProgress() &&
        !g_exitClaimed.exchange(true)) {
        removeInFlightTempFiles();
        static const char kLine[] = "raylab: interrupted by a second signal\n";
        [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, kLine, sizeof kLine - 1);
        ::_exit(128 + sig);
    }
    errno = saved;
}

/// The signal that stopped the run; a stop without one (another MPI rank
/// cancelled the frame) counts as SIGINT, as it always has.
int stopSignal() { return cancelSignal() != 0 ? cancelSignal() : SIGINT; }

const char* signalName(int sig) {
    switch (sig) {
        case SIGINT: return "SIGINT";
        case SIGTERM: return "SIGTERM";
        case SIGHUP: return "SIGHUP";
        default: return "a signal";
    }
}

std::string interruptLine() {
    std::lock_guard<std::mutex> lock(g_outcomeMutex);
    return std::string("raylab: interrupted by ") + signalName(stopSignal()) + ": " + g_outcome + "\n";
}

/// Waits for `seconds`, or less when another signal is posted.
void waitOrSecondSignal(double seconds) {
    timespec deadline {};
    ::clock_gettime(CLOCK_REALTIME, &deadline);
    const long nanos = long(seconds * 1e9);
    deadline.tv_sec += (deadline.tv_nsec + nanos) / 1000000000L;
    deadline.tv_nsec = (deadline.tv_nsec + nanos) % 1000000000L;
    while (::sem_timedwait(&g_wake, &deadline) != 0 && errno == EINTR) {
    }
}

extern "C" void* watchdog(void*) {
    while (::sem_wait(&g_wake) != 0) {
    }
    // The phases get a moment to stop at their check points (then main
    // claims the exit); a second signal cuts it short.
    if (g_signalsSeen.load() < 2) waitOrSecondSignal(kForcedExitDelaySeconds);
    // Never in the middle of renaming an output group: the commit undoes its
    // renames when it sees the request, and then the exit is safe.
    while (commitInProgress()) std::this_thread::sleep_for(std::chrono::milliseconds(5));
    if (g_exitClaimed.exchange(true)) return nullptr;
    removeInFlightTempFiles();
    const std::string line = interruptLine();
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, line.data(), line.size());
    ::_exit(128 + stopSignal());
}

/// Starts the watchdog on a small stack (it counts against `ulimit -v`); the
/// process goes on without one when no thread can be started.
void startWatchdog() {
    // Test seam: RAYLAB_TEST_NO_WATCHDOG=1 leaves only the check points, so a
    // test can show that a phase stops by itself (docs/robustness.md).
    if (const char* off = std::getenv("RAYLAB_TEST_NO_WATCHDOG"); off && *off == '1') return;
    pthread_attr_t attr;
    if (::pthread_attr_init(&attr) != 0) return;
    ::pthread_attr_setstacksize(&attr, 256 * 1024);
    ::pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
    pthread_t thread;
    if (::pthread_create(&thread, &attr, watchdog, nullptr) == 0) g_watchdogRunning.store(true);
    ::pthread_attr_destroy(&attr);
}

/// Opens /dev/null on 0, 1 or 2 when closed (`raylab ... >&-`).
void openMissingStandardStreams() {
    for (int fd = 0; fd <= 2; ++fd)
        if (::fcntl(fd, F_GETFD) == -1 && errno == EBADF) {
            const int opened = ::open("/dev/null", O_RDWR);
            if (opened >= 0 && opened != fd) {  // lower descriptors were open already
                ::dup2(opened, fd);
                ::close(opened);
            }
        }
}

}  // namespace

void installSignalHandling() {
    openMissingStandardStreams();
    ::sem_init(&g_wake, 0, 0);
    struct sigaction sa {};
    sa.sa_handler = onStopSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;  // reads and writes go on; the check points stop the work
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(sig, &sa, nullptr);
    std::signal(SIGPIPE, SIG_IGN);
    startWatchdog();
}

void setInterruptOutcome(const std::string& outcome) {
    std::lock_guard<std::mutex> lock(g_outcomeMutex);
    g_outcome = outcome;
}

int reportInterrupted() {
    if (!g_exitClaimed.exchange(true)) {
        const std::string line = interruptLine();
        [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, line.data(), line.size());
    }
    return 128 + stopSignal();
}

void claimExit() { g_exitClaimed.store(true); }

}  // namespace raylab

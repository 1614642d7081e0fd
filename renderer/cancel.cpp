#include "renderer/cancel.h"

namespace raylab {

std::atomic<bool> g_cancelRequested{false};

namespace {

std::atomic<int> g_signal{0};
std::atomic<int> g_commits{0};

static_assert(std::atomic<int>::is_always_lock_free && std::atomic<bool>::is_always_lock_free,
              "set from signal handlers: the atomics must be lock-free");

}  // namespace

void requestCancel(int signal) noexcept {
    int none = 0;
    g_signal.compare_exchange_strong(none, signal);
    g_cancelRequested.store(true);
}

int cancelSignal() noexcept { return g_signal.load(); }

void throwIfCancelled() {
    if (cancelRequested()) throw Cancelled(cancelSignal());
}

CommitSection::CommitSection() noexcept { g_commits.fetch_add(1); }
CommitSection::~CommitSection() { g_commits.fetch_sub(1); }

bool commitInProgress() noexcept { return g_commits.load() > 0; }

}  // namespace raylab

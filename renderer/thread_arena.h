#pragma once
// Running a parallel step on at most n threads without throttling the process.

#include <tbb/info.h>
#include <tbb/task_arena.h>

namespace raylab {

/// f() with its TBB work limited to `threads` threads: in the default arena
/// when threads <= 0 or at least TBB's default concurrency (a larger arena
/// only makes TBB warn on stderr that it cannot have the workers), else in
/// an arena of that size. Unlike tbb::global_control, other work in the
/// process keeps its threads.
template <class F>
auto runWithThreads(int threads, F&& f) -> decltype(f()) {
    if (threads <= 0 || threads >= tbb::info::default_concurrency()) return f();
    tbb::task_arena arena(threads);
    return arena.execute(f);
}

}  // namespace raylab

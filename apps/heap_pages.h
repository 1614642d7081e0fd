#pragma once
// The malloc heaps of the main thread and of TBB's workers on transparent
// huge pages.
//
// Why: on this project's VMs a 4 KiB page fault costs ~10-13 us and the
// faults of one process are serial (docs/benchmarks.md, bar 3). glibc serves
// every block from 128 KiB up with a fresh mmap of small pages, so the scene
// loader's vectors, OpenEXR's line buffers and compressors (~3.4 MB per EXR)
// and the rest fault in 4 KiB at a time, and a freed block goes back to the
// kernel, so the next one faults again. With a fixed threshold of 32 MiB those
// blocks come from the heap instead, freed memory stays there for the next
// one, and the heap's first 64 MiB are advised as huge pages: one fault per
// 2 MiB.
//
// A heap's head, below its first 2 MiB boundary, would stay on small pages
// (a 2 MiB page needs its whole aligned range untouched when it is first
// touched): it is reserved by a block that is never touched, so allocations
// start on the boundary. A TBB worker's allocations come from an arena of its
// own, which glibc grows a page at a time; useHugePageWorkerHeaps grows it
// once, advises it and reserves its head the same way (gears' polygons are
// built on a worker). Together: gears' page faults 1,700-1,860 -> ~560 a
// process, balls' (EXR) 1,430-1,710 -> ~600 (docs/benchmarks.md).

namespace raylab {

/// Once, at the start of main (before any thread exists). Only advice and
/// malloc tuning: if the heap cannot grow (ulimit -v), nothing changes.
void useHugePageHeap();

/// From the first call on, for the rest of the process, every TBB worker
/// that joins the calling thread's arena puts its malloc arena on huge pages
/// when it first enters (address space only: the memory is touched, and
/// counted, as it is used). Called by the commands that render rather than
/// in main, so that commands without TBB (--help, --version) do not start its
/// scheduler. Idempotent.
void useHugePageWorkerHeaps();

}  // namespace raylab

#pragma once
// The main thread's malloc heap on transparent huge pages.
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

namespace raylab {

/// Once, at the start of main (before any thread exists). Only advice and
/// malloc tuning: if the heap cannot grow (ulimit -v), nothing changes.
void useHugePageHeap();

}  // namespace raylab

#!/usr/bin/env python3
"""Whole-process speed-up of `raylab render` from 1 to N threads (issue 20, bar 3).

    scripts/bench-threads.py [--repeats 7] [--threads 1,2] [--raylab build/bin/raylab[,OTHER]]
                             [--nice N] [--output exr] [--per-cpu] -- SCENE [render flags ...]

Runs `raylab render SCENE FLAGS -o OUT.exr --quiet --threads T`
(--output png: OUT.png, the 8-bit output alone)
for every thread count T (and every binary given), interleaved: each round runs
every command once, in an order that rotates between rounds, after one untimed
warm-up of each. Prints, per binary and thread count, the medians of the
process's wall-clock time, its CPU time (user + system), and raylab's own
--stats phases (render, write; from untimed runs with --stats S.json after
each round's timed ones: the statistics file, which lists every object, is not
part of the render), the speed-up of the wall time against the
first thread count, and the write as a share of the render; then the same
speed-up round by round (each round's first-count run against its N-thread
run), median and range: less exposed to the machine's drift than the ratio of
two medians, and its range shows how far one run can be trusted. The "rest"
column is the wall time outside the render and the write (start-up, loading,
the build, the buffers, the output's commit, exit; each round's timed run less
its --stats run's phases): the serial part of the process that more threads
do not shorten. A last line per thread count gives the time the N-thread
process would have to lose to reach --target (default 1.8, bar 3) against the
first thread count's wall time, with its render and write as they scale. --nice N: each
command in a session of its own at niceness N (see scripts/bench-povray.py:
plain nice does not help against other sessions' jobs), set from this script
right after the spawn so that the spawn stays a cheap vfork. --per-cpu: each
round also runs the first thread count's command pinned to each CPU in turn
(the affinity is inherited from this script, set around the spawn), and the
table gets one row per CPU. On a VM whose CPUs are not equally fast at a
given moment (docs/benchmarks.md, session 2026-12-06 14:38) a one-thread
run's time depends on where it lands, and the two-thread render is bounded by
the CPUs' summed rates: the last line gives that bound, 1 / (1/r0 + 1/r1) for
the pinned renders r0, r1. A benchmark, not a
test: it asserts nothing.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

NICE = None


def set_priority(pid):
    """The child's session (its autogroup) and its first thread at niceness NICE; threads
    it starts later inherit it. Done from here, not in a preexec_fn: any preexec_fn makes
    Python fork() the interpreter instead of vfork(), ~20 ms per run on this VM, counted
    in every wall time and none of it raylab's."""
    try:
        with open("/proc/%d/autogroup" % pid, "w") as fh:
            fh.write(str(NICE))
    except OSError:
        pass
    try:
        os.setpriority(os.PRIO_PROCESS, pid, NICE)
    except OSError:
        pass


def run(cmd, cpu=None):
    if cpu is not None:
        everywhere = os.sched_getaffinity(0)
        os.sched_setaffinity(0, {cpu})  # the child inherits it at the spawn
    t0 = time.perf_counter()
    try:
        proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                stderr=subprocess.PIPE, start_new_session=NICE is not None)
    finally:
        if cpu is not None:
            os.sched_setaffinity(0, everywhere)
    if NICE is not None:
        set_priority(proc.pid)
    _, status, ru = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("bench-threads: %s failed: %s" % (" ".join(cmd), proc.stderr.read().decode(errors="replace")))
    return wall, ru.ru_utime + ru.ru_stime


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--threads", default="1,2")
    top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap.add_argument("--raylab", default=os.path.join(top, "build", "bin", "raylab"),
                    help="comma-separated binaries (each timed in the same rounds)")
    ap.add_argument("--nice", type=int)
    ap.add_argument("--output", default="exr", help="the output's extension (exr, png, ...)")
    ap.add_argument("--target", type=float, default=1.8, help="the speed-up the last lines measure against")
    ap.add_argument("--per-cpu", action="store_true",
                    help="also run the first thread count pinned to each CPU (a row per CPU)")
    ap.add_argument("render", nargs="+", help="SCENE and render flags (after --)")
    args = ap.parse_args()
    global NICE
    NICE = args.nice
    threads = [int(t) for t in args.threads.split(",")]
    binaries = [os.path.abspath(b) for b in args.raylab.split(",")]
    work = tempfile.mkdtemp(prefix="bench-threads-")
    cpus = sorted(os.sched_getaffinity(0)) if args.per_cpu else []
    # A case is (binary, threads, CPU it is pinned to or None).
    cases = [(b, t, None) for b in binaries for t in threads]
    cases += [(b, threads[0], c) for b in binaries for c in cpus]

    def cmd(case, stats=False):
        b, t, _ = case
        return ([b, "render"] + args.render + ["-o", os.path.join(work, "out." + args.output), "--quiet",
                                               "--threads", str(t)]
                + (["--stats", os.path.join(work, "s.json")] if stats else []))

    samples = {c: [] for c in cases}
    for c in cases:
        run(cmd(c), c[2])  # warm-up
    load_before = os.getloadavg()
    for r in range(args.repeats):
        k = r % len(cases)
        order = cases[k:] + cases[:k]
        timed = {c: run(cmd(c), c[2]) for c in order}
        # The phases, untimed, once the round's timed runs are done (so those
        # stay back to back).
        for c in order:
            run(cmd(c, stats=True), c[2])
            with open(os.path.join(work, "s.json")) as fh:
                st = json.load(fh)["time_s"]
            samples[c].append((*timed[c], st["render"], st["write"]))
    load_after = os.getloadavg()
    med = statistics.median
    print("raylab render %s -o OUT.%s; %d interleaved rounds, medians; load average before %.1f %.1f %.1f, after %.1f %.1f %.1f%s"
          % (" ".join(args.render), args.output, args.repeats, *load_before, *load_after,
             "; niceness %d" % NICE if NICE is not None else ""))
    print()
    print("| binary | threads | wall s | CPU s | render s | write s | rest s | wall speed-up | write ÷ render |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for b in binaries:
        base = None
        for t, pin in [(t, None) for t in threads] + [(threads[0], c) for c in cpus]:
            s = samples[(b, t, pin)]
            wall, cpu, ren, wr = (med(x[i] for x in s) for i in range(4))
            rest = med(x[0] - x[2] - x[3] for x in s)
            base = base or wall
            print("| %s | %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f× | %.0f%% |"
                  % (b, "%d on CPU %d" % (t, pin) if pin is not None else "%d" % t,
                     wall, cpu, ren, wr, rest, base / wall, 100 * wr / ren))
    print()
    for b in binaries:
        first = samples[(b, threads[0], None)]
        if cpus:
            rates = {c: med(x[2] for x in samples[(b, threads[0], c)]) for c in cpus}
            fast, slow = min(rates.values()), max(rates.values())
            print("%s, render pinned: %s; the slowest CPU takes %.2f× the fastest's time; "
                  "%d threads on these CPUs can at best render in %.1f ms (%.2f× the fastest CPU alone)"
                  % (b, ", ".join("CPU %d %.1f ms" % (c, 1e3 * r) for c, r in rates.items()),
                     slow / fast, len(cpus), 1e3 / sum(1 / r for r in rates.values()),
                     fast * sum(1 / r for r in rates.values())))
        for t in threads[1:]:
            ratios = sorted(f[0] / x[0] for f, x in zip(first, samples[(b, t, None)]))
            print("%s, %d -> %d threads, wall speed-up round by round: median %.2f× (%.2f–%.2f×)"
                  % (b, threads[0], t, med(ratios), ratios[0], ratios[-1]))
            # What --target asks of the N-thread process, with the first
            # count's wall time as measured.
            base = med(x[0] for x in first)
            wall = med(x[0] for x in samples[(b, t, None)])
            goal = base / args.target
            print("%s, %d threads: %.2f× needs the process within %.1f ms; it takes %.1f ms (%s)"
                  % (b, t, args.target, 1e3 * goal, 1e3 * wall,
                     "met" if wall <= goal else "%.1f ms too long" % (1e3 * (wall - goal))))
            if cpus:
                pinned = {c: med(x[0] for x in samples[(b, threads[0], c)]) for c in cpus}
                print("%s, %d threads against the one-thread process on each CPU: %s"
                      % (b, t, ", ".join("CPU %d %.2f×" % (c, w / wall) for c, w in pinned.items())))
    return 0


if __name__ == "__main__":
    sys.exit(main())

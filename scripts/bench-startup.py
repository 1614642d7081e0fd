#!/usr/bin/env python3
"""raylab's fixed cost per process: start-up, a tiny render, exit (issue 20, bar 1).

    scripts/bench-startup.py [--runs 21] [--warmup 3] BINARY [BINARY ...]

Times, for every binary given (e.g. main's and a branch's build/bin/raylab),
`raylab --help` and `raylab render ../shared/scenes/spd/tetra.nff --spd
--width 8 --height 8 -o OUT.exr --quiet` (run from the repository's root),
interleaved: each round runs every command with every binary once, the
binaries' order reversed every other round, after --warmup untimed rounds.
Prints the medians of the process's wall-clock time and CPU time (user +
system, from wait4), the fastest wall time, and the 1-minute load average
before and after. A benchmark, not a test: it asserts nothing but that every
run exits 0.
"""

import argparse
import os
import statistics
import sys
import tempfile
import time


def run_once(argv):
    """(wall s, CPU s) of one process; stdout discarded."""
    t0 = time.perf_counter()
    pid = os.posix_spawn(argv[0], argv, os.environ,
                         file_actions=[(os.POSIX_SPAWN_OPEN, 1, "/dev/null", os.O_WRONLY, 0)])
    _, status, usage = os.wait4(pid, 0)
    wall = time.perf_counter() - t0
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"bench-startup: {' '.join(argv)} failed")
    return wall, usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=21)
    parser.add_argument("--warmup", type=int, default=3)
    parser.add_argument("binaries", nargs="+")
    args = parser.parse_args()
    out = os.path.join(tempfile.mkdtemp(prefix="raylab-startup-"), "x.exr")
    commands = {
        "raylab --help": ["--help"],
        "render tetra --spd 8x8": ["render", "../shared/scenes/spd/tetra.nff", "--spd", "--width",
                                   "8", "--height", "8", "-o", out, "--quiet"],
    }
    times = {(c, b): ([], []) for c in commands for b in args.binaries}
    load_before = os.getloadavg()[0]
    for round_ in range(args.warmup + args.runs):
        order = args.binaries if round_ % 2 == 0 else list(reversed(args.binaries))
        for name, words in commands.items():
            for binary in order:
                wall, cpu = run_once([binary] + words)
                if round_ >= args.warmup:
                    times[(name, binary)][0].append(wall)
                    times[(name, binary)][1].append(cpu)
    load_after = os.getloadavg()[0]
    print(f"{args.runs} runs each (after {args.warmup} warm-up rounds), "
          f"load average {load_before:.2f} -> {load_after:.2f}")
    print("| command | binary | wall median ms | CPU median ms | fastest wall ms |")
    print("|---|---|---:|---:|---:|")
    for name in commands:
        for binary in args.binaries:
            wall, cpu = times[(name, binary)]
            print(f"| `{name}` | {binary} | {1000 * statistics.median(wall):.1f} | "
                  f"{1000 * statistics.median(cpu):.1f} | {1000 * min(wall):.1f} |")


if __name__ == "__main__":
    main()

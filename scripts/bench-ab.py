#!/usr/bin/env python3
"""Two or more raylab binaries on one render, whole process, interleaved (issue 20).

    scripts/bench-ab.py [--rounds 15] [--pause 0.2] [--output exr] BINARY BINARY [...] -- SCENE [render flags]

Each round runs `BINARY render SCENE [flags] -o OUT.exr --quiet` (--output
png: OUT.png, the 8-bit output alone; any extension raylab writes) once with
every binary, the order reversed every other round, --pause seconds apart
(fresh memory costs differ with how long the machine has been idle:
docs/benchmarks.md). Prints each binary's median wall-clock time and CPU time
(user + system, from wait4) and, against the first binary, the median over
rounds of the per-round ratios first ÷ other: a ratio taken within one round
is less exposed to the machine's drift than the ratio of two medians. Every
run must exit 0. A benchmark, not a test.
"""

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time


def run_once(argv):
    start = time.perf_counter()
    proc = subprocess.Popen(argv)
    _, status, usage = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("bench-ab: %s failed (%s)" % (" ".join(argv), status))
    return wall, usage.ru_utime + usage.ru_stime


def main():
    parser = argparse.ArgumentParser(
        usage="bench-ab.py [--rounds N] [--pause S] [--output EXT] BINARY BINARY [...] -- SCENE [render flags]",
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=15)
    parser.add_argument("--pause", type=float, default=0.2)
    parser.add_argument("--output", default="exr", help="the output's extension (exr, png, ...)")
    parser.add_argument("binaries", nargs="+")
    split = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    args = parser.parse_args(sys.argv[1:split])
    render = sys.argv[split + 1:]
    if len(args.binaries) < 2 or not render:
        sys.exit("bench-ab: give two binaries or more, and a scene after --")
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "out." + args.output)
        # Keyed by position: the same binary may be given twice (an A/A check of the noise).
        indices = list(range(len(args.binaries)))
        wall = {i: [] for i in indices}
        cpu = {i: [] for i in indices}
        for r in range(args.rounds):
            for i in indices if r % 2 == 0 else indices[::-1]:
                w, c = run_once([args.binaries[i], "render"] + render + ["-o", out, "--quiet"])
                wall[i].append(w)
                cpu[i].append(c)
                time.sleep(args.pause)
    print("raylab render %s -o OUT.%s; %d interleaved rounds, %.1f s apart" %
          (" ".join(render), args.output, args.rounds, args.pause))
    print("| binary | wall median s | CPU median s | first ÷ this, wall, per round | CPU, per round |")
    print("|---|---:|---:|---:|---:|")
    for i, binary in enumerate(args.binaries):
        ratio = lambda series: statistics.median(x / y for x, y in zip(series[0], series[i]))
        print("| %s | %.4f | %.4f | %.3f | %.3f |" % (binary, statistics.median(wall[i]),
                                                     statistics.median(cpu[i]), ratio(wall),
                                                     ratio(cpu)))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""raylab against POV-Ray 3.7 on the seven SPD scenes (issue 20, bar 1).

    scripts/bench-povray.py [--repeats 3] [--threads 2] [--scenes balls,gears,...]
                            [--pov-triangles mesh2[,mesh][,objects]] [--pov-polygons triangulate|polygon]
                            [--raylab build/bin/raylab] [--raylab-before OTHER] [--povray povray]
                            [--raylab-output exr|png]
                            [--spd-dir ../shared/scenes/spd] [--images DIR]
                            [--json FILE] [--work DIR]

For each scene: balls, gears, rings, teapot and tetra are read from
../shared/scenes/spd (SPD's default-size files); mount and tree are written by
scripts/spd/generate.py (byte-identical to SPD's generators). Every NFF is
converted to POV-Ray's language by scripts/spd/nff2pov.py. Neither step is
timed. Then, after one untimed warm-up run of each renderer per scene (it
also makes the pictures), the two commands

    povray +ISCENE.pov +OSCENE.png +W512 +H512 -D -A +WT<threads> -V -GA
    raylab render SCENE.nff --spd -o SCENE.exr --quiet --threads <threads>

(--raylab-output png: -o SCENE.png, the 8-bit RGB PNG POV-Ray writes too,
instead of the EXR with every AOV layer; raylab then computes no layer)

run interleaved, N rounds (the order of the commands rotates between scenes
and rounds), and the table shows the median wall-clock time of each whole
process (start-up, parse, build, render, writing the picture) and the ratio
of the medians, and beside it the median of each round's own ratio (less
moved when the machine's speed drifts during the run). -A: no anti-aliasing
(POV then traces one ray through each pixel centre; raylab's --spd traces
the 513x513 pixel corners); -D: no display window; -V -GA: no console output;
max_trace_level 5 is in the scene (SPD depth 5, the eye ray is level 1 in
both). Neither writes statistics in the timed runs (POV-Ray: -GA; raylab: no
--stats, whose JSON lists every object: 877 KB for gears). raylab's own
breakdown (parse, build, render, write) comes from an untimed run with --stats
after each scene's timed runs in every round (medians); "other" is the rest of
that run's wall time (process start, Embree device and thread set-up, the
statistics file, exit). CPU time (user + system, from wait4) is printed too: it is less disturbed than wall time when other jobs share the
cores; --nice -20 (root) runs each measured command in a session of its own
whose scheduler group has niceness -20, so that it takes the cores from other
jobs (Linux shares CPU time between sessions first, so a plain `nice` alone
does not help against other users' builds).

--pov-triangles mesh2,objects (any of mesh2, mesh, objects) times POV-Ray on
each form of the scene in the same rounds and compares raylab with the fastest
(per scene); the times of every form are printed below the table.

--raylab-before OTHER times a second raylab binary (e.g. a build of main) in
the same rounds, right after or before the first (alternating), and prints both
with their ratios: a before/after table measured under the same load, with the
median of each round's own ratio (steadier when the machine's speed drifts).

--images DIR writes DIR/SCENE.png: raylab's picture (left, `--png` of the
warm-up run) and POV-Ray's (right), box-filtered to 256x256, plus the mean
difference between them. A benchmark, not a test: it asserts nothing about
speed. Exit status 1 if a renderer fails or a tool is missing.
"""

import argparse
import datetime
import json
import os
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(TOP, "scripts", "spd"))
import generate  # noqa: E402
import nff2pov  # noqa: E402
import png_compare  # noqa: E402

SCENES = ["balls", "gears", "mount", "rings", "teapot", "tetra", "tree"]
GENERATED = {"mount", "tree"}


def die(msg):
    sys.stderr.write("bench-povray: error: %s\n" % msg)
    sys.exit(1)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as fh:
            for line in fh:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def mem_total_gib():
    try:
        with open("/proc/meminfo") as fh:
            for line in fh:
                if line.startswith("MemTotal:"):
                    return int(line.split()[1]) / 1024.0 / 1024.0
    except OSError:
        pass
    return float("nan")


def loadavg():
    try:
        return os.getloadavg()
    except OSError:
        return (float("nan"),) * 3


NICE = None  # --nice: scheduling priority of the timed commands


def set_priority():
    """In the child before exec: a session of its own, whose scheduler autogroup
    (Linux groups CPU time by session when kernel.sched_autogroup_enabled is 1,
    and a process's niceness counts only inside its group) gets niceness NICE,
    and the process itself too."""
    os.setsid()
    try:
        with open("/proc/self/autogroup", "w") as fh:
            fh.write(str(NICE))
    except OSError:
        pass  # no autogroups: the process niceness below is what counts
    os.setpriority(os.PRIO_PROCESS, 0, NICE)


def run_timed(cmd, log_path):
    """Runs cmd; returns (wall seconds, user+system CPU seconds)."""
    with open(log_path, "ab") as log:
        t0 = time.perf_counter()
        proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                preexec_fn=set_priority if NICE is not None else None)
        _, status, ru = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - t0
        proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        with open(log_path, "rb") as fh:
            tail = fh.read()[-2000:].decode(errors="replace")
        die("%s failed (exit %d):\n%s" % (" ".join(cmd), proc.returncode, tail))
    return wall, ru.ru_utime + ru.ru_stime


def tool_version(cmd):
    try:
        out = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=30).stdout
        lines = [l for l in out.decode(errors="replace").splitlines() if l.strip() and "configuration file" not in l]
        return lines[0].strip() if lines else "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def git_commit():
    try:
        out = subprocess.run(["git", "-C", TOP, "rev-parse", "--short", "HEAD"], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, timeout=30).stdout.decode().strip()
        dirty = subprocess.run(["git", "-C", TOP, "status", "--porcelain", "--untracked-files=no"],
                               stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, timeout=30).stdout.strip()
        return out + ("+changes" if dirty else "") if out else "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def main(argv=None):
    ap = argparse.ArgumentParser(description="raylab vs POV-Ray on the SPD scenes (interleaved, medians).")
    ap.add_argument("--repeats", type=int, default=3, help="timed rounds (default 3)")
    ap.add_argument("--threads", type=int, default=2, help="threads of both renderers (default 2)")
    ap.add_argument("--scenes", default=",".join(SCENES), help="comma-separated subset of " + ",".join(SCENES))
    ap.add_argument("--raylab", default=os.path.join(TOP, "build", "bin", "raylab"))
    ap.add_argument("--raylab-before", metavar="PATH",
                    help="a second raylab binary timed in the same rounds (before/after of a change)")
    ap.add_argument("--raylab-output", choices=["exr", "png"], default="exr",
                    help="what raylab writes in the timed runs: exr (default: the EXR with every AOV layer, "
                         "21 channels) or png (an 8-bit RGB PNG, the output POV-Ray writes)")
    ap.add_argument("--povray", default="povray")
    ap.add_argument("--spd-dir", default=os.path.join(TOP, "..", "shared", "scenes", "spd"),
                    help="where balls/gears/rings/teapot/tetra.nff are (default ../shared/scenes/spd)")
    ap.add_argument("--pov-triangles", default="mesh2",
                    help="nff2pov --triangles: mesh2, mesh, objects, or several comma-separated: each form is "
                         "timed in the same interleaved rounds and the table shows the fastest (default mesh2)")
    ap.add_argument("--pov-polygons", choices=["triangulate", "polygon"], default="triangulate",
                    help="nff2pov --polygons (default triangulate)")
    ap.add_argument("--nice", type=int, metavar="N",
                    help="run both renderers at this niceness, each in a session (scheduler autogroup) of its "
                         "own with the same niceness (e.g. -20, needs root): on a shared machine the other "
                         "jobs then wait instead of the measured commands")
    ap.add_argument("--images", metavar="DIR", help="write raylab | POV-Ray thumbnails DIR/SCENE.png")
    ap.add_argument("--json", metavar="FILE", help="write every sample and median as JSON")
    ap.add_argument("--work", metavar="DIR", help="keep the scenes and outputs here (default: a temporary folder)")
    args = ap.parse_args(argv)

    scenes = [s for s in args.scenes.split(",") if s]
    args.pov_forms = [f for f in args.pov_triangles.split(",") if f]
    for f in args.pov_forms:
        if f not in ("mesh2", "mesh", "objects"):
            die("unknown --pov-triangles form '%s' (mesh2, mesh, objects)" % f)
    if not args.pov_forms:
        die("--pov-triangles needs a form")
    for s in scenes:
        if s not in SCENES:
            die("unknown scene '%s' (one of %s)" % (s, ", ".join(SCENES)))
    if args.repeats < 1 or args.threads < 1:
        die("--repeats and --threads must be >= 1")
    global NICE
    NICE = args.nice
    if NICE is not None:
        r = subprocess.run([sys.executable, "-c", "pass"], preexec_fn=set_priority, stderr=subprocess.DEVNULL)
        if r.returncode != 0:
            die("cannot set niceness %d (negative values need root)" % NICE)
    raylab = os.path.abspath(args.raylab)
    if not os.access(raylab, os.X_OK):
        die("no raylab binary at %s (build first, or give --raylab)" % raylab)
    if args.raylab_before:
        args.raylab_before = os.path.abspath(args.raylab_before)
        if not os.access(args.raylab_before, os.X_OK):
            die("no raylab binary at %s (--raylab-before)" % args.raylab_before)
    povray = shutil.which(args.povray)
    if not povray:
        die("POV-Ray not found ('%s'): scripts/install-deps.sh --optional installs it" % args.povray)

    work = os.path.abspath(args.work) if args.work else tempfile.mkdtemp(prefix="bench-povray-")
    os.makedirs(work, exist_ok=True)
    try:
        return bench(args, scenes, raylab, povray, work)
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)


def bench(args, scenes, raylab, povray, work):
    # ---- prepare the scenes (untimed) ----
    nff = {}
    for s in scenes:
        path = os.path.join(work, s + ".nff")
        if s in GENERATED:
            fn, size = generate.GENERATORS[s]
            with open(path, "w", encoding="ascii") as fh:
                fh.write(fn(size))
        else:
            src = os.path.join(args.spd_dir, s + ".nff")
            if not os.path.isfile(src):
                die("%s is missing (give --spd-dir, or leave the scene out with --scenes)" % src)
            shutil.copyfile(src, path)
        nff[s] = path
        with open(path, encoding="ascii") as fh:
            text = fh.read()
        for form in args.pov_forms:
            with open(os.path.join(work, "%s_%s.pov" % (s, form)), "w", encoding="ascii") as fh:
                fh.write(nff2pov.convert(text, form, args.pov_polygons, s + ".nff"))

    def pov_cmd(s, form):
        return [povray, "+I" + os.path.join(work, "%s_%s.pov" % (s, form)),
                "+O" + os.path.join(work, "%s_pov_%s.png" % (s, form)),
                "+W512", "+H512", "-D", "-A", "+WT%d" % args.threads, "-V", "-GA"]

    def ray_cmd(s, extra=(), binary=None, stats=False):
        return ([binary or raylab, "render", nff[s], "--spd", "-o", os.path.join(work, s + "." + args.raylab_output),
                 "--quiet", "--threads", str(args.threads)]
                + (["--stats", os.path.join(work, s + "_stats.json")] if stats else []) + list(extra))

    machine = {
        "cpu": cpu_model(), "logical_cpus": os.cpu_count(), "memory_gib": round(mem_total_gib(), 1),
        "os": platform.platform(), "povray": tool_version([povray, "--version"]),
        "raylab_commit": git_commit(), "threads": args.threads, "repeats": args.repeats, "nice": NICE,
        "raylab_output": args.raylab_output,
        "pov_form": "triangles %s, polygons %s" % (" / ".join(args.pov_forms), args.pov_polygons),
        "date": datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
        "load_before": loadavg(),
    }

    # ---- warm-up: one untimed run of each, which also makes the pictures ----
    log = os.path.join(work, "log.txt")
    for s in scenes:
        for form in args.pov_forms:
            run_timed(pov_cmd(s, form), log)
        run_timed(ray_cmd(s, ["--png", os.path.join(work, s + "_raylab.png")]), log)

    # ---- timed, interleaved rounds ----
    runners = ["pov_" + f for f in args.pov_forms] + ["raylab"] + (["before"] if args.raylab_before else [])
    samples = {s: {k: [] for k in runners + [r + "_cpu" for r in runners] + ["stats"]} for s in scenes}
    # The two raylab binaries run back to back, in either order, as one slot:
    # the VM's speed drifts within seconds, and a POV-Ray run between them
    # would put them in different phases.
    slots = [["pov_" + f] for f in args.pov_forms] + [["raylab"] + (["before"] if args.raylab_before else [])]
    for r in range(args.repeats):
        for i, s in enumerate(scenes):
            # rotate the order of the commands between rounds and scenes
            k = (r + i) % len(slots)
            order = [who for slot in slots[k:] + slots[:k]
                     for who in (slot if (r + i) % 2 == 0 else slot[::-1])]
            for who in order:
                if who.startswith("pov_"):
                    wall, cpu = run_timed(pov_cmd(s, who[4:]), log)
                elif who == "before":
                    wall, cpu = run_timed(ray_cmd(s, binary=args.raylab_before), log)
                else:
                    wall, cpu = run_timed(ray_cmd(s), log)
                samples[s][who].append(wall)
                samples[s][who + "_cpu"].append(cpu)
            # raylab's breakdown: one untimed run with --stats after this
            # scene's timed runs (so the two raylab binaries stay back to back)
            stats_wall, _ = run_timed(ray_cmd(s, stats=True), log)
            with open(os.path.join(work, s + "_stats.json")) as fh:
                st = json.load(fh)
            phases = dict(st["time_s"])
            # the rest of that run's own wall time
            phases["other"] = stats_wall - sum(phases[k] for k in ("parse", "build", "render", "write"))
            samples[s]["stats"].append(phases)
            samples[s]["rays"] = st["rays"]["total"]
            samples[s]["primitives"] = st["primitives"]
    machine["load_after"] = loadavg()

    # ---- report ----
    med = statistics.median

    def per_round(numerators, denominators):
        # The median of each round's own ratio, the two runs of a round
        # close in time: steadier than the ratio of the medians when the
        # machine's speed drifts.
        return med([a / b for a, b in zip(numerators, denominators)])

    rows = []
    for s in scenes:
        d = samples[s]
        forms = {f: med(d["pov_" + f]) for f in args.pov_forms}
        best = min(forms, key=forms.get)
        pov, ray = forms[best], med(d["raylab"])
        phase = {k: med([t[k] for t in d["stats"]]) for k in ("parse", "build", "render", "write", "other")}
        rows.append({"scene": s, "povray_s": pov, "povray_form": best, "povray_forms_s": forms,
                     "raylab_s": ray, "ratio": pov / ray,
                     # POV-Ray (the fastest form) ÷ raylab per round; the ratio of
                     # the medians stays the headline figure.
                     "round_ratio": per_round(d["pov_" + best], d["raylab"]),
                     "povray_cpu_s": med(d["pov_%s_cpu" % best]), "raylab_cpu_s": med(d["raylab_cpu"]),
                     "raylab_phases_s": phase, "rays": d.get("rays"), "primitives": d.get("primitives"),
                     "samples": {k: v for k, v in d.items() if k != "stats"}})
        if args.raylab_before:
            rows[-1]["before_s"] = med(d["before"])
            rows[-1]["before_cpu_s"] = med(d["before_cpu"])
            rows[-1]["round_speedup"] = per_round(d["before"], d["raylab"])

    la, lb = machine["load_before"], machine["load_after"]
    print("machine: %s, %d logical CPUs, %.1f GiB; %s" % (machine["cpu"], machine["logical_cpus"],
                                                           machine["memory_gib"], machine["os"]))
    print("%s; raylab %s; %d threads each; %d interleaved rounds, medians; %s"
          % (machine["povray"], machine["raylab_commit"], args.threads, args.repeats, machine["date"]))
    print("load average (1/5/15 min): before %.2f %.2f %.2f, after %.2f %.2f %.2f%s"
          % (la + lb + ("; both renderers at niceness %d" % NICE if NICE is not None else "",)))
    print("POV-Ray scene form: %s" % machine["pov_form"])
    print("raylab writes: %s" % ("an EXR with every AOV layer (21 channels)" if args.raylab_output == "exr"
                                 else "an 8-bit RGB PNG, as POV-Ray does (no AOV layer is computed)"))
    print()
    several = len(args.pov_forms) > 1
    print("| scene | POV-Ray s%s | raylab s | raylab faster by | per round | POV-Ray CPU s | raylab CPU s |"
          " raylab parse | build | render | write | other |" % (" (fastest form)" if several else ""))
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for row in rows:
        p = row["raylab_phases_s"]
        print("| %s | %.3f%s | %.3f | **%.1f×** | %.1f× | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f |" % (
            row["scene"], row["povray_s"], " (%s)" % row["povray_form"] if several else "", row["raylab_s"],
            row["ratio"], row["round_ratio"], row["povray_cpu_s"], row["raylab_cpu_s"], p["parse"],
            p["build"], p["render"], p["write"], p["other"]))
    print()
    print("raylab faster by: POV-Ray's median ÷ raylab's; per round: the median over rounds of each"
          " round's POV-Ray ÷ raylab")
    lowest = min(rows, key=lambda r: r["ratio"])
    lowest_round = min(rows, key=lambda r: r["round_ratio"])
    print("smallest ratio: %.1f× (%s); per round %.1f× (%s)"
          % (lowest["ratio"], lowest["scene"], lowest_round["round_ratio"], lowest_round["scene"]))
    if args.raylab_before:
        print()
        print("raylab before (%s) and after (%s), same rounds:" % (args.raylab_before, raylab))
        print()
        print("| scene | before s | after s | after faster by | per round | POV-Ray ÷ before | POV-Ray ÷ after | before CPU s | after CPU s |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        for row in rows:
            print("| %s | %.3f | %.3f | %.2f× | %.2f× | %.1f× | %.1f× | %.3f | %.3f |" % (
                row["scene"], row["before_s"], row["raylab_s"], row["before_s"] / row["raylab_s"],
                row["round_speedup"], row["povray_s"] / row["before_s"], row["ratio"],
                row["before_cpu_s"], row["raylab_cpu_s"]))
        print()
        print("per round: the median over rounds of before ÷ after, the two binaries run back to back")
    if several:
        print()
        print("POV-Ray wall s by scene form (medians of the same rounds):")
        print()
        print("| scene | " + " | ".join(args.pov_forms) + " |")
        print("|---|" + "---:|" * len(args.pov_forms))
        for row in rows:
            print("| %s | %s |" % (row["scene"], " | ".join("%.3f" % row["povray_forms_s"][f] for f in args.pov_forms)))

    if args.images:
        os.makedirs(args.images, exist_ok=True)
        print()
        for s in scenes:
            a = png_compare.read_png(os.path.join(work, s + "_raylab.png"))
            b = png_compare.read_png(os.path.join(work, "%s_pov_%s.png" % (s, args.pov_forms[0])))
            c = png_compare.compare(a, b)
            wa, ha, ra = png_compare.downscale(*a, 2)
            _, _, rb = png_compare.downscale(*b, 2)
            gap = b"\xff" * 12
            png_compare.write_png(os.path.join(args.images, s + ".png"), 2 * wa + 4, ha,
                                  [x + gap + y for x, y in zip(ra, rb)])
            print("%s: raylab | POV-Ray in %s; mean |difference| %.1f of 255, pixels differing by > 32 levels %.1f%%"
                  % (s, os.path.join(args.images, s + ".png"), sum(c["mean_abs"]) / 3, 100 * c["over32"]))

    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"machine": machine, "scenes": rows}, fh, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""What texturing costs per frame (issue 18): renders a textured scene with every
--texture-filter / --texture-footprint and the same scene with every texture replaced
by a constant colour (bump and normal maps dropped), one thread, interleaved rounds,
and prints the median render time of each and the texture share of the frame.

With --before OTHER_RAYLAB every round renders each setting with both binaries,
alternately (the same load for both), and the table gets a column per binary.

usage: scripts/bench-texture-cost.py [--raylab build/bin/raylab] [--before OTHER_RAYLAB]
                                     [--scene scenes/textures.json] [--only SETTING ...]
                                     [--repeats 5] [--width 320 --height 200] [--spp 1]
"""
import argparse, json, os, re, statistics, subprocess, sys, tempfile

ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
ap.add_argument("--raylab", default="build/bin/raylab")
ap.add_argument("--before", help="a second raylab to time in the same rounds")
ap.add_argument("--only", nargs="+", metavar="SETTING",
                help="time only these settings (point, bilinear, trilinear, anisotropic; "
                     "the untextured copy always)")
ap.add_argument("--scene", default="scenes/textures.json")
ap.add_argument("--repeats", type=int, default=5)
ap.add_argument("--width", type=int, default=320)
ap.add_argument("--height", type=int, default=200)
ap.add_argument("--spp", type=int, default=1, help="samples per pixel (footprints shrink with it)")
a = ap.parse_args()

text = open(a.scene).read()
doc = json.loads(re.sub(r"//[^\n]*", "", text))
for m in doc.get("materials", {}).values():
    for k in list(m):
        if isinstance(m[k], dict):  # a texture or a checker
            if k in ("bump", "normal_map"):
                del m[k]
            else:
                m[k] = 0.7
# Meshes keep their geometry but take a plain material instead of their MTL maps.
doc.setdefault("materials", {})["untextured mesh"] = {"kd": [0.7, 0.7, 0.7]}
for o in doc.get("objects", []):
    if o.get("type") == "mesh":
        o["material"] = "untextured mesh"
# The untextured copy sits beside the scene so its relative mesh paths still resolve.
fd, plain = tempfile.mkstemp(suffix=".json", dir=os.path.dirname(os.path.abspath(a.scene)))
with os.fdopen(fd, "w") as f:
    json.dump(doc, f)

variants = [("untextured copy", plain, [])]
for filt in ["point", "bilinear", "trilinear", "anisotropic"]:
    if a.only and filt not in a.only:
        continue
    for fp in (["cones", "differentials"] if filt in ("trilinear", "anisotropic") else ["differentials"]):
        name = filt + (", " + fp if filt in ("trilinear", "anisotropic") else "")
        variants.append((name, a.scene, ["--texture-filter", filt, "--texture-footprint", fp]))
binaries = [("after", a.raylab)] + ([("before", a.before)] if a.before else [])
times = {(b[0], v[0]): [] for b in binaries for v in variants}
out = tempfile.mkdtemp()
stats = os.path.join(out, "stats.json")
try:
    for r in range(a.repeats):
        for name, scene, flags in variants:
            # Alternate which binary goes first, so neither always follows the other.
            for label, exe in (binaries if r % 2 == 0 else binaries[::-1]):
                subprocess.run([exe, "render", scene, "-o", os.path.join(out, "o.exr"),
                                "--stats", stats, "--quiet", "--threads", "1", "--spp", str(a.spp),
                                "--width", str(a.width), "--height", str(a.height)] + flags,
                               check=True, stderr=subprocess.DEVNULL)
                times[(label, name)].append(json.load(open(stats))["time_s"]["render"])
finally:
    os.remove(plain)
print("%s, %dx%d, %d spp, 1 thread, median render time of %d interleaved rounds, load average %s"
      % (a.scene, a.width, a.height, a.spp, a.repeats, " ".join("%.2f" % x for x in os.getloadavg())))
labels = [b[0] for b in binaries]
heads = ["%s: render ms | %s: texture share" % (l, l) if a.before else "render ms | texture share of the frame"
         for l in labels]
print("| setting | " + " | ".join(heads) + " |")
print("|---|" + "---:|---:|" * len(labels))
for name, _, _ in variants:
    cells = []
    for label in labels:
        base = statistics.median(times[(label, "untextured copy")])
        m = statistics.median(times[(label, name)])
        share = "-" if name == "untextured copy" else "%.0f%%" % (100 * max(0.0, m - base) / m)
        cells += ["%.1f" % (1e3 * m), share]
    print("| %s | %s |" % (name, " | ".join(cells)))

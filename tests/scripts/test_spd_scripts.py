#!/usr/bin/env python3
"""Tests of scripts/spd (SPD generators, NFF -> POV-Ray converter, PNG tool) and
a smoke run of scripts/bench-povray.py. Registered with ctest (one test per
class, tests/CMakeLists.txt). Needs neither ../shared nor the network; the
POV-Ray cases are skipped when povray is not installed (it is optional)."""

import hashlib
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import unittest
import zlib

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(TOP, "scripts", "spd"))
import generate  # noqa: E402
import nff2pov  # noqa: E402
import png_compare  # noqa: E402

POVRAY = shutil.which("povray")
RAYLAB = os.environ.get("RAYLAB_BINARY", os.path.join(TOP, "build", "bin", "raylab"))


def sha256(text):
    return hashlib.sha256(text.encode("ascii")).hexdigest()


def entity_counts(text):
    counts = {}
    for line in text.splitlines():
        word = line.split()[0]
        if re.match(r"^[a-z]+$", word):
            counts[word] = counts.get(word, 0) + 1
    return counts


class Generators(unittest.TestCase):
    # SHA-256 of what SPD's own C generators (mount.c, tree.c with lib*.c, default
    # settings, built with gcc on x86-64) write; the port was compared byte for byte
    # at sizes 1-7 (mount) and 1, 5, 8, 11 (tree).
    MOUNT_6 = "c48f8bdbcc7f28e661939b9c246e41c78d562662bc9b43819000cdc9538809b9"
    TREE_11 = "57ae111e5e70e6ca13caf5868804a43a1ca68dadf5dfffcbef265adefcada8a2"
    MOUNT_2 = "2287d7240c1993527be641e79563829ddd86bb1aa516ffd58ea13b8c58127dab"
    TREE_3 = "7aef2a852b0e4e29941205835bdf3ed17910335610f3b5b3d4b8d910d1f5b8f5"

    def test_mount_default_is_spds_file(self):
        text = generate.mount()
        c = entity_counts(text)
        # mount.c: 2 * 4^size triangles, 4 glass spheres, 1 light, 2 materials
        self.assertEqual(c["p"], 8192)
        self.assertEqual(c["s"], 4)
        self.assertEqual(c["l"], 1)
        self.assertEqual(c["f"], 2)
        lines = text.splitlines()
        self.assertEqual(lines[:10], ["b 0.078 0.361 0.753", "v", "from -1.6 1.6 1.7", "at 0 0 0",
                                      "up 0 0 1", "angle 45", "hither 0.01", "resolution 512 512",
                                      "l -100 -100 100", "f 1 1 1 0.1 0.1 101.148 0.9 1.5"])
        # first sphere: the pyramid's top, centre + (0, 0, r sqrt(3/2))
        self.assertEqual(lines[10], "s -0.8 0.8 1.20821 0.17")
        self.assertEqual(sha256(text), self.MOUNT_6)

    def test_tree_default_is_spds_file(self):
        text = generate.tree()
        c = entity_counts(text)
        # tree.c: 2^(size+1) - 1 cones and spheres, 1 square, 7 lights
        self.assertEqual(c["c"], 4095)
        self.assertEqual(c["s"], 4095)
        self.assertEqual(c["p"], 1)
        self.assertEqual(c["l"], 7)
        lines = text.splitlines()
        i = lines.index("f 0.55 0.4 0.2 1 0 100000 0 0")
        # the trunk: radius 0.15 at the base, 0.15 * 0.67 at its top
        self.assertEqual(lines[i + 1], "c 0 0 0 0.15 0 0 1 0.1005")
        self.assertEqual(lines[i + 2], "s 0 0 1 0.1005")
        self.assertEqual(sha256(text), self.TREE_11)

    def test_smaller_sizes(self):
        self.assertEqual(sha256(generate.mount(2)), self.MOUNT_2)
        self.assertEqual(sha256(generate.tree(3)), self.TREE_3)
        self.assertEqual(entity_counts(generate.mount(1))["p"], 8)
        c = entity_counts(generate.tree(1))
        self.assertEqual((c["c"], c["s"]), (3, 3))
        with self.assertRaises(ValueError):
            generate.mount(8)

    def test_gauss_rand_matches_c(self):
        # lib_gauss_rand(seed) as SPD's libvec.c computes it (printed with %.17g)
        self.assertEqual(generate.gauss_rand(21), -0.19090945614389554)
        self.assertEqual(generate.gauss_rand(1000), 0.078479818846182797)
        self.assertEqual(generate.gauss_rand(65556), 0.53048975688352196)

    def test_command_line(self):
        with tempfile.TemporaryDirectory() as d:
            out = os.path.join(d, "tree.nff")
            subprocess.run([sys.executable, os.path.join(TOP, "scripts", "spd", "generate.py"), "tree", "-s", "3",
                            "-o", out], check=True)
            with open(out) as fh:
                self.assertEqual(sha256(fh.read()), self.TREE_3)


SMALL_NFF = """# every entity the converter handles
b 0.1 0.2 0.3
v
from 0 -5 1
at 0 0 1
up 0 0 1
angle 40
hither 0.5
resolution 64 32
l 3 -3 5
l -3 -3 5 1 0.5 0.25
f 1 0.5 0.25 0.8 0.3 20 0 0
s 0 0 1 0.5
s 1 0 1 -0.25
c 0 0 0 0.2 0 0 1 0.1
c 1 1 0 0.1 1 1 1 0.1
p 3
-2 -2 0
2 -2 0
2 2 0
p 5
-1 -1 0.01
1 -1 0.01
1 1 0.01
0 0 0.01
-1 1 0.01
f 0.5 1 1 0.2 0 100000 0.8 1.5
pp 3
0 0 2 0 0 1
1 0 2 0 0 1
0 1 2 0 0 1
"""


def parse_vec(s):
    return tuple(float(x) for x in s.strip("<>").split(","))


class Nff2Pov(unittest.TestCase):
    def setUp(self):
        self.pov = nff2pov.convert(SMALL_NFF, source="small.nff")

    def test_camera_as_spd_writes_it(self):
        cam = re.search(r"camera \{\s*location (\S+)\s*direction (\S+)\s*right (\S+)\s*up (\S+)\s*\}", self.pov)
        loc, d, r, u = (parse_vec(cam.group(k)) for k in range(1, 5))
        self.assertEqual(loc, (0, -5, 1))
        for a, b in zip(d, (0, 1, 0)):
            self.assertAlmostEqual(a, b, places=12)
        h = 2 * math.tan(math.radians(40) / 2)  # full field of view edge to edge
        for a, b in zip(u, (0, 0, h)):
            self.assertAlmostEqual(a, b, places=12)
        # right = -(up x view) * width (SPD's sign): screen right is +x when looking
        # along +y with +z up; width = height * 64/32
        for a, b in zip(r, (2 * h, 0, 0)):
            self.assertAlmostEqual(a, b, places=12)

    def test_lights_and_ambient(self):
        ia = math.sqrt(2) / 4  # sqrt(L)/(2L), L = 2
        lights = re.findall(r"light_source \{ (\S+) rgb (\S+) \}", self.pov)
        self.assertEqual(len(lights), 2)
        self.assertEqual(parse_vec(lights[0][0]), (3, -3, 5))
        for a in parse_vec(lights[0][1]):
            self.assertAlmostEqual(a, ia, places=15)
        self.assertEqual(parse_vec(lights[1][1]), (1, 0.5, 0.25))  # an explicit colour is kept
        self.assertIn("max_trace_level 5", self.pov)
        self.assertIn("background { rgb <0.1,0.2,0.3> }", self.pov)
        m0 = re.search(r"#declare M0 = material \{\s*texture \{ pigment \{ rgb (\S+) \} finish \{ ([^}]*) \} \}", self.pov)
        self.assertEqual(parse_vec(m0.group(1)), (1, 0.5, 0.25))
        fin = m0.group(2).split()
        vals = dict(zip(fin[0::2], (float(x) for x in fin[1::2])))
        self.assertAlmostEqual(vals["ambient"], 0.8 * ia, places=15)
        self.assertEqual((vals["diffuse"], vals["phong"], vals["phong_size"], vals["reflection"]), (0.8, 0.3, 20, 0.3))

    def test_transmitter(self):
        m1 = re.search(r"#declare M1 = material \{\s*texture \{ pigment \{ rgbt (\S+) \} finish \{ ([^}]*) \} \}\s*"
                       r"interior \{ ior ([0-9.]+) \}", self.pov)
        self.assertIsNotNone(m1)
        self.assertEqual(parse_vec(m1.group(1)), (0.5, 1, 1, 0.8))
        fin = m1.group(2).split()
        vals = dict(zip(fin[0::2], (float(x) for x in fin[1::2])))
        self.assertAlmostEqual(vals["diffuse"], 0.2 / 0.2)  # Kd / (1 - T): POV weights diffuse by 1 - T
        self.assertNotIn("reflection", vals)
        self.assertEqual(float(m1.group(3)), 1.5)

    def test_primitives(self):
        self.assertIn("sphere { <0,0,1>,0.5 material { M0 } }", self.pov)
        self.assertIn("sphere { <1,0,1>,0.25 material { M0 } }", self.pov)  # inside-visible: |r|
        self.assertIn("cone { <0,0,0>,0.2,<0,0,1>,0.1 open material { M0 } }", self.pov)
        self.assertIn("cylinder { <1,1,0>,<1,1,1>,0.1 open material { M0 } }", self.pov)
        # one flat mesh2 for M0 (1 triangle + the pentagon's 3), one smooth for M1
        flat = re.search(r"mesh2 \{\s*vertex_vectors \{ (\d+),.*?face_indices \{ (\d+),.*?material \{ M0 \}",
                         self.pov, re.S)
        self.assertEqual(int(flat.group(2)), 4)
        smooth = re.search(r"mesh2 \{[^}]*\}\s*normal_vectors \{ (\d+),.*?face_indices \{ (\d+),"
                           r".*?normal_indices \{ (\d+),.*?material \{ M1 \}", self.pov, re.S)
        self.assertEqual(int(smooth.group(2)), 1)

    def test_other_forms(self):
        objs = nff2pov.convert(SMALL_NFF, triangles="objects")
        self.assertEqual(objs.count("triangle {") - objs.count("smooth_triangle {"), 4)
        self.assertEqual(objs.count("smooth_triangle {"), 1)
        mesh = nff2pov.convert(SMALL_NFF, triangles="mesh")
        self.assertEqual(mesh.count("mesh {"), 2)
        poly = nff2pov.convert(SMALL_NFF, polygons="polygon")
        self.assertIn("polygon { 6, <-1,-1,0.01>", poly)  # closed: first vertex repeated

    def test_errors(self):
        with self.assertRaises(nff2pov.NffError):
            nff2pov.convert("v\nfrom 0 0 0\nat 1 0 0\nup 0 0 1\nangle 45\ns 0 0 zero 1\n")
        with self.assertRaises(nff2pov.NffError):
            nff2pov.convert("q 1 2 3\n")
        with self.assertRaises(nff2pov.NffError):
            nff2pov.convert("s 0 0 0 1\n")  # no view


def shoelace(pts):
    return 0.5 * sum(pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
                     for i in range(len(pts)))


class EarClip(unittest.TestCase):
    def check(self, pts):
        tris = nff2pov.ear_clip([(x, y, 0.0) for x, y in pts])
        self.assertEqual(len(tris), len(pts) - 2)
        total = 0.0
        for a, b, c in tris:
            area = shoelace([pts[a], pts[b], pts[c]])
            self.assertGreater(area * math.copysign(1, shoelace(pts)), 0)  # same winding as the polygon
            total += area
        self.assertAlmostEqual(total, shoelace(pts), places=9)

    def test_gear_outline(self):
        # a 36-tooth gear face like gears.nff's: 144 vertices, concave
        pts = []
        for t in range(36):
            a = 2 * math.pi * t / 36
            for frac, r in ((-0.19, 1.0), (0.19, 1.0), (0.3, 0.9), (0.7, 0.9)):
                ang = a + frac * 2 * math.pi / 36
                pts.append((r * math.cos(ang), r * math.sin(ang)))
        self.check(pts)
        self.check(pts[::-1])  # clockwise too

    def test_concave_and_collinear(self):
        self.check([(0, 0), (4, 0), (4, 4), (2, 1), (0, 4)])
        self.check([(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)])
        self.assertEqual(nff2pov.ear_clip([(0, 0, 0), (1, 0, 0), (2, 0, 0)]), [])


class PngTool(unittest.TestCase):
    def encode(self, rows, width, filt):
        """A PNG (RGB, 8-bit) whose every row uses filter type filt."""
        raw = b""
        prev = bytes(width * 3)
        for r in rows:
            out = bytearray()
            for i, v in enumerate(r):
                a = r[i - 3] if i >= 3 else 0
                b = prev[i]
                c = prev[i - 3] if i >= 3 else 0
                if filt == 0:
                    p = 0
                elif filt == 1:
                    p = a
                elif filt == 2:
                    p = b
                elif filt == 3:
                    p = (a + b) >> 1
                else:
                    pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                    p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                out.append((v - p) & 255)
            raw += bytes([filt]) + bytes(out)
            prev = r

        def chunk(kind, body):
            return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

        return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, len(rows), 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

    def test_filters_and_compare(self):
        w, h = 7, 5
        rows = [bytes((x * 37 + y * 11 + c * 5) & 255 for x in range(w) for c in range(3)) for y in range(h)]
        with tempfile.TemporaryDirectory() as d:
            for filt in range(5):
                path = os.path.join(d, "f%d.png" % filt)
                with open(path, "wb") as fh:
                    fh.write(self.encode(rows, w, filt))
                self.assertEqual(png_compare.read_png(path), (w, h, rows), "filter %d" % filt)
            out = os.path.join(d, "sbs.png")
            png_compare.write_png(out, w, h, rows)
            img = png_compare.read_png(out)
            r = png_compare.compare(img, img)
            self.assertEqual((r["mean_abs"], r["over8"], r["psnr"]), ([0, 0, 0], 0, float("inf")))
            w2, h2, small = png_compare.downscale(w, h, rows, 2)
            self.assertEqual((w2, h2, len(small[0])), (3, 2, 9))


@unittest.skipUnless(POVRAY, "povray is not installed (scripts/install-deps.sh --optional)")
class WithPovray(unittest.TestCase):
    def test_converted_scenes_render(self):
        with tempfile.TemporaryDirectory() as d:
            for name, text in (("small", SMALL_NFF), ("tree3", generate.tree(3)), ("mount2", generate.mount(2))):
                pov = os.path.join(d, name + ".pov")
                with open(pov, "w") as fh:
                    fh.write(nff2pov.convert(text, source=name))
                r = subprocess.run([POVRAY, "+I" + pov, "+O" + os.path.join(d, name + ".png"), "+W32", "+H32",
                                    "-D", "-A", "+WT1", "-V", "-GA"], stdout=subprocess.PIPE,
                                   stderr=subprocess.STDOUT)
                log = r.stdout.decode(errors="replace")
                self.assertEqual(r.returncode, 0, log)
                self.assertNotIn("Warning", log)
                self.assertEqual(png_compare.read_png(os.path.join(d, name + ".png"))[:2], (32, 32))

    @unittest.skipUnless(os.access(RAYLAB, os.X_OK), "no raylab binary")
    def test_bench_script_smoke(self):
        # the benchmark's plumbing on one generated scene, one round: it must print
        # a table row and write the thumbnail; its timings are not looked at
        with tempfile.TemporaryDirectory() as d:
            r = subprocess.run([sys.executable, os.path.join(TOP, "scripts", "bench-povray.py"), "--scenes", "tree",
                                "--repeats", "1", "--threads", "1", "--raylab", RAYLAB,
                                "--raylab-before", RAYLAB, "--raylab-output", "png",
                                "--images", d, "--json", os.path.join(d, "b.json")],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
            out = r.stdout.decode(errors="replace")
            self.assertEqual(r.returncode, 0, out)
            self.assertRegex(out, r"\| tree \| [0-9.]+ \| [0-9.]+ \| \*\*[0-9.]+×\*\* \| [0-9.]+× \|")
            self.assertIn("raylab writes: an 8-bit RGB PNG", out)
            # the before/after table, with each round's own ratio
            self.assertRegex(out, r"\| tree \| [0-9.]+ \| [0-9.]+ \| [0-9.]+× \| [0-9.]+× \|")
            with open(os.path.join(d, "b.json")) as fh:
                scene = json.load(fh)["scenes"][0]
                self.assertGreater(scene["round_speedup"], 0)
                # one round: its own ratio is the ratio of the medians
                self.assertAlmostEqual(scene["round_ratio"], scene["ratio"], places=9)
            self.assertTrue(os.path.isfile(os.path.join(d, "tree.png")))
            self.assertEqual(png_compare.read_png(os.path.join(d, "tree.png"))[:2], (516, 256))


if __name__ == "__main__":
    unittest.main()

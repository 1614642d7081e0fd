#!/usr/bin/env python3
"""Writes the small OBJ/MTL models of the OBJ gallery (docs/obj.md, "Gallery").

    python3 scenes/obj_gallery/make_gallery.py OUT_DIR

One model per rule of docs/obj.md, each tiny and written by this script (the
project ships no third-party model), plus a JSON scene around each model that
fixes the camera and the lights, so the old and the new raylab differ only by
the OBJ/MTL rule shown. The output is deterministic (same bytes every run).
scripts/render-obj-gallery.sh runs this and renders the pictures.

    faces.obj       concave faces: an L, a ten-corner star, a comb, a ring with a slit
    no_illum.obj    a sphere whose material has no `illum` line
    no_ka.obj       a sphere whose material has no `Ka` line
    ns0.obj         a sphere with `Ns 0` and `Ks 0.9`
    names.obj       `usemtl` names with inner blanks and trailing blanks
    paths.obj       `mtllib mats\\colours.mtl` and `mtllib Mats/METALS.MTL`
                    (the files are mats/colours.mtl and mats/metals.mtl)
    smoothing.obj   cube-spheres without vn under `s off` and `s 1`, a cylinder
                    with its side in `s 1` and its caps in `s 2`
    colours.obj     a terrain with vertex colours (`v x y z r g b`)
    house_zup.obj   a house modelled with +Z up (as CAD programs write it)
    tall.obj        a tall, slender figure (a lathe-turned post), +Y up
    bench.obj       a long park bench, +Y up (a wide model)
"""
import math
import os
import sys


def fmt(x):
    s = "%.5f" % x
    if "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def vec(p):
    return " ".join(fmt(c) for c in p)


class Obj:
    """An OBJ text being built: vertices are deduplicated on their printed
    position, so faces of one surface share corners (smoothing groups average
    over shared corners)."""

    def __init__(self, header):
        self.lines = ["# " + h for h in header]
        self.index = {}
        self.count = 0
        self.ncount = 0

    def line(self, text):
        self.lines.append(text)

    def v(self, p, colour=None):
        key = vec(p)
        if colour is None and key in self.index:
            return self.index[key]
        self.count += 1
        if colour is None:
            self.index[key] = self.count
            self.lines.append("v " + key)
        else:
            self.lines.append("v " + key + " " + vec(colour))
        return self.count

    def vn(self, n):
        self.ncount += 1
        self.lines.append("vn " + vec(n))
        return self.ncount

    def face(self, corners, normals=None):
        if normals is None:
            self.lines.append("f " + " ".join(str(c) for c in corners))
        else:
            self.lines.append("f " + " ".join("%d//%d" % cn for cn in zip(corners, normals)))

    def text(self):
        return "\n".join(self.lines) + "\n"


def write(out, name, text):
    path = os.path.join(out, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", newline="\n") as f:
        f.write(text)


def scene(obj, eye, look_at, lights, ambient=0.25, background=(0.16, 0.18, 0.22), fov=40):
    """A JSON scene around one OBJ mesh (its materials from its MTL)."""
    light_text = ",\n        ".join(
        '{"type": "directional", "direction": [%s], "intensity": %s}'
        % (", ".join(fmt(c) for c in d), fmt(i)) for d, i in lights)
    return ("// OBJ gallery scene (scenes/obj_gallery/make_gallery.py): the camera and lights\n"
            "// are fixed so that only the OBJ/MTL rule differs between raylab versions.\n"
            "{\n"
            '    "camera": {"eye": [%s], "look_at": [%s], "fov": %s},\n'
            '    "background": [%s],\n'
            '    "ambient": [%s, %s, %s],\n'
            '    "lights": [\n        %s\n    ],\n'
            '    "objects": [{"type": "mesh", "file": "%s"}]\n'
            "}\n") % (", ".join(fmt(c) for c in eye), ", ".join(fmt(c) for c in look_at),
                      fmt(fov), ", ".join(fmt(c) for c in background),
                      fmt(ambient), fmt(ambient), fmt(ambient), light_text, obj)


# ---------------------------------------------------------------- shapes


def uv_sphere(obj, centre, r, nu=48, nv=24):
    """A sphere with vertex normals (smooth in every raylab version)."""
    rows = []
    for j in range(nv + 1):
        theta = math.pi * j / nv
        row = []
        for i in range(nu):
            phi = 2 * math.pi * i / nu
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            p = tuple(centre[k] + r * n[k] for k in range(3))
            row.append((obj.v(p), obj.vn(n)))
        rows.append(row)
    for j in range(nv):
        for i in range(nu):
            a, b = rows[j][i], rows[j][(i + 1) % nu]
            c, d = rows[j + 1][(i + 1) % nu], rows[j + 1][i]
            # Counter-clockwise seen from outside; the poles make triangles.
            if j == 0:
                quad = [a, d, c]
            elif j == nv - 1:
                quad = [a, d, b]
            else:
                quad = [a, d, c, b]
            obj.face([q[0] for q in quad], [q[1] for q in quad])


def cube_sphere(obj, centre, r, n=4):
    """A cube whose faces are n x n quads, pushed onto a sphere; no normals."""
    axes = [(0, 1, 2), (1, 2, 0), (2, 0, 1)]
    for a, b, c in axes:
        for sign in (1, -1):
            grid = []
            for i in range(n + 1):
                row = []
                for j in range(n + 1):
                    q = [0.0, 0.0, 0.0]
                    q[a] = sign
                    q[b] = -1 + 2 * i / n
                    q[c] = -1 + 2 * j / n
                    length = math.sqrt(sum(x * x for x in q))
                    row.append(obj.v(tuple(centre[k] + r * q[k] / length for k in range(3))))
                grid.append(row)
            for i in range(n):
                for j in range(n):
                    quad = [grid[i][j], grid[i + 1][j], grid[i + 1][j + 1], grid[i][j + 1]]
                    # (b, c, a) is right-handed: counter-clockwise from outside on +a.
                    obj.face(quad if sign > 0 else quad[::-1])


def cylinder(obj, centre, r, h, n=12, side_group="1", cap_group="2"):
    """An upright n-sided cylinder; the side in one smoothing group, the caps in another."""
    bottom = [obj.v((centre[0] + r * math.cos(2 * math.pi * i / n), centre[1],
                     centre[2] - r * math.sin(2 * math.pi * i / n))) for i in range(n)]
    top = [obj.v((centre[0] + r * math.cos(2 * math.pi * i / n), centre[1] + h,
                  centre[2] - r * math.sin(2 * math.pi * i / n))) for i in range(n)]
    obj.line("s " + side_group)
    for i in range(n):
        k = (i + 1) % n
        obj.face([bottom[i], bottom[k], top[k], top[i]])
    obj.line("s " + cap_group)
    obj.face(top)
    obj.face(bottom[::-1])


def box_faces(obj, x0, y0, z0, x1, y1, z1):
    """An axis-aligned box of six quads."""
    c = [obj.v((x, y, z)) for z in (z0, z1) for y in (y0, y1) for x in (x0, x1)]
    # c index = 4*z + 2*y + x; faces counter-clockwise from outside.
    for f in ([0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]):
        obj.face([c[k] for k in f])


def floor(obj, y, half):
    corners = [obj.v((-half, y, half)), obj.v((half, y, half)),
               obj.v((half, y, -half)), obj.v((-half, y, -half))]
    obj.face(corners)


FLOOR_MTL = "newmtl floor\nKa 0.55 0.55 0.5\nKd 0.55 0.55 0.5\nKs 0\nillum 1\n"


# ---------------------------------------------------------------- the rules


def faces(out):
    """Four concave faces, each one OBJ face in the z = 0 plane, seen from +z."""
    obj = Obj(["concave faces, one OBJ face each (make_gallery.py):",
               "an L (with a collinear corner), a ten-corner star, a comb, a ring with a slit"])
    obj.line("mtllib faces.mtl")

    def place(points, dx, dy, s=1.0):
        return [obj.v((dx + s * x, dy + s * y, 0)) for x, y in points]

    # The L starts at a corner from which a fan crosses the notch.
    ell = [(3, 0), (3, 1), (1, 1), (1, 3), (0, 3), (0, 0), (1.5, 0)]
    star = []
    for k in range(10):
        a = math.pi / 2 + k * math.pi / 5
        rad = 1.5 if k % 2 == 0 else 0.6
        star.append((rad * math.cos(a), rad * math.sin(a)))
    comb = [(0, 0), (7, 0), (7, 3), (6, 3), (6, 1), (5, 1), (5, 3), (4, 3), (4, 1),
            (3, 1), (3, 3), (2, 3), (2, 1), (1, 1), (1, 3), (0, 3)]
    # A ring cut open by a thin slit: the outer circle counter-clockwise, then
    # the inner circle back (one outline, a hole that a fan fills).
    ring = []
    m, slit = 24, math.radians(6)
    for i in range(m + 1):
        a = -math.pi / 2 + slit / 2 + (2 * math.pi - slit) * i / m
        ring.append((1.5 * math.cos(a), 1.5 * math.sin(a)))
    for i in range(m, -1, -1):
        a = -math.pi / 2 + slit / 2 + (2 * math.pi - slit) * i / m
        ring.append((0.8 * math.cos(a), 0.8 * math.sin(a)))

    obj.line("o L")
    obj.line("usemtl orange")
    obj.face(place(ell, -4.0, 0.4))
    obj.line("o star")
    obj.line("usemtl yellow")
    obj.face(place(star, 2.5, 1.9))
    obj.line("o comb")
    obj.line("usemtl teal")
    obj.face(place(comb, -4.25, -2.65, 0.5))
    obj.line("o ring")
    obj.line("usemtl violet")
    obj.face(place(ring, 2.5, -1.9))
    write(out, "faces.obj", obj.text())
    write(out, "faces.mtl",
          "newmtl orange\nKa 0.9 0.45 0.1\nKd 0.9 0.45 0.1\nillum 1\n"
          "newmtl yellow\nKa 0.9 0.8 0.15\nKd 0.9 0.8 0.15\nillum 1\n"
          "newmtl teal\nKa 0.1 0.6 0.55\nKd 0.1 0.6 0.55\nillum 1\n"
          "newmtl violet\nKa 0.55 0.3 0.85\nKd 0.55 0.3 0.85\nillum 1\n")
    write(out, "faces.json", scene("faces.obj", (0.3, 0.2, 10.5), (-0.1, 0, 0),
                                   [((0, 0, -1), 0.8)], ambient=0.2))


def sphere_on_floor(out, name, header, material):
    """A smooth sphere on a floor, lit from the left: its right side is in shadow."""
    obj = Obj(header)
    obj.line("mtllib %s.mtl" % name)
    obj.line("usemtl floor")
    floor(obj, 0, 3)
    obj.line("usemtl ball")
    uv_sphere(obj, (0, 1, 0), 1)
    write(out, name + ".obj", obj.text())
    write(out, name + ".mtl", FLOOR_MTL + "newmtl ball\n" + material)
    write(out, name + ".json", scene(name + ".obj", (0.6, 2.6, 5.2), (0, 0.8, 0),
                                     [((1, -0.6, 0.25), 0.9)], ambient=0.3))


def materials(out):
    sphere_on_floor(out, "no_illum", ["a sphere whose MTL material has no illum line"],
                    "Ka 0.7 0.12 0.1\nKd 0.7 0.12 0.1\nKs 0.6\nNs 60\n")
    sphere_on_floor(out, "no_ka", ["a sphere whose MTL material has no Ka line"],
                    "Kd 0.15 0.35 0.75\nKs 0.5\nNs 60\nillum 2\n")
    sphere_on_floor(out, "ns0", ["a sphere with Ns 0 and a strong Ks"],
                    "Ka 0.2 0.6 0.25\nKd 0.2 0.6 0.25\nKs 0.9\nNs 0\nillum 2\n")


def names(out):
    """Three spheres whose material names have blanks inside and after them."""
    obj = Obj(["material names with inner and trailing blanks (make_gallery.py)"])
    obj.line("mtllib names.mtl")
    obj.line("usemtl floor")
    floor(obj, 0, 4)
    obj.line("usemtl Hard Shiny Plastic Red")
    uv_sphere(obj, (-2.2, 0.9, 0), 0.9, 24, 12)
    obj.line("usemtl Brushed Blue Steel   ")  # trailing blanks after the name
    uv_sphere(obj, (0, 0.9, 0), 0.9, 24, 12)
    obj.line("usemtl green")  # one word: read right before too
    uv_sphere(obj, (2.2, 0.9, 0), 0.9, 24, 12)
    write(out, "names.obj", obj.text())
    write(out, "names.mtl", FLOOR_MTL +
          "newmtl Hard Shiny Plastic Red\nKa 0.8 0.1 0.1\nKd 0.8 0.1 0.1\nKs 0.6\nNs 80\nillum 2\n"
          "newmtl Brushed Blue Steel  \nKa 0.2 0.3 0.8\nKd 0.2 0.3 0.8\nKs 0.4\nNs 20\nillum 2\n"
          "newmtl green  \nKa 0.15 0.65 0.2\nKd 0.15 0.65 0.2\nKs 0.3\nNs 40\nillum 2\n")  # trailing blanks
    write(out, "names.json", scene("names.obj", (0.5, 3.2, 7.6), (0, 0.6, 0),
                                   [((0.6, -1, -0.5), 0.9)], ambient=0.3))


def paths(out):
    """Libraries named with a Windows separator and with different letter case."""
    obj = Obj(["material libraries named the Windows way and in another letter case",
               "(the files are mats/colours.mtl and mats/metals.mtl; make_gallery.py)"])
    obj.line("mtllib mats\\colours.mtl")
    obj.line("mtllib Mats/METALS.MTL")
    obj.line("usemtl floor")
    floor(obj, 0, 4)
    obj.line("usemtl orange")
    cube_sphere(obj, (-1.3, 1, 0), 1, 6)
    obj.line("usemtl gold")
    uv_sphere(obj, (1.3, 1, 0), 1, 24, 12)
    write(out, "paths.obj", obj.text())
    write(out, "mats/colours.mtl", FLOOR_MTL +
          "newmtl orange\nKa 0.9 0.4 0.05\nKd 0.9 0.4 0.05\nKs 0.3\nNs 30\nillum 2\n")
    write(out, "mats/metals.mtl",
          "newmtl gold\nKa 0.8 0.5 0.08\nKd 0.8 0.5 0.08\nKs 0.8 0.7 0.4\nNs 90\nillum 2\n"
          "Pm 1\nPr 0.25\n")  # PBR keys, as Blender's exporter writes them
    write(out, "paths.json", scene("paths.obj", (0.5, 3.0, 6.6), (0, 0.8, 0),
                                   [((0.6, -1, -0.5), 0.9)], ambient=0.3))


def smoothing(out):
    obj = Obj(["smoothing groups, no vn: s off, s 1, and a cylinder with its side",
               "in s 1 and its caps in s 2 (make_gallery.py)"])
    obj.line("mtllib smoothing.mtl")
    obj.line("usemtl floor")
    floor(obj, 0, 5)
    obj.line("usemtl clay")
    obj.line("o flat ball")
    obj.line("s off")
    cube_sphere(obj, (-2.3, 1, 0), 1, 4)
    obj.line("o smooth ball")
    obj.line("s 1")
    cube_sphere(obj, (0, 1, 0), 1, 4)
    obj.line("o cylinder")
    cylinder(obj, (2.3, 0, 0), 0.85, 1.9, 12)
    write(out, "smoothing.obj", obj.text())
    write(out, "smoothing.mtl", FLOOR_MTL +
          "newmtl clay\nKa 0.75 0.6 0.45\nKd 0.75 0.6 0.45\nKs 0.35\nNs 40\nillum 2\n")
    write(out, "smoothing.json", scene("smoothing.obj", (0.4, 4.2, 7.2), (0, 0.8, 0),
                                       [((0.7, -0.8, -0.6), 0.9)], ambient=0.25))


def colours(out):
    """A terrain, each vertex coloured by its height, with vertex normals."""
    obj = Obj(["a terrain with vertex colours v x y z r g b (make_gallery.py)"])
    obj.line("mtllib colours.mtl")
    n, size = 28, 6.0

    def height(x, z):
        return (0.9 * math.exp(-((x - 0.8) ** 2 + (z + 0.6) ** 2) / 1.6)
                + 0.6 * math.exp(-((x + 1.5) ** 2 + (z - 1.0) ** 2) / 1.0)
                + 0.12 * math.sin(2.1 * x) * math.cos(1.7 * z))

    def colour(y):
        # Linear RGB: water, sand, grass, rock, snow.
        stops = [(-0.12, (0.02, 0.08, 0.45)), (0.02, (0.6, 0.5, 0.2)), (0.12, (0.06, 0.32, 0.04)),
                 (0.5, (0.25, 0.13, 0.05)), (0.8, (0.9, 0.9, 0.9))]
        if y <= stops[0][0]:
            return stops[0][1]
        for (y0, c0), (y1, c1) in zip(stops, stops[1:]):
            if y <= y1:
                t = (y - y0) / (y1 - y0)
                return tuple(a + (b - a) * t for a, b in zip(c0, c1))
        return stops[-1][1]

    ids = []
    for i in range(n + 1):
        row = []
        for j in range(n + 1):
            x, z = -size / 2 + size * j / n, -size / 2 + size * i / n
            y, e = height(x, z), 1e-4
            nx = -(height(x + e, z) - height(x - e, z)) / (2 * e)
            nz = -(height(x, z + e) - height(x, z - e)) / (2 * e)
            length = math.sqrt(nx * nx + 1 + nz * nz)
            row.append((obj.v((x, y, z), colour(y)), obj.vn((nx / length, 1 / length, nz / length))))
        ids.append(row)
    obj.line("usemtl white")
    for i in range(n):
        for j in range(n):
            quad = [ids[i][j], ids[i + 1][j], ids[i + 1][j + 1], ids[i][j + 1]]
            obj.face([q[0] for q in quad], [q[1] for q in quad])
    write(out, "colours.obj", obj.text())
    # Vertex colours multiply kd only, so the ambient term is left out (Ka 0) and
    # a fill light keeps the slopes turned from the key from going black.
    write(out, "colours.mtl", "newmtl white\nKa 0 0 0\nKd 1 1 1\nKs 0\nillum 1\n")
    write(out, "colours.json", scene("colours.obj", (0.5, 5.2, 6.8), (0, 0, 0.3),
                                     [((0.5, -1, -0.4), 0.85), ((-0.7, -0.5, 0.2), 0.3)],
                                     ambient=0.2))


def house_zup(out):
    """A house with +Z up: walls, a gable roof and a chimney, bare-OBJ framed."""
    obj = Obj(["a house modelled with +Z up, as CAD programs write it (make_gallery.py)"])
    obj.line("mtllib house_zup.mtl")
    w, d, h, ridge = 4.0, 3.0, 2.2, 3.6  # x width, y depth, wall height, ridge height

    def box(*corners):
        box_faces(obj, *corners)

    obj.line("o walls")
    obj.line("usemtl wall")
    box(0, 0, 0, w, d, h)
    obj.line("o roof")
    obj.line("usemtl roof")
    o = 0.25  # overhang
    a, b = obj.v((-o, -o, h - 0.15)), obj.v((w + o, -o, h - 0.15))
    c, e = obj.v((w + o, d / 2, ridge)), obj.v((-o, d / 2, ridge))
    f, g = obj.v((-o, d + o, h - 0.15)), obj.v((w + o, d + o, h - 0.15))
    obj.face([a, b, c, e])  # front slope (faces -y and up)
    obj.face([g, f, e, c])  # back slope
    obj.line("usemtl wall")
    ga, gb, gc = obj.v((0, 0, h)), obj.v((0, d, h)), obj.v((0, d / 2, ridge - 0.1))
    obj.face([ga, gc, gb])  # gable at x = 0 faces -x
    ha, hb, hc = obj.v((w, 0, h)), obj.v((w, d, h)), obj.v((w, d / 2, ridge - 0.1))
    obj.face([ha, hb, hc])
    obj.line("o door")
    obj.line("usemtl door")
    box(1.6, -0.05, 0, 2.4, 0.02, 1.5)
    obj.line("o chimney")
    obj.line("usemtl brick")
    box(2.9, 0.5, 2.5, 3.4, 1.0, 4.0)
    write(out, "house_zup.obj", obj.text())
    write(out, "house_zup.mtl",
          "newmtl wall\nKd 0.85 0.8 0.65\nKs 0.05\nillum 2\n"
          "newmtl roof\nKd 0.6 0.15 0.1\nKs 0.2\nNs 20\nillum 2\n"
          "newmtl door\nKd 0.3 0.2 0.1\nillum 1\n"
          "newmtl brick\nKd 0.55 0.3 0.2\nillum 1\n")


def tall(out):
    """A lathe-turned post four times taller than wide (+Y up), with normals."""
    obj = Obj(["a tall lathe-turned post, +Y up (make_gallery.py)"])
    obj.line("mtllib tall.mtl")
    # Profile (radius, height) from the base up: base, shaft, collar, knob.
    profile = [(0.0, 0.0), (0.5, 0.0), (0.5, 0.15), (0.32, 0.3), (0.22, 0.5), (0.2, 2.4),
               (0.28, 2.6), (0.36, 2.7), (0.28, 2.8), (0.18, 2.95), (0.3, 3.2), (0.36, 3.45),
               (0.3, 3.7), (0.16, 3.88), (0.0, 3.95)]
    n = 32
    # A normal per profile point: perpendicular to the profile, averaged over its two segments.
    normals2 = []
    for k, (r, y) in enumerate(profile):
        segs = []
        for a, b in ((k - 1, k), (k, k + 1)):
            if 0 <= a and b < len(profile):
                dr, dy = profile[b][0] - profile[a][0], profile[b][1] - profile[a][1]
                length = math.hypot(dr, dy)
                segs.append((dy / length, -dr / length))
        nr, ny = sum(s[0] for s in segs), sum(s[1] for s in segs)
        length = math.hypot(nr, ny)
        normals2.append((nr / length, ny / length))
    rings = []
    for k, (r, y) in enumerate(profile):
        ring = []
        for i in range(n):
            phi = 2 * math.pi * i / n
            c, s = math.cos(phi), -math.sin(phi)
            nr, ny = normals2[k]
            ring.append((obj.v((r * c, y, r * s)), obj.vn((nr * c, ny, nr * s))))
        rings.append(ring)
    obj.line("usemtl bronze")
    for k in range(len(profile) - 1):
        for i in range(n):
            j = (i + 1) % n
            quad = [rings[k][i], rings[k][j], rings[k + 1][j], rings[k + 1][i]]
            keep, seen = [], set()
            for q in quad:  # at a pole two corners are one vertex: a triangle
                if q[0] not in seen:
                    seen.add(q[0])
                    keep.append(q)
            obj.face([q[0] for q in keep], [q[1] for q in keep])
    write(out, "tall.obj", obj.text())
    write(out, "tall.mtl", "newmtl bronze\nKd 0.6 0.4 0.2\nKs 0.6 0.5 0.35\nNs 60\nillum 2\n")


def bench(out):
    """A park bench five times longer than deep (+Y up): a wide model."""
    obj = Obj(["a park bench, long along x, +Y up (make_gallery.py)"])
    obj.line("mtllib bench.mtl")
    obj.line("usemtl wood")
    for k in range(4):  # seat slats
        z0 = -0.45 + 0.23 * k
        box_faces(obj, -2.5, 0.8, z0, 2.5, 0.88, z0 + 0.19)
    for k in range(2):  # backrest slats
        y0 = 1.15 + 0.25 * k
        box_faces(obj, -2.5, y0, -0.55, 2.5, y0 + 0.18, -0.47)
    obj.line("usemtl iron")
    for x in (-2.2, 2.2):
        box_faces(obj, x - 0.06, 0, 0.3, x + 0.06, 0.8, 0.4)  # front leg
        box_faces(obj, x - 0.06, 0, -0.47, x + 0.06, 1.7, -0.37)  # back leg and post
        box_faces(obj, x - 0.06, 0.7, -0.47, x + 0.06, 0.8, 0.4)  # seat rail
    write(out, "bench.obj", obj.text())
    write(out, "bench.mtl", "newmtl wood\nKd 0.55 0.33 0.15\nKs 0.1\nNs 10\nillum 2\n"
                            "newmtl iron\nKd 0.08 0.1 0.09\nKs 0.4\nNs 40\nillum 2\n")


def main():
    if len(sys.argv) != 2:
        sys.stderr.write("usage: make_gallery.py OUT_DIR\n")
        return 2
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    faces(out)
    materials(out)
    names(out)
    paths(out)
    smoothing(out)
    colours(out)
    house_zup(out)
    tall(out)
    bench(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())

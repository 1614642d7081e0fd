#!/usr/bin/env python3
"""Writes the small demo meshes in this folder (deterministic output).

    python3 scenes/meshes/make_meshes.py

torus.obj + torus.mtl: a smooth torus (quads with vertex normals), major
radius 1, minor radius 0.35, around the y axis, centred on the origin.
gem.obj + gem.mtl: a flat-shaded icosphere (icosahedron subdivided once,
no vertex normals), radius 1, centred on the origin, in a gold mirror
material (illum 3) on the upper half and a glass material (illum 7) below.
"""
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def fmt(x):
    s = "%.5f" % x
    return "0.00000" if s == "-0.00000" else s


def write_torus(nu=36, nv=18, major=1.0, minor=0.35):
    lines = ["# torus: major radius %g, minor radius %g, %d x %d quads (make_meshes.py)"
             % (major, minor, nu, nv), "mtllib torus.mtl", "o torus"]
    for i in range(nu):
        phi = 2 * math.pi * i / nu
        for j in range(nv):
            theta = 2 * math.pi * j / nv
            # Point on the tube circle around the ring point (cos phi, 0, sin phi) * major.
            nx = math.cos(theta) * math.cos(phi)
            ny = math.sin(theta)
            nz = math.cos(theta) * math.sin(phi)
            lines.append("v %s %s %s" % (fmt(major * math.cos(phi) + minor * nx),
                                         fmt(minor * ny),
                                         fmt(major * math.sin(phi) + minor * nz)))
            lines.append("vn %s %s %s" % (fmt(nx), fmt(ny), fmt(nz)))
    lines.append("usemtl coral")
    for i in range(nu):
        for j in range(nv):
            a = i * nv + j + 1
            b = ((i + 1) % nu) * nv + j + 1
            c = ((i + 1) % nu) * nv + (j + 1) % nv + 1
            d = i * nv + (j + 1) % nv + 1
            # Counter-clockwise seen from outside: the normal is d(theta) x d(phi).
            lines.append("f %d//%d %d//%d %d//%d %d//%d" % (a, a, d, d, c, c, b, b))
    with open(os.path.join(HERE, "torus.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(HERE, "torus.mtl"), "w") as f:
        f.write("# coral plastic: diffuse + Blinn-Phong highlight\n"
                "newmtl coral\nKa 0.9 0.35 0.3\nKd 0.9 0.35 0.3\nKs 0.5 0.5 0.5\nNs 60\nillum 2\n")


def write_gem():
    t = (1 + math.sqrt(5)) / 2
    verts = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
             (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    verts = [tuple(c / math.sqrt(1 + t * t) for c in v) for v in verts]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    midpoint = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in midpoint:
            m = [(verts[a][k] + verts[b][k]) / 2 for k in range(3)]
            n = math.sqrt(sum(c * c for c in m))
            verts.append(tuple(c / n for c in m))
            midpoint[key] = len(verts) - 1
        return midpoint[key]

    sub = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        sub += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    lines = ["# icosphere (icosahedron subdivided once), radius 1, flat shaded (make_meshes.py)",
             "mtllib gem.mtl", "o gem"]
    lines += ["v %s %s %s" % tuple(fmt(c) for c in v) for v in verts]
    for name, upper in (("gold", True), ("glass", False)):
        lines.append("usemtl " + name)
        for f in sub:
            centroid_y = sum(verts[i][1] for i in f) / 3
            if (centroid_y >= 0) == upper:
                lines.append("f %d %d %d" % tuple(i + 1 for i in f))
    with open(os.path.join(HERE, "gem.obj"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(HERE, "gem.mtl"), "w") as f:
        f.write("# illum 3: mirror km = Ks; illum 7: refraction kt = 1 - d, ior Ni\n"
                "newmtl gold\nKa 0.2 0.15 0.05\nKd 0.35 0.25 0.08\nKs 0.8 0.6 0.2\nNs 200\n"
                "illum 3\n\n"
                "newmtl glass\nKa 0 0 0\nKd 0.02 0.04 0.05\nKs 0.1 0.1 0.1\nNs 300\nd 0.1\nNi 1.5\n"
                "illum 7\n")


if __name__ == "__main__":
    write_torus()
    write_gem()

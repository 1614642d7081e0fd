#!/usr/bin/env python3
"""Converts an NFF scene (Eric Haines' Neutral File Format, the SPD's format) to
POV-Ray 3.7 scene language, for timing POV-Ray against raylab on the same scene.

    scripts/spd/nff2pov.py SCENE.nff -o SCENE.pov [--triangles mesh2|mesh|objects]
                                                  [--polygons triangulate|polygon]

What the SPD's own POV conversion (its readnff and lib*.c, output format
"POV-Ray 3.1") does, with the NFF read as raylab reads it (docs/spd.md), so
that both renderers show the same picture:

  v from/at/up/angle   camera: location = from; direction = unit(at - from);
                       up = the up vector made perpendicular, scaled to
                       2 tan(angle/2); right = -(up x direction) at the same
                       length (POV is left-handed; SPD negates right). The
                       field of view is `angle` edge to edge, as in raylab.
                       hither has no POV equivalent and is left out.
  b R G B              background.
  l X Y Z [R G B]      point light; without a colour sqrt(L)/(2L) for L lights
                       (SPD's relative intensity; raylab's NFF reading).
  f R G B Kd Ks Shine T ior
                       pigment R G B (transmit T when T > 0); finish: ambient
                       Kd*sqrt(L)/(2L) (raylab: ka = colour*Kd times Ia), diffuse
                       Kd, phong Ks phong_size Shine (white Phong highlight),
                       reflection Ks; T > 0: interior { ior }. POV weights a
                       transmitting surface's ambient and diffuse terms by
                       (1 - T); raylab does not, so both are divided by (1 - T).
  s X Y Z r            sphere of radius |r| (POV's objects are two-sided).
  c base r0 apex r1    open cone (open cylinder when r0 = r1), |radii|.
  p N, pp N            triangles (pp: smooth_triangle with the vertex normals);
                       polygons of more vertices are ear-clipped into triangles
                       (--polygons triangulate, the SPD converter also splits
                       them) or written as POV `polygon` objects.

Triangles go into one mesh per material (--triangles mesh2, the default:
POV-Ray parses indexed meshes fastest and traces them with their own bounding
tree), as a `mesh` of triangle statements, or as one object per triangle as
SPD's converter writes them (--triangles objects). Global settings: no
anti-aliasing is a command-line matter (-A); max_trace_level 5 (SPD depth 5;
POV counts the eye ray as level 1, like SPD); assumed_gamma 1 (colours are
linear, as in raylab).

Python 3 standard library only.
"""

import argparse
import math
import os
import sys


class NffError(Exception):
    pass


# ---- reading NFF ----------------------------------------------------------

def tokens(text):
    """(token, line) pairs; '#' starts a comment to the end of the line."""
    for lineno, line in enumerate(text.splitlines(), 1):
        cut = line.find("#")
        if cut >= 0:
            line = line[:cut]
        for tok in line.split():
            yield tok, lineno


def is_number(tok):
    try:
        float(tok)
        return True
    except ValueError:
        return False


class Scene:
    def __init__(self):
        self.frm = self.at = self.up = None
        self.angle = None
        self.hither = None
        self.resolution = None
        self.background = (0.0, 0.0, 0.0)
        self.lights = []       # (position, colour or None)
        self.materials = []    # (r, g, b, kd, ks, shine, t, ior)
        self.objects = []      # (kind, material index, data)


def read_nff(text):
    sc = Scene()
    toks = list(tokens(text))
    i = 0
    n = len(toks)

    def num(what):
        nonlocal i
        if i >= n:
            raise NffError("unexpected end of file: expected %s" % what)
        tok, line = toks[i]
        try:
            v = float(tok)
        except ValueError:
            raise NffError("line %d: expected a number for %s, got '%s'" % (line, what, tok))
        if not math.isfinite(v):
            raise NffError("line %d: %s must be finite" % (line, what))
        i += 1
        return v

    def nums(k, what):
        return tuple(num(what) for _ in range(k))

    def keyword(word):
        nonlocal i
        if i >= n or toks[i][0] != word:
            got = toks[i][0] if i < n else "end of file"
            raise NffError("expected '%s' in the view block, got '%s'" % (word, got))
        i += 1

    def material():
        if not sc.materials:
            # raylab: objects before any 'f' get a plain white diffuse surface
            sc.materials.append((1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 1.0))
        return len(sc.materials) - 1

    while i < n:
        tok, line = toks[i]
        i += 1
        if tok == "v":
            keyword("from"); sc.frm = nums(3, "from")
            keyword("at"); sc.at = nums(3, "at")
            keyword("up"); sc.up = nums(3, "up")
            keyword("angle"); sc.angle = num("angle")
            if i < n and toks[i][0] == "hither":
                i += 1
                sc.hither = num("hither")
            if i < n and toks[i][0] == "resolution":
                i += 1
                sc.resolution = (int(num("resolution x")), int(num("resolution y")))
        elif tok == "b":
            sc.background = nums(3, "background colour")
        elif tok == "l":
            pos = nums(3, "light position")
            col = None
            if i < n and is_number(toks[i][0]):
                col = nums(3, "light colour")
            sc.lights.append((pos, col))
        elif tok == "f":
            sc.materials.append(nums(8, "f R G B Kd Ks Shine T ior"))
        elif tok == "s":
            sc.objects.append(("s", material(), nums(4, "sphere")))
        elif tok == "c":
            sc.objects.append(("c", material(), nums(8, "cone")))
        elif tok in ("p", "pp"):
            count = int(num("vertex count"))
            if count < 3:
                raise NffError("line %d: a polygon needs 3 vertices or more" % line)
            per = 6 if tok == "pp" else 3
            verts = [nums(per, "vertex") for _ in range(count)]
            sc.objects.append((tok, material(), verts))
        else:
            raise NffError("line %d: unknown entity '%s'" % (line, tok))
    if sc.frm is None:
        raise NffError("no view ('v') block")
    return sc


# ---- geometry helpers -----------------------------------------------------

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def unit(a):
    d = math.sqrt(dot(a, a))
    return scale(a, 1.0 / d) if d > 0 else a


def newell_normal(pts):
    nx = ny = nz = 0.0
    for k in range(len(pts)):
        a, b = pts[k], pts[(k + 1) % len(pts)]
        nx += (a[1] - b[1]) * (a[2] + b[2])
        ny += (a[2] - b[2]) * (a[0] + b[0])
        nz += (a[0] - b[0]) * (a[1] + b[1])
    return (nx, ny, nz)


def ear_clip(pts):
    """Index triples of a simple polygon (any winding, concave allowed), by ear
    clipping in the plane of its dominant normal axis. Collinear vertices are
    clipped as zero-area ears at the end. Returns [] for a zero-area polygon."""
    nrm = newell_normal(pts)
    ax = max(range(3), key=lambda k: abs(nrm[k]))
    if nrm[ax] == 0.0:
        return []
    u, v = [(1, 2), (2, 0), (0, 1)][ax]
    sign = 1.0 if nrm[ax] > 0 else -1.0
    p2 = [(p[u], p[v]) for p in pts]

    def area2(a, b, c):
        return sign * ((p2[b][0] - p2[a][0]) * (p2[c][1] - p2[a][1]) -
                       (p2[b][1] - p2[a][1]) * (p2[c][0] - p2[a][0]))

    def inside(p, a, b, c):
        # p inside or on triangle a, b, c (counter-clockwise after 'sign')
        return area2(a, b, p) >= 0 and area2(b, c, p) >= 0 and area2(c, a, p) >= 0

    idx = list(range(len(pts)))
    tris = []
    k = 0
    stall = 0
    while len(idx) > 3:
        m = len(idx)
        a, b, c = idx[(k - 1) % m], idx[k % m], idx[(k + 1) % m]
        ear = area2(a, b, c) > 0
        if ear:
            for q in idx:
                if q in (a, b, c):
                    continue
                if p2[q] in (p2[a], p2[b], p2[c]):
                    continue
                if inside(q, a, b, c):
                    ear = False
                    break
        if ear:
            tris.append((a, b, c))
            del idx[k % m]
            stall = 0
        else:
            k += 1
            stall += 1
            if stall > m:
                # no convex ear left: only degenerate (collinear) corners remain
                a, b, c = idx[(k - 1) % m], idx[k % m], idx[(k + 1) % m]
                del idx[k % m]
                stall = 0
    if len(idx) == 3 and area2(*idx) > 0:
        tris.append(tuple(idx))
    return tris


# ---- writing POV ----------------------------------------------------------

def f(x):
    """A number as POV reads it back exactly (shortest round-trip repr)."""
    r = repr(float(x))
    if r.endswith(".0"):
        r = r[:-2]
    return "0" if r == "-0" else r


def vec(v):
    return "<%s,%s,%s>" % (f(v[0]), f(v[1]), f(v[2]))


def light_intensity(sc):
    L = max(1, len(sc.lights))
    return math.sqrt(L) / (2.0 * L)


def write_pov(sc, out, triangles="mesh2", polygons="triangulate", source=""):
    w = out.write
    ia = light_intensity(sc)
    w("// POV-Ray 3.7 scene written by raylab's scripts/spd/nff2pov.py from %s\n" % source)
    w("#version 3.7;\n")
    w("global_settings { assumed_gamma 1.0 max_trace_level 5 }\n")
    w("background { rgb %s }\n" % vec(sc.background))

    # camera, as SPD's lib_output_viewpoint writes it for POV-Ray
    frm, at, up0 = sc.frm, sc.at, unit(sc.up)
    view = unit(sub(at, frm))
    right = unit(cross(up0, view))
    up = unit(cross(view, right))
    height = 2.0 * math.tan(math.pi * sc.angle / 360.0)
    resx, resy = sc.resolution or (512, 512)
    width = height * resx / resy  # SPD: aspect 1 with square pixels
    w("camera {\n  location %s\n  direction %s\n  right %s\n  up %s\n}\n" % (
        vec(frm), vec(view), vec(scale(right, -width)), vec(scale(up, height))))

    for pos, col in sc.lights:
        c = col if col is not None else (ia, ia, ia)
        w("light_source { %s rgb %s }\n" % (vec(pos), vec(c)))

    used = sorted({o[1] for o in sc.objects})
    for m in used:
        r, g, b, kd, ks, shine, t, ior = sc.materials[m]
        att = 1.0 / (1.0 - t) if 0 < t < 1 else 1.0
        pig = "rgb %s" % vec((r, g, b)) if t <= 0 else "rgbt <%s,%s,%s,%s>" % (f(r), f(g), f(b), f(t))
        fin = "ambient %s diffuse %s" % (f(kd * ia * att), f(kd * att))
        if ks > 0:
            fin += " phong %s phong_size %s reflection %s" % (f(ks), f(shine), f(ks))
        w("#declare M%d = material {\n  texture { pigment { %s } finish { %s } }\n" % (m, pig, fin))
        if t > 0:
            w("  interior { ior %s }\n" % f(ior))
        w("}\n")

    # group triangles per material, in file order of the material's first use
    tri_groups = {}   # (material, smooth) -> list of (verts[3], normals[3] or None)

    def add_tri(m, vs, ns):
        tri_groups.setdefault((m, ns is not None), []).append((vs, ns))

    for kind, m, data in sc.objects:
        if kind == "s":
            x, y, z, r = data
            w("sphere { %s,%s material { M%d } }\n" % (vec((x, y, z)), f(abs(r)), m))
        elif kind == "c":
            bx, by, bz, br, axx, ay, az, ar = data
            if abs(br) == abs(ar):
                w("cylinder { %s,%s,%s open material { M%d } }\n" % (
                    vec((bx, by, bz)), vec((axx, ay, az)), f(abs(br)), m))
            else:
                w("cone { %s,%s,%s,%s open material { M%d } }\n" % (
                    vec((bx, by, bz)), f(abs(br)), vec((axx, ay, az)), f(abs(ar)), m))
        else:
            pts = [v[:3] for v in data]
            nrms = [v[3:] for v in data] if kind == "pp" else None
            if len(pts) > 3 and polygons == "polygon" and kind == "p":
                w("polygon { %d, %s material { M%d } }\n" % (
                    len(pts) + 1, ", ".join(vec(p) for p in pts + [pts[0]]), m))
                continue
            tris = [(0, 1, 2)] if len(pts) == 3 else ear_clip(pts)
            for a, b, c in tris:
                vs = (pts[a], pts[b], pts[c])
                if dot(cross(sub(vs[1], vs[0]), sub(vs[2], vs[0])),
                       cross(sub(vs[1], vs[0]), sub(vs[2], vs[0]))) == 0.0:
                    continue  # zero area (raylab drops these too); POV would warn
                add_tri(m, vs, (nrms[a], nrms[b], nrms[c]) if nrms else None)

    for (m, smooth), tris in tri_groups.items():
        if triangles == "objects":
            for vs, ns in tris:
                if ns:
                    w("smooth_triangle { %s,%s, %s,%s, %s,%s material { M%d } }\n" % (
                        vec(vs[0]), vec(ns[0]), vec(vs[1]), vec(ns[1]), vec(vs[2]), vec(ns[2]), m))
                else:
                    w("triangle { %s, %s, %s material { M%d } }\n" % (vec(vs[0]), vec(vs[1]), vec(vs[2]), m))
        elif triangles == "mesh":
            w("mesh {\n")
            for vs, ns in tris:
                if ns:
                    w("  smooth_triangle { %s,%s, %s,%s, %s,%s }\n" % (
                        vec(vs[0]), vec(ns[0]), vec(vs[1]), vec(ns[1]), vec(vs[2]), vec(ns[2])))
                else:
                    w("  triangle { %s, %s, %s }\n" % (vec(vs[0]), vec(vs[1]), vec(vs[2])))
            w("  material { M%d }\n}\n" % m)
        else:
            vindex, vlist = {}, []
            nindex, nlist = {}, []
            faces, nfaces = [], []

            def vid(p):
                if p not in vindex:
                    vindex[p] = len(vlist)
                    vlist.append(p)
                return vindex[p]

            def nid(p):
                if p not in nindex:
                    nindex[p] = len(nlist)
                    nlist.append(p)
                return nindex[p]

            for vs, ns in tris:
                faces.append(tuple(vid(p) for p in vs))
                if smooth:
                    nfaces.append(tuple(nid(p) for p in ns))
            w("mesh2 {\n  vertex_vectors { %d,\n" % len(vlist))
            w(",\n".join("    " + vec(p) for p in vlist) + "\n  }\n")
            if smooth:
                w("  normal_vectors { %d,\n" % len(nlist))
                w(",\n".join("    " + vec(p) for p in nlist) + "\n  }\n")
            w("  face_indices { %d,\n" % len(faces))
            w(",\n".join("    <%d,%d,%d>" % t for t in faces) + "\n  }\n")
            if smooth:
                w("  normal_indices { %d,\n" % len(nfaces))
                w(",\n".join("    <%d,%d,%d>" % t for t in nfaces) + "\n  }\n")
            w("  material { M%d }\n}\n" % m)


def convert(text, triangles="mesh2", polygons="triangulate", source=""):
    import io
    sc = read_nff(text)
    buf = io.StringIO()
    write_pov(sc, buf, triangles, polygons, source)
    return buf.getvalue()


def main(argv=None):
    ap = argparse.ArgumentParser(description="Convert an NFF scene to POV-Ray 3.7 scene language.")
    ap.add_argument("nff")
    ap.add_argument("-o", "--output", help="output .pov (default: standard output)")
    ap.add_argument("--triangles", choices=["mesh2", "mesh", "objects"], default="mesh2",
                    help="triangles as one mesh2/mesh per material, or one object each (default mesh2)")
    ap.add_argument("--polygons", choices=["triangulate", "polygon"], default="triangulate",
                    help="polygons of more than 3 vertices: ear-clipped triangles or POV polygon objects")
    args = ap.parse_args(argv)
    try:
        with open(args.nff, encoding="utf-8-sig") as fh:
            text = fh.read()
        pov = convert(text, args.triangles, args.polygons, os.path.basename(args.nff))
    except (OSError, NffError, UnicodeDecodeError) as e:
        sys.stderr.write("nff2pov: error: %s: %s\n" % (args.nff, e))
        return 1
    if args.output:
        tmp = args.output + ".tmp"
        with open(tmp, "w", encoding="ascii") as fh:
            fh.write(pov)
        os.replace(tmp, args.output)
    else:
        sys.stdout.write(pov)
    return 0


if __name__ == "__main__":
    sys.exit(main())

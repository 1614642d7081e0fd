#!/usr/bin/env python3
"""Writes SPD scenes that ../shared/scenes/spd does not have: mount and tree.

Eric Haines' Standard Procedural Databases (public domain) generate their
scenes with small C programs (mount.c, tree.c and the lib*.c output library).
This is the project's own port of the two generators and of the NFF branch of
that library: the same arithmetic in the same order (IEEE double, the same
libm), printed with C's %g, so the default sizes give files byte-identical to
what SPD's generators write (checked against SPD's C generators; the tests
pin the SHA-256 of both files).

    scripts/spd/generate.py mount [-s SIZE] [-o FILE]   # default size 6:  8192 triangles + 4 glass spheres
    scripts/spd/generate.py tree  [-s SIZE] [-o FILE]   # default size 11: 4095 cones + 4095 spheres + 1 square

Without -o the NFF goes to standard output. Python 3 standard library only.
"""

import argparse
import math
import sys

PI = 3.141592653589793  # def.h


def g(x):
    """C's printf("%g")."""
    return "%g" % x


def vec_g(v):
    return "%s %s %s" % (g(v[0]), g(v[1]), g(v[2]))


# ---- libvec.c -------------------------------------------------------------

def normalize(v):
    """lib_normalize_vector, in place; returns the divisor."""
    d = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    if d > 0.0:
        v[0] /= d
        v[1] /= d
        v[2] /= d
    return d


def zero_matrix():
    return [[0.0] * 4 for _ in range(4)]


def identity_matrix():
    m = zero_matrix()
    for i in range(4):
        m[i][i] = 1.0
    return m


X_AXIS, Y_AXIS, Z_AXIS = 0, 1, 2


def rotate_matrix(axis, angle):
    """lib_create_rotate_matrix (row vectors: p' = p M)."""
    m = zero_matrix()
    c = math.cos(angle)
    s = math.sin(angle)
    if axis == X_AXIS:
        m[0][0] = 1.0
        m[1][1] = c
        m[2][2] = c
        m[1][2] = s
        m[2][1] = -s
    elif axis == Y_AXIS:
        m[1][1] = 1.0
        m[0][0] = c
        m[2][2] = c
        m[2][0] = s
        m[0][2] = -s
    else:
        m[2][2] = 1.0
        m[0][0] = c
        m[1][1] = c
        m[0][1] = s
        m[1][0] = -s
    m[3][3] = 1.0
    return m


def axis_rotate_matrix(a, angle):
    """lib_create_axis_rotate_matrix: rotation by angle about the unit axis a."""
    c = math.cos(angle)
    s = math.sin(angle)
    omc = 1.0 - c
    X, Y, Z = a[0], a[1], a[2]
    return [
        [X * X + (1.0 - X * X) * c, X * Y * omc + Z * s, X * Z * omc - Y * s, 0.0],
        [X * Y * omc - Z * s, Y * Y + (1.0 - Y * Y) * c, Y * Z * omc + X * s, 0.0],
        [X * Z * omc + Y * s, Y * Z * omc - X * s, Z * Z + (1.0 - Z * Z) * c, 0.0],
        [0.0, 0.0, 0.0, 1.0],
    ]


def matrix_multiply(a, b):
    """lib_matrix_multiply: a * b, the sum in C's order."""
    return [[a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j] + a[i][3] * b[3][j]
             for j in range(4)] for i in range(4)]


def transform_vector(v, m):
    return [v[0] * m[0][0] + v[1] * m[1][0] + v[2] * m[2][0],
            v[0] * m[0][1] + v[1] * m[1][1] + v[2] * m[2][1],
            v[0] * m[0][2] + v[1] * m[1][2] + v[2] * m[2][2]]


def transform_point(v, m):
    return [v[0] * m[0][0] + v[1] * m[1][0] + v[2] * m[2][0] + m[3][0],
            v[0] * m[0][1] + v[1] * m[1][1] + v[2] * m[2][1] + m[3][1],
            v[0] * m[0][2] + v[1] * m[1][2] + v[2] * m[2][2] + m[3][2]]


M1, IA1, IC1 = 134456, 8121, 28411


def gauss_rand(iseed):
    """lib_gauss_rand: Numerical Recipes' GASDEV on a small LCG.
    C's 'ix1 * 2.0 * RM1' expands to ix1 * 2.0 * 1.0/M1 (RM1 is an unbracketed macro)."""
    ix2 = iseed
    while True:
        ix1 = (IC1 + ix2 * IA1) % M1
        ix2 = (IC1 + ix1 * IA1) % M1
        v1 = ix1 * 2.0 * 1.0 / M1 - 1.0
        v2 = ix2 * 2.0 * 1.0 / M1 - 1.0
        r = v1 * v1 + v2 * v2
        if r < 1.0:
            break
    fac = math.sqrt(-2.0 * math.log(r) / r)
    return v1 * fac


# ---- the NFF branch of libpr1.c, libpr2.c, libply.c -----------------------

class NffWriter:
    def __init__(self):
        self.lines = []

    def background(self, c):
        self.lines.append("b " + vec_g(c))

    def viewpoint(self, frm, at, up, angle, hither, resx, resy):
        self.lines += ["v", "from " + vec_g(frm), "at " + vec_g(at), "up " + vec_g(up),
                       "angle " + g(angle), "hither " + g(hither),
                       "resolution %d %d" % (resx, resy)]

    def light(self, p):
        self.lines.append("l " + vec_g(p))

    def color(self, col, ka, kd, ks, ks_spec, ang, kt, ior):
        """lib_output_color: the highlight's half angle becomes a Phong exponent."""
        del ka, ks_spec  # not in NFF
        ang_radians = PI * ang / 180.0
        if ang_radians <= 0.0:
            phong_pow = 100000.0
        elif ang_radians >= PI / 2.0:
            phong_pow = 1.0
        else:
            phong_pow = math.log(0.5) / math.log(math.cos(ang_radians))
        self.lines.append("f %s %s %s %s %s %s" % (vec_g(col), g(kd), g(ks), g(phong_pow), g(kt), g(ior)))

    def sphere(self, c, r):
        self.lines.append("s %s %s" % (vec_g(c), g(r)))

    def cylcone(self, base, base_r, apex, apex_r):
        self.lines.append("c %s %s %s %s" % (vec_g(base), g(base_r), vec_g(apex), g(apex_r)))

    def polygon(self, verts):
        """lib_output_polygon: adjacent vertices closer than EPSILON2 merge; fewer than 3: nothing."""
        verts = [list(v) for v in verts]
        i = 0
        while i < len(verts):
            d = [verts[i][k] - verts[(i + 1) % len(verts)][k] for k in range(3)]
            if normalize(d) < 1.0e-6:
                del verts[i]
            else:
                i += 1
        if len(verts) < 3:
            return
        self.lines.append("p %d" % len(verts))
        self.lines += [vec_g(v) for v in verts]

    def text(self):
        return "\n".join(self.lines) + "\n"


# ---- mount.c --------------------------------------------------------------

def mount(size_factor=6):
    """Fractal mountain (Carpenter's midpoint subdivision with SPD's original,
    'faulty' hash, as in the 1987 article) and a pyramid of four glass spheres."""
    if not 1 <= size_factor <= 7:
        raise ValueError("mount: size must be 1..7 (the C hash shifts by 7 - size)")
    out = NffWriter()
    fractal_dimension = 2.2
    mountain_no = 21
    x_corner, y_corner, width_all = -1.0, -1.0, 2.0

    def hash_rand(a, b, c):
        return ((a << (23 - c)) + (b << (15 - c)) + (a << (7 - c))) & 0xffff

    out.background([0.078, 0.361, 0.753])
    out.viewpoint([-1.6, 1.6, 1.7], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 45.0, 0.01, 512, 512)
    out.light([-100.0, -100.0, 100.0])
    out.color([1.0, 1.0, 1.0], 0.0, 0.1, 0.1, 0.4, 6.7, 0.9, 1.5)

    # create_spheres(center): the pyramid of crystal spheres
    center = [-0.8, 0.8, 1.00]
    radius = 0.17
    axis = [1.0, 1.0, 0.0]
    normalize(axis)
    angle = math.acos(-1.0 / 3.0)
    pt = [0.0, 0.0, radius * math.sqrt(3.0 / 2.0)]
    out.sphere([center[0] + pt[0], center[1] + pt[1], center[2] + pt[2]], radius)
    new_pt = transform_vector(pt, axis_rotate_matrix(axis, angle))
    for i in range(3):
        s = transform_vector(new_pt, rotate_matrix(Z_AXIS, float(i) * 2.0 * PI / 3.0))
        out.sphere([s[0] + center[0], s[1] + center[1], s[2] + center[2]], radius)

    out.color([0.5, 0.45, 0.35], 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)

    num_pts = 1 << size_factor
    fnum_pts = float(num_pts)
    ratio = 2.0 / math.exp(math.log(2.0) / (fractal_dimension - 1.0))
    roughness = math.sqrt(ratio * ratio - 1.0)

    def grow(width, ll_x, ll_y, ll_fz, lr_fz, ur_fz, ul_fz):
        if width == 1:
            l_fx = x_corner + float(ll_x) * width_all / fnum_pts
            r_fx = x_corner + float(ll_x + 1) * width_all / fnum_pts
            l_fy = y_corner + float(ll_y) * width_all / fnum_pts
            u_fy = y_corner + float(ll_y + 1) * width_all / fnum_pts
            corners = [(l_fx, l_fy, ll_fz), (r_fx, l_fy, lr_fz), (r_fx, u_fy, ur_fz), (l_fx, u_fy, ul_fz)]
            for tri in range(2):
                out.polygon([corners[(v + tri * 2) % 4] for v in range(3)])
            return
        half = width >> 1
        hside_length = float(half) * width_all / fnum_pts
        rise_height = hside_length * roughness
        iz = mountain_no + hash_rand(ll_x + half, ll_y, size_factor)
        lower_fz = (ll_fz + lr_fz) / 2.0 + rise_height * gauss_rand(iz)
        iz = mountain_no + hash_rand(ll_x + width, ll_y + half, size_factor)
        right_fz = (lr_fz + ur_fz) / 2.0 + rise_height * gauss_rand(iz)
        iz = mountain_no + hash_rand(ll_x + half, ll_y + width, size_factor)
        upper_fz = (ur_fz + ul_fz) / 2.0 + rise_height * gauss_rand(iz)
        iz = mountain_no + hash_rand(ll_x, ll_y + half, size_factor)
        left_fz = (ul_fz + ll_fz) / 2.0 + rise_height * gauss_rand(iz)
        iz = mountain_no + hash_rand(ll_x + half, ll_y + half, size_factor)
        middle_fz = (ll_fz + lr_fz + ur_fz + ul_fz) / 4.0 + 1.4142136 * rise_height * gauss_rand(iz)
        grow(half, ll_x, ll_y, ll_fz, lower_fz, middle_fz, left_fz)
        grow(half, ll_x + half, ll_y, lower_fz, lr_fz, right_fz, middle_fz)
        grow(half, ll_x + half, ll_y + half, middle_fz, right_fz, ur_fz, upper_fz)
        grow(half, ll_x, ll_y + half, left_fz, middle_fz, upper_fz, ul_fz)

    grow(num_pts, 0, 0, 0.0, 0.0, 0.0, 0.0)
    return out.text()


# ---- tree.c ---------------------------------------------------------------

def tree(size_factor=11):
    """Aono & Kunii's binary tree of cones with a sphere at every joint, on a
    green square, seven lights."""
    if not 0 <= size_factor <= 20:
        raise ValueError("tree: size must be 0..20")
    out = NffWriter()
    br_angle = (40.0, 25.0)
    br_contr = (0.65, 0.70)
    div_angle = (90.0, 140.0 + 90.0)
    br_diameter = 0.67
    width_height_ratio = 0.15

    out.background([0.078, 0.361, 0.753])
    out.viewpoint([4.5, 0.4, 2.0], [0.0, 0.0, 1.5], [0.0, 0.0, 1.0], 45.0, 1.0, 512, 512)
    for p in ([-5.0, 5.0, 50.0], [30.0, -30.0, 30.0], [-40.0, -30.0, 20.0], [10.0, 30.0, 40.0],
              [-30.0, 40.0, 10.0], [50.0, 25.0, 20.0], [-10.0, -60.0, 30.0]):
        out.light(p)
    out.color([0.2, 0.7, 0.2], 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    out.polygon([[50.0, 50.0, 0.0], [-50.0, 50.0, 0.0], [-50.0, -50.0, 0.0], [50.0, -50.0, 0.0]])
    out.color([0.55, 0.4, 0.2], 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0)

    # create_tree(): one rotate-scale-translate matrix per branch
    rst = []
    for i in range(2):
        temp1 = rotate_matrix(X_AXIS, br_angle[i] * PI / 180.0)
        temp2 = rotate_matrix(Z_AXIS, div_angle[i] * PI / 180.0)
        tempr = matrix_multiply(temp1, temp2)
        tempst = identity_matrix()
        tempst[0][0] = br_contr[i]
        tempst[1][1] = br_contr[i]
        tempst[2][2] = br_contr[i]
        tempst[3][2] = 1.0
        rst.append(matrix_multiply(tempr, tempst))

    def grow(cur, scale, depth):
        base = transform_point([0.0, 0.0, 0.0], cur)
        base_r = scale * width_height_ratio
        apex = transform_point([0.0, 0.0, 1.0], cur)
        apex_r = base_r * br_diameter
        out.cylcone(base, base_r, apex, apex_r)
        out.sphere(apex, apex_r)
        if depth > 0:
            for i in range(2):
                grow(matrix_multiply(rst[i], cur), scale * br_diameter, depth - 1)

    grow(identity_matrix(), 1.0, size_factor)
    return out.text()


GENERATORS = {"mount": (mount, 6), "tree": (tree, 11)}


def main(argv=None):
    ap = argparse.ArgumentParser(description="Write an SPD scene (NFF) that ../shared does not have.")
    ap.add_argument("scene", choices=sorted(GENERATORS))
    ap.add_argument("-s", "--size", type=int, help="SPD size factor (default: SPD's, mount 6, tree 11)")
    ap.add_argument("-o", "--output", help="output file (default: standard output)")
    args = ap.parse_args(argv)
    fn, default_size = GENERATORS[args.scene]
    sys.setrecursionlimit(10000)
    try:
        text = fn(default_size if args.size is None else args.size)
    except ValueError as e:
        ap.error(str(e))
    if args.output:
        tmp = args.output + ".tmp"
        with open(tmp, "w", encoding="ascii", newline="\n") as f:
            f.write(text)
        import os
        os.replace(tmp, args.output)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Writes the textures and the textured OBJ of scenes/textures*.json.

raylab ships no third-party image: everything here is computed. Pure Python
(zlib and struct), so it runs anywhere python3 does:

    python3 scenes/textures/make_textures.py   # rewrites the files beside it
"""
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write_png(name, width, height, pixels, channels=3):
    """8-bit PNG from rows of pixel tuples (0..255)."""
    raw = b"".join(b"\0" + bytes(v for px in row for v in px) for row in pixels)
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)
    colour_type = {1: 0, 3: 2, 4: 6}[channels]
    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour_type, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 9))
    png += chunk(b"IEND", b"")
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(png)


def hsv(h, s, v):
    i = int(h * 6) % 6
    f = h * 6 - int(h * 6)
    p, q, t = v * (1 - s), v * (1 - f * s), v * (1 - (1 - f) * s)
    r, g, b = [(v, t, p), (q, v, p), (p, v, t), (p, q, v), (t, p, v), (v, p, q)][i]
    return tuple(int(round(255 * c)) for c in (r, g, b))


def uv_grid(size=256, cells=8):
    """A UV test grid: hue runs with u, brightness with v (bright at the top,
    v = 1), white lines between cells, a red corner marker at the top left."""
    rows = []
    for y in range(size):
        row = []
        v = 1 - (y + 0.5) / size
        for x in range(size):
            u = (x + 0.5) / size
            cx, cy = int(u * cells), int(v * cells)
            line = (x % (size // cells)) < 2 or (y % (size // cells)) < 2
            if line:
                px = (255, 255, 255)
            elif x < size // cells and y < size // cells:
                px = (230, 20, 20)
            else:
                px = hsv(cx / cells, 0.55, 0.35 + 0.6 * (cy + 0.5) / cells)
            row.append(px)
        rows.append(row)
    return rows


def fine_checker(size=512, squares=64):
    """Black and white squares: the classic aliasing pattern for a floor."""
    n = size // squares
    return [[(235,) * 3 if ((x // n) + (y // n)) % 2 == 0 else (20,) * 3 for x in range(size)]
            for y in range(size)]


def height_field(u, v, bumps=6):
    """Round dimples on a grid, heights in [0, 1]."""
    fu, fv = (u * bumps) % 1 - 0.5, (v * bumps) % 1 - 0.5
    r = math.hypot(fu, fv) / 0.45
    return 0.5 * (1 + math.cos(math.pi * r)) if r < 1 else 0.0


def bump_maps(size=128):
    """The height field as a grey map and its tangent-space normal map
    (OpenGL convention: green towards +v, the image's top)."""
    h = [[height_field((x + 0.5) / size, 1 - (y + 0.5) / size) for x in range(size)]
         for y in range(size)]
    grey = [[(int(round(255 * h[y][x])),) for x in range(size)] for y in range(size)]
    strength = 4.0  # height per unit of uv, in the normal map's units
    normals = []
    for y in range(size):
        row = []
        for x in range(size):
            dhdu = (h[y][(x + 1) % size] - h[y][(x - 1) % size]) * size / 2 * strength / size * 8
            dhdv = (h[(y - 1) % size][x] - h[(y + 1) % size][x]) * size / 2 * strength / size * 8
            n = (-dhdu, -dhdv, 1.0)
            l = math.sqrt(sum(c * c for c in n))
            row.append(tuple(int(round(255 * (c / l * 0.5 + 0.5))) for c in n))
        normals.append(row)
    return grey, normals


def crate_obj():
    """A unit cube with texture coordinates per face (each face shows the
    whole image upright) and an MTL naming the grid and the bump map."""
    corners = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
    faces = [  # counter-clockwise seen from outside, starting at the lower left
        (0b001, 0b101, 0b111, 0b011),  # +z
        (0b100, 0b000, 0b010, 0b110),  # -z
        (0b101, 0b100, 0b110, 0b111),  # +x
        (0b000, 0b001, 0b011, 0b010),  # -x
        (0b011, 0b111, 0b110, 0b010),  # +y
        (0b000, 0b100, 0b101, 0b001),  # -y
    ]
    index = {(bool(i & 4), bool(i & 2), bool(i & 1)): i for i in range(8)}
    lines = ["# A textured crate, written by make_textures.py", "mtllib crate.mtl"]
    for i in range(8):
        x, y, z = (0.5 if i & 4 else -0.5), (0.5 if i & 2 else -0.5), (0.5 if i & 1 else -0.5)
        lines.append("v %g %g %g" % (x, y, z))
    for uv in ((0, 0), (1, 0), (1, 1), (0, 1)):
        lines.append("vt %g %g" % uv)
    lines.append("usemtl crate")
    for f in faces:
        lines.append("f " + " ".join("%d/%d" % (c + 1, k + 1) for k, c in enumerate(f)))
    with open(os.path.join(HERE, "crate.obj"), "w") as out:
        out.write("\n".join(lines) + "\n")
    with open(os.path.join(HERE, "crate.mtl"), "w") as out:
        out.write("# written by make_textures.py\nnewmtl crate\nKa 1 1 1\nKd 1 1 1\n"
                  "Ks 0.2 0.2 0.2\nNs 40\nmap_Kd uv_grid.png\nmap_Ka uv_grid.png\n"
                  "bump -bm 0.02 bumps.png\n")
    del index, corners


if __name__ == "__main__":
    write_png("uv_grid.png", 256, 256, uv_grid())
    write_png("checker_fine.png", 512, 512, fine_checker())
    grey, normals = bump_maps()
    write_png("bumps.png", 128, 128, grey, channels=1)
    write_png("bumps_normal.png", 128, 128, normals)
    crate_obj()

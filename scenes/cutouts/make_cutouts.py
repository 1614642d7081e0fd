#!/usr/bin/env python3
"""Writes the masks and the plant OBJ of scenes/cutouts.json (alpha cut-outs).

Everything is computed (raylab ships no third-party image), with the PNG
writer of scenes/textures/make_textures.py:

    python3 scenes/cutouts/make_cutouts.py   # rewrites the files beside it
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "textures"))
from make_textures import write_png  # noqa: E402


def smooth_edge(distance, width):
    """Coverage 1 inside (distance < 0), 0 outside, a linear ramp `width`
    wide across the edge: soft edges, so the cut-off value matters."""
    return min(1.0, max(0.0, 0.5 - distance / width))


def leaf(size=128):
    """RGBA leaf: a pointed blade along v (stem at the bottom), a lighter
    midrib and side veins, alpha soft over about 3 texels."""
    rows = []
    for y in range(size):
        row = []
        v = 1 - (y + 0.5) / size          # 0 at the stem, 1 at the tip
        for x in range(size):
            u = (x + 0.5) / size - 0.5    # -0.5 .. 0.5 across
            half = 0.42 * math.sin(math.pi * min(1.0, max(0.0, (v - 0.04) / 0.94))) ** 0.8
            distance = (abs(u) - half) * size  # in texels, < 0 inside
            a = smooth_edge(distance, 3.0)
            vein = abs(u) < 0.012 or abs((v - 0.1) - 1.6 * abs(u)) % 0.16 < 0.012
            shade = 0.75 + 0.25 * v
            r, g, b = (0.35, 0.75, 0.25) if vein else (0.12 * shade, 0.45 * shade, 0.1 * shade)
            row.append((int(255 * r), int(255 * g), int(255 * b), int(round(255 * a))))
        rows.append(row)
    return rows


def fence(size=64):
    """RGBA chain-link tile: two diagonal wires (galvanised grey), holes
    between them transparent, edges soft over about 2 texels."""
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            u, v = (x + 0.5) / size, (y + 0.5) / size
            d1 = abs(((u + v) % 1.0) - 0.5)   # distance to the wire along u + v = 0.5 (mod 1)
            d2 = abs(((u - v) % 1.0) - 0.5)
            wire = min(d1, d2) * size / math.sqrt(2)  # texels from the nearest wire's centre
            a = smooth_edge(wire - 3.0, 2.0)
            grey = int(150 + 60 * (1 - wire / 3.0)) if wire < 3 else 150
            row.append((grey, grey, min(255, grey + 10), int(round(255 * a))))
        rows.append(row)
    return rows


def soft_dots(size=64):
    """Grey coverage mask of scenes/accuracy/soft_mask.json: one dot per
    tile, opaque to 0.15 tile from its centre and fading linearly to nothing
    at 0.45, so a cut-off c puts the dot's edge at 0.45 - 0.3 c: every
    cut-off gives a different silhouette (the accuracy sweep's
    "alpha-cutoff" rows)."""
    rows = []
    for y in range(size):
        row = []
        for x in range(size):
            r = math.hypot((x + 0.5) / size - 0.5, (y + 0.5) / size - 0.5)
            a = min(1.0, max(0.0, (0.45 - r) / 0.3))
            row.append((int(round(255 * a)),))
        rows.append(row)
    return rows


def plant_obj(cards=7):
    """Leaf cards around a stem: each a quad from the stem outwards and up,
    uv (0, 0) at the stem end; MTL with map_Kd and map_d on the same PNG."""
    lines = ["# Leaf cards around a stem, written by make_cutouts.py", "mtllib plant.mtl",
             "vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1", "usemtl leaf"]
    vertices = 0
    for k in range(cards):
        a = 2 * math.pi * k / cards + 0.3
        tilt = 0.55 + 0.25 * (k % 3) / 2
        length, width, height = 1.0 - 0.08 * (k % 3), 0.45, 0.15 + 0.12 * k
        dx, dz = math.cos(a), math.sin(a)      # outwards
        sx, sz = -dz, dx                        # across
        up = math.sin(tilt) * length
        out = math.cos(tilt) * length
        p0 = (-sx * width / 2, height, -sz * width / 2)
        p1 = (sx * width / 2, height, sz * width / 2)
        p2 = (p1[0] + dx * out, height + up, p1[2] + dz * out)
        p3 = (p0[0] + dx * out, height + up, p0[2] + dz * out)
        for p in (p0, p1, p2, p3):
            lines.append("v %.6f %.6f %.6f" % p)
        lines.append("f %d/1 %d/2 %d/3 %d/4" % tuple(vertices + i for i in (1, 2, 3, 4)))
        vertices += 4
    with open(os.path.join(HERE, "plant.obj"), "w") as out:
        out.write("\n".join(lines) + "\n")
    with open(os.path.join(HERE, "plant.mtl"), "w") as out:
        out.write("# written by make_cutouts.py: the leaf's colour and its alpha as the mask\n"
                  "newmtl leaf\nKd 1 1 1\nKa 1 1 1\nKs 0.1 0.1 0.1\nNs 20\n"
                  "map_Kd leaf.png\nmap_Ka leaf.png\nmap_d leaf.png\n")


if __name__ == "__main__":
    write_png("../cutouts/leaf.png", 128, 128, leaf(), channels=4)
    write_png("../cutouts/fence.png", 64, 64, fence(), channels=4)
    write_png("../cutouts/soft_dots.png", 64, 64, soft_dots(), channels=1)
    plant_obj()

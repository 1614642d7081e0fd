#!/usr/bin/env python3
"""Compares two 8-bit PNG pictures of the same size and writes them side by side.

    scripts/spd/png_compare.py A.png B.png [--side-by-side OUT.png] [--scale N]

Prints the mean absolute difference per channel (0..255), the share of pixels
whose largest channel difference exceeds 8 and 32 levels, and the PSNR. With
--side-by-side, writes A | B (each box-filtered down by --scale, default 1)
with a 4-pixel white gap: the thumbnails in docs/img/povray/ come from here.

Reads non-interlaced 8-bit grey, grey+alpha, RGB and RGBA PNGs (what raylab's
--png and POV-Ray's +FN write); Python 3 standard library only.
"""

import argparse
import math
import struct
import sys
import zlib


def read_png(path):
    with open(path, "rb") as fh:
        data = fh.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("%s: not a PNG" % path)
    pos = 8
    idat = []
    width = height = depth = ctype = interlace = None
    while pos < len(data):
        (length,) = struct.unpack(">I", data[pos:pos + 4])
        kind = data[pos + 4:pos + 8]
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            width, height, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat.append(body)
        elif kind == b"IEND":
            break
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(ctype)
    if depth != 8 or channels is None or interlace != 0:
        raise ValueError("%s: only 8-bit non-interlaced grey/RGB(A) PNGs are read" % path)
    raw = zlib.decompress(b"".join(idat))
    stride = width * channels
    rows = []
    prev = bytearray(stride)
    p = 0
    for _ in range(height):
        ftype = raw[p]
        line = bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        bpp = channels
        if ftype == 1:
            for i in range(bpp, stride):
                line[i] = (line[i] + line[i - bpp]) & 255
        elif ftype == 2:
            for i in range(stride):
                line[i] = (line[i] + prev[i]) & 255
        elif ftype == 3:
            for i in range(stride):
                left = line[i - bpp] if i >= bpp else 0
                line[i] = (line[i] + ((left + prev[i]) >> 1)) & 255
        elif ftype == 4:
            for i in range(stride):
                a = line[i - bpp] if i >= bpp else 0
                b = prev[i]
                c = prev[i - bpp] if i >= bpp else 0
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[i] = (line[i] + pred) & 255
        rows.append(line)
        prev = line
    # to RGB
    rgb = []
    for line in rows:
        if channels == 3:
            rgb.append(bytes(line))
        elif channels == 4:
            out = bytearray(width * 3)
            out[0::3], out[1::3], out[2::3] = line[0::4], line[1::4], line[2::4]
            rgb.append(bytes(out))
        else:
            grey = line[0::channels]
            out = bytearray(width * 3)
            out[0::3], out[1::3], out[2::3] = grey, grey, grey
            rgb.append(bytes(out))
    return width, height, rgb


def write_png(path, width, height, rows):
    raw = b"".join(b"\x00" + bytes(r) for r in rows)

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xffffffff)

    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    with open(path, "wb") as fh:
        fh.write(png)


def downscale(width, height, rows, n):
    if n == 1:
        return width, height, rows
    w2, h2 = width // n, height // n
    out = []
    for y in range(h2):
        line = bytearray(w2 * 3)
        for x in range(w2):
            for c in range(3):
                s = 0
                for dy in range(n):
                    r = rows[y * n + dy]
                    base = x * n * 3 + c
                    for dx in range(n):
                        s += r[base + dx * 3]
                line[x * 3 + c] = (s + n * n // 2) // (n * n)
        out.append(bytes(line))
    return w2, h2, out


def compare(a, b):
    wa, ha, ra = a
    wb, hb, rb = b
    if (wa, ha) != (wb, hb):
        raise ValueError("sizes differ: %dx%d vs %dx%d" % (wa, ha, wb, hb))
    sums = [0, 0, 0]
    sq = 0
    over8 = over32 = 0
    for la, lb in zip(ra, rb):
        for x in range(wa):
            d = [abs(la[3 * x + c] - lb[3 * x + c]) for c in range(3)]
            for c in range(3):
                sums[c] += d[c]
                sq += d[c] * d[c]
            m = max(d)
            over8 += m > 8
            over32 += m > 32
    n = wa * ha
    mse = sq / (3.0 * n)
    psnr = float("inf") if mse == 0 else 10.0 * math.log10(255.0 ** 2 / mse)
    return {"mean_abs": [s / n for s in sums], "over8": over8 / n, "over32": over32 / n, "psnr": psnr}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--side-by-side", metavar="OUT.png")
    ap.add_argument("--scale", type=int, default=1, help="box-filter each picture down by this factor")
    args = ap.parse_args(argv)
    a, b = read_png(args.a), read_png(args.b)
    r = compare(a, b)
    print("mean |difference| R %.2f G %.2f B %.2f (of 255); pixels differing > 8: %.1f%%, > 32: %.1f%%; PSNR %.1f dB"
          % (r["mean_abs"][0], r["mean_abs"][1], r["mean_abs"][2], 100 * r["over8"], 100 * r["over32"], r["psnr"]))
    if args.side_by_side:
        wa, ha, ra = downscale(*a, args.scale)
        _, _, rb = downscale(*b, args.scale)
        gap = b"\xff" * (4 * 3)
        write_png(args.side_by_side, 2 * wa + 4, ha, [x + gap + y for x, y in zip(ra, rb)])
    return 0


if __name__ == "__main__":
    sys.exit(main())

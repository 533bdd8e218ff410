#!/usr/bin/env python3
"""Small image probes for bench/peers/effects (no third-party modules).

  spot_radius.py moment IMAGE        sum, centroid (x, y) and second moment E[r^2] about the centroid, in pixels,
                                     of the image's mean channel (a blurred spot on black)
  spot_radius.py pixel IMAGE X Y     the RGB value of pixel (X, Y), (0, 0) the top-left

Reads PFM (Trazo; rows stored bottom-up) and binary PPM, 8 or 16 bits (POV-Ray +FP16 with File_Gamma=1.0:
linear values over 65535; values above 1 clamp).
"""
import struct
import sys


def _tokens(data, count):
    """The first `count` header tokens of a PNM/PFM file (comments skipped) and the offset after them."""
    out, i = [], 0
    while len(out) < count:
        while data[i:i + 1].isspace():
            i += 1
        if data[i:i + 1] == b'#':
            while data[i:i + 1] not in (b'\n', b''):
                i += 1
            continue
        j = i
        while not data[j:j + 1].isspace():
            j += 1
        out.append(data[i:j].decode())
        i = j
    return out, i + 1  # one whitespace byte ends the header


def read_image(path):
    """(width, height, rows): rows[y][x] = (r, g, b), y = 0 the top row."""
    with open(path, 'rb') as f:
        data = f.read()
    if data[:2] in (b'PF', b'Pf'):
        (magic, w, h, scale), off = _tokens(data, 4)
        w, h, scale = int(w), int(h), float(scale)
        ch = 3 if magic == 'PF' else 1
        fmt = ('<' if scale < 0 else '>') + 'f' * (w * h * ch)
        vals = struct.unpack_from(fmt, data, off)
        rows = []
        for y in range(h):
            base = (h - 1 - y) * w * ch  # PFM stores the bottom row first
            row = []
            for x in range(w):
                p = vals[base + x * ch: base + x * ch + ch]
                row.append(tuple(p) if ch == 3 else (p[0],) * 3)
            rows.append(row)
        return w, h, rows
    if data[:2] == b'P6':
        (_, w, h, maxval), off = _tokens(data, 4)
        w, h, maxval = int(w), int(h), int(maxval)
        n = w * h * 3
        vals = struct.unpack_from('>' + ('H' if maxval > 255 else 'B') * n, data, off)
        rows = [[tuple(vals[(y * w + x) * 3 + c] / maxval for c in range(3)) for x in range(w)] for y in range(h)]
        return w, h, rows
    sys.exit(f'{path}: not a PFM or binary PPM')


def moment(path):
    w, h, rows = read_image(path)
    s = sx = sy = sxx = syy = 0.0
    for y in range(h):
        for x in range(w):
            v = sum(rows[y][x]) / 3.0
            if v == 0.0:
                continue
            cx, cy = x + 0.5, y + 0.5
            s += v
            sx += v * cx
            sy += v * cy
            sxx += v * cx * cx
            syy += v * cy * cy
    if s <= 0.0:
        sys.exit(f'{path}: black image')
    mx, my = sx / s, sy / s
    r2 = sxx / s - mx * mx + syy / s - my * my
    print(f'sum {s:.6g} cx {mx:.4f} cy {my:.4f} r2 {r2:.6f}')


def pixel(path, x, y):
    _, _, rows = read_image(path)
    r, g, b = rows[y][x]
    print(f'{r:.6f} {g:.6f} {b:.6f}')


if __name__ == '__main__':
    if len(sys.argv) == 3 and sys.argv[1] == 'moment':
        moment(sys.argv[2])
    elif len(sys.argv) == 5 and sys.argv[1] == 'pixel':
        pixel(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]))
    else:
        sys.exit(__doc__)

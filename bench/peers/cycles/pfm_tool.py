#!/usr/bin/env python3
"""Small PFM probes for the Cornell comparison (python3, no modules beyond the standard library).

  pfm_tool.py stats IMAGE.pfm [--exclude-above T]
      "pixels N excluded K mean r g b max r g b" over pixels whose every channel is <= T (default: all)
  pfm_tool.py pixel IMAGE.pfm X Y
      "r g b" of pixel (X, Y), (0, 0) = top-left
  pfm_tool.py average OUT.pfm A.pfm B.pfm [...] [--weights wa wb ...]
      the (weighted) mean of images of one size, e.g. a reference from several seeds
  pfm_tool.py lightmask OUT.pfm W H
      1 where a pixel's square overlaps the Cornell box's light as the camera of scenes/cornell_box.scene sees
      it (SPEC §3's camera: vertical FOV 39.3077, pixel (0, 0) top-left), else 0: image_error --relmse --mask
  pfm_tool.py png OUT.png A.pfm [B.pfm ...] [--scale S] [--downsample K] [--gap G]
      the images side by side (G black pixels between them), each first averaged over K×K blocks (linear)
      and then each pixel scaled S times (nearest), through
      SPEC §7's `srgb` view: round(255 * sRGB(clamp(x, 0, 1))), Exposure 0
"""
import array
import struct
import sys
import zlib


def read_pfm(path):
    with open(path, "rb") as f:
        data = f.read()
    parts, pos = [], 0
    while len(parts) < 4:  # "PF", width, height, scale, separated by whitespace
        while data[pos:pos + 1].isspace():
            pos += 1
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        parts.append(data[pos:end].decode())
        pos = end
    pos += 1
    kind, w, h, scale = parts[0], int(parts[1]), int(parts[2]), float(parts[3])
    channels = 3 if kind == "PF" else 1
    px = array.array("f")
    px.frombytes(data[pos:pos + 4 * w * h * channels])
    if (scale < 0) != (sys.byteorder == "little"):
        px.byteswap()
    if channels == 1:
        px = array.array("f", [v for v in px for _ in range(3)])
    return w, h, px  # bottom row first, RGB


def write_pfm(path, w, h, px):
    out = array.array("f", px)
    if sys.byteorder != "little":
        out.byteswap()
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(out.tobytes())


def srgb8(x):
    x = 0.0 if not x > 0.0 else (1.0 if x > 1.0 else x)  # NaN -> 0
    y = 12.92 * x if x < 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    return int(255.0 * y + 0.5)


def write_png(path, w, h, rows):  # rows: top row first, each bytes of RGB8
    # Each row under the PNG filter (None, Sub, Up, Average, Paeth) with the least sum of |bytes| (the usual
    # heuristic): noisy renders compress a third better than unfiltered.
    def paeth(a, b, c):
        p = a + b - c
        pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
        return a if pa <= pb and pa <= pc else (b if pb <= pc else c)

    out, prev = [], bytes(3 * w)
    for row in rows:
        cands = []
        for kind in range(5):
            f = bytearray(len(row))
            for i, x in enumerate(row):
                a = row[i - 3] if i >= 3 else 0
                b = prev[i]
                c = prev[i - 3] if i >= 3 else 0
                pred = (0, a, b, (a + b) // 2, paeth(a, b, c) if kind == 4 else 0)[kind]
                f[i] = (x - pred) & 0xFF
            cands.append((sum(v if v < 128 else 256 - v for v in f), kind, f))
        _, kind, f = min(cands)
        out.append(bytes([kind]) + bytes(f))
        prev = row
    raw = b"".join(out)

    def chunk(tag, body):
        return struct.pack(">I", len(body)) + tag + body + struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF)

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


CAMERA = (278.0, 273.0, -800.0)  # looking along +z, up +y: the image's right is -x
TAN_HALF_FOV = 12.5 / 35.0  # tan(39.3077 deg / 2)
LIGHT = [(343, 548.7, 227), (343, 548.7, 332), (213, 548.7, 332), (213, 548.7, 227)]


def light_mask(w, h):
    # The light's corners in pixel coordinates (x right, y down); a pinhole maps the rectangle to a convex quad.
    quad = []
    for X, Y, Z in LIGHT:
        d = Z - CAMERA[2]
        sx, sy = -(X - CAMERA[0]) / d / TAN_HALF_FOV, (Y - CAMERA[1]) / d / TAN_HALF_FOV  # vertical FOV: h spans 2
        quad.append((w / 2 + sx * h / 2, h / 2 - sy * h / 2))

    def overlaps(px, py):  # separating axes: the square's two axes and the quad's four edge normals
        square = [(px, py), (px + 1, py), (px + 1, py + 1), (px, py + 1)]
        axes = [(1, 0), (0, 1)] + [(quad[i][1] - quad[i - 1][1], quad[i - 1][0] - quad[i][0]) for i in range(4)]
        for ax, ay in axes:
            a = [ax * x + ay * y for x, y in square]
            b = [ax * x + ay * y for x, y in quad]
            if max(a) <= min(b) or max(b) <= min(a):
                return False
        return True

    px = array.array("f", [0.0]) * (3 * w * h)
    for y in range(h):  # y counted from the top; PFM rows from the bottom
        for x in range(w):
            if overlaps(x, y):
                i = 3 * ((h - 1 - y) * w + x)
                px[i] = px[i + 1] = px[i + 2] = 1.0
    return px


def downsample(image, k):  # k×k box means, in linear values
    w, h, px = image
    if k == 1:
        return image
    W, H = w // k, h // k
    out = array.array("f", [0.0]) * (3 * W * H)
    for Y in range(H):
        for X in range(W):
            for c in range(3):
                out[3 * (Y * W + X) + c] = sum(px[3 * ((Y * k + j) * w + X * k + i) + c]
                                               for j in range(k) for i in range(k)) / (k * k)
    return W, H, out


def option(args, name, default, count=1):
    if name not in args:
        return default
    i = args.index(name)
    values = args[i + 1:i + 1 + count] if count > 0 else args[i + 1:]
    del args[i:i + 1 + len(values)]
    return values[0] if count == 1 else values


def main(argv):
    if len(argv) < 2:
        sys.exit(__doc__)
    cmd, args = argv[1], argv[2:]
    if cmd == "stats":
        above = float(option(args, "--exclude-above", "inf"))
        w, h, px = read_pfm(args[0])
        s, m, n = [0.0] * 3, [float("-inf")] * 3, 0
        for i in range(w * h):
            p = px[3 * i:3 * i + 3]
            if max(p) > above:
                continue
            n += 1
            for c in range(3):
                s[c] += p[c]
                m[c] = max(m[c], p[c])
        n1 = max(n, 1)
        print("pixels %d excluded %d mean %.6g %.6g %.6g max %.6g %.6g %.6g" %
              (n, w * h - n, s[0] / n1, s[1] / n1, s[2] / n1, *m))
    elif cmd == "pixel":
        w, h, px = read_pfm(args[0])
        x, y = int(args[1]), int(args[2])
        i = 3 * ((h - 1 - y) * w + x)
        print("%.6g %.6g %.6g" % tuple(px[i:i + 3]))
    elif cmd == "average":
        out, inputs = args[0], args[1:]
        weights = option(inputs, "--weights", None, count=0)
        weights = [float(v) for v in weights] if weights else [1.0] * len(inputs)
        total = sum(weights)
        acc, size = None, None
        for path, wgt in zip(inputs, weights):
            w, h, px = read_pfm(path)
            if size and size != (w, h):
                sys.exit("pfm_tool: sizes differ")
            size = (w, h)
            acc = [wgt * v for v in px] if acc is None else [a + wgt * v for a, v in zip(acc, px)]
        write_pfm(out, size[0], size[1], [a / total for a in acc])
    elif cmd == "lightmask":
        w, h = int(args[1]), int(args[2])
        mask = light_mask(w, h)
        write_pfm(args[0], w, h, mask)
        print("lightmask %d pixels" % (sum(mask) // 3))
    elif cmd == "png":
        scale = int(option(args, "--scale", "1"))
        down = int(option(args, "--downsample", "1"))
        gap = int(option(args, "--gap", "4"))
        out, images = args[0], [downsample(read_pfm(p), down) for p in args[1:]]
        h = images[0][1]
        if any(img[1] != h for img in images):
            sys.exit("pfm_tool: heights differ")
        lut_rows = []
        for y in range(h - 1, -1, -1):  # top row first
            row = bytearray()
            for k, (w, _, px) in enumerate(images):
                if k:
                    row += b"\x00\x00\x00" * gap
                base = 3 * y * w
                for x in range(w):
                    rgb = bytes(srgb8(px[base + 3 * x + c]) for c in range(3))
                    row += rgb * scale
            lut_rows.extend([bytes(row)] * scale)
        width = len(lut_rows[0]) // 3
        write_png(out, width, len(lut_rows), lut_rows)
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)

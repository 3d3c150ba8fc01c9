# imagequality.py - how far an image is from a reference: box filtering in linear light
# and the PSNR of the luma. Shared by tools/antialias-quality and tests/antialias.sh.
# Usage as a program: python3 tools/imagequality.py REFERENCE.ppm N IMAGE.ppm prints the
# PSNR (dB) of IMAGE against REFERENCE shrunk N times (each N x N block averaged).
# See LICENSE for copyright and licence.
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from netpbm import read_ppm  # noqa: E402


def srgb_to_linear(code):
    v = code / 255.0
    return v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4


def linear_to_srgb(v):
    v = min(max(v, 0.0), 1.0)
    return 255.0 * (v * 12.92 if v <= 0.0031308 else 1.055 * v ** (1 / 2.4) - 0.055)


LINEAR = [srgb_to_linear(c) for c in range(256)]


def box_down(rgb, width, height, n):
    """The image n times smaller, each n x n block averaged in linear light, as float codes."""
    out_w, out_h = width // n, height // n
    out = [0.0] * (out_w * out_h * 3)
    area = float(n * n)
    for by in range(out_h):
        acc = [[0.0] * out_w for _ in range(3)]
        for y in range(by * n, by * n + n):
            row = rgb[y * width * 3:(y + 1) * width * 3]
            for c in range(3):
                vals = list(map(LINEAR.__getitem__, row[c::3]))
                a = acc[c]
                for bx in range(out_w):
                    a[bx] += sum(vals[bx * n:bx * n + n])
        base = by * out_w * 3
        for c in range(3):
            a = acc[c]
            for bx in range(out_w):
                out[base + bx * 3 + c] = linear_to_srgb(a[bx] / area)
    return out


def psnr(image, reference):
    """PSNR (dB) of the luma (BT.709 weights on the sRGB codes) of image against reference."""
    err = 0.0
    count = len(reference) // 3
    for i in range(count):
        r, g, b = image[3 * i:3 * i + 3]
        rr, rg, rb = reference[3 * i:3 * i + 3]
        d = 0.2126 * (r - rr) + 0.7152 * (g - rg) + 0.0722 * (b - rb)
        err += d * d
    mse = err / count
    return float("inf") if mse == 0 else 10 * math.log10(255.0 * 255.0 / mse)


def main(argv):
    if len(argv) != 4:
        sys.stderr.write("usage: imagequality.py REFERENCE.ppm N IMAGE.ppm\n")
        return 2
    n = int(argv[2])
    rw, rh, ref = read_ppm(argv[1])
    w, h, image = read_ppm(argv[3])
    if (rw // n, rh // n) != (w, h):
        sys.stderr.write("imagequality.py: sizes differ\n")
        return 1
    print("%.2f" % psnr(list(image), box_down(ref, rw, rh, n)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
# ppm2png.py - converts rt's binary PPM (P6, maxval 255) to PNG, standard library only.
# Usage: python3 tools/ppm2png.py IN.ppm OUT.png   (IN may be - for standard input)
# See LICENSE for copyright and licence.
import os
import struct
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from netpbm import parse_netpbm  # noqa: E402


def read_ppm(data):
    """(width, height, RGB bytes) of P6 image bytes with maxval 255."""
    return parse_netpbm(data, b"P6", 255, 3)


def png_chunk(kind, body):
    # Each chunk: length, type, body, CRC of type and body.
    return (struct.pack(">I", len(body)) + kind + body +
            struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))


def write_png(width, height, pixels):
    stride = 3 * width
    # Filter type 0 (none) at the start of every row.
    raw = b"".join(b"\0" + pixels[y * stride:(y + 1) * stride] for y in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    # An sRGB chunk says the samples are already sRGB-encoded, as rt writes them.
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header) +
            png_chunk(b"sRGB", b"\0") + png_chunk(b"IDAT", zlib.compress(raw, 9)) +
            png_chunk(b"IEND", b""))


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: ppm2png.py IN.ppm OUT.png\n")
        return 2
    data = sys.stdin.buffer.read() if argv[1] == "-" else open(argv[1], "rb").read()
    try:
        png = write_png(*read_ppm(data))
    except (ValueError, IndexError) as e:
        sys.stderr.write("ppm2png.py: %s: %s\n" % (argv[1], e))
        return 1
    with open(argv[2], "wb") as f:
        f.write(png)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

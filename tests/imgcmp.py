#!/usr/bin/env python3
# imgcmp.py - compares a render with its golden reference (binary PPM, maxval 255).
# Usage: python3 tests/imgcmp.py GOT.ppm EXPECTED.ppm
# Exit status 0 when they match within the tolerance, 1 when they differ (one line on
# standard output says how), 2 when a file cannot be read.
#
# Tolerance: every channel of every pixel within 2 (of 255) of the reference, and at
# most 0.5% of the pixels different at all. The references come from the double build
# with this compiler and libm; another compiler or libm may round the last bit of a
# sqrt, pow or tan differently, which moves a pixel's 8-bit code by one now and then
# (a difference of 2 where two such changes add up). A real change - a different
# colour, a missing light, a shifted or leaking edge - either moves some channel by
# more than 2 or touches far more than 0.5% of the pixels.
# See LICENSE for copyright and licence.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from netpbm import read_ppm  # noqa: E402

MAX_CHANNEL_DIFF = 2      # largest allowed difference of one channel, in 8-bit codes
MAX_DIFF_FRACTION = 0.005  # largest allowed fraction of pixels that differ at all



def compare(got, expected):
    """Returns None when got matches expected within the tolerance, else what differs."""
    gw, gh, gp = got
    ew, eh, ep = expected
    if (gw, gh) != (ew, eh):
        return "size %dx%d, expected %dx%d" % (gw, gh, ew, eh)
    differing, worst, worst_at = 0, 0, None
    for i in range(0, len(ep), 3):
        d = max(abs(gp[i] - ep[i]), abs(gp[i + 1] - ep[i + 1]), abs(gp[i + 2] - ep[i + 2]))
        if d:
            differing += 1
            if d > worst:
                worst, worst_at = d, i
    allowed = int(MAX_DIFF_FRACTION * ew * eh)
    if worst <= MAX_CHANNEL_DIFF and differing <= allowed:
        return None
    x, y = (worst_at // 3) % ew, (worst_at // 3) // ew
    return ("%d of %d pixels differ (at most %d allowed), by up to %d (at most %d allowed); "
            "worst at x=%d y=%d: got %s, expected %s" %
            (differing, ew * eh, allowed, worst, MAX_CHANNEL_DIFF, x, y,
             tuple(gp[worst_at:worst_at + 3]), tuple(ep[worst_at:worst_at + 3])))


def main(argv):
    if len(argv) != 3:
        sys.stderr.write("usage: imgcmp.py GOT.ppm EXPECTED.ppm\n")
        return 2
    images = []
    for path in argv[1:]:
        try:
            images.append(read_ppm(path))
        except (OSError, ValueError, IndexError) as e:
            print("cannot read %s: %s" % (path, e))
            return 2
    difference = compare(images[0], images[1])
    if difference:
        print(difference)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

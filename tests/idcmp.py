# idcmp.py - the share of pixels whose first-hit object differs between two --ids
# images (16-bit binary PGM), printed as a percentage with four decimals.
# Usage: python3 tests/idcmp.py A.pgm B.pgm
# See LICENSE for copyright and licence.
import sys


def pgm(p):
    d = open(p, 'rb').read()
    f = []
    i = 0
    while len(f) < 4:
        while d[i:i + 1].isspace():
            i += 1
        j = i
        while not d[j:j + 1].isspace():
            j += 1
        f.append(d[i:j])
        i = j
    i += 1
    w, h = int(f[1]), int(f[2])
    return w, h, d[i:i + w * h * 2]


a = pgm(sys.argv[1])
b = pgm(sys.argv[2])
if a[:2] != b[:2]:
    sys.exit('idcmp.py: the images differ in size')
n = a[0] * a[1]
diff = sum(1 for k in range(n) if a[2][2 * k:2 * k + 2] != b[2][2 * k:2 * k + 2])
print('%.4f' % (100.0 * diff / n))

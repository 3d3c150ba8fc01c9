# idcmp.py - the share of pixels whose first-hit object differs between two --ids
# images (16-bit binary PGM), printed as a percentage with four decimals.
# Usage: python3 tests/idcmp.py A.pgm B.pgm
# See LICENSE for copyright and licence.
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from netpbm import read_ids  # noqa: E402

a = read_ids(sys.argv[1])
b = read_ids(sys.argv[2])
if a[:2] != b[:2]:
    sys.exit('idcmp.py: the images differ in size')
n = a[0] * a[1]
diff = sum(1 for k in range(n) if a[2][2 * k:2 * k + 2] != b[2][2 * k:2 * k + 2])
print('%.4f' % (100.0 * diff / n))

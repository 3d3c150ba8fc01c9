#!/usr/bin/env python3
# oracle.py - an independent visibility (and shadow) oracle for rt's --ids images.
#
# Usage: python3 tests/oracle.py SCENE.nff --ids RT_IDS.pgm [--image RT.ppm] [-s WxH] [-v]
#            [--more-ids OTHER.pgm ...] [--write-wrong]
#
# For every pixel it works out, from the scene's decimal numbers taken exactly, the SET of
# object ids the eye ray through the pixel centre may legitimately hit first, and counts
# the pixels where rt's id (from `rt --ids -o RT_IDS.pgm`) is not in that set:
#
#     wrong N of M pixels (P%)
#
# With --image (rt's P6 render of the same scene at the same size) it also checks the
# shadows of the pixels whose first hit is certain and prints
#
#     false shadows N of L clearly lit pixels
#     false lights N of D clearly dark pixels
#
# A false shadow is a pixel that some light clearly reaches (the segment from the exact hit
# point to the light is clear of every object, the light is in front of the surface with
# cosine > 1e-3, and that light alone should lift the pixel above its ambient-only colour)
# but which rt shows at its ambient-only colour (black with `ambient 0`). A false light is
# a pixel every light of which is clearly facing away or clearly blocked by an opaque
# object, on a material without mirror or transmission, that rt shows brighter than that.
# A light through a transmitting object, or grazing the surface (|cosine| <= 1e-3), gets
# no verdict; a pixel is judged only when its first hit is certain and rt agrees with it.
# --more-ids judges further --ids images of the same scene and size in the same pass (a
# `wrong N of M pixels (P%) FILE` line each); --write-wrong writes each image's wrong
# pixels to IDS.wrong, one index y * width + x per line (tools/speed-vs-error uses both).
# -v lists the first wrong pixels (with every object tested and its status) and the first
# false shadows and lights, and prints the running time on standard error.
# Exit status 0, or 2 when an input cannot be read, does not match the scene's size, or
# uses what the oracle does not model (cones). See LICENSE for copyright and licence.
#
# How it decides. The camera follows src/camera.c: forward = normalize(at - from),
# right = normalize(forward x up), up' = right x forward, and pixel (i, j) (row 0 at the
# top) looks along forward + u right + v up' with u = (2i + 1 - W) / W tan(angle / 2) and
# v = (H - 2j - 1) / W tan(angle / 2). That direction is computed in `decimal` at 50
# digits (tan by its series, pi by Machin's formula) and then taken as an exact rational.
# The scene's numbers are read as exact rationals (fractions.Fraction; rt's own reading
# rounds them, the oracle's does not) and scaled by their common denominator to integers,
# so every plane, polygon and polyhedron test is exact rational arithmetic, done on
# integers; sphere hits need a square root, taken with math.isqrt to 2^-200.
#
#   * polygon (p, pp): the plane of the Newell normal through the vertices' centroid (as
#     rt has it, so non-planar input means what it means to rt) gives the hit's distance;
#     inside by the even-odd rule where the ray's line meets the vertex loop seen along
#     the ray (rt's ray-frame test: for non-planar input it is what rt means by inside,
#     and neighbours that share an edge share its test exactly). Opaque `p` are
#     one-sided (seen only from the side where the vertices run counter-clockwise); `pp`
#     and transmitting polygons are two-sided; shadow rays are blocked from either side.
#   * sphere: the near root, or the far one from inside or for a negative radius.
#   * plane: two-sided. box and polyhedron: the t-interval of the half-spaces.
#   Objects rt skips (radius 0, zero area, zero thickness) are skipped and not numbered.
#
# An object is AMBIGUOUS for a ray when the ideal ray passes within EPS (1e-12) times the
# local scale (the largest of |eye|, |hit point| and the distance, in scene units) of its
# boundary: a polygon edge or vertex, a sphere's silhouette, a box edge, or meets its
# plane edge-on; hit and miss are then both acceptable. Accepted ids:
#   * with a certain hit at distance t and nothing ambiguous in front of it: the objects
#     hit or ambiguous at t (within EPS relative: coplanar or touching objects);
#   * with ambiguous objects in front (or no certain hit at all): those objects, plus
#     whatever the ray meets when it is moved off them: 16 rays displaced by 1e-8 of the
#     scale in directions round the pixel's ray, each evaluated without ambiguity. So a
#     ray exactly along an edge shared by two tiles accepts either tile but not what lies
#     behind them (a crack is wrong), while a ray along the outer edge of a surface or a
#     sphere's silhouette accepts what is behind too.
# Shadow segments run from the exact hit point to the light (0 < tau < 1) and are judged
# the same way, with the surface hit excluded (a flat or convex surface cannot shadow
# itself from a light it faces) and a plane that the segment only touches at its start
# (a coplanar neighbour, a floor at a wall's foot) not counted as blocking.
# A floating-point pass decides every test whose margin is over 1e-9 of the scale (far
# above double's rounding: the decision cannot change); everything closer is decided on
# the exact path. Per pixel only the objects whose projected bounds cover it are tested.
import argparse
import math
import os
import sys
import time
from decimal import Decimal, localcontext
from fractions import Fraction

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tools'))
from netpbm import read_ids, read_ppm  # noqa: E402

EPS = 1e-12      # ambiguity band, relative to the local scale
CONF = 1e-9      # the float pass decides only what is farther than this from a decision
PERTURB = 1e-8   # displacement of the rays that look past ambiguous objects
COS_CLEAR = 1e-3  # a light counts as clearly in front (or behind) past this cosine
SQRT_BITS = 200


class OracleError(Exception):
    pass


# ---- small vector helpers (tuples) --------------------------------------------------

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def scale(a, k):
    return (a[0] * k, a[1] * k, a[2] * k)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])


def maxabs(a):
    return max(abs(a[0]), abs(a[1]), abs(a[2]))


def fnormalize(a):
    n = norm(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def seg_dist2d(p, a, b):
    """Distance from 2D point p to segment ab (floats)."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    px, py = p[0] - a[0], p[1] - a[1]
    ll = dx * dx + dy * dy
    s = 0.0 if ll == 0 else max(0.0, min(1.0, (px * dx + py * dy) / ll))
    ex, ey = px - s * dx, py - s * dy
    return math.sqrt(ex * ex + ey * ey)


def ray_basis(d):
    """Two unit vectors (floats) perpendicular to d and to each other."""
    dn = fnormalize(d)
    a = (1.0, 0.0, 0.0) if abs(dn[0]) <= abs(dn[1]) and abs(dn[0]) <= abs(dn[2]) else \
        ((0.0, 1.0, 0.0) if abs(dn[1]) <= abs(dn[2]) else (0.0, 0.0, 1.0))
    u = fnormalize(cross(dn, a))
    return u, cross(dn, u)


def along_ray(points, origin, u, v):
    """The points as seen along the ray (floats): their offsets from the origin in the
    perpendicular basis u, v, in which the ray's line is the point (0, 0)."""
    return [(dot(sub(p, origin), u), dot(sub(p, origin), v)) for p in points]


def even_odd(loop, p):
    """Is p inside the closed 2D loop (even-odd rule)? Exact for integer or Fraction input."""
    inside = False
    a = loop[-1]
    for b in loop:
        if (a[1] > p[1]) != (b[1] > p[1]):
            c = (a[0] - p[0]) * (b[1] - a[1]) + (p[1] - a[1]) * (b[0] - a[0])
            if (c > 0) == (b[1] > a[1]):
                inside = not inside
        a = b
    return inside


def loop_distance(loop, p):
    """Distance from 2D point p to the closed loop's edges (floats)."""
    mind = float('inf')
    a = loop[-1]
    for b in loop:
        mind = min(mind, seg_dist2d(p, a, b))
        a = b
    return mind


def isqrt_frac(n):
    """sqrt of a non-negative integer as a Fraction, exact for squares, else to 2^-SQRT_BITS."""
    r = math.isqrt(n)
    if r * r == n:
        return Fraction(r)
    return Fraction(math.isqrt(n << (2 * SQRT_BITS)), 1 << SQRT_BITS)


# ---- high-precision trigonometry (decimal) -------------------------------------------

def dec_pi():
    # Machin: pi = 16 atan(1/5) - 4 atan(1/239)
    def atan_inv(x):
        x = Decimal(x)
        total, term, k, x2 = Decimal(0), 1 / x, 1, x * x
        sign = 1
        while True:
            t = term / k
            if t == 0 or abs(t) < Decimal(10) ** -(60 + 5):
                break
            total += sign * t
            term /= x2
            k += 2
            sign = -sign
        return total
    return 16 * atan_inv(5) - 4 * atan_inv(239)


def dec_tan(x):
    # sin and cos by their series (|x| < pi / 2 here)
    s, c = Decimal(0), Decimal(0)
    term, k = Decimal(x), 1
    tiny = Decimal(10) ** -70
    while abs(term) > tiny:  # sin
        s += term
        term = -term * x * x / ((k + 1) * (k + 2))
        k += 2
    term, k = Decimal(1), 0
    while abs(term) > tiny:  # cos
        c += term
        term = -term * x * x / ((k + 1) * (k + 2))
        k += 2
    return s / c


# ---- the scene ---------------------------------------------------------------------

def tokenize(text):
    toks = []
    for lineno, line in enumerate(text.splitlines(), 1):
        line = line.split('#', 1)[0]
        for t in line.split():
            toks.append((t, lineno))
    return toks


def is_number(t):
    try:
        Fraction(t)
        return True
    except (ValueError, ZeroDivisionError):
        return False


def srgb_decode(c):
    c = float(c)
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def srgb_encode(x):
    x = min(max(x, 0.0), 1.0)
    y = 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    return int(math.floor(y * 255 + 0.5))


class Material:
    def __init__(self, vals):
        self.color = [srgb_decode(v) for v in vals[0:3]]
        self.kd, self.ks, self.shine, self.kt = (float(v) for v in vals[3:7])


class Scene:
    def __init__(self):
        self.view = None
        self.lights = []      # (position Fractions, colour or None)
        self.background = (0, 0, 0)
        self.ambient = (0.0, 0.0, 0.0)
        self.objects = []     # (kind, material, data)


def parse_scene(path):
    with open(path, 'rb') as f:
        text = f.read().decode('latin-1')
    if text.startswith('\u00ef\u00bb\u00bf'):
        text = text[3:]
    toks = tokenize(text)
    sc = Scene()
    pos = [0]
    mat = [Material(['1', '1', '1', '1', '0', '0', '0', '1'])]

    def tok():
        if pos[0] >= len(toks):
            raise OracleError('%s: unexpected end of scene' % path)
        t = toks[pos[0]]
        pos[0] += 1
        return t

    def num():
        t, line = tok()
        try:
            return Fraction(t)
        except (ValueError, ZeroDivisionError):
            raise OracleError('%s:%d: expected a number, got %r' % (path, line, t))

    def nums(n):
        return [num() for _ in range(n)]

    def count():
        t, line = tok()
        if not t.lstrip('+').isdigit():
            raise OracleError('%s:%d: expected a count, got %r' % (path, line, t))
        return int(t)

    def number_on_line(line):
        return pos[0] < len(toks) and toks[pos[0]][1] == line and is_number(toks[pos[0]][0])

    while pos[0] < len(toks):
        cmd, line = tok()
        if cmd == 'v':
            view = {}
            for key, n in (('from', 3), ('at', 3), ('up', 3), ('angle', 1), ('hither', 1),
                           ('resolution', 2)):
                k, kl = tok()
                if k != key:
                    raise OracleError('%s:%d: expected %s in the view' % (path, kl, key))
                view[key] = nums(n)
            view['resolution'] = [int(x) for x in view['resolution']]
            sc.view = view
        elif cmd == 'b':
            sc.background = tuple(nums(3))
        elif cmd == 'ambient':
            sc.ambient = tuple(float(x) for x in nums(3))
        elif cmd == 'l':
            p = tuple(nums(3))
            colour = tuple(float(x) for x in nums(3)) if number_on_line(line) else None
            sc.lights.append((p, colour))
        elif cmd == 'f':
            mat[0] = Material(nums(8))
        elif cmd == 'absorb':
            num()
            if number_on_line(line):
                nums(2)
        elif cmd in ('depth', 'cutoff'):
            num()
        elif cmd == 's':
            c = tuple(nums(3))
            r = num()
            if r != 0:
                sc.objects.append(('sphere', mat[0], (c, r)))
        elif cmd in ('p', 'pp'):
            n = count()
            verts = []
            for _ in range(n):
                verts.append(tuple(nums(3)))
                if cmd == 'pp':
                    nums(3)
            # Newell normal; zero area polygons are skipped (and not numbered) by rt.
            nn = newell(verts)
            if nn != (0, 0, 0):
                sc.objects.append(('polygon', mat[0], (verts, cmd == 'pp')))
        elif cmd == 'plane':
            v = nums(6)
            sc.objects.append(('plane', mat[0], (tuple(v[0:3]), tuple(v[3:6]))))
        elif cmd == 'box':
            v = nums(6)
            lo = tuple(min(v[k], v[k + 3]) for k in range(3))
            hi = tuple(max(v[k], v[k + 3]) for k in range(3))
            if all(lo[k] < hi[k] for k in range(3)):
                planes = []
                for k in range(3):
                    n = [0, 0, 0]
                    n[k] = 1
                    planes.append((tuple(n), hi[k]))
                    n = [0, 0, 0]
                    n[k] = -1
                    planes.append((tuple(n), -lo[k]))
                sc.objects.append(('hedron', mat[0], planes))
        elif cmd == 'polyhedron':
            n = count()
            planes = []
            for _ in range(n):
                v = nums(4)
                planes.append((tuple(v[0:3]), v[3]))
            sc.objects.append(('hedron', mat[0], planes))
        elif cmd == 'c':
            raise OracleError('%s:%d: cones are not modelled by the oracle' % (path, line))
        else:
            raise OracleError('%s:%d: unknown command %r' % (path, line, cmd))
    if sc.view is None:
        raise OracleError('%s: no view' % path)
    return sc


def newell_sums(verts):
    nx = ny = nz = 0
    n = len(verts)
    for i in range(n):
        a, b = verts[i], verts[(i + 1) % n]
        nx += (a[1] - b[1]) * (a[2] + b[2])
        ny += (a[2] - b[2]) * (a[0] + b[0])
        nz += (a[0] - b[0]) * (a[1] + b[1])
    return (nx, ny, nz)


def newell(verts):
    """rt's polygon normal: Newell's; where the signed areas cancel (a symmetric bow-tie,
    which the even-odd rule still fills), that of the first three consecutive vertices
    not on one line; zero only when every vertex is on one line."""
    n = newell_sums(verts)
    i = 0
    while n == (0, 0, 0) and len(verts) > 3 and i + 3 <= len(verts):
        n = newell_sums(verts[i:i + 3])
        i += 1
    return n


# ---- rays ---------------------------------------------------------------------------
# An exact ray is X(tau) = (O + tau D) / w with integer vectors O, D and an integer w > 0,
# in scene units times the scene's common denominator LS. Its float twin is (Of, Df), in
# scene units, with X(tau) = Of + tau Df for the same tau.

class Ray:
    __slots__ = ('O', 'w', 'D', 'Of', 'Df', 'dlen', 'edlen', 'tmax')

    def __init__(self, O, w, D, Of, Df, LS, tmax=None):
        self.O, self.w, self.D, self.Of, self.Df = O, w, D, Of, Df
        self.dlen = norm(Df)   # scene units per unit of the float tau
        # scene units per unit of the exact tau
        self.edlen = norm(tuple(float(Fraction(c, w * LS)) for c in D))
        self.tmax = tmax  # None: a ray; 1: a segment to tau = 1 (both taus agree then)


class Result:
    """An exact test's answer: inside (the ideal ray meets it), tau, ambiguous, the hit point
    as (Q, W) with X = Q / W in LS units, and the outward normal there (floats)."""
    __slots__ = ('inside', 'tau', 'amb', 'Q', 'W', 'normal', 'dist', 'scale')

    def __init__(self, inside, tau=None, amb=False, Q=None, W=None, normal=None, dist=None,
                 scale=None):
        self.inside, self.tau, self.amb = inside, tau, amb
        self.Q, self.W, self.normal, self.dist, self.scale = Q, W, normal, dist, scale


class World:
    def __init__(self, sc):
        self.sc = sc
        dens = [1]

        def note(v):
            dens.append(Fraction(v).denominator)
        v = sc.view
        for k in ('from', 'at'):
            for x in v[k]:
                note(x)
        for (p, _) in sc.lights:
            for x in p:
                note(x)
        for kind, _, data in sc.objects:
            if kind == 'sphere':
                for x in data[0]:
                    note(x)
                note(data[1])
            elif kind == 'polygon':
                for p in data[0]:
                    for x in p:
                        note(x)
            elif kind == 'plane':
                for x in data[0]:
                    note(x)
        LS = 1
        for d in dens:
            LS = LS * d // math.gcd(LS, d)
        self.LS = LS
        self.objs = [make_object(kind, m, data, LS) for kind, m, data in sc.objects]
        self.eye = v['from']
        self.E = tuple(int(x * LS) for x in self.eye)
        self.Ef = tuple(float(x) for x in self.eye)
        self.lights = []
        n_plain = len(sc.lights)
        for (p, colour) in sc.lights:
            inten = colour if colour is not None else (1 / math.sqrt(n_plain),) * 3
            self.lights.append((tuple(int(x * LS) for x in p), tuple(float(x) for x in p), inten))

    def setup_camera(self, W, H):
        v = self.sc.view
        with localcontext() as ctx:
            ctx.prec = 50
            fr = [Decimal(x.numerator) / Decimal(x.denominator) for x in v['from']]
            at = [Decimal(x.numerator) / Decimal(x.denominator) for x in v['at']]
            up = [Decimal(x.numerator) / Decimal(x.denominator) for x in v['up']]
            ang = v['angle'][0]
            ang = Decimal(ang.numerator) / Decimal(ang.denominator)

            def dnorm(a):
                n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
                return [a[0] / n, a[1] / n, a[2] / n]

            def dcross(a, b):
                return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                        a[0] * b[1] - a[1] * b[0]]
            F = dnorm([at[k] - fr[k] for k in range(3)])
            R = dnorm(dcross(F, dnorm(up)))
            U = dcross(R, F)
            ctx.prec = 70
            T = +dec_tan(ang * dec_pi() / 360)
            ctx.prec = 50
            T = +T
            self.cam = (F, R, U, T)
            self.Ff = tuple(float(x) for x in F)
            self.Rf = tuple(float(x) for x in R)
            self.Uf = tuple(float(x) for x in U)
            self.Tf = float(T)
            self.W, self.H = W, H

    def eye_ray(self, i, j):
        F, R, U, T = self.cam
        W, H = self.W, self.H
        with localcontext() as ctx:
            ctx.prec = 50
            u = Decimal(2 * i + 1 - W) / Decimal(W) * T
            v = Decimal(H - 2 * j - 1) / Decimal(W) * T
            d = [F[k] + u * R[k] + v * U[k] for k in range(3)]
        fr = [Fraction(x) for x in d]
        den = 1
        for x in fr:
            den = den * x.denominator // math.gcd(den, x.denominator)
        D = tuple(int(x * den) for x in fr)
        Df = fnormalize(tuple(float(x) for x in d))
        return Ray(self.E, 1, D, self.Ef, Df, self.LS)

    def offset_ray(self, base, du, dv):
        """A ray from the eye along base.Df + du right + dv up (float direction, exact ints)."""
        d = tuple(base.Df[k] + du * self.Rf[k] + dv * self.Uf[k] for k in range(3))
        m = maxabs(d)
        D = tuple(int(round(x / m * (1 << 62))) for x in d)
        Df = fnormalize(tuple(float(x) for x in D))
        return Ray(self.E, 1, D, self.Ef, Df, self.LS)

    def pixel_box(self, pts):
        """Conservative pixel ranges (i0, i1, j0, j1) holding the projections of pts, or None."""
        F, R, U, T = self.Ff, self.Rf, self.Uf, self.Tf
        W, H = self.W, self.H
        imin = jmin = float('inf')
        imax = jmax = -float('inf')
        for p in pts:
            rel = sub(p, self.Ef)
            z = dot(rel, F)
            if z <= 1e-6 * norm(rel):
                return None
            x = dot(rel, R) / z
            y = dot(rel, U) / z
            i = (x / T * W + W - 1) / 2
            j = (H - 1 - y / T * W) / 2
            imin, imax = min(imin, i), max(imax, i)
            jmin, jmax = min(jmin, j), max(jmax, j)
        return (max(0, int(math.floor(imin)) - 2), min(W - 1, int(math.ceil(imax)) + 2),
                max(0, int(math.floor(jmin)) - 2), min(H - 1, int(math.ceil(jmax)) + 2))


def make_object(kind, m, data, LS):
    if kind == 'sphere':
        return Sphere(m, data, LS)
    if kind == 'polygon':
        return Polygon(m, data, LS)
    if kind == 'plane':
        return Plane(m, data, LS)
    return Hedron(m, data, LS)


# ---- shapes -------------------------------------------------------------------------
# Each has ffloat(ray) -> (code, tau): code 0 a sure miss, 1 a sure hit at tau, 2 unsure;
# and exact(ray) -> Result. Both honour ray.tmax (segments: 0 < tau < 1).

def _tau_ok_float(tau, ray, S):
    """code for a float tau: 0 no, 1 yes, 2 too close to an end to say."""
    dl = ray.dlen
    if tau * dl <= -CONF * S:
        return 0
    if tau * dl < CONF * S:
        return 2
    if ray.tmax is not None:
        if (tau - ray.tmax) * dl >= CONF * S:
            return 0
        if (ray.tmax - tau) * dl < CONF * S:
            return 2
    return 1


def _tau_ok_exact(tau, ray, S):
    """(inside, ambiguous) for an exact tau against 0 < tau < tmax."""
    dl = ray.edlen * float(abs(tau))
    inside = tau > 0 and (ray.tmax is None or tau < ray.tmax)
    amb = dl < EPS * S
    if ray.tmax is not None and abs(float(ray.tmax - tau)) * ray.edlen < EPS * S:
        amb = True
    return inside, amb


class Polygon:
    def __init__(self, m, data, LS):
        verts, patch = data
        self.mat = m
        self.two_sided = patch or m.kt > 0
        self.Vi = [tuple(int(x * LS) for x in p) for p in verts]
        self.N = newell(self.Vi)                     # integer, same direction as the decimal one
        self.n = len(verts)
        self.sumV = tuple(sum(p[k] for p in self.Vi) for k in range(3))
        self.offset_num = dot(self.N, self.sumV)      # n N.X = N.sumV on the plane
        self.Vf = [tuple(float(x) for x in p) for p in verts]
        Nf = tuple(float(c) for c in newell(verts))
        self.Nf = fnormalize(Nf)
        cen = tuple(sum(p[k] for p in self.Vf) / self.n for k in range(3))
        self.df = dot(self.Nf, cen)
        self.lo = tuple(min(p[k] for p in self.Vf) for k in range(3))
        self.hi = tuple(max(p[k] for p in self.Vf) for k in range(3))
        self.size = max(maxabs(p) for p in self.Vf)
        self.pts = self.Vf

    def ffloat(self, ray):
        Nf = self.Nf
        den = dot(Nf, ray.Df)
        cosf = abs(den) / ray.dlen
        if cosf < 1e-6:
            return 2, None
        if den > 0 and not self.two_sided and ray.tmax is None:
            return 0, None
        tau = (self.df - dot(Nf, ray.Of)) / den
        X = add(ray.Of, scale(ray.Df, tau))
        S = max(maxabs(ray.Of), maxabs(X), abs(tau) * ray.dlen, self.size * 1e-3)
        ok = _tau_ok_float(tau, ray, S)
        if ok == 2 and ray.tmax is not None and \
           ray.w * self.offset_num == self.n * dot(self.N, ray.O):
            return 0, None   # a segment starting exactly in the plane (see exact)
        if ok != 1:
            return ok, None
        u, v = ray_basis(ray.Df)
        loop = along_ray(self.Vf, ray.Of, u, v)
        if loop_distance(loop, (0.0, 0.0)) < CONF * S:
            return 2, None
        return (1, tau) if even_odd(loop, (0.0, 0.0)) else (0, None)

    def exact(self, ray):
        N = self.N
        nd = dot(N, ray.D)
        Nn = norm(tuple(float(c) for c in N))
        cosf = abs(float(nd)) / (Nn * norm(tuple(float(c) for c in ray.D)))
        if nd == 0:
            return Result(False, amb=True)
        if nd > 0 and not self.two_sided and ray.tmax is None:
            return Result(False, amb=cosf < EPS)
        num = ray.w * self.offset_num - self.n * dot(N, ray.O)
        if num == 0 and ray.tmax is not None:
            # a segment starting in the plane leaves it at once: it touches, never crosses
            return Result(False)
        den = self.n * nd
        if den < 0:
            num, den = -num, -den
        tau = Fraction(num, den)
        Q = add(scale(ray.O, den), scale(ray.D, num))
        Wt = ray.w * den
        X = tuple(q / Wt for q in Q)  # in LS units (float, correctly rounded)
        # exact even-odd test seen along the ray: every point (vertices times w, the ray's
        # origin O) moved along D onto the plane where D's largest coordinate k is 0
        # (times D_k, to stay in integers), then that coordinate dropped
        k = max(range(3), key=lambda i: abs(ray.D[i]))
        Dk = ray.D[k]

        def seen(P, P_k):
            q = tuple(P[i] * Dk - P_k * ray.D[i] for i in range(3))
            return tuple(q[i] for i in range(3) if i != k)
        loop = [seen(tuple(c * ray.w for c in V), V[k] * ray.w) for V in self.Vi]
        inside = even_odd(loop, seen(ray.O, ray.O[k]))
        return self._finish(ray, tau, Q, Wt, X, inside, cosf)

    def _finish(self, ray, tau, Q, Wt, X, inside, cosf):
        # distances in scene units: X is in LS units; uvf and the ray floats in scene units
        LSf = self.LSf
        Xs = (X[0] / LSf, X[1] / LSf, X[2] / LSf)
        dist = abs(float(tau)) * ray.edlen
        S = max(maxabs(ray.Of), maxabs(Xs), dist, self.size * 1e-3)
        if ray.tmax is not None and dist < EPS * S:
            # a segment leaving (a point within EPS of) the plane crosses it nowhere else
            return Result(False)
        inside_t, amb_t = _tau_ok_exact(tau, ray, S)
        u, v = ray_basis(ray.Df)
        mind = loop_distance(along_ray(self.Vf, ray.Of, u, v), (0.0, 0.0))
        amb = amb_t or mind < EPS * S or cosf < EPS
        n = self.Nf
        return Result(inside and inside_t, tau, amb, Q, Wt, n, dist, S)


class Sphere:
    def __init__(self, m, data, LS):
        c, r = data
        self.mat = m
        self.inside_only = r < 0
        r = abs(r)
        self.Ci = tuple(int(x * LS) for x in c)
        self.ri = int(r * LS)
        self.Cf = tuple(float(x) for x in c)
        self.rf = float(r)
        self.lo = tuple(x - self.rf for x in self.Cf)
        self.hi = tuple(x + self.rf for x in self.Cf)
        self.size = maxabs(self.Cf) + self.rf
        self.pts = [(self.Cf[0] + sx * self.rf, self.Cf[1] + sy * self.rf, self.Cf[2] + sz * self.rf)
                    for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]

    def ffloat(self, ray):
        dl = ray.dlen
        Du = (ray.Df[0] / dl, ray.Df[1] / dl, ray.Df[2] / dl)
        oc = sub(ray.Of, self.Cf)
        dperp = norm(cross(oc, Du))
        r = self.rf
        b = dot(oc, Du)
        S = max(maxabs(ray.Of), self.size, abs(b) + r)
        if abs(dperp - r) < CONF * S:
            return 2, None
        if dperp > r:
            return 0, None
        h = math.sqrt((r - dperp) * (r + dperp))
        t0, t1 = -b - h, -b + h       # distances along the unit direction
        # the eye (or the segment's start) on the surface
        if abs(norm(oc) - r) < CONF * S:
            return 2, None
        for t in ((t1,) if self.inside_only else (t0, t1)):
            ok = _tau_ok_float(t / dl, ray, S)
            if ok == 2:
                return 2, None
            if ok == 1:
                return 1, t / dl
        return 0, None

    def exact(self, ray):
        D = ray.D
        oc = sub(ray.O, scale(self.Ci, ray.w))
        a = dot(D, D)
        b = dot(D, oc)
        rw = self.ri * ray.w
        c = dot(oc, oc) - rw * rw
        disc = b * b - a * c
        LSf = self.LSf
        # distance of the ray from the centre, minus r (scene units), from r^2 - d^2 = disc / (a w^2)
        gap = -float(Fraction(disc, a * ray.w * ray.w)) / (LSf * LSf) / (2 * self.rf)
        b_s = float(Fraction(b, ray.w)) / math.sqrt(float(a)) / LSf
        S = max(maxabs(ray.Of), self.size, abs(b_s) + self.rf)
        amb = abs(gap) < EPS * S
        if disc < 0:
            # a near miss is ambiguous at the ray's closest approach to the centre
            return Result(False, amb=amb, scale=S, dist=max(-b_s, 0.0))
        sq = isqrt_frac(disc)
        roots = [(-b - sq) / a, (-b + sq) / a]
        if self.inside_only:
            roots = roots[1:]
        # the start on the surface
        if abs(float(Fraction(c, ray.w * ray.w)) / (LSf * LSf)) < EPS * S * self.rf * 2:
            amb = True
        for tau in roots:
            inside_t, amb_t = _tau_ok_exact(tau, ray, S)
            if amb_t:
                amb = True
            if inside_t:
                tau = Fraction(tau)
                Q = add(scale(ray.O, tau.denominator), scale(D, tau.numerator))
                Wt = ray.w * tau.denominator
                Xs = tuple(float(Fraction(q, Wt)) / LSf for q in Q)
                n = fnormalize(sub(Xs, self.Cf))
                return Result(True, tau, amb, Q, Wt, n, float(tau) * ray.edlen, S)
        return Result(False, amb=amb, scale=S)


class Plane:
    def __init__(self, m, data, LS):
        p, n = data
        self.mat = m
        nden = 1
        for x in n:
            nden = nden * x.denominator // math.gcd(nden, x.denominator)
        self.Ni = tuple(int(x * nden) for x in n)
        self.Pi = tuple(int(x * LS) for x in p)
        self.off = dot(self.Ni, self.Pi)
        self.Nf = fnormalize(tuple(float(x) for x in n))
        self.Pf = tuple(float(x) for x in p)
        self.df = dot(self.Nf, self.Pf)
        self.size = maxabs(self.Pf)
        self.lo = None
        self.pts = None

    def ffloat(self, ray):
        den = dot(self.Nf, ray.Df)
        if abs(den) < 1e-6 * ray.dlen:
            return 2, None
        tau = (self.df - dot(self.Nf, ray.Of)) / den
        X = add(ray.Of, scale(ray.Df, tau))
        S = max(maxabs(ray.Of), maxabs(X), abs(tau) * ray.dlen, self.size)
        ok = _tau_ok_float(tau, ray, S)
        if ok == 2 and ray.tmax is not None and ray.w * self.off == dot(self.Ni, ray.O):
            return 0, None
        return (ok, tau if ok == 1 else None)

    def exact(self, ray):
        nd = dot(self.Ni, ray.D)
        cosf = abs(float(nd)) / (norm(tuple(float(c) for c in self.Ni)) *
                                 norm(tuple(float(c) for c in ray.D)))
        if nd == 0:
            return Result(False, amb=True)
        num = ray.w * self.off - dot(self.Ni, ray.O)
        if num == 0 and ray.tmax is not None:
            return Result(False)
        den = nd
        if den < 0:
            num, den = -num, -den
        tau = Fraction(num, den)
        Q = add(scale(ray.O, den), scale(ray.D, num))
        Wt = ray.w * den
        LSf = self.LSf
        Xs = tuple(float(Fraction(q, Wt)) / LSf for q in Q)
        dist = abs(float(tau)) * ray.edlen
        S = max(maxabs(ray.Of), maxabs(Xs), dist, self.size)
        if ray.tmax is not None and dist < EPS * S:
            return Result(False)
        inside_t, amb_t = _tau_ok_exact(tau, ray, S)
        return Result(inside_t, tau, amb_t or cosf < EPS, Q, Wt, self.Nf, dist, S)


class Hedron:
    def __init__(self, m, planes, LS):
        self.mat = m
        self.planes = []
        self.planesf = []
        for n, d in planes:
            den = 1
            for x in n:
                den = den * x.denominator // math.gcd(den, x.denominator)
            ni = tuple(n[k] * den for k in range(3))
            di = d * den * LS                    # n.X <= d with X in LS units
            # make di an integer by scaling both
            k = di.denominator
            ni = tuple(int(x * k) for x in ni)
            di = int(di * k)
            self.planes.append((ni, di))
            nf = tuple(float(x) for x in n)
            ln = norm(nf)
            self.planesf.append((scale(nf, 1 / ln), float(d) / ln))
        self.size = max([abs(d) for _, d in self.planesf] + [0.0])
        # bounds: only for boxes (axis-aligned planes), else unbounded
        self.lo = self.pts = None
        if len(self.planesf) == 6 and all(sum(1 for c in n if c != 0) == 1 for n, _ in self.planesf):
            lo, hi = [None] * 3, [None] * 3
            for n, d in self.planesf:
                k = [i for i in range(3) if n[i] != 0][0]
                if n[k] > 0:
                    hi[k] = d / n[k]
                else:
                    lo[k] = d / n[k]
            if None not in lo and None not in hi:
                self.lo, self.hi = tuple(lo), tuple(hi)
                self.pts = [(x, y, z) for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                            for z in (lo[2], hi[2])]

    def _interval(self, vals):
        """vals: list of (num, den) with the plane's f(tau) = den tau - num <= 0 inside.
        Returns (t_in, k_in, t_out, k_out, outside_parallel)."""
        t_in, k_in, t_out, k_out = None, -1, None, -1
        for k, (num, den) in enumerate(vals):
            if den == 0:
                if num < 0:
                    return None
                continue
            t = num / den
            if den < 0:
                if t_in is None or t > t_in:
                    t_in, k_in = t, k
            else:
                if t_out is None or t < t_out:
                    t_out, k_out = t, k
        return t_in, k_in, t_out, k_out

    def _margin(self, X, skip):
        """max over the planes other than `skip` of the signed distance n.X - d (floats)."""
        g = -float('inf')
        for k, (n, d) in enumerate(self.planesf):
            if k != skip:
                g = max(g, dot(n, X) - d)
        return g

    def _decide(self, t_in, k_in, t_out, k_out, ray):
        """Which t is the hit, if any: (tau, plane) or None; for floats and exact alike."""
        tmax = ray.tmax
        if t_in is not None and (t_out is None or t_in < t_out) and t_in > 0 and \
           (tmax is None or t_in < tmax):
            return t_in, k_in
        if (t_in is None or t_in <= 0) and t_out is not None and t_out > 0 and \
           (tmax is None or t_out < tmax) and (t_in is None or t_in < t_out):
            return t_out, k_out
        return None

    def ffloat(self, ray):
        vals = [(d - dot(n, ray.Of), dot(n, ray.Df)) for n, d in self.planesf]
        for num, den in vals:
            if abs(den) < 1e-6 * ray.dlen and abs(num) < 1e-3 * max(self.size, 1e-300):
                return 2, None
        iv = self._interval([(num, den) if abs(den) >= 1e-6 * ray.dlen else (num, 0.0)
                             for num, den in vals])
        if iv is None:
            return 0, None
        t_in, k_in, t_out, k_out = iv
        S = max(maxabs(ray.Of), self.size)
        for t, k in ((t_in, k_in), (t_out, k_out)):
            if t is None:
                continue
            X = add(ray.Of, scale(ray.Df, t))
            S2 = max(S, abs(t) * ray.dlen, maxabs(X))
            if abs(self._margin(X, k)) < CONF * S2:
                return 2, None
            if abs(t) * ray.dlen < CONF * S2:
                return 2, None
            if ray.tmax is not None and abs(ray.tmax - t) * ray.dlen < CONF * S2:
                return 2, None
        hit = self._decide(t_in, k_in, t_out, k_out, ray)
        return (1, hit[0]) if hit else (0, None)

    def exact(self, ray):
        vals = []
        for n, d in self.planes:
            vals.append((Fraction(ray.w * d - dot(n, ray.O)), Fraction(dot(n, ray.D))))
        S = max(maxabs(ray.Of), self.size)
        amb = False
        for (num, den), (n, _) in zip(vals, self.planes):
            # a ray parallel to a face, within EPS of its plane
            if den == 0 and abs(float(num / (ray.w * self.LS))) / norm(n) < EPS * max(S, 1.0):
                amb = True
        iv = self._interval(vals)
        if iv is None:
            return Result(False, amb=amb, scale=S)
        t_in, k_in, t_out, k_out = iv
        near = None
        for t, k in ((t_in, k_in), (t_out, k_out)):
            if t is None:
                continue
            Xs = tuple(float((ray.O[c] + t * ray.D[c]) / (ray.w * self.LS)) for c in range(3))
            d = abs(float(t)) * ray.edlen
            S2 = max(S, d, maxabs(Xs))
            if abs(self._margin(Xs, k)) < EPS * S2:
                amb = True
                if t > 0 and (near is None or d < near):
                    near = d
            amb = _tau_ok_exact(t, ray, S2)[1] or amb
        hit = self._decide(t_in, k_in, t_out, k_out, ray)
        if not hit:
            # a near miss is ambiguous where the ray passes the edge
            return Result(False, amb=amb, scale=S, dist=near if near is not None else None)
        tau, k = hit
        Q = add(scale(ray.O, tau.denominator), scale(ray.D, tau.numerator))
        Wt = ray.w * tau.denominator
        return Result(True, tau, amb, Q, Wt, self.planesf[k][0], float(tau) * ray.edlen, S)


# ---- the per-pixel decision ---------------------------------------------------------

class Entry:
    __slots__ = ('k', 'status', 'dist', 'ex')

    def __init__(self, k, status, dist, ex):
        self.k, self.status, self.dist, self.ex = k, status, dist, ex


def evaluate(world, ray, cands):
    """Entries (object index, 'hit' or 'amb', float distance, exact Result or None)."""
    out = []
    objs = world.objs
    for k in cands:
        o = objs[k]
        code, tau = o.ffloat(ray)
        if code == 0:
            continue
        if code == 1:
            out.append(Entry(k, 'hit', tau * ray.dlen, None))
            continue
        ex = o.exact(ray)
        if ex.amb:
            out.append(Entry(k, 'amb', ex.dist if ex.dist is not None else float('inf'), ex))
        elif ex.inside:
            out.append(Entry(k, 'hit', ex.dist, ex))
    return out


def refine(world, ray, entries):
    """Exact tests for the entries the float pass decided (for exact depth comparisons)."""
    for e in entries:
        if e.ex is None:
            e.ex = world.objs[e.k].exact(ray)
            if e.ex.amb:
                e.status = 'amb'
            elif not e.ex.inside:
                raise AssertionError('float pass and exact test disagree')


def first_hit_strict(world, ray, cands):
    """Object indices (or [-1] for the background) a generic ray meets first, taking each
    exact test's inside flag as it is (no ambiguity): the rays that look past objects."""
    best, ids = None, []
    objs = world.objs
    for k in cands:
        o = objs[k]
        code, tau = o.ffloat(ray)
        if code == 0:
            continue
        if code == 1:
            d = tau * ray.dlen
        else:
            ex = o.exact(ray)
            if not ex.inside:
                continue
            d = ex.dist
        if best is None or d < best * (1 - 1e-7):
            best, ids = d, [k]
        elif d <= best * (1 + 1e-7):
            ids.append(k)
            best = min(best, d)
    return ids if ids else [-1]


def classify_pixel(world, ray, cands):
    """(acceptable rt ids as a set, the certain Entry or None, the entries tested).

    With a certain hit at depth t: the objects hit or ambiguous at t (within EPS). If some
    ambiguous object lies in front of t, a ray past it may or may not reach t: the rays moved
    off the ambiguous objects decide what lies behind them (a crack between two tiles in
    front of a backdrop is then wrong, the backdrop beside a sphere's silhouette right).
    Without a certain hit the same, with the background in place of t."""
    entries = evaluate(world, ray, cands)
    hits = [e for e in entries if e.status == 'hit']
    ambs = [e for e in entries if e.status == 'amb']
    near = None
    acc = []
    front = ambs
    if hits:
        tn = min(e.dist for e in hits)
        window = [e for e in entries if abs(e.dist - tn) <= tn * 1e-7]
        if len(window) == 1:
            near = window[0]
            acc = window
        else:
            refine(world, ray, window)
            whits = [e for e in window if e.status == 'hit']
            if whits:
                tau_n = min(e.ex.tau for e in whits)
                near = [e for e in whits if e.ex.tau == tau_n][0]
                S = max(e.ex.scale for e in window if e.ex.scale is not None)
                acc = [e for e in window if e.ex.tau is not None and
                       abs(float(e.ex.tau - tau_n)) * ray.edlen <= EPS * S]
            else:
                tn = min(e.dist for e in hits if e not in window) if len(hits) > len(window) \
                    else float('inf')
        front = [e for e in ambs if e not in acc and e.dist < tn]
    if not front:
        ids = set(e.k + 1 for e in acc)
        if not acc:
            ids.add(0)
        certain = near if near is not None and len(acc) == 1 and acc[0].status == 'hit' \
            else None
        return ids, certain, entries
    # look past the ambiguous objects in front
    ids = set(e.k + 1 for e in front)
    d = min(e.dist for e in front)
    S = max([e.ex.scale for e in front if e.ex is not None and e.ex.scale is not None] +
            [maxabs(ray.Of), d])
    eps = PERTURB * S / max(d, 1e-300)
    for n in range(16):
        phi = 2 * math.pi * (n + 0.31) / 16
        r2 = world.offset_ray(ray, eps * math.cos(phi), eps * math.sin(phi))
        for k in first_hit_strict(world, r2, cands):
            ids.add(k + 1)
    return ids, None, entries


# ---- shadows ------------------------------------------------------------------------

def segment_blocked(world, P_Q, P_W, Pf, light, skip):
    """'clear', 'blocked' or 'amb' for the segment from the exact point Q / W to light."""
    Li, Lf, _ = light
    O = P_Q
    w = P_W
    D = tuple(w * Li[c] - O[c] for c in range(3))
    Df = sub(Lf, Pf)
    ray = Ray(O, w, D, Pf, Df, world.LS, tmax=1)
    lo = tuple(min(Pf[c], Lf[c]) for c in range(3))
    hi = tuple(max(Pf[c], Lf[c]) for c in range(3))
    amb = False
    for k, o in enumerate(world.objs):
        if k == skip:
            continue
        if o.lo is not None:
            pad = 1e-6 * (o.size + 1e-300)
            if any(o.hi[c] < lo[c] - pad or o.lo[c] > hi[c] + pad for c in range(3)):
                continue
        code, _ = o.ffloat(ray)
        if code == 0:
            continue
        if o.mat.kt > 0:
            # light through glass is dimmed, refracted shadows are not modelled: no verdict
            amb = True
            continue
        if code == 1:
            return 'blocked'
        ex = o.exact(ray)
        if ex.amb:
            amb = True
        elif ex.inside:
            return 'blocked'
    return 'amb' if amb else 'clear'


def shade_class(world, ray, ent):
    """('lit' | 'dark' | None, the ambient-only 8-bit colour, material) for a certain hit."""
    o = world.objs[ent.k]
    ex = ent.ex if ent.ex is not None else o.exact(ray)
    if ex.amb or not ex.inside:
        return None, None, o.mat
    LSf = world.LS
    Pf = tuple(float(Fraction(q, ex.W)) / LSf for q in ex.Q)
    n = ex.normal
    if dot(n, ray.Df) > 0:
        n = scale(n, -1)
    m = o.mat
    amb_rgb = tuple(srgb_encode(world.sc.ambient[c] * m.color[c]) for c in range(3))
    lit = False
    dark = True
    for light in world.lights:
        Lf = light[1]
        Ld = sub(Lf, Pf)
        ln = norm(Ld)
        cosv = dot(n, Ld) / ln if ln > 0 else 0.0
        if cosv < -COS_CLEAR:
            continue
        if cosv < COS_CLEAR:
            dark = False
            continue
        state = segment_blocked(world, ex.Q, ex.W, Pf, light, ent.k)
        if state == 'blocked':
            continue
        dark = False
        if state == 'clear':
            # would this light alone change the pixel by 2 levels in some channel?
            inten = light[2]
            for c in range(3):
                a = world.sc.ambient[c] * m.color[c]
                v = a + m.kd * m.color[c] * cosv * inten[c]
                if srgb_encode(v) - srgb_encode(a) >= 2:
                    lit = True
    if lit:
        return 'lit', amb_rgb, m
    if dark:
        return 'dark', amb_rgb, m
    return None, amb_rgb, m


# ---- main ---------------------------------------------------------------------------

def main(argv):
    ap = argparse.ArgumentParser(description='Independent visibility oracle for rt --ids images.')
    ap.add_argument('scene')
    ap.add_argument('--ids', required=True)
    ap.add_argument('--more-ids', action='append', default=[],
                    help='another --ids image of the same scene and size, judged in the '
                         'same pass (repeatable); a line each, ending with its name')
    ap.add_argument('--write-wrong', action='store_true',
                    help='write the wrong pixels of each ids image to IDS.wrong, one '
                         'index (y * width + x) per line')
    ap.add_argument('--image')
    ap.add_argument('-s', dest='size')
    ap.add_argument('-v', action='store_true')
    args = ap.parse_args(argv)
    t0 = time.time()
    try:
        sc = parse_scene(args.scene)
        world = World(sc)
        if args.size:
            W, H = (int(x) for x in args.size.lower().split('x'))
        else:
            W, H = sc.view['resolution']
        iw, ih, isamples = read_ids(args.ids)
        if (iw, ih) != (W, H):
            raise OracleError('%s is %dx%d, the scene asks for %dx%d' % (args.ids, iw, ih, W, H))
        more = []
        for path in args.more_ids:
            mw, mh, msamples = read_ids(path)
            if (mw, mh) != (W, H):
                raise OracleError('%s is %dx%d, expected %dx%d' % (path, mw, mh, W, H))
            more.append((path, msamples, []))
        img = None
        if args.image:
            pw, ph, img = read_ppm(args.image)
            if (pw, ph) != (W, H):
                raise OracleError('%s is %dx%d, expected %dx%d' % (args.image, pw, ph, W, H))
    except (OSError, ValueError, OracleError, IndexError) as e:
        print('oracle.py: %s' % e, file=sys.stderr)
        return 2
    for o in world.objs:
        o.LS, o.LSf = world.LS, float(world.LS)
    world.setup_camera(W, H)

    # candidate objects per pixel, from their projected bounds
    cand = [[] for _ in range(W * H)]
    for k, o in enumerate(world.objs):
        box = world.pixel_box(o.pts) if o.pts is not None else None
        if box is None:
            box = (0, W - 1, 0, H - 1)
        i0, i1, j0, j1 = box
        for j in range(j0, j1 + 1):
            row = j * W
            for i in range(i0, i1 + 1):
                cand[row + i].append(k)

    wrong = []
    lit_n = dark_n = false_shadow = false_light = 0
    fs_list, fl_list = [], []
    try:
        for j in range(H):
            for i in range(W):
                px = j * W + i
                rt_id = (isamples[2 * px] << 8) | isamples[2 * px + 1]
                ray = world.eye_ray(i, j)
                ids, certain, entries = classify_pixel(world, ray, cand[px])
                for (_, msamples, mwrong) in more:
                    if (msamples[2 * px] << 8) | msamples[2 * px + 1] not in ids:
                        mwrong.append(px)
                if rt_id not in ids:
                    wrong.append((i, j, rt_id, ids, entries))
                    continue
                if img is None or certain is None or rt_id != certain.k + 1:
                    continue
                cls, amb_rgb, m = shade_class(world, ray, certain)
                if cls is None:
                    continue
                rgb = tuple(img[3 * px:3 * px + 3])
                near_dark = all(abs(rgb[c] - amb_rgb[c]) <= 1 for c in range(3))
                if cls == 'lit':
                    lit_n += 1
                    if near_dark:
                        false_shadow += 1
                        fs_list.append((i, j, rgb))
                elif m.ks == 0 and m.kt == 0:
                    dark_n += 1
                    if not near_dark:
                        false_light += 1
                        fl_list.append((i, j, rgb))
    except OracleError as e:
        print('oracle.py: %s' % e, file=sys.stderr)
        return 2
    n = W * H
    print('wrong %d of %d pixels (%.4f%%)' % (len(wrong), n, 100.0 * len(wrong) / n))
    for (path, _, mwrong) in more:
        print('wrong %d of %d pixels (%.4f%%) %s' % (len(mwrong), n, 100.0 * len(mwrong) / n,
                                                     path))
    if args.write_wrong:
        lists = [(args.ids, [j * W + i for (i, j, _, _, _) in wrong])]
        lists += [(path, mwrong) for (path, _, mwrong) in more]
        for (path, pixels) in lists:
            with open(path + '.wrong', 'w') as f:
                f.write(''.join('%d\n' % px for px in pixels))
    if img is not None:
        print('false shadows %d of %d clearly lit pixels' % (false_shadow, lit_n))
        print('false lights %d of %d clearly dark pixels' % (false_light, dark_n))
    if args.v:
        for (i, j, rt_id, ids, entries) in wrong[:20]:
            desc = ', '.join('%d:%s@%.17g' % (e.k + 1, e.status, e.dist) for e in entries)
            print('  pixel %d,%d: rt %d, acceptable %s; tested %s' %
                  (i, j, rt_id, sorted(ids), desc))
        for (i, j, rgb) in fs_list[:10]:
            print('  false shadow at pixel %d,%d: rt %s' % (i, j, rgb))
        for (i, j, rgb) in fl_list[:10]:
            print('  false light at pixel %d,%d: rt %s' % (i, j, rgb))
        print('oracle.py: %.2f s' % (time.time() - t0), file=sys.stderr)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))

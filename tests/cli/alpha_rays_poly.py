#!/usr/bin/env python3
"""Independent A(alpha) of a method given by its characteristic polynomial
p(lambda, z) (any degree in both, complex coefficients allowed), floats
only, no recstab: f(theta) = max over r > 0 of the largest |root| of
p(., -r e^{i theta}) (mpmath.polyroots; a log-r scan, then ternary search
around the worst r), alpha = the largest theta with f <= 1 + 1e-9 on both
sides (theta and -theta) by bisection.  Usage: alpha_rays_poly.py NAME,
NAME one of the methods below.  Used for tests/unit/analysis/test_astability.c
(test_rays_route), which keeps the printed degrees of enright3 as a literal
upper bound of alpha (a run takes about 7 minutes; the lower bound there is
its own boundary-locus scan).
When every ray up to 89.9 degrees is inside it also scans theta = 90
(the imaginary axis) and says whether it is inside.
  enright3: Enright's second-derivative method, k = 3 (order 5):
    y1 - y0 = h (307/540 f1 + 19/40 f0 - 1/20 f-1 + 7/1080 f-2) - 19/180 h^2 y1''
    (coefficients from the order conditions, solved by hand / sympy)
  enright2: the same family, k = 2 (order 4):
    y1 - y0 = h (29/48 f1 + 5/12 f0 - 1/48 f-1) - 1/8 h^2 y1''
    (every ray up to 89.9 degrees inside, and the axis)"""
import cmath
import math
import sys
import mpmath

mpmath.mp.dps = 20


def enright3(z):
    # 1080 (l^3 - l^2) = z (614 l^3 + 513 l^2 - 54 l + 7) - 114 z^2 l^3 (times 1080, y_{n-2} -> 1):
    # p = (1080 - 614 z + 114 z^2) l^3 - (1080 + 513 z) l^2 + 54 z l - 7 z, highest power first
    return [1080 - 614 * z + 114 * z * z, -1080 - 513 * z, 54 * z, -7 * z]


def enright2(z):
    # 48 (l^2 - l) = z (29 l^2 + 20 l - 1) - 6 z^2 l^2:
    # p = (48 - 29 z + 6 z^2) l^2 - (48 + 20 z) l + z
    return [48 - 29 * z + 6 * z * z, -48 - 20 * z, z]


def maxroot(c):
    c = [complex(v) for v in c]
    while abs(c[0]) == 0:
        c = c[1:]
    if len(c) == 1:
        return 0.0
    return max(abs(complex(r)) for r in mpmath.polyroots(c, maxsteps=200, extraprec=40))


def fmax(th, P):
    f = lambda lr: maxroot(P(-math.exp(lr) * cmath.exp(1j * th)))
    grid = [i / 50 for i in range(-350, 451)]
    vals = [f(x) for x in grid]
    b = max(range(len(grid)), key=lambda i: vals[i])
    lo, hi = grid[max(b - 1, 0)], grid[min(b + 1, len(grid) - 1)]
    for _ in range(60):
        m1 = lo + (hi - lo) / 3
        m2 = hi - (hi - lo) / 3
        if f(m1) < f(m2):
            lo = m1
        else:
            hi = m2
    return max(f(lo), max(vals))


def main():
    P = {"enright3": enright3, "enright2": enright2}[sys.argv[1]]
    lo, hi = 0.0, math.radians(89.9)
    for _ in range(40):
        m = (lo + hi) / 2
        if fmax(m, P) <= 1 + 1e-9 and fmax(-m, P) <= 1 + 1e-9:
            lo = m
        else:
            hi = m
    print(math.degrees(lo))
    if math.degrees(hi - lo) < 1e-6 and math.degrees(lo) > 89.89:
        ax = fmax(math.pi / 2, P) <= 1 + 1e-9 and fmax(-math.pi / 2, P) <= 1 + 1e-9
        print("imaginary axis", "inside" if ax else "NOT inside")


main()

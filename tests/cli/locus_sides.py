#!/usr/bin/env python3
"""Independent count of the AB4 z-plane locus points that separate nothing
(issue 15 part 2, map re(z), im(z)): floats and pure Python only, no recstab.

The locus of Adams-Bashforth 4 is z(phi) = rho(w)/sigma(w), w = exp(i phi),
rho = w^4 - w^3, sigma = (55 w^3 - 59 w^2 + 37 w - 9)/24, sampled at the
721 angles phi_j = 2 pi j/720 as recstab's locus_table does.  At each point
the roots of rho - z sigma are counted outside the unit circle
(Durand-Kerner) at z +- h n (n the unit normal, h = 1e-5 max(1, |z|));
a point separates iff exactly one side has no root outside.  Prints
"total dropped".  Takes about 20 s, so the suite keeps its result (721 366)
as a literal: tests/cli/suite_complex.sh."""
import cmath
import math

RHO = [1, -1, 0, 0, 0]
SIG = [0, 55 / 24, -59 / 24, 37 / 24, -9 / 24]


def roots(c):
    n = len(c) - 1
    c = [x / c[0] for x in c]
    r = [(0.4 + 0.9j) ** k for k in range(n)]
    for _ in range(300):
        nr = []
        for i in range(n):
            v = sum(c[k] * r[i] ** (n - k) for k in range(n + 1))
            d = 1
            for j in range(n):
                if j != i:
                    d *= r[i] - r[j]
            nr.append(r[i] - v / d)
        r = nr
    return r


def ev(c, w):
    return sum(ci * w ** (len(c) - 1 - i) for i, ci in enumerate(c))


def nout(z):
    return sum(1 for x in roots([a - z * b for a, b in zip(RHO, SIG)]) if abs(x) > 1)


def zf(phi):
    w = cmath.exp(1j * phi)
    return ev(RHO, w) / ev(SIG, w)


total = dropped = 0
for j in range(721):
    phi = 2 * math.pi * j / 720
    z = zf(phi)
    t = zf(phi + 2 * math.pi * 1e-3 / 720) - z
    n = 1j * t / abs(t)
    h = 1e-5 * max(1, abs(z))
    total += 1
    if (nout(z + h * n) == 0) == (nout(z - h * n) == 0):
        dropped += 1
print(total, dropped)

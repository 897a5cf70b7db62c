#!/usr/bin/env python3
"""Independent A(alpha) for the methods over Q(sqrt 3) / Q(sqrt 2) that
recstab decides with its rays route over Q(sqrt d) (src/analysis/an_astability.c,
rs_an_astability_alpha_qd), no recstab:
  low    : rk sdirk3-low, the 2-stage SDIRK of order 3 with g = (3 - sqrt 3)/6
  plus   : rk sdirk3, g = (3 + sqrt 3)/6 (A-stable, Hairer and Wanner II, IV.6)
  pade03 : R(z) = 1/(1 - w + w^2/2 - w^3/6), w = sqrt(2) z (the unit test's R;
           the scaling by sqrt 2 keeps every ray, so alpha is Pade (0,3)'s)
  1. R from its definition with sympy (the tableaux: R = 1 + z b^T (I - zA)^-1 1);
  2. floats: f(theta) = max over r > 0 of |R(-r e^{i theta})| (log-r grid, then
     ternary search around the worst r); alpha = the largest theta with f <= 1
     by bisection (prints 90 when every ray up to 90 - 1e-9 degrees is inside);
  3. pade03 only: sympy derives the critical polynomial of the rays route on
     the rational R(z) (G = |N|^2 - |D|^2 on z = -s (1 - i u) over s^m, the
     discriminant in s), and prints the factor whose root is tan(alpha).
Usage: alpha_sdirk3.py low|plus|pade03 (about 10 s each)."""
import cmath
import math
import sys
import sympy as sp

mode = sys.argv[1] if len(sys.argv) > 1 else "low"
z = sp.symbols("z")
if mode == "pade03":
    w = sp.sqrt(2) * z
    R = 1 / (1 - w + w ** 2 / 2 - w ** 3 / 6)
else:
    g = (3 + sp.sqrt(3)) / 6 if mode == "plus" else (3 - sp.sqrt(3)) / 6
    A = sp.Matrix([[g, 0], [1 - 2 * g, g]])
    b = sp.Matrix([[sp.Rational(1, 2), sp.Rational(1, 2)]])
    R = 1 + z * (b * (sp.eye(2) - z * A).inv() * sp.ones(2, 1))[0]
Rf = sp.lambdify(z, R, "cmath")


def fmax(th):
    f = lambda lr: abs(Rf(-math.exp(lr) * cmath.exp(1j * th)))
    grid = [i / 200 for i in range(-1400, 1801)]
    vals = [f(x) for x in grid]
    k = max(range(len(grid)), key=lambda i: vals[i])
    lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
    for _ in range(100):
        m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
        if f(m1) < f(m2):
            lo = m1
        else:
            hi = m2
    return max(f(lo), max(vals))


if fmax(math.pi / 2 - 1e-11) <= 1 + 1e-12:
    print("alpha_float 90")
else:
    lo, hi = 0.0, math.pi / 2
    for _ in range(50):
        mid = (lo + hi) / 2
        if fmax(mid) <= 1 + 1e-12:
            lo = mid
        else:
            hi = mid
    print("alpha_float %.14f %.14f" % (math.degrees(lo), math.degrees(hi)))
print("R(inf) =", sp.nsimplify(sp.limit(R, z, sp.oo)) if mode != "pade03" else 0)

if mode == "pade03":
    s, u = sp.symbols("s u", real=True)
    # the rational Pade (0, 3): N = 1, D = 1 - x + x^2/2 - x^3/6 (times 6)
    x = -s * (1 - sp.I * u)
    Dx = sp.expand(6 - 6 * x + 3 * x ** 2 - x ** 3)
    G = sp.expand(36 - (sp.re(Dx) ** 2 + sp.im(Dx) ** 2))
    G = sp.expand(sp.cancel(G / s ** min(m[0] for m in sp.Poly(G, s).monoms())))
    ta = math.tan(math.radians(88.230152007216))
    for f, _ in sp.factor_list(sp.discriminant(sp.Poly(G, s)), u)[1]:
        if any(abs(float(r) - ta) < 1e-6 * ta for r in sp.Poly(f, u).real_roots()):
            print("tan_alpha_minpoly", sp.Poly(f, u).as_expr())

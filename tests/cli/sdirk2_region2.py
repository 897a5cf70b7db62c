"""region a, c of cases/complex/sdirk2-coupled-region2.case against the
method's definition, no recstab arithmetic: SDIRK2 (Alexander; g = 1 -
sqrt(2)/2, A = [g, 0; 1-g, g], b = [1-g, g]) on y' = -a y + c x with x
frozen at x[n], backward Euler on x' = -c y - x with y frozen at y[n]
(Jacobi), step 1.  The step is linear in (y, x): M's columns are the steps
of (1, 0) and (0, 1), computed in mpmath at 60 digits; rho(M) from the 2x2
eigenvalues.  Checks (prints "ok ..." / "FAIL ..."):
  - at 300 random rational points (a in (0, 6), c in (-4, 4), seeded) the
    printed stable formula, evaluated exactly with Fractions, holds iff
    rho(M) < 1 (points with |rho - 1| < 1e-40 would be skipped: none is);
  - the marginal formula holds at none of them (the marginal set is a curve);
  - at each marginal cell's sample with a rational a, rho(M) = 1 to 1e-25;
  - the boundary at a = 1 is 17 c^4 - 92 c^2 + 124 (by hand in
    sdirk2-coupled-conditions.case: |lambda|^2 = C/A = 1 there), and the
    formula is complete.
Usage: sdirk2_region2.py REGION.json"""
import json
import random
import sys
from fractions import Fraction

import mpmath

mpmath.mp.dps = 60


def step_matrix(a, c):
    """M with (y, x)[n+1] = M (y, x)[n], from the stage equations"""
    g = 1 - mpmath.sqrt(2) / 2
    cols = []
    for y, x in ((mpmath.mpf(1), mpmath.mpf(0)), (mpmath.mpf(0), mpmath.mpf(1))):
        k1 = (-a * y + c * x) / (1 + a * g)
        k2 = (-a * (y + (1 - g) * k1) + c * x) / (1 + a * g)
        cols.append((y + (1 - g) * k1 + g * k2, (x - c * y) / 2))
    return [[cols[0][0], cols[1][0]], [cols[0][1], cols[1][1]]]


def mp(v):
    return mpmath.mpf(v.numerator) / v.denominator if isinstance(v, Fraction) else mpmath.mpf(v)


def rho(a, c):
    m = step_matrix(mp(a), mp(c))
    tr = m[0][0] + m[1][1]
    det = m[0][0] * m[1][1] - m[0][1] * m[1][0]
    disc = mpmath.sqrt(mpmath.mpc(tr * tr - 4 * det))
    return max(abs((tr + disc) / 2), abs((tr - disc) / 2))


def holds(cond, a, c):
    poly, rel = cond.rsplit(" ", 2)[0], cond.rsplit(" ", 2)[1]
    v = eval(poly.replace("^", "**"), {"a": a, "c": c})
    return {">": v > 0, ">=": v >= 0, "<": v < 0, "<=": v <= 0, "=": v == 0, "!=": v != 0}[rel]


def dnf(f, a, c):
    return any(all(holds(k, a, c) for k in conj) for conj in f)


def main():
    doc = json.load(open(sys.argv[1]))
    res = [r for r in doc["cases"][0]["results"] if r["analysis"] == "region"][0]
    st, mg = res["formula"]["stable"], res["formula"]["marginal"]
    rnd = random.Random(15)
    bad, n, skipped = [], 0, 0
    for _ in range(300):
        a = Fraction(rnd.randint(1, 5999), 1000)
        c = Fraction(rnd.randint(-3999, 3999), 1000)
        r = rho(a, c)
        if abs(r - 1) < mpmath.mpf(10) ** -40:
            skipped += 1
            continue
        n += 1
        if dnf(st, a, c) != (r < 1) or dnf(mg, a, c):
            bad.append((str(a), str(c), float(r)))
    if not bad and skipped == 0 and n == 300:
        print("ok region a, c over Q(sqrt 2): the formula agrees with rho(M) from the definition at 300 random points")
    else:
        print("FAIL region a, c: %d disagreements %s, %d skipped" % (len(bad), bad[:3], skipped))
    marg = [e for e in res["cells"] if e["status"] == "marginal" and isinstance(e["a"], str)
            and isinstance(e["c"], dict)]
    worst = max((abs(rho(Fraction(e["a"]), mpmath.mpf(e["c"]["approx"])) - 1) for e in marg), default=None)
    # approx carries 30 digits: rho = 1 to about 1e-28 there
    if marg and worst < mpmath.mpf(10) ** -25:
        print("ok region a, c: rho(M) = 1 (to 1e-25) at the %d marginal cells' samples" % len(marg))
    else:
        print("FAIL region a, c marginal samples: %d cells, worst |rho - 1| %s" % (len(marg), worst))
    bnd = res["boundary"]
    # quartics in c agreeing at 5 points are equal
    at1 = [[eval(b.replace("^", "**"), {"a": 1, "c": Fraction(k)}) for k in (0, 1, 2, 3, 4)] for b in bnd]
    want = [17 * k ** 4 - 92 * k ** 2 + 124 for k in (0, 1, 2, 3, 4)]
    if len(bnd) == 1 and at1[0] == want and res["formula_complete"] is True:
        print("ok region a, c: one boundary curve, 17 c^4 - 92 c^2 + 124 at a = 1; formula complete")
    else:
        print("FAIL region a, c boundary: %s complete=%s" % (bnd, res["formula_complete"]))


if __name__ == "__main__":   # sdirk2_map2.py imports rho
    main()

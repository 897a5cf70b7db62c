"""region a, b of cases/complex/sdirk2-complex-region2.case against the
method's definition, no recstab arithmetic: SDIRK2 (Alexander; g = 1 -
sqrt(2)/2, A = [g, 0; 1-g, g], b = [1-g, g]) on y' = (a + b q) y at the
complex set value q = i, step 1: z = a + i b, one step from y = 1 solves
the two stages in mpmath (60 digits) and gives R(z); the step is stable iff
|R(z)| < 1.  Checks (prints "ok ..." / "FAIL ..."):
  - at 300 random rational points of the case's box (seeded) the printed
    stable formula, evaluated exactly with Fractions, holds iff |R| < 1 and
    the marginal one at none (|R| = 1 is a curve; no point is that close);
  - every decided cell's sample (rational, or the 30-digit approx of an
    algebraic one) has |R| < 1 (stable), > 1 (unstable) or = 1 to 1e-25
    (marginal), and each of the three occurs;
  - the case's hand values: the point (0, 0) marginal (R(0) = 1), (1, 0)
    unstable (R(1) = 2 sqrt 2), the one singular cell at (2 + sqrt 2, 0)
    (D(1/g) = 0);
  - no sample disagreed (samples_cross_checked).
Usage: sdirk2_cx_region2.py REGION.json"""
import json
import random
import sys
from fractions import Fraction

import mpmath

mpmath.mp.dps = 60


def absR(a, b):
    """|R(a + i b)| from the stage equations k_j = z (y + sum_l A_jl k_l)"""
    g = 1 - mpmath.sqrt(2) / 2
    z = mpmath.mpc(a, b)
    k1 = z / (1 - g * z)
    k2 = z * (1 + (1 - g) * k1) / (1 - g * z)
    return abs(1 + (1 - g) * k1 + g * k2)


def num(v):
    if isinstance(v, dict):
        return mpmath.mpf(v["approx"])
    f = Fraction(v)
    return mpmath.mpf(f.numerator) / f.denominator


def sat(conj, pt):
    for cond in conj:
        poly, rel = cond.rsplit(" ", 2)[0], cond.rsplit(" ", 2)[1]
        v = eval(poly.replace("^", "**"), dict(pt))
        if not {">": v > 0, ">=": v >= 0, "<": v < 0, "<=": v <= 0, "=": v == 0, "!=": v != 0}[rel]:
            return False
    return True


def main():
    doc = json.load(open(sys.argv[1]))
    res = [r for r in doc["cases"][0]["results"] if r["analysis"] == "region"][0]
    st, mg = res["formula"]["stable"], res["formula"]["marginal"]
    rnd = random.Random(15)
    bad = []
    for _ in range(300):
        a = Fraction(rnd.randint(1, 5999), 1000)
        b = Fraction(rnd.randint(1, 3999), 1000)
        r = absR(num(str(a)), num(str(b)))
        pt = {"a": a, "b": b}
        if abs(r - 1) < mpmath.mpf(10) ** -40 or any(sat(c, pt) for c in st) != (r < 1) or any(sat(c, pt) for c in mg):
            bad.append((str(a), str(b), float(r)))
    if not bad:
        print("ok region a, b over Q(sqrt 2)(i): the formula agrees with |R(a + i b)| from the tableau at 300 points")
    else:
        print("FAIL region a, b over Q(sqrt 2)(i): %d disagreements %s" % (len(bad), bad[:3]))
    seen, wrong = set(), []
    tol = mpmath.mpf(10) ** -25
    for e in res["cells"]:
        s = e["status"]
        if s not in ("stable", "unstable", "marginal"):
            continue
        r = absR(num(e["a"]), num(e["b"]))
        want = "marginal" if abs(r - 1) < tol else "stable" if r < 1 else "unstable"
        seen.add(s)
        if want != s:
            wrong.append((s, float(r)))
    if not wrong and seen == {"stable", "unstable", "marginal"}:
        print("ok region a, b over Q(sqrt 2)(i): every decided cell's sample agrees with |R| (stable, unstable, "
              "marginal to 1e-25)")
    else:
        print("FAIL region a, b cells: %d wrong %s, statuses %s" % (len(wrong), wrong[:3], sorted(seen)))
    pts = {(json.dumps(e["a"]), json.dumps(e["b"])): e["status"] for e in res["cells"] if e["dim"] == 0}
    sing = [e for e in res["cells"] if e["status"] == "singular"]
    if (pts.get(('"0"', '"0"')) == "marginal" and pts.get(('"1"', '"0"')) == "unstable" and len(sing) == 1
            and isinstance(sing[0]["a"], dict) and sing[0]["a"]["minpoly"] == "a^2 - 4*a + 2"
            and abs(num(sing[0]["a"]) - 2 - mpmath.sqrt(2)) < mpmath.mpf(10) ** -25 and sing[0]["b"] == "0"):
        print("ok region a, b: (0, 0) marginal, (1, 0) unstable, singular only at (2 + sqrt 2, 0), as by hand")
    else:
        print("FAIL region a, b hand values: %s %s %s" % (pts.get(('"0"', '"0"')), pts.get(('"1"', '"0"')), sing))
    sc = res.get("samples_cross_checked", {})
    if res.get("over") == "Q(sqrt 2)(i)" and sc.get("disagree") == 0 and sc.get("rational_three_ways", 0) > 0:
        print("ok region a, b: over Q(sqrt 2)(i), %d rational and %d algebraic samples, none disagreed"
              % (sc["rational_three_ways"], sc["algebraic_two_ways"]))
    else:
        print("FAIL region a, b: over %s samples %s" % (res.get("over"), sc))


main()

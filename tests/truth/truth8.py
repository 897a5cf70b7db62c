#!/usr/bin/env python3
"""truth8.py -- classes not planted before h-truth8, every route against a truth
derived here independently of recstab (SymPy expansion; mpmath roots at 50 digits):

  rsym     symbolic Routh arrays that are singular for every parameter value, planted
           in q(z) and carried to p(lambda) = (lambda + 1)^n q((lambda - 1)/(lambda + 1))
           (whose bilinear image is q again):
             zero row   q = A(z) B(z), A even or odd in z with parameters (z^2 + a,
                        z^2 - a, z^4 + a z^2 + b, z^3 + a z, ...): q(z) and q(-z) share A,
                        whose roots are symmetric about z = 0 -- never Re z < 0 for all;
             zero pivot q = z^4 + s z^3 + c z^2 + s c z + a (D_2 = s c - s c = 0), and the
                        degree-5 analogue: the Hurwitz minor D_2 vanishes identically;
             last row   q = z B(z): q(0) = 0, lambda = 1 a root;
           truth: never asymptotically stable for every value (the reasons above, by hand),
           confirmed at random rational points by mpmath roots of p (max |lambda| >= 1);
           routh, hurwitz and jury must say "never stable" (weaker answers are FAIL for
           routh, "weak" for the others), exit 0 (3 is an inconsistency), and routh at a set
           point must match mpmath's classification.
           control    q = (z + c)(z^2 + a z + d), c, d > 0: stable at a = 1 (Routh by hand:
                        a d > 0 ... all coefficients positive, a + c > 0, (a + c)(a c + d) > c d):
                        routh must not say never.

Usage: truth8.py PART SEED COUNT   prints "ok ..." / "FAIL ..." / "weak ..." lines.
"""
import os
import random
import sys
from fractions import Fraction as F

import mpmath
import sympy as sp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import truth as T  # noqa: E402
import truth6 as T6  # noqa: E402

fail = T6.fail
rf = T.rand_frac
mpmath.mp.dps = 50
z, lam, a, b = sp.symbols("z lambda a b")


def nzf(rng, lo, hi):
    while True:
        v = rf(rng, lo, hi)
        if v != 0:
            return v


def R(v):
    return sp.Rational(v.numerator, v.denominator)


def p_of_q(q):
    """p(lambda) = (lambda + 1)^n q((lambda - 1)/(lambda + 1)), n = deg_z q"""
    n = sp.degree(q, z)
    return sp.expand(sp.cancel((lam + 1) ** n * q.subs(z, (lam - 1) / (lam + 1))))


def ptext(p):
    return str(p).replace("**", "^")


def num_status(p, vals):
    """'stable' / 'not' / None (degree drop) from mpmath roots of p at vals"""
    pv = sp.Poly(sp.expand(p.subs(vals)), lam)
    if pv.degree() < sp.degree(p, lam):
        return None
    cs = [mpmath.mpf(sp.Rational(c).p) / sp.Rational(c).q for c in pv.all_coeffs()]
    if pv.degree() == 0:
        return "stable"
    roots = mpmath.polyroots(cs, maxsteps=400, extraprec=400)
    m = max(abs(r) for r in roots)
    return "stable" if m < 1 - mpmath.mpf(10) ** -15 else "not"


def plant(rng, kind):
    """q(z) of the class, and the parameters it uses"""
    if kind == "zero_row":
        A = rng.choice([z ** 2 + a, z ** 2 - a, z ** 2 + a ** 2 + 1, z ** 4 + a * z ** 2 + b,
                        z ** 3 + a * z, a * z ** 2 + 1, z ** 2 + a * b, z ** 4 - a])
        B = 1
        for _ in range(rng.randint(1, 2)):
            B *= rng.choice([z + R(nzf(rng, -3, 3)), z ** 2 + R(rf(rng, -2, 3)) * z + R(nzf(rng, -1, 3)),
                             z + a + R(rf(rng, 0, 2))])
        return sp.expand(A * B)
    if kind == "zero_pivot":
        s, c = R(nzf(rng, -3, 3)), R(nzf(rng, -3, 3))
        if rng.random() < 0.5:
            return sp.expand(z ** 4 + s * z ** 3 + c * z ** 2 + s * c * z + a)
        d = R(rf(rng, -2, 2))
        return sp.expand(z ** 5 + s * z ** 4 + c * z ** 3 + s * c * z ** 2 + (d + b) * z + a)
    if kind == "last_row":
        B = rng.choice([z ** 2 + a * z + R(nzf(rng, -2, 2)), (z + a) * (z + R(nzf(rng, -2, 2))),
                        z ** 3 + a * z ** 2 + b * z + 1])
        return sp.expand(z * B)
    # control: stable at a = 1 (b = 1)
    c, d = R(nzf(rng, 0, 3)), R(nzf(rng, 0, 3))
    c, d = abs(c), abs(d)
    return sp.expand((z + c) * (z ** 2 + a * z + d) * rng.choice([1, z + b]))


def part_rsym(rng, count):
    kinds = ["zero_row", "zero_pivot", "last_row", "control"]
    for k in range(count):
        kind = kinds[k % 4]
        tag = "rsym-%d-%s" % (k, kind)
        q = plant(rng, kind)
        p = p_of_q(q)
        params = [s for s in (a, b) if q.has(s)]
        text = ("title truth8 %s\nparam %s\nchar %s\nanalyse routh\nanalyse hurwitz\nanalyse jury\n"
                % (kind, " ".join(str(s) for s in params), ptext(p)))
        rc, doc, err = T.run(text, ["--time-limit", "30"])
        bad = []
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        res = {r["analysis"]: r for r in doc["cases"][0]["results"]}
        pts = []
        for _ in range(6):
            vals = {s: R(rf(rng, -3, 3)) for s in params}
            if kind == "control" and not pts:
                vals = {s: sp.Integer(1) for s in params}
            pts.append((vals, num_status(p, vals)))
        if kind != "control":
            for vals, st in pts:
                if st == "stable":
                    bad.append("truth broken: stable at %s (planted never)" % vals)
            if res["routh"].get("verdict") != "never stable":
                bad.append("routh verdict %r" % res["routh"].get("verdict"))
            for name in ("hurwitz", "jury"):
                if res[name].get("verdict") != "never stable":
                    print("weak %s: %s verdict %r" % (tag, name, res[name].get("verdict")))
        else:
            if pts[0][1] != "stable":
                bad.append("control not stable at a = 1 by mpmath (generator bug)")
            if res["routh"].get("verdict") == "never stable":
                bad.append("routh says never, stable at a = 1")
        for name in ("routh", "hurwitz", "jury"):
            sc = res[name].get("sample_check")
            if sc is not None and not sc.get("agree", True):
                bad.append("%s sample check disagrees" % name)
            cr = res[name].get("cross_route")
            if cr is not None and cr.get("agree") is False:
                bad.append("%s cross route disagrees" % name)
        # routh at two set points against mpmath
        for vals, st in pts[:2]:
            if st is None:
                continue
            args = ["--time-limit", "30"] + sum((["--set", "%s=%s" % (s, v)] for s, v in vals.items()), [])
            rc2, doc2, err2 = T.run(text.replace("analyse hurwitz\nanalyse jury\n", ""), args)
            if rc2 != 0 or doc2 is None:
                bad.append("routh at %s: exit %d (%s)" % (vals, rc2, err2.strip()[:120]))
                continue
            got = doc2["cases"][0]["results"][0].get("status")
            if (got == "stable") != (st == "stable"):
                bad.append("routh at %s: %s, mpmath %s" % (vals, got, st))
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
        else:
            print("ok %s: %s" % (tag, res["routh"].get("verdict", "no verdict")))


def main():
    part, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = random.Random(seed)
    parts = {"rsym": part_rsym}
    if part not in parts:
        sys.exit("unknown part " + part)
    parts[part](rng, count)
    sys.exit(1 if T.NFAIL or T6.NFAIL else 0)


if __name__ == "__main__":
    main()

"""Shared by tests/cli/suite_complex.sh's checks of region c for all over
Q(sqrt 2) (cases/complex/sdirk2-forall.case, z = c a; sdirk2-forall3.case,
z = c a b): SDIRK2's stability function from the tableau in mpmath and the
intervals derived by hand in those cases' comments."""
import json
from fractions import Fraction
import mpmath as mp

mp.mp.dps = 30
G = 1 - mp.sqrt(2) / 2


def R(z):
    """R(z) = 1 + z b^T (I - z A)^-1 1, A = [g, 0; 1 - g, g], b = (1 - g, g)"""
    A = mp.matrix([[G, 0], [1 - G, G]]); b = mp.matrix([[1 - G, G]])
    return 1 + z * (b * mp.inverse(mp.eye(2) - z * A) * mp.matrix([1, 1]))[0]


def end(x):
    return None if x is None else (x if isinstance(x, str) else (x["minpoly"], x["root_index"]))


def num(x):
    """a rational string or an algebraic value's certified digits"""
    return mp.mpf(x["approx"]) if isinstance(x, dict) else mp.mpf(Fraction(x).numerator) / Fraction(x).denominator


P, Q = ("c^2 - 4*c + 2", 1), ("c^2 - 12*c + 4", 1)           # 2 + sqrt 2, 6 + 4 sqrt 2
# z = c * (1 at the smallest product of the quantified ones): the ends 0, 2 + sqrt 2, 6 + 4 sqrt 2
WANT = [("stable", None, "0", False, False), ("marginal", "0", "0", True, True), ("unstable", "0", P, False, False),
        ("singular", P, P, True, True), ("unstable", P, Q, False, False), ("marginal", Q, Q, True, True),
        ("stable", Q, None, False, False)]


def load(path):
    res = json.load(open(path))["cases"][0]["results"]
    r = [r for r in res if r["analysis"] == "region"][0]
    got = [(iv["status"], end(iv["lo"]), end(iv["hi"]), iv["lo_closed"], iv["hi_closed"]) for iv in r["intervals"]]
    return res, r, got


def check(path, for_all, factors):
    """the region's intervals against WANT, its keys, and at every open
    interval's sample c: stable iff max |R(c f)| < 1 over f in factors (the
    products of the quantified parameters on a grid); every unstable cell's
    counterexample re-checked (|R(z)| > 1 at z = c times the quantified
    values); returns (all results, the list of failures)"""
    res, r, got = load(path)
    bad = []
    if got != WANT: bad.append("intervals %r" % (got,))
    if r.get("over") != "Q(sqrt 2)" or r.get("for_all") != for_all or not r["point_checks"]["agree"]:
        bad.append("keys")
    for iv in r["intervals"]:
        for ev in iv["evidence"]:
            if ev["cell"] == "interval":
                c = num(ev["sample"])
                m = max(abs(R(c * f)) for f in factors)
                if (iv["status"] == "stable") != (m < 1): bad.append("sample %s: max |R| %s" % (ev["sample"], m))
            if iv["status"] == "unstable":
                cx = ev.get("counterexample")
                if cx is None: bad.append("no counterexample"); continue
                z = num(cx["c"])
                for v in for_all: z *= num(cx[v])
                if not abs(R(z)) > 1: bad.append("counterexample %r" % cx)
    return res, r, bad

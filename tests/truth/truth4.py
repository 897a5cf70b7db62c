#!/usr/bin/env python3
"""truth4.py -- planted-truth property tests, fourth batch (h-truth4).  Each truth
is planted and derived here independently of recstab (Fractions, the Gaussian
rationals of truth.py, mpmath at 60 digits where named):

  radius   char lambda^k * prod(lambda - r_i) with distinct planted r_i (rational, or
           Gaussian on a char line with i) and k roots at 0: `radius` must list exactly
           the planted roots, the k zeros with multiplicity k (over Q(i) p's own roots,
           not p conj(p)'s), and its printed certified [lower, upper] -- rounded
           outward -- must contain rho = max |r_i| computed by mpmath at 60 digits.
  lead     a leading coefficient that vanishes at a planted c: p = (a - c) Q(lambda)
           (p = 0 at a = c) or p = (a - c) lambda^n + Q(lambda), deg Q < n (a degree
           drop at a = c), Q planted from roots.  `region a` must list a = c as a
           one-point singular interval ("vanishes" true resp. false) and match the own
           exact verdict (truth.py's Routh on the bilinear image, Fractions) at probe
           points beside it; `jury` and `hurwitz` conditions, evaluated at the probes and
           at a = c, must say stable exactly where the own verdict is stable (never at c).
  implicit a singular implicit step of a system: `recurrence 1 = A1(a)`, `recurrence 0 = -B`
           with A1(a) = S diag(a - c, 1, ...) S^-1 (det A1 = a - c) and B rational: at a = c
           the step cannot be solved (det(lambda A1 - B) drops a degree), elsewhere the
           verdict is that of M = A1^-1 B (its characteristic polynomial by Faddeev-LeVerrier
           in Fractions, the own Routh route); `region a` must list a = c as singular and
           match at probe points, `stability` at a = c must say singular.

Usage: truth4.py PART SEED COUNT   prints "ok ..." / "FAIL ..." lines.
"""
import os
import random
import sys
from fractions import Fraction as F

import mpmath

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import truth as T  # noqa: E402

ok, rand_frac, G = T.ok, T.rand_frac, T.G
NFAIL = 0
mpmath.mp.dps = 60


def fail(msg, text=None, tag=None):
    global NFAIL
    NFAIL += 1
    print("FAIL " + msg)
    if text is not None and tag is not None:
        T.save_failing(text, tag)


def distinct_roots(rng, n, gaussian):
    roots = []
    while len(roots) < n:
        kind = rng.random()
        if gaussian:
            r = T.inside_point(rng) if kind < 0.5 else T.outside_point(rng)
        else:
            r = G(rand_frac(rng, -1, 1) if kind < 0.5 else rand_frac(rng, -3, 3))
        if r.abs2() != 0 and r not in roots:
            roots.append(r)
    return roots


# ---------------------------------------------------------------- part radius
def part_radius(rng, count):
    for k in range(count):
        gaussian = rng.random() < 0.4
        n = rng.randint(1, 3)
        kz = rng.randint(0, 3)
        roots = distinct_roots(rng, n, gaussian)
        c = T.poly_from_roots(roots)
        text = "title truth4 radius\nchar lambda^%d*(%s)\nanalyse radius\n" % (kz, T.poly_text(c))
        rc, doc, err = T.run(text)
        tag = "radius-%d" % k
        res = T.find(doc, "radius")
        if rc != 0 or res is None:
            fail("%s: exit %d %s" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        got = [(float(F(z["re"])), float(F(z["im"]))) for z in res.get("roots") or []]
        want = [(float(r.re), float(r.im)) for r in roots] + [(0.0, 0.0)] * kz
        zmult = [z.get("multiplicity") for z in res.get("roots") or [] if F(z["re"]) == 0 and F(z["im"]) == 0]
        if not T.match_multiset(got, want) or (kz > 0 and zmult != [kz] * kz):
            fail("%s: roots %s, planted %s (zeros x%d, multiplicities %s)" % (tag, got, want, kz, zmult), text, tag)
            continue
        rho = max(mpmath.sqrt(mpmath.mpf(r.re.numerator) ** 2 / r.re.denominator ** 2
                              + mpmath.mpf(r.im.numerator) ** 2 / r.im.denominator ** 2) for r in roots)
        lo, hi = mpmath.mpf(res["lower"]), mpmath.mpf(res["upper"])
        if not (lo <= rho <= hi):
            fail("%s: certified [%s, %s] misses rho = %s" % (tag, res["lower"], res["upper"],
                                                              mpmath.nstr(rho, 40)), text, tag)
            continue
        ok("%s: %d roots (%d at 0)%s, [%s, %s] contains rho" % (tag, n + kz, kz, " over Q(i)" if gaussian else "",
                                                              res["lower"], res["upper"]))


# ---------------------------------------------------------------- part lead
def own_status(coeffs):
    """exact status of a real polynomial (Fractions c[0..n]); singular when c[n] = 0 at the
    formal degree, None when the own route cannot decide (a circle root)"""
    c = list(coeffs)
    while c and c[-1] == 0:
        c.pop()
    if len(c) < len(coeffs):
        return "singular"
    z = 0
    while z < len(c) - 1 and c[z] == 0:
        z += 1          # roots at 0: inside
    c = c[z:]
    if len(c) == 1:
        return "stable"
    return T.real_roots_status([x / c[-1] for x in c])


def formula_says(res, a):
    """1 / 0 from a jury or hurwitz result's conditions at a (None: not evaluable)"""
    v = res.get("verdict", "")
    if v.startswith("never"):
        return 0
    if "branches" in res and res["branches"]:
        br = [b if isinstance(b, list) else b.get("conditions", []) for b in res["branches"]]
        return int(T.ev_formula(br, a, F(0)))
    conds = list(res.get("conditions") or []) + list(res.get("nonzero") or [])
    return int(all(T.ev_cond(x, a, F(0)) for x in conds))


def part_lead(rng, count):
    for k in range(count):
        cval = rand_frac(rng, -2, 2)
        n = rng.randint(1, 3)
        roots = [G(rand_frac(rng, -1, 1) if rng.random() < 0.6 else rand_frac(rng, -3, 3)) for _ in range(n)]
        roots = [r for r in roots if r.abs2() != 1] or [G(F(1, 2))]
        q = [x.re for x in T.poly_from_roots(roots)]
        vanish = rng.random() < 0.5
        if vanish:
            # p = (a - c) Q: every coefficient has the factor a - c
            text_p = " + ".join("(a - (%s))*(%s)*lambda^%d" % (cval, x, i) for i, x in enumerate(q))
            nform = len(q) - 1

            def p_at(a, q=q, cval=cval):
                return [(a - cval) * x for x in q]
        else:
            # p = (a - c) lambda^(n+1) + Q: the degree drops by one at a = c
            text_p = "(a - (%s))*lambda^%d + " % (cval, len(q)) + " + ".join(
                "(%s)*lambda^%d" % (x, i) for i, x in enumerate(q))
            nform = len(q)

            def p_at(a, q=q, cval=cval):
                return list(q) + [a - cval]
        text = ("title truth4 lead\nparam a\nchar %s\nanalyse region a\nanalyse jury\nanalyse hurwitz\n" % text_p)
        rc, doc, err = T.run(text)
        tag = "lead-%d" % k
        reg, jury, hur = T.find(doc, "region"), T.find(doc, "jury"), T.find(doc, "hurwitz")
        if rc != 0 or reg is None or jury is None or hur is None:
            fail("%s: exit %d %s" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        pt = [x for x in reg["intervals"] if x.get("lo") == str(cval) and x.get("hi") == str(cval)]
        if len(pt) != 1 or pt[0]["status"] != "singular" or pt[0].get("vanishes") != vanish:
            fail("%s: a = %s not a singular point with vanishes=%s: %s" % (tag, cval, vanish, pt), text, tag)
            continue
        bad = None
        probes = [cval] + [cval + d for d in (F(1, 97), F(-1, 89), F(3, 7), F(-5, 11), F(2), F(-3))]
        for a in probes:
            own = own_status(p_at(a)) if a != cval else "singular"
            if len(p_at(a)) - 1 != nform:
                own = "singular"
            if own is None:
                continue
            st = T.region_status_at(reg, a)
            if st is not None and st != own:
                bad = "region at a = %s says %s, own %s" % (a, st, own)
                break
            for name, res in (("jury", jury), ("hurwitz", hur)):
                says = formula_says(res, a)
                if says != (own == "stable"):
                    bad = "%s conditions at a = %s say %s, own %s" % (name, a, says, own)
                    break
            if bad:
                break
        if bad:
            fail("%s: %s" % (tag, bad), text, tag)
            continue
        ok("%s: %s at a = %s singular (vanishes %s), region, jury, hurwitz agree at %d probes" %
           (tag, "p = (a - c) Q" if vanish else "degree drop", cval, vanish, len(probes)))


def charpoly(M):
    """det(lambda I - M) coefficients c[0..n] (Faddeev-LeVerrier, Fractions)"""
    n = len(M)
    c = [F(0)] * (n + 1)
    c[n] = F(1)
    Mk = [[F(0)] * n for _ in range(n)]
    I = [[F(int(i == j)) for j in range(n)] for i in range(n)]
    for k in range(1, n + 1):
        Mk = T.mat_mul(M, [[Mk[i][j] + c[n - k + 1] * I[i][j] for j in range(n)] for i in range(n)])
        c[n - k] = -sum(Mk[i][i] for i in range(n)) / k
    return c


def det(M):
    """determinant by Gaussian elimination in Fractions"""
    M = [list(r) for r in M]
    n, d = len(M), F(1)
    for i in range(n):
        p = next((r for r in range(i, n) if M[r][i] != 0), None)
        if p is None:
            return F(0)
        if p != i:
            M[i], M[p] = M[p], M[i]
            d = -d
        d *= M[i][i]
        for r in range(i + 1, n):
            f = M[r][i] / M[i][i]
            M[r] = [M[r][j] - f * M[i][j] for j in range(n)]
    return d


def part_implicit(rng, count):
    for k in range(count):
        n = rng.randint(2, 3)
        cval = rand_frac(rng, -2, 2)
        S, Si = T.rand_invertible(rng, n)
        B = [[rand_frac(rng, -1, 1, (1, 2, 3, 4)) for _ in range(n)] for _ in range(n)]

        def A1(a):
            d = [a - cval] + [F(1)] * (n - 1)
            return [[sum(S[i][m] * d[m] * Si[m][j] for m in range(n)) for j in range(n)] for i in range(n)]
        ent = [["(%s)*(a - (%s)) + (%s)" % (S[i][0] * Si[0][j], cval,
                                            sum(S[i][m] * Si[m][j] for m in range(1, n))) for j in range(n)]
               for i in range(n)]
        negB = [[-x for x in r] for r in B]
        text = ("title truth4 implicit\nparam a\nrecurrence 1 = [%s]\nrecurrence 0 = %s\nanalyse region a\n"
                % ("; ".join(", ".join(r) for r in ent), T.mat_text(negB)))
        tag = "implicit-%d" % k
        rc, doc, err = T.run(text)
        reg = T.find(doc, "region")
        if rc != 0 or reg is None:
            fail("%s: exit %d %s" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        rc2, doc2, err2 = T.run(text.replace("analyse region a", "analyse stability"), ("--set", "a=%s" % cval))
        st_c = T.find(doc2, "stability")
        bad = None
        # det(lambda A1(c) - B) at n + 1 values of lambda: all 0 iff it vanishes identically
        # (B singular on A1(c)'s kernel): then no recurrence at a = c, stability says singular
        # with "vanishes" (h-polish; it was an input error, exit 2, when truth4 was written)
        vanish = all(det([[x * A1(cval)[i][j] - B[i][j] for j in range(n)] for i in range(n)]) == 0
                     for x in range(n + 1))
        if vanish and not (rc2 == 0 and st_c is not None and st_c.get("status") == "singular"
                           and st_c.get("vanishes") is True):
            bad = "stability at a = c (det vanishes): exit %d %s %s" % (rc2, st_c and st_c.get("status"),
                                                                         err2.strip()[:120])
        elif not vanish and (rc2 != 0 or st_c is None or st_c.get("status") != "singular"):
            bad = "stability at a = c: exit %d %s" % (rc2, st_c and st_c.get("status"))
        pt = [x for x in reg["intervals"] if x.get("lo") == str(cval) and x.get("hi") == str(cval)]
        if bad is None and (len(pt) != 1 or pt[0]["status"] != "singular" or pt[0].get("vanishes") != vanish):
            bad = "a = %s not a singular point (vanishes %s): %s" % (cval, vanish, pt)
        probes = [cval + d for d in (F(1, 97), F(-1, 89), F(3, 7), F(-5, 11), F(2), F(-3))]
        for a in probes if bad is None else []:
            M = T.mat_mul(T.mat_inv(A1(a)), B)
            own = own_status(charpoly(M))
            st = T.region_status_at(reg, a)
            if own is not None and st is not None and st != own:
                bad = "region at a = %s says %s, own %s" % (a, st, own)
        if bad:
            fail("%s: %s" % (tag, bad), text, tag)
            continue
        ok("%s: %d x %d, det A1 = a - (%s): singular there, region agrees at %d probes" % (tag, n, n, cval,
                                                                                           len(probes)))


def part_quick(rng, count):
    part_radius(rng, count)
    part_lead(rng, count)
    part_implicit(rng, count)


PARTS = {"quick": part_quick, "radius": part_radius, "lead": part_lead, "implicit": part_implicit}

if __name__ == "__main__":
    part, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    PARTS[part](random.Random(seed), count)
    n = NFAIL + T.NFAIL
    sys.exit(1 if n else 0)

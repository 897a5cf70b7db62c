#!/usr/bin/env python3
"""truth3.py -- planted-truth property tests, third batch (h-truth3).  Each truth
is planted and derived here independently of recstab (Fractions, Gaussian
rationals of truth.py; mpmath only where named):

  zeros    roots at 0 with multiplicity k: char lambda^k * prod(lambda - r_i) with
           planted r_i (inside, outside, +-1, circle points, Gaussian over Q(i)),
           over Q, over Q(i) (a char line with i, or `param z complex` set to a
           Gaussian value), and x[n+1] = M x[n] with M = S diag(N, D) S^-1, N a
           nilpotent Jordan block (k eigenvalues 0): the counts of stability,
           jury, routh (and the Q(i) analyses) must be the planted k + inside, on,
           outside; modes must list the planted roots, the k zeros included.
  circle   multiplicity-m roots on the unit circle of x[n+1] = M x[n],
           M = S diag(blocks) S^-1 with m copies of a circle block -- +1, -1, or the
           companion [[0, -1], [1, 1]] of lambda^2 - lambda + 1 (e^{+-i pi/3}, not a
           rational-tangent rotation) -- either semisimple (diagonal copies:
           marginal) or chained by identity blocks (Jordan: unstable), beside
           planted roots inside: stability / jury / routh verdict and the on count.
  lmm      (lmm3 in run_big.sh) linear multistep methods from the literature written as a new user
           would (`eq y[n+2] - y[n] = q/3*(y[n+2] + 4*y[n+1] + y[n])`, f = q y):
           Milne-Simpson, Nystrom (leapfrog), AB2, AB3, AM2 (3rd order), BDF2..BDF6
           zero-stable, BDF7 not (root condition of rho at q = 0: Hairer-Norsett-
           Wanner I, III.3; Cryer 1972 for BDF7); the real stability interval's left
           end of the explicit Adams methods is rho(-1)/sigma(-1) (a root leaves
           through -1): AB2 -1, AB3 -6/11, AM2 -6 (Hairer-Wanner II, V.1, Fig. 1.1);
           Milne-Simpson and Nystrom are unstable at every real q != 0 (the
           parasitic root near -1 leaves the circle: weak stability, HNW I, III.9).
  algclaim claims whose true interval ends are algebraic: lambda - (a^2 - c)/d is
           stable iff c - d < a^2 < c + d, ends sqrt(c -+ d); `claim stable when
           L < a < U` with rational L, U just inside / just outside must be proved /
           refuted, `region a` must give the ends (mpmath 30 digits).
  simlimit simulate vs the planted verdict (roots at 0 included) and `limit h -> 0`
           of lambda^k (lambda - h r) ... : k + planted roots tend to 0.

Usage: truth3.py PART SEED COUNT   prints "ok ..." / "FAIL ..." lines.
"""
import os
import random
import sys
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import truth as T  # noqa: E402

ok, rand_frac, G = T.ok, T.rand_frac, T.G
NFAIL = 0


def fail(msg):
    global NFAIL
    NFAIL += 1
    print("FAIL " + msg)


def counts(res):
    return (res.get("status"), res.get("inside"), res.get("on"), res.get("outside"))


def planted(roots):
    st, i, o, u = T.planted_truth(roots)
    return st, i, o, u


def conj_no_zero_row(rng, J):
    """S J S^-1 with no zero row: an equation x_i[n+1] = 0 is normalised by its lowest shift
    to x_i[n] = 0 (scheme.c, row_shift: equations are shift-invariant), which removes one root
    at 0 of det(lambda I - M) -- the roots at 0 of a system depend on how it is written, so the
    planted count holds for the one-step form only when every row keeps its lambda"""
    while True:
        S, Si = T.rand_invertible(rng, len(J))
        M = T.mat_mul(T.mat_mul(S, J), Si)
        if all(any(x != 0 for x in row) for row in M):
            return M


# ---------------------------------------------------------------- part zeros
def part_zeros(rng, count):
    for k in range(count):
        kz = rng.randint(1, 3)
        mode = rng.choice(["real", "real", "qi-char", "qi-set", "system"])
        roots = []
        for _ in range(rng.randint(1, 3)):
            c = rng.random()
            if mode == "real" or mode == "system":
                if c < 0.45:
                    roots.append(G(rand_frac(rng, -1, 1) or F(1, 2)))
                elif c < 0.75:
                    roots.append(G(rng.choice([F(3, 2), F(-2), F(5, 3), F(-7, 4)])))
                else:
                    roots.append(G(rng.choice([1, -1])))
            else:
                roots.append(rng.choice([T.inside_point, T.outside_point, T.circle_point])(rng))
        roots = [r for r in roots if not (r.re == 0 and r.im == 0)] or [G(F(1, 3))]
        allr = [G(0)] * kz + roots
        st, i, o, u = planted(allr)
        tag = "zeros-%d-%s" % (k, mode)
        if mode == "system":
            # x[n+1] = M x[n], M = S diag(N_kz, diag(roots)) S^-1, N_kz nilpotent (one Jordan block at 0)
            n = kz + len(roots)
            J = [[F(0)] * n for _ in range(n)]
            for j in range(kz - 1):
                J[j][j + 1] = F(1)
            for j, r in enumerate(roots):
                J[kz + j][kz + j] = r.re
            # repeated circle roots of a system are semisimple here (diagonal): marginal
            circ = [r for r in roots if r.abs2() == 1]
            if u == 0 and o > 0:
                st = "marginal"
            M = conj_no_zero_row(rng, J)
            names = ["x%d" % (j + 1) for j in range(n)]
            body = "unknown %s\n" % " ".join(names) + "".join(
                "eq %s[n+1] = %s\n" % (names[a], " + ".join("(%s)*%s[n]" % (M[a][b], names[b]) for b in range(n)))
                for a in range(n))
            del circ
        elif mode == "real":
            body = "char lambda^%d*%s\n" % (kz, "*".join("(lambda - (%s))" % r.re for r in roots))
        elif mode == "qi-char":
            body = "char lambda^%d*%s\n" % (kz, "*".join("(lambda - %s)" % r.fmt() for r in roots))
        else:
            # z = the first root; the others as numbers
            z = roots[0]
            body = "param z complex\nchar lambda^%d*(lambda - z)%s\nset z = %s + (%s)*i\n" % (
                kz, "".join("*(lambda - %s)" % r.fmt() for r in roots[1:]), z.re, z.im)
        if mode == "qi-set" and roots[0].im == 0:
            # a real set value: no complex set, the char line is over Q(i) only through the others
            mode = "qi-char"
        # a char line over Q(i) is a block system only when p itself is not real
        # (a conjugate pair multiplies out to real coefficients)
        cplx = any(c.im != 0 for c in T.poly_from_roots(roots))
        analyses = ["stability", "jury", "routh"] + (["modes"] if mode != "system" else [])
        text = "title planted roots at 0\n" + body + "".join("analyse %s\n" % a for a in analyses)
        rc, doc, err = T.run(text, ["--time-limit", "20"])
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], T.save_failing(text, tag)))
            continue
        bad = []
        for a in ("stability", "jury", "routh"):
            r = T.find(doc, a)
            if r is None:
                bad.append("%s missing" % a)
                continue
            got = counts(r)
            want = (st, i, o, u)
            if mode == "qi-char" and cplx and a == "stability":
                # the real block form [[A, -B], [B, A]] (det = p conj(p)) decides too: its
                # counts, kept under block_form, are every root twice
                b = r.get("block_form") or {}
                bgot = (b.get("inside"), b.get("on"), b.get("outside"))
                if bgot != (2 * i, 2 * o, 2 * u):
                    bad.append("stability block_form %s, planted twice %s" % (bgot, (i, o, u)))
            # jury / routh over Q(i) with symbolic machinery print the counts beside conditions
            if got != want:
                bad.append("%s %s, planted %s" % (a, got, want))
            if a != "routh" and r.get("at_zero") not in (None, kz) and not (mode == "qi-char" and cplx):
                bad.append("%s at_zero %s, planted %d" % (a, r.get("at_zero"), kz))
        m = T.find(doc, "modes")
        if m is not None:
            got = [(float(x["root"]["re"]), float(x["root"]["im"])) for x in m["modes"] + m.get("spurious", [])]
            want = [(float(r.re), float(r.im)) for r in allr]
            if not T.match_multiset(got, want, 1e-9):
                bad.append("modes roots %s, planted %s" % (got, want))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:3]), T.save_failing(text, tag)))
        else:
            ok("%s: counts agree (%s, %d at 0, %d inside, %d on, %d outside)" % (tag, st, kz, i - kz, o, u))


# ---------------------------------------------------------------- part circle
def part_circle(rng, count):
    for k in range(count):
        kind = rng.choice(["+1", "-1", "e^{i pi/3}"])
        m = rng.randint(2, 3) if kind != "e^{i pi/3}" else 2
        defective = rng.random() < 0.5
        blk = [[F(1)]] if kind == "+1" else [[F(-1)]] if kind == "-1" else [[F(0), F(-1)], [F(1), F(1)]]
        b = len(blk)
        n0 = b * m
        J = [[F(0)] * n0 for _ in range(n0)]
        for c in range(m):
            for i in range(b):
                for j in range(b):
                    J[c * b + i][c * b + j] = blk[i][j]
            if defective and c + 1 < m:      # identity block above the diagonal: one Jordan chain
                for i in range(b):
                    J[c * b + i][(c + 1) * b + i] = F(1)
        extra = [rand_frac(rng, -1, 1, (2, 3, 4, 5)) for _ in range(rng.randint(0, 2))]
        extra = [x for x in extra if abs(x) < 1]
        n = n0 + len(extra)
        Jf = [[F(0)] * n for _ in range(n)]
        for i in range(n0):
            for j in range(n0):
                Jf[i][j] = J[i][j]
        for i, x in enumerate(extra):
            Jf[n0 + i][n0 + i] = x
        M = conj_no_zero_row(rng, Jf)
        names = ["x%d" % (j + 1) for j in range(n)]
        text = ("title planted circle multiplicity\nunknown %s\n" % " ".join(names) + "".join(
            "eq %s[n+1] = %s\n" % (names[a], " + ".join("(%s)*%s[n]" % (M[a][c], names[c]) for c in range(n)))
            for a in range(n)) + "analyse stability\nanalyse jury\nanalyse routh\n")
        # truth: circle roots of multiplicity m (each eigenvalue of blk m times); bounded iff semisimple
        want_st = "unstable" if defective else "marginal"
        zeros_in = sum(1 for x in extra if x == 0)
        want = (want_st, len(extra), n0, 0)
        tag = "circle-%d-%s-x%d-%s" % (k, kind, m, "jordan" if defective else "semisimple")
        rc, doc, err = T.run(text, ["--time-limit", "20"])
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], T.save_failing(text, tag)))
            continue
        bad = []
        for a in ("stability", "jury", "routh"):
            r = T.find(doc, a)
            got = counts(r) if r else None
            if got != want:
                bad.append("%s %s, planted %s" % (a, got, want))
        del zeros_in
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:3]), T.save_failing(text, tag)))
        else:
            ok("%s: %s agrees (%d x %d)" % (tag, want_st, n, n))


# ---------------------------------------------------------------- part lmm
# rho, sigma coefficients (lowest power first) for y[n+j], f = q y; literature as in the module text
LMM = {
    "milne-simpson": ([F(-1), F(0), F(1)], [F(1, 3), F(4, 3), F(1, 3)]),
    "nystrom": ([F(-1), F(0), F(1)], [F(0), F(2), F(0)]),
    "ab2": ([F(0), F(-1), F(1)], [F(-1, 2), F(3, 2), F(0)]),
    "ab3": ([F(0), F(0), F(-1), F(1)], [F(5, 12), F(-16, 12), F(23, 12), F(0)]),
    "am2": ([F(0), F(-1), F(1)], [F(-1, 12), F(8, 12), F(5, 12)]),
    "bdf2": ([F(1, 2), F(-2), F(3, 2)], [F(0), F(0), F(1)]),
    "bdf3": ([F(-1, 3), F(3, 2), F(-3), F(11, 6)], [F(0), F(0), F(0), F(1)]),
    "bdf4": ([F(1, 4), F(-4, 3), F(3), F(-4), F(25, 12)], [F(0)] * 4 + [F(1)]),
    "bdf5": ([F(-1, 5), F(5, 4), F(-10, 3), F(5), F(-5), F(137, 60)], [F(0)] * 5 + [F(1)]),
    "bdf6": ([F(1, 6), F(-6, 5), F(15, 4), F(-20, 3), F(15, 2), F(-6), F(49, 20)], [F(0)] * 6 + [F(1)]),
    "bdf7": ([F(-1, 7), F(7, 6), F(-21, 5), F(35, 4), F(-35, 3), F(21, 2), F(-7), F(363, 140)], [F(0)] * 7 + [F(1)]),
}


def lmm_case(name, qval=None):
    rho, sig = LMM[name]
    k = len(rho) - 1

    def side(c, mul):
        t = ["(%s)*y[n+%d]" % (x, j) if j else "(%s)*y[n]" % x for j, x in enumerate(c) if x != 0]
        return (mul + "(" + " + ".join(t) + ")") if t else "0"
    text = "title %s as a new user writes it\nparam q\nunknown y\neq %s = %s\n" % (
        name, side(rho, ""), side(sig, "q*"))
    if qval is not None:
        text += "set q = %s\n" % qval
    del k
    return text


def lmm_roots_status(name, q):
    """the exact status of rho - q sigma at rational q: mpmath roots at 60 digits, the root
    condition decided with a 1e-40 margin (a root within it is on the circle only when the
    polynomial has it exactly: checked by evaluating at +-1)"""
    import mpmath
    mpmath.mp.dps = 60
    rho, sig = LMM[name]
    c = [r - q * s for r, s in zip(rho, sig)]
    while c and c[-1] == 0:
        c.pop()
    rts = mpmath.polyroots([mpmath.mpf(x.numerator) / x.denominator for x in reversed(c)], maxsteps=200, extraprec=200)
    on = [r for r in rts if abs(abs(r) - 1) < mpmath.mpf(10) ** -40]
    out = [r for r in rts if abs(r) > 1 + mpmath.mpf(10) ** -40]
    if out:
        return "unstable"
    if on:
        # simple circle roots only (a double root would show as two close ones)
        for a in range(len(on)):
            for b in range(a + 1, len(on)):
                if abs(on[a] - on[b]) < mpmath.mpf(10) ** -20:
                    return "unstable"
        return "marginal"
    return "stable"


def part_lmm(rng, count):
    names = sorted(LMM)
    rng.shuffle(names)
    left_end = {"ab2": F(-1), "ab3": F(-6, 11), "am2": F(-6)}
    for k, name in enumerate(names[:max(count, 1)] if count < len(names) else names):
        tag = "lmm-%s" % name
        bad = []
        # zero-stability: the verdict at q = 0 (root condition of rho)
        text = lmm_case(name, 0) + "analyse stability\n"
        rc, doc, err = T.run(text, ["--time-limit", "20"])
        want0 = "unstable" if name == "bdf7" else "marginal"
        r = T.find(doc, "stability") if doc else None
        if rc != 0 or r is None or r.get("status") != want0:
            bad.append("q = 0: %s (exit %d %s), literature %s" % (r and r.get("status"), rc, err.strip()[:80], want0))
        # random real q: the own root status
        for _ in range(3):
            q = rand_frac(rng, -3, 1, (1, 2, 3, 5, 7))
            text = lmm_case(name, q) + "analyse stability\n"
            rc, doc, err = T.run(text, ["--time-limit", "20"])
            r = T.find(doc, "stability") if doc else None
            want = lmm_roots_status(name, q)
            if name in ("milne-simpson", "nystrom") and q != 0 and want != "unstable":
                bad.append("own root status %s at q = %s contradicts the literature (weakly stable)" % (want, q))
            if r is None or r.get("status") != want:
                bad.append("q = %s: %s (exit %d %s), own roots %s" % (q, r and r.get("status"), rc, err.strip()[:80], want))
        if name in left_end:
            text = lmm_case(name) + "analyse region q\n"
            rc, doc, err = T.run(text, ["--time-limit", "20"])
            reg = T.find(doc, "region") if doc else None
            if reg is None:
                bad.append("region: exit %d %s" % (rc, err.strip()[:120]))
            else:
                ivs = [iv for iv in reg.get("intervals", []) if iv.get("status") == "stable"]
                los = [F(iv["lo"]) for iv in ivs if iv.get("lo") not in (None, "-inf") and T.is_rat(iv["lo"])]
                if left_end[name] not in los or not any(iv.get("hi") == "0" for iv in ivs):
                    bad.append("region stable intervals %s, literature (%s, 0)" %
                               ([(iv.get("lo"), iv.get("hi")) for iv in ivs], left_end[name]))
            # claims on the literature interval and just beyond it
            e = left_end[name]
            for lo, want in ((e, "proved"), (e - F(1, 10), "refuted")):
                text = lmm_case(name) + "claim stable when %s < q < 0\n" % lo
                rc, doc, err = T.run(text, ["--time-limit", "30"])
                c = T.find(doc, "claim") if doc else None
                if c is None or c.get("status") != want:
                    bad.append("claim %s < q < 0: %s (exit %d), literature %s" % (lo, c and c.get("status"), rc, want))
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad[:3])))
        else:
            ok("%s: zero-stability, point verdicts%s agree with the literature" %
               (tag, ", region and claims" if name in left_end else ""))


# ---------------------------------------------------------------- part algclaim
def part_algclaim(rng, count):
    import mpmath
    mpmath.mp.dps = 30
    for k in range(count):
        # c - d < a^2 < c + d with c + d not a rational square
        while True:
            c = rand_frac(rng, F(1, 2), 4, (1, 2, 3))
            d = rand_frac(rng, F(1, 4), 2, (1, 2, 3))
            if d <= 0 or c <= 0:
                continue
            hi2 = c + d
            if mpmath.sqrt(hi2) != int(mpmath.sqrt(hi2)) and F(int(mpmath.sqrt(mpmath.mpf(hi2.numerator) / hi2.denominator) * 10 ** 6), 10 ** 6) ** 2 != hi2:
                break
        lo2 = c - d
        U = mpmath.sqrt(mpmath.mpf(hi2.numerator) / hi2.denominator)
        L = mpmath.sqrt(mpmath.mpf(lo2.numerator) / lo2.denominator) if lo2 > 0 else mpmath.mpf(0)
        # rational bounds: inside (a in (Lq, Uq) with sqrt(lo2) < Lq, Uq < sqrt(hi2)) and outside
        eps = F(1, rng.choice([10, 100, 1000]))
        Uin = F(int(U * 10 ** 6), 10 ** 6) - eps
        Uout = F(int(U * 10 ** 6) + 1, 10 ** 6) + eps
        Lin = F(int(L * 10 ** 6) + 1, 10 ** 6) + eps if lo2 > 0 else eps
        if Lin >= Uin:
            ok("algclaim-%d: skipped (empty rational interval)" % k)
            continue
        poly = "char lambda - (a^2 - (%s))/(%s)\n" % (c, d)
        text = ("title planted algebraic ends\nparam a\nassume a > 0\n" + poly + "analyse region a\n"
                "claim stable when %s < a < %s\nclaim stable when %s < a < %s\n" % (Lin, Uin, Lin, Uout))
        tag = "algclaim-%d" % k
        rc, doc, err = T.run(text, ["--time-limit", "30"])
        if doc is None or rc not in (0, 1):
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], T.save_failing(text, tag)))
            continue
        bad = []
        cl = [r for r in doc["cases"][0]["results"] if r.get("analysis") == "claim"]
        if [x.get("status") for x in cl] != ["proved", "refuted"]:
            bad.append("claims %s, planted proved/refuted (ends %s, %s)" % ([x.get("status") for x in cl],
                                                                            mpmath.nstr(L, 15), mpmath.nstr(U, 15)))
        reg = T.find(doc, "region")
        ends = set()
        for iv in (reg or {}).get("intervals", []):
            for key in ("lo", "hi"):
                v = iv.get(key + "_approx", iv.get(key))
                if v not in (None, "inf", "-inf"):
                    try:
                        ends.add(float(v))
                    except ValueError:
                        pass
        want = [float(U)] + ([float(L)] if lo2 > 0 else [])
        for w in want:
            if not any(abs(e - w) < 1e-12 for e in ends):
                bad.append("region ends %s miss %s" % (sorted(ends), w))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:3]), T.save_failing(text, tag)))
        else:
            ok("%s: claims and region ends agree (sqrt(%s), sqrt(%s))" % (tag, lo2, hi2))


# ---------------------------------------------------------------- part simlimit
def part_simlimit(rng, count):
    for k in range(count):
        kz = rng.randint(1, 3)
        roots = [rand_frac(rng, -1, 1, (2, 3, 4)) or F(1, 2) for _ in range(rng.randint(1, 2))]
        roots = [r for r in roots if r != 0] or [F(1, 2)]
        if rng.random() < 0.5:
            roots.append(rng.choice([F(3, 2), F(-5, 4)]))
        st, i, o, u = planted([G(0)] * kz + [G(r) for r in roots])
        # p(lambda; h) = lambda^kz prod (lambda - h r): at h = 1 the planted roots, at h -> 0 all tend to 0
        body = "param h\nchar lambda^%d*%s\n" % (kz, "*".join("(lambda - h*(%s))" % r for r in roots))
        text = ("title planted simulate and limit\n" + body + "set h = 1\nanalyse simulate steps=400\n"
                "analyse stability\n")
        tag = "simlimit-%d" % k
        rc, doc, err = T.run(text, ["--time-limit", "20"])
        bad = []
        if doc is None or rc not in (0, 1):
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], T.save_failing(text, tag)))
            continue
        s = T.find(doc, "simulate")
        vd = (s or {}).get("verdict", {})
        if (vd.get("status"), vd.get("inside"), vd.get("on"), vd.get("outside")) != (st, i, o, u):
            bad.append("simulate verdict %s, planted %s" % (vd, (st, i, o, u)))
        if not (s or {}).get("check", {}).get("consistent", False):
            bad.append("simulate check %s" % (s or {}).get("check"))
        text2 = "title planted limit\n" + body + "analyse limit h -> 0\nanalyse limit h -> inf\n"
        rc, doc, err = T.run(text2, ["--time-limit", "20"])
        lims = [r for r in doc["cases"][0]["results"] if r.get("analysis") == "limit"] if doc else []
        if len(lims) != 2:
            bad.append("limit: exit %d %s" % (rc, err.strip()[:100]))
        else:
            for lim, w0, winf in ((lims[0], len(roots) + kz, 0), (lims[1], kz, len(roots))):
                n0 = sum(x["multiplicity"] for x in lim["roots"] if x["value"] != "inf" and float(x["abs"]) == 0)
                ninf = sum(x["multiplicity"] for x in lim["roots"] if x["value"] == "inf")
                # lambda^k prod(lambda - h r), r != 0: h -> 0 every root -> 0 (the k at 0 for every h);
                # h -> inf the k stay at 0 and the planted h r -> inf
                if (n0, ninf) != (w0, winf):
                    bad.append("limit h -> %s: %d roots to 0, %d to inf; planted %d, %d" % (lim["to"], n0, ninf, w0, winf))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:3]), T.save_failing(text, tag)))
        else:
            ok("%s: simulate verdict and limit agree (%s)" % (tag, st))


def part_quick(rng, count):
    """the make-check sample"""
    part_zeros(rng, 2 * count)
    part_circle(rng, count)
    part_algclaim(rng, max(1, count // 2))
    part_simlimit(rng, max(1, count // 2))


PARTS = {"quick": part_quick, "zeros": part_zeros, "circle": part_circle, "lmm": part_lmm, "lmm3": part_lmm,
         "algclaim": part_algclaim, "simlimit": part_simlimit}

if __name__ == "__main__":
    part, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = random.Random(seed * 1000003 + sum(map(ord, part)))
    PARTS[part](rng, count)
    sys.exit(1 if NFAIL else 0)

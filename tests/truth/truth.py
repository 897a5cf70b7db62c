#!/usr/bin/env python3
"""truth.py -- planted-truth property tests of recstab's newest verdicts.

Every case is generated at random (fixed seed) from data whose verdict is known
by construction and derived here independently of recstab (rational / Gaussian
rational arithmetic with fractions.Fraction only, no recstab code):

  qi      char polynomials over Q(i) with planted roots (Gaussian rationals
          inside / outside the unit circle, circle points (1 + i t)^2/(1 + t^2)
          with rational t, 1, -1, i, -i, repeated roots, conjugate pairs):
          stability / radius / modes / jury / hurwitz vs the planted counts.
  jordan  x[n+1] = M x[n] with M = S J S^-1 (S random integer, J planted:
          circle eigenvalues 1, -1, rotations by rational-tangent angles,
          semisimple repeats or Jordan blocks, eigenvalues inside/outside):
          marginal vs unstable; a parametrised family whose Jordan block
          appears at one value only (region).
  pade    y' = q y by the (m, n) Pade approximant of e^z: A-stable iff
          n - 2 <= m <= n (Ehle 1969; Hairer-Wanner II, Thm IV.4.12);
          R(inf) = 0 when m < n, (-1)^n when m = n (L-stable iff m < n).
  lmm     random 2-step LMMs rho(x) - q sigma(x): recstab's A-stability vs the
          boundary locus Re(rho/sigma)(e^{i phi}) evaluated exactly at rational
          tan(phi/2) (a negative value is an exact refutation).
  region2 random real quadratics / cubics whose coefficients are affine or
          quadratic in (a, b): the region formula vs an exact own verdict at
          random rational points and at rational points on p(1) = 0, p(-1) = 0.
  sweep   sweep of a parameter vs the own verdict at each grid point.
  forall  `region A for all [w]` of planted products whose uniform range is derived by hand.
  qi-region  `region a`, `hurwitz` and `jury` conditions of Q(i) polynomials with roots
          a m u (u on the circle, m rational) and planted fixed roots vs the exact truth.
  zregion `region re(z), im(z)` of Q(z) lambda - P(z) vs |P(z)|^2 < |Q(z)|^2 at Gaussian
          rational z, including points on the boundary (roots of P - e Q, |e| = 1).
  forall5 `region A for all [w]` of families undecided before h-forall5: a root -1 for every w,
          conditions past Polya's cap, irrational ends (see part_forall5).
  claimreg  `claim stable when` each rational interval of `region a`: never refuted on a
          stable interval, refuted on an unstable one; the own verdict at its midpoint.

Usage: truth.py PART SEED COUNT [RECSTAB]   prints "ok ..." / "FAIL ..." lines.
"""
import json
import os
import random
import subprocess
import sys
import tempfile
from fractions import Fraction as F

RS = os.environ.get("RS", "build/recstab")
TMP = tempfile.mkdtemp(prefix="truth-")
NFAIL = 0


def ok(msg):
    print("ok " + msg)


def fail(msg):
    global NFAIL
    NFAIL += 1
    print("FAIL " + msg)


def run(text, args=()):
    path = os.path.join(TMP, "c.case")
    with open(path, "w") as f:
        f.write(text)
    p = subprocess.run([RS, "--json", *args, path], capture_output=True, text=True)
    try:
        doc = json.loads(p.stdout) if p.stdout.strip() else None
    except ValueError:
        doc = None
    return p.returncode, doc, p.stderr


def save_failing(text, tag):
    """keep a failing case next to the temp dir for the report"""
    d = os.environ.get("TRUTH_KEEP", "/tmp/truth-failures")
    os.makedirs(d, exist_ok=True)
    path = os.path.join(d, tag + ".case")
    with open(path, "w") as f:
        f.write(text)
    return path


# ---------------------------------------------------------------- Gaussian rationals
class G:
    """a + b i with a, b Fractions"""
    __slots__ = ("re", "im")

    def __init__(self, re, im=0):
        self.re, self.im = F(re), F(im)

    def __add__(s, o):
        o = o if isinstance(o, G) else G(o)
        return G(s.re + o.re, s.im + o.im)

    __radd__ = __add__

    def __neg__(s):
        return G(-s.re, -s.im)

    def __sub__(s, o):
        return s + (-(o if isinstance(o, G) else G(o)))

    def __mul__(s, o):
        o = o if isinstance(o, G) else G(o)
        return G(s.re * o.re - s.im * o.im, s.re * o.im + s.im * o.re)

    __rmul__ = __mul__

    def conj(s):
        return G(s.re, -s.im)

    def abs2(s):
        return s.re * s.re + s.im * s.im

    def __truediv__(s, o):
        o = o if isinstance(o, G) else G(o)
        d = o.abs2()
        n = s * o.conj()
        return G(n.re / d, n.im / d)

    def __eq__(s, o):
        o = o if isinstance(o, G) else G(o)
        return s.re == o.re and s.im == o.im

    def __hash__(s):
        return hash((s.re, s.im))

    def fmt(s):
        return "(%s + (%s)*i)" % (s.re, s.im)

    def __repr__(s):
        return "%s%+s*i" % (s.re, s.im)


def rand_frac(rng, lo, hi, dens=(1, 2, 3, 4, 5, 6, 7, 8, 9)):
    d = rng.choice(dens)
    return F(rng.randint(int(lo * d), int(hi * d)), d)


def circle_point(rng):
    c = rng.random()
    if c < 0.25:
        return rng.choice([G(1), G(-1), G(0, 1), G(0, -1)])
    t = rand_frac(rng, -4, 4)
    return G(1 - t * t, 2 * t) / G(1 + t * t)


def inside_point(rng):
    while True:
        r = G(rand_frac(rng, -1, 1), rand_frac(rng, -1, 1))
        if r.abs2() < 1:
            return r


def outside_point(rng):
    while True:
        r = G(rand_frac(rng, -2, 2), rand_frac(rng, -2, 2))
        if r.abs2() > 1:
            return r


def poly_from_roots(roots, lead=G(1)):
    """coefficients c[0..n] (Gaussian), c[k] of lambda^k"""
    c = [lead]
    for r in roots:
        n = [G(0)] * (len(c) + 1)
        for k, a in enumerate(c):
            n[k + 1] = n[k + 1] + a
            n[k] = n[k] - a * r
        c = n
    return c


def poly_text(c, var="lambda"):
    return " + ".join("%s*%s^%d" % (a.fmt(), var, k) for k, a in enumerate(c))


def planted_truth(roots):
    inside = sum(1 for r in roots if r.abs2() < 1)
    on = sum(1 for r in roots if r.abs2() == 1)
    out = len(roots) - inside - on
    circ = [r for r in roots if r.abs2() == 1]
    if on == 0 and out == 0:
        st = "stable"
    elif out == 0 and len(set(circ)) == len(circ):
        st = "marginal"
    else:
        st = "unstable"
    return st, inside, on, out


def find(doc, name):
    if not doc:
        return None
    for r in doc["cases"][0]["results"]:
        if r.get("analysis") == name:
            return r
    return None


def dec(s):
    return F(s)


# ---------------------------------------------------------------- part qi
def part_qi(rng, count):
    for k in range(count):
        n = rng.randint(1, 4)
        roots = []
        for _ in range(n):
            c = rng.random()
            roots.append(inside_point(rng) if c < 0.45 else
                         circle_point(rng) if c < 0.8 else outside_point(rng))
        c = rng.random()
        if c < 0.25:
            roots.append(rng.choice(roots))           # a repeated root
        elif c < 0.5:
            roots.append(rng.choice(roots).conj())    # a conjugate (maybe equal)
        form = rng.choice(["product", "expanded", "set", "scaled"])
        st, ni, no, nout = planted_truth(roots)
        lead = G(1)
        head = "title planted Q(i) roots %s\n" % roots
        if form == "product":
            body = "char " + "*".join("(lambda - %s)" % r.fmt() for r in roots)
        elif form == "expanded":
            body = "char " + poly_text(poly_from_roots(roots))
        elif form == "scaled":
            lead = G(rand_frac(rng, -3, 3) or 1, rand_frac(rng, -3, 3))
            body = "char %s*" % lead.fmt() + "*".join("(lambda - %s)" % r.fmt() for r in roots)
        else:
            head += "param a\n"
            body = ("char (lambda - a)" + "".join("*(lambda - %s)" % r.fmt() for r in roots[1:])
                    + "\nset a = %s%s%s*i" % (roots[0].re, "+" if roots[0].im >= 0 else "-", abs(roots[0].im)))
        text = head + body + "\nanalyse stability\nanalyse radius\nanalyse modes\nanalyse jury\nanalyse hurwitz\n"
        if form != "set":               # simulate refuses complex set values (documented)
            text += "analyse simulate steps=400\n"
        tag = "qi-%d-%s" % (k, form)
        rc, doc, err = run(text)
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        bad = []
        s = find(doc, "stability")
        own = s.get("complex_check") if s.get("complex_check") else (s if s.get("over") == "Q(i)" or s["degree"] == len(roots) else None)
        if s["status"] != st:
            bad.append("stability %s, planted %s" % (s["status"], st))
        # roots at 0: divided out of p at complex set values, kept in a char line's p over Q(i)
        # (both conventions occur; the verdict is the same): accept either count
        nz = sum(1 for x in roots if x.abs2() == 0)
        okc = ((ni, no, nout), (ni - nz, no, nout))
        if own is not None and (own["inside"], own["on"], own["outside"]) not in okc:
            bad.append("stability counts %s/%s/%s, planted %d/%d/%d" % (own["inside"], own["on"], own["outside"], ni, no, nout))
        r = find(doc, "radius")
        rho2 = max(x.abs2() for x in roots)
        lo, hi = dec(r["lower"]), dec(r["upper"])
        if not (lo * lo <= rho2 <= hi * hi):
            bad.append("radius [%s, %s] misses sqrt(%s)" % (r["lower"], r["upper"], rho2))
        for name in ("jury", "hurwitz"):
            j = find(doc, name)
            if j is None:
                bad.append("%s missing" % name)
                continue
            if "status" in j and j["status"] != st:
                bad.append("%s status %s, planted %s" % (name, j.get("status"), st))
            v = j.get("verdict", "")
            if "status" not in j and ((v == "stable under the assumptions") != (st == "stable")):
                bad.append("%s verdict '%s', planted %s" % (name, v, st))
            if "inside" in j and j.get("over") == "Q(i)" and (j["inside"], j["on"], j["outside"]) not in okc:
                bad.append("%s counts %s/%s/%s" % (name, j["inside"], j["on"], j["outside"]))
            if j.get("verdict") == "never stable" and st == "stable":
                bad.append("%s says never stable at a stable point" % name)
        sim = find(doc, "simulate")
        if sim is not None and isinstance(sim.get("verdict"), dict) and sim["verdict"].get("status") not in (None, st):
            bad.append("simulate's verdict %s" % sim["verdict"])
        m = find(doc, "modes")
        if m is not None:
            ec = m.get("exact_check")     # over Q(i) only (a real p: the real route's modes)
            if ec is not None and (ec["status"] != st or (ec["inside"], ec["on"], ec["outside"]) not in okc):
                bad.append("modes exact_check %s" % ec)
            # roots at 0 are divided out of a real p, listed over Q(i): compare the others
            got = [(float(x["root"]["re"]), float(x["root"]["im"])) for x in m["modes"] + m.get("spurious", [])
                   if isinstance(x, dict) and "root" in x and (float(x["root"]["re"]), float(x["root"]["im"])) != (0.0, 0.0)]
            want = [(float(x.re), float(x.im)) for x in roots if x.abs2() != 0]
            if not match_multiset(got, want):
                bad.append("modes roots %s, planted %s" % (got, want))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad), save_failing(text, tag)))
        else:
            ok("%s: %s %d/%d/%d" % (tag, st, ni, no, nout))


def match_multiset(got, want, tol=1e-9):
    want = list(want)
    for g in got:
        for j, w in enumerate(want):
            if abs(g[0] - w[0]) < tol and abs(g[1] - w[1]) < tol:
                del want[j]
                break
        else:
            return False
    return not want


# ---------------------------------------------------------------- matrices over Q
def mat_mul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(len(B))) for j in range(len(B[0]))] for i in range(len(A))]


def mat_inv(A):
    n = len(A)
    M = [list(map(F, r)) + [F(int(i == j)) for j in range(n)] for i, r in enumerate(A)]
    for c in range(n):
        p = next((r for r in range(c, n) if M[r][c] != 0), None)
        if p is None:
            return None
        M[c], M[p] = M[p], M[c]
        pv = M[c][c]
        M[c] = [x / pv for x in M[c]]
        for r in range(n):
            if r != c and M[r][c] != 0:
                f = M[r][c]
                M[r] = [x - f * y for x, y in zip(M[r], M[c])]
    return [r[n:] for r in M]


def rand_invertible(rng, n):
    while True:
        S = [[F(rng.randint(-2, 2)) for _ in range(n)] for _ in range(n)]
        Si = mat_inv(S)
        if Si is not None:
            return S, Si


def mat_text(M):
    return "[" + "; ".join(", ".join(str(x) for x in r) for r in M) + "]"


def block_diag(blocks):
    n = sum(len(b) for b in blocks)
    J = [[F(0)] * n for _ in range(n)]
    o = 0
    for b in blocks:
        for i in range(len(b)):
            for j in range(len(b)):
                J[o + i][o + j] = F(b[i][j])
        o += len(b)
    return J


def rot(t):
    c, s = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
    return [[c, -s], [s, c]]


# ---------------------------------------------------------------- part jordan
def part_jordan(rng, count):
    for k in range(count):
        blocks, status = [], "stable"
        kinds = rng.sample(["one", "minus", "rot", "in", "in2", "out"], rng.randint(1, 3))
        circle_kind = rng.choice(["one", "minus", "rot"])
        if circle_kind not in kinds:
            kinds.append(circle_kind)
        defective = False
        has_out = False
        has_circle = False
        for kd in kinds:
            if kd in ("one", "minus"):
                v = F(1) if kd == "one" else F(-1)
                has_circle = True
                c = rng.random()
                if c < 0.4:
                    blocks.append([[v]])
                elif c < 0.7:
                    blocks += [[[v]], [[v]]]                  # semisimple double
                else:
                    blocks.append([[v, 1], [0, v]])          # Jordan block
                    defective = True
            elif kd == "rot":
                has_circle = True
                R = rot(rand_frac(rng, -3, 3) or F(1, 2))
                c = rng.random()
                if c < 0.4:
                    blocks.append(R)
                elif c < 0.7:
                    blocks += [R, R]
                else:
                    blocks.append([R[0] + [1, 0], R[1] + [0, 1], [0, 0] + R[0], [0, 0] + R[1]])
                    defective = True
            elif kd == "in":
                blocks.append([[rand_frac(rng, -1, 1) * F(9, 10)]])
            elif kd == "in2":
                v = rand_frac(rng, -1, 1) * F(9, 10)
                blocks.append([[v, 1], [0, v]])              # Jordan block inside: harmless
            else:
                v = rng.choice([F(3, 2), F(-5, 4), F(2)])
                blocks.append([[v]])
                has_out = True
        rng.shuffle(blocks)
        J = block_diag(blocks)
        n = len(J)
        if n > 6:
            continue
        S, Si = rand_invertible(rng, n)
        M = mat_mul(mat_mul(S, J), Si)
        truth = "unstable" if (has_out or defective) else ("marginal" if has_circle else "stable")
        I = [[F(int(i == j)) for j in range(n)] for i in range(n)]
        negM = [[-x for x in r] for r in M]
        form = rng.choice(["recurrence", "eq"])
        if form == "recurrence":
            body = "recurrence 1 = %s\nrecurrence 0 = %s\n" % (mat_text(I), mat_text(negM))
        else:
            names = ["x%d" % (i + 1) for i in range(n)]
            body = "unknown " + " ".join(names) + "\n" + "".join(
                "eq %s[n+1] = %s\n" % (names[i], " + ".join("(%s)*%s[n]" % (M[i][j], names[j]) for j in range(n)))
                for i in range(n))
        text = ("title planted Jordan structure %s\n%sanalyse stability\nanalyse jury\nanalyse routh\n"
                "analyse simulate\nclaim bounded\n" % (kinds, body))
        tag = "jordan-%d-%s" % (k, form)
        rc, doc, err = run(text)
        if rc not in (0, 1) or doc is None or (rc == 1 and truth in ("stable", "marginal")):
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        s = find(doc, "stability")
        j = find(doc, "jury")
        bad = []
        if s["status"] != truth:
            bad.append("stability %s, planted %s" % (s["status"], truth))
        if j is not None and j.get("status") not in (None, truth):
            bad.append("jury %s, planted %s" % (j.get("status"), truth))
        ro = find(doc, "routh")
        if ro is not None and ro.get("status") not in (None, truth):
            bad.append("routh %s, planted %s" % (ro.get("status"), truth))
        cl = find(doc, "claim")
        want_claim = "proved" if truth in ("stable", "marginal") else "refuted"
        if cl is None or cl.get("status") != want_claim:
            bad.append("claim bounded %s, planted %s" % (cl and cl.get("status"), want_claim))
        if rc == 1 and want_claim == "proved":
            bad.append("exit 1 with a bounded scheme")
        if bad:
            fail("%s: %s (J blocks %s); case %s" % (tag, "; ".join(bad), blocks, save_failing(text, tag)))
        else:
            ok("%s: %s (%d x %d)" % (tag, truth, n, n))


def part_jordan_param(rng, count):
    """J(a) = diag([[1, 1], [0, 1 - a]], inside...): eigenvalues 1 and 1 - a.
    a < 0: 1 - a > 1, unstable; a = 0: a 2x2 Jordan block at 1, unstable;
    0 < a < 2: 1 simple, 1 - a inside, marginal; a = 2: 1 and -1 simple,
    marginal; a > 2: 1 - a < -1, unstable.  So marginal exactly on (0, 2]."""
    for k in range(count):
        inside = [[rand_frac(rng, -1, 1) * F(9, 10)] for _ in range(rng.randint(0, 2))]
        n = 2 + len(inside)
        S, Si = rand_invertible(rng, n)
        # M(a) = S J(a) S^-1 = S J0 S^-1 - a S E22 S^-1, E22 the (1,1) unit (0-based)
        J0 = block_diag([[[1, 1], [0, 1]]] + [[[v[0]]] for v in inside])
        E = [[F(0)] * n for _ in range(n)]
        E[1][1] = F(1)
        M0 = mat_mul(mat_mul(S, J0), Si)
        M1 = mat_mul(mat_mul(S, E), Si)
        names = ["x%d" % (i + 1) for i in range(n)]
        body = "param a\nunknown " + " ".join(names) + "\n" + "".join(
            "eq %s[n+1] = %s\n" % (names[i], " + ".join("((%s) - (%s)*a)*%s[n]" % (M0[i][j], M1[i][j], names[j])
                                                        for j in range(n)))
            for i in range(n))
        text = ("title Jordan block at a = 0 only\n%sanalyse region a\nclaim bounded when 0 < a <= 2\n"
                "claim bounded when 0 <= a <= 2\nclaim bounded when 1 <= a <= 5/2\n" % body)
        tag = "jordan-param-%d" % k
        rc, doc, err = run(text)
        if rc != 1 or doc is None:      # exit 1: two claims are false
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        cl = [r.get("status") for r in doc["cases"][0]["results"] if r.get("analysis") == "claim"]
        if cl[0] == "refuted" or cl[1:] != ["refuted", "refuted"]:
            fail("%s: claims %s, planted [proved, refuted (Jordan block at a = 0), refuted (a > 2)]; case %s"
                 % (tag, cl, save_failing(text, tag)))
            continue
        reg = find(doc, "region")
        got = summarize_region(reg)
        want = [("unstable", "-inf", False, "0", False), ("unstable", "0", True, "0", True),
                ("unstable", "0", False, "0", False),
                ("marginal", "0", False, "2", True), ("unstable", "2", False, "inf", False)]
        if not region_matches(reg, [(-1, "unstable"), (0, "unstable"), (F(1, 3), "marginal"), (1, "marginal"),
                                    (2, "marginal"), (F(5, 2), "unstable"), (7, "unstable")]):
            fail("%s: region %s, planted marginal exactly on (0, 2]; case %s" % (tag, got, save_failing(text, tag)))
        else:
            ok("%s: marginal exactly on (0, 2]" % tag)
        del want


def summarize_region(reg):
    if reg is None:
        return None
    return [(x.get("status"), x.get("lo", x.get("from")), x.get("hi", x.get("to"))) for x in reg.get("intervals", [])]


def end_bracket(e):
    """(lo, hi) Fractions bracketing an interval end: a rational string, or an
    algebraic end {"minpoly", "interval": [lo, hi]}; None for an infinite end"""
    if e is None or e in ("-inf", "inf"):
        return None
    if isinstance(e, dict):
        return F(e["interval"][0]), F(e["interval"][1])
    return F(str(e)), F(str(e))


def region_status_at(reg, v):
    """status of the 1-D region at rational v from the JSON intervals; None when
    v falls inside the isolating interval of an algebraic end (cannot tell)"""
    v = F(v)
    for x in reg.get("intervals", []):
        lo, hi = end_bracket(x.get("lo")), end_bracket(x.get("hi"))
        if (lo is not None and lo[0] != lo[1] and lo[0] <= v <= lo[1]) or \
           (hi is not None and hi[0] != hi[1] and hi[0] <= v <= hi[1]):
            return None
        okl = lo is None or v > lo[1] or (x.get("lo_closed") and lo[0] == lo[1] == v)
        okh = hi is None or v < hi[0] or (x.get("hi_closed") and hi[0] == hi[1] == v)
        if okl and okh:
            return x.get("status")
    return "none"


def is_rat(s):
    try:
        F(str(s))
        return True
    except (ValueError, ZeroDivisionError):
        return False


def region_matches(reg, probes):
    if reg is None:
        return False
    for v, st in probes:
        if region_status_at(reg, v) != st:
            return False
    return True


# ---------------------------------------------------------------- part pade
def pade(m, n):
    """P, Q of the (m, n) Pade approximant of e^z (Hairer-Wanner II, (IV.3.30))"""
    fact = [1]
    for i in range(1, m + n + 2):
        fact.append(fact[-1] * i)
    P = [F(fact[m + n - j] * fact[m], fact[m + n] * fact[j] * fact[m - j]) for j in range(m + 1)]
    Q = [F(fact[m + n - j] * fact[n], fact[m + n] * fact[j] * fact[n - j]) * (-1) ** j for j in range(n + 1)]
    return P, Q


def ptext(c, var):
    return " + ".join("(%s)*%s^%d" % (a, var, k) for k, a in enumerate(c)) or "0"


def part_pade(rng, count):
    pairs = [(m, n) for m in range(0, 5) for n in range(0, 5) if m + n >= 1]
    rng.shuffle(pairs)
    for (m, n) in pairs[:count]:
        P, Q = pade(m, n)
        text = ("title Pade (%d, %d) of exp\nparam q\nchar (%s)*lambda - (%s)\nanalyse astability\n"
                % (m, n, ptext(Q, "q"), ptext(P, "q")))
        a_truth = n - 2 <= m <= n
        l_truth = a_truth and m < n
        tag = "pade-%d-%d" % (m, n)
        rc, doc, err = run(text)
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        a = find(doc, "astability")
        bad = []
        if a.get("a_stable") != a_truth:
            bad.append("a_stable %s, Ehle says %s" % (a.get("a_stable"), a_truth))
        if "l_stable" in a and a.get("l_stable") != l_truth:
            bad.append("l_stable %s, expected %s" % (a.get("l_stable"), l_truth))
        lim = a.get("limit_at_infinity")
        # |R(inf)|: 0 if m < n, |P_m/Q_n| = 1 if m = n, inf if m > n
        want_lim = 0 if m < n else (1 if m == n else "inf")
        if lim is not None and str(lim) != str(want_lim):
            bad.append("limit_at_infinity %s, expected %s" % (lim, want_lim))
        if a_truth:
            ri = a.get("real_interval")
            if ri is None or ri[0] != "-inf":
                bad.append("real_interval %s should start at -inf" % ri)
        if m >= 1 and n == 0 and m <= 2:
            # Taylor of degree 1, 2: |R(x)| <= 1 on [-2, 0] exactly (R(-2) = -1, 1 resp.)
            ri = a.get("real_interval")
            if ri is None or str(ri[0]) != "-2" or str(ri[1]) != "0":
                bad.append("real_interval %s, expected [-2, 0]" % ri)
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad), save_failing(text, tag)))
        else:
            ok("%s: a_stable %s" % (tag, a_truth))


# ---------------------------------------------------------------- part lmm
def lmm_truth(rho, s):
    """exact A-stability of rho(x) - q sigma(x) (real rational coefficients, degree 2), or None.
    True when E(t) = Re(rho(x) conj sigma(x)) (1 + t^2)^2 > 0 for every real t and at x = -1
    (the boundary locus strictly in Re q > 0), the degree does not drop in Re q <= 0, and the
    method is strictly stable at q = -1: then the closed left half-plane meets no locus point,
    the root count is constant on it and every root is inside.  False when E < 0 somewhere
    (a locus point with Re q < 0, exactly), when q = -1 is unstable, or when the degree drops at
    a real q0 < 0.  Real-root counting of E by sympy (exact, independent of recstab)."""
    import sympy
    t = sympy.symbols("t", real=True)
    xt = (1 + sympy.I * t) ** 2
    den = 1 + t ** 2
    rt = sum(sympy.Rational(c.numerator, c.denominator) * xt ** j * den ** (2 - j) for j, c in enumerate(rho))
    st = sum(sympy.Rational(c.numerator, c.denominator) * sympy.conjugate(xt) ** j * den ** (2 - j) for j, c in enumerate(s))
    E = sympy.Poly(sympy.expand(sympy.re(sympy.expand(rt * st))), t)
    at_m1 = sum(c * (-1) ** j for j, c in enumerate(rho)) * sum(c * (-1) ** j for j, c in enumerate(s))
    k = len(rho) - 1
    lead_drop = None if s[k] == 0 else rho[k] / s[k]          # q where the degree drops
    own = exact_status([r + c for r, c in zip(rho, s)])     # rho - (-1) sigma
    if E.is_zero:
        return None
    # a rational t with E < 0: exact refutation
    for ti in range(-60, 61):
        if E.eval(F(ti, 6)) < 0:
            return False
    if own == "unstable" or (lead_drop is not None and lead_drop < 0):
        return False
    # E(0) = rho(1) sigma(1) = 0 (consistency): the locus touches Re q = 0 at q = 0 only, where
    # the roots are 1 (simple: rho'(1) = 1 - c != 0) and c, |c| <= 1, c != 1: the root condition holds
    m = 0
    while E.eval(0) == 0 and not E.is_zero:
        E = sympy.Poly(sympy.cancel(E.as_expr() / t), t)
        m += 1
    if m % 2 == 0 and E.count_roots() == 0 and E.LC() > 0 and at_m1 > 0 and own == "stable" and \
            (lead_drop is None or lead_drop > 0) and abs(rho[0]) <= 1:
        return True
    return None


def part_lmm(rng, count):
    """random consistent 2-step LMMs rho(x) = (x - 1)(x - c), sigma with sigma(1) = rho'(1):
    recstab's a_stable against lmm_truth (exact; None = not decided here, not compared)."""
    for k in range(count):
        c = rand_frac(rng, -1, 1, (1, 2, 3, 4))
        if c == 1:
            c = F(0)
        w = [rand_frac(rng, -1, 3, (1, 2, 4)) for _ in range(3)]
        if sum(w) == 0:
            w = [F(1), F(1), F(1)]
        s = [x * (1 - c) / sum(w) for x in w]              # sigma(1) = rho'(1) = 1 - c
        rho = [c, -1 - c, F(1)]
        text = ("title random 2-step LMM\nparam q\nchar %s - q*(%s)\nanalyse astability\n"
                % (ptext(rho, "lambda"), ptext(s, "lambda")))
        tag = "lmm-%d" % k
        want = lmm_truth(rho, s)
        rc, doc, err = run(text)
        if rc != 0 or doc is None:
            if rc == 2 and err.strip():
                ok("%s: refused (%s)" % (tag, err.strip()[:80]))
            else:
                fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        got = find(doc, "astability").get("a_stable")
        if want is not None and got != want:
            fail("%s: a_stable %s, exact truth %s; case %s" % (tag, got, want, save_failing(text, tag)))
        else:
            ok("%s: a_stable %s (truth %s)" % (tag, got, "not decided" if want is None else want))


# ---------------------------------------------------------------- own exact verdict of a real polynomial
def real_roots_status(c):
    """status of the real polynomial with Fraction coefficients c[0..n] (c[n] != 0), decided
    exactly: Schur-Cohn-Jury by hand via Sturm counts is long, so use the classic route:
    p stable iff the bilinear transform q(z) has all roots in Re z < 0 (Routh table exactly);
    circle roots located by gcd(p, p*) -- implemented here independently of recstab."""
    n = len(c) - 1
    # reciprocal p*(x) = x^n p(1/x): circle roots are common roots of p and p* (real p)
    g = pgcd(c, c[::-1])
    if len(g) > 1:
        # roots on the circle exist (or reciprocal pairs r, 1/r off the circle)
        return None
    q = bilinear(c)
    if q[-1] == 0 or len(q) - 1 < n:
        return None  # root at -1: on the circle, handled as None above normally
    return "stable" if routh_all_left(q) else "unstable"


def padd(a, b):
    n = max(len(a), len(b))
    r = [(a[i] if i < len(a) else 0) + (b[i] if i < len(b) else 0) for i in range(n)]
    while len(r) > 1 and r[-1] == 0:
        r.pop()
    return r


def pmul(a, b):
    r = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            r[i + j] += x * y
    return r


def pmod(a, b):
    a = list(a)
    while len(a) >= len(b) and any(a):
        f = a[-1] / b[-1]
        sh = len(a) - len(b)
        for i, y in enumerate(b):
            a[sh + i] -= f * y
        a.pop()
    while len(a) > 1 and a[-1] == 0:
        a.pop()
    return a or [F(0)]


def pgcd(a, b):
    a = [F(x) for x in a]
    b = [F(x) for x in b]
    while len(b) > 1 and b[-1] == 0:
        b.pop()
    while any(b):
        a, b = b, pmod(a, b)
        if not any(b):
            break
    return a


def bilinear(c):
    """q(z) = (1 - z)^n p((1 + z)/(1 - z))"""
    n = len(c) - 1
    q = [F(0)]
    for k, a in enumerate(c):
        term = [F(a)]
        for _ in range(k):
            term = pmul(term, [F(1), F(1)])
        for _ in range(n - k):
            term = pmul(term, [F(1), F(-1)])
        q = padd(q, term)
    return q + [F(0)] * (n + 1 - len(q))


def routh_all_left(q):
    """all roots of the real q in Re z < 0 (q has degree len(q) - 1, no roots on the axis
    since p has no circle roots): Routh's first column, exact, no zero pivots else None"""
    n = len(q) - 1
    a = q[::-1]  # a[0] leading
    r0 = a[0::2]
    r1 = a[1::2]
    col = [r0[0]]
    rows = [r0, r1]
    for _ in range(n):
        p, c = rows[-2], rows[-1]
        if not c or c[0] == 0:
            # zero pivot: decide by perturbation-free fallback -- not stable (a pivot 0
            # with no axis roots means a sign change), report unstable
            return False
        col.append(c[0])
        nxt = [(c[0] * (p[i + 1] if i + 1 < len(p) else 0) - p[0] * (c[i + 1] if i + 1 < len(c) else 0)) / c[0]
               for i in range(max(len(p), len(c)) - 1)]
        while nxt and nxt[-1] == 0 and len(nxt) > 1:
            nxt.pop()
        rows.append(nxt)
        if len(col) == n + 1:
            break
    return all(x > 0 for x in col) or all(x < 0 for x in col)


# ---------------------------------------------------------------- part region2
def rand_lin(rng):
    """a random affine or quadratic form in a, b with small rational coefficients (as text)"""
    terms = []
    for mono in ["1", "a", "b"] + (["a*b", "a^2", "b^2"] if rng.random() < 0.4 else []):
        if rng.random() < 0.7:
            terms.append("(%s)*%s" % (rand_frac(rng, -2, 2, (1, 2, 4)), mono))
    return " + ".join(terms) or "0"


def ev(expr, a, b):
    return eval(expr.replace("^", "**"), {"a": a, "b": b, "F": F})


def ev_formula(conj_list, a, b):
    for conj in conj_list:
        if all(ev_cond(c, a, b) for c in conj):
            return True
    return False


def ev_cond(c, a, b):
    for op in ("<=", ">=", "!=", "<", ">", "="):
        if " %s " % op in c:
            lhs, rhs = c.split(" %s " % op)
            x, y = ev(ratify(lhs), a, b), ev(ratify(rhs), a, b)
            return {"<=": x <= y, ">=": x >= y, "!=": x != y, "<": x < y, ">": x > y, "=": x == y}[op]
    raise ValueError(c)


def ratify(s):
    """integers in a polynomial text -> Fractions so that / is exact"""
    import re
    return re.sub(r"(?<![\w.])(\d+)", r"F(\1)", s).replace("**F(", "**int(")


def part_region2(rng, count):
    for k in range(count):
        deg = rng.choice([2, 2, 3])
        coefs = [rand_lin(rng) for _ in range(deg)] + ["1"]
        # keep the leading coefficient 1 (no singular points): p = lambda^deg + ...
        ptxt = " + ".join("(%s)*lambda^%d" % (cf, i) for i, cf in enumerate(coefs))
        text = "title random 2-parameter scheme\nparam a b\nchar %s\nanalyse region a, b\n" % ptxt
        tag = "region2-%d" % k
        rc, doc, err = run(text, ["--time-limit", "20"])
        if rc == 2 and ("limit" in err or "not supported" in err or "refused" in err or "cannot" in err):
            ok("%s: refused with a reason (%s)" % (tag, err.strip()[:100]))
            continue
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        reg = find(doc, "region")
        form = reg.get("formula", {})
        stable_f = form.get("stable", [])
        marg_f = form.get("marginal", [])
        complete = reg.get("formula_complete", False)
        pts = []
        for _ in range(25):
            pts.append((rand_frac(rng, -3, 3), rand_frac(rng, -3, 3)))
        # points exactly on p(1) = 0 / p(-1) = 0 where it is solvable for b (affine in b)
        for sgn in (1, -1):
            for _ in range(3):
                a0 = rand_frac(rng, -2, 2)
                f = lambda bb, a0=a0, sgn=sgn: sum(ev(ratify(cf), a0, bb) * sgn ** i for i, cf in enumerate(coefs))
                f0, f1, f2 = f(F(0)), f(F(1)), f(F(2))
                if f2 - 2 * f1 + f0 == 0 and f1 != f0:   # affine in b on this line
                    pts.append((a0, -f0 / (f1 - f0)))
        bad = []
        for (a, b) in pts:
            c = [ev(ratify(cf), a, b) for cf in coefs]
            st = exact_status(c)
            if st is None:
                continue
            fs = ev_formula(stable_f, a, b)
            fm = ev_formula(marg_f, a, b)
            if (st == "stable") != fs:
                bad.append("at a=%s, b=%s own %s, formula stable=%s" % (a, b, st, fs))
            if complete and (st == "marginal") != fm:
                bad.append("at a=%s, b=%s own %s, formula marginal=%s" % (a, b, st, fm))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:3]), save_failing(text, tag)))
        else:
            ok("%s: %d points agree (degree %d)" % (tag, len(pts), deg))


def exact_status(c):
    """own exact status of a real monic polynomial, including simple circle roots at +-1
    (deflated) -- None when a circle root other than +-1 or a repeated one occurs"""
    c = [F(x) for x in c]
    on = 0
    for r in (F(1), F(-1)):
        while len(c) > 1 and sum(x * r ** i for i, x in enumerate(c)) == 0:
            # synthetic division by (lambda - r)
            n = len(c) - 1
            qd = [F(0)] * n
            acc = F(0)
            for i in range(n, 0, -1):
                acc = acc * r + c[i]
                qd[i - 1] = acc
            c = qd
            on += 1
    if on > 1:
        # two circle roots at +-1: simple if they are 1 and -1, repeated otherwise -- leave it
        return None
    if len(c) == 1:
        return "marginal" if on else "stable"
    st = real_roots_status(c)
    if st is None:
        return None
    if on:
        return "marginal" if st == "stable" else "unstable"
    return st


# ---------------------------------------------------------------- part sweep
def part_sweep(rng, count):
    for k in range(count):
        deg = rng.choice([2, 3])
        coefs = []
        for _ in range(deg):
            coefs.append("(%s) + (%s)*a" % (rand_frac(rng, -1, 1, (1, 2, 4)), rand_frac(rng, -1, 1, (1, 2, 4))))
        coefs.append("1")
        ptxt = " + ".join("(%s)*lambda^%d" % (cf, i) for i, cf in enumerate(coefs))
        text = "title random sweep\nparam a\nchar %s\nanalyse sweep a from -2 to 2 steps 16\n" % ptxt
        tag = "sweep-%d" % k
        rc, doc, err = run(text)
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        sw = find(doc, "sweep")
        rows = sw.get("rows") or sw.get("points") or []
        cols = sw.get("columns")
        bad = []
        n = 0
        for row in rows:
            if isinstance(row, list) and cols:
                row = dict(zip(cols, row))
            a = F(str(row.get("a", row.get("value"))))
            c = [ev(ratify(cf), a, F(0)) for cf in coefs]
            st = exact_status(c)
            if st is None:
                continue
            n += 1
            got = row.get("status") or row.get("verdict")
            if got != st:
                bad.append("a=%s: sweep %s, own %s" % (a, got, st))
        if not rows:
            bad.append("no rows in %s" % list(sw.keys()))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:3]), save_failing(text, tag)))
        else:
            ok("%s: %d points agree" % (tag, n))


# ---------------------------------------------------------------- part forall
def part_forall(rng, count):
    """region A for all [w], w > 0, p = ((1 + w^2) lambda - x w) ((1 + w) lambda - (y - w)),
    x = alpha1 A + beta1, y = alpha2 A + beta2 (random rationals).  By hand:
    x w/(1 + w^2) has sup |.| = |x|/2 at w = 1 only: inside for every w iff |x| < 2,
    on the circle (at w = 1 only, value sign(x)) iff |x| = 2, outside at w = 1 iff |x| > 2;
    (y - w)/(1 + w) decreases from y (w -> 0) to -1 (w -> inf): inside for every w > 0 iff
    -1 < y <= 1, equal to -1 for every w iff y = -1, outside for some w otherwise.
    Uniform verdict = the worst over w: a double root -1 at w = 1 when x = -2 and y = -1."""
    for k in range(count):
        a1 = rng.choice([F(1), F(-1), F(1, 2), F(2), F(-3, 2)])
        b1 = rand_frac(rng, -2, 2, (1, 2))
        a2 = rng.choice([F(1), F(-1), F(1, 3), F(3, 2)])
        b2 = rand_frac(rng, -2, 2, (1, 2))
        if rng.random() < 0.2:      # make the two families' edges meet: x = -2 where y = -1
            # a1 A + b1 = -2 and a2 A + b2 = -1 at the same A
            A0 = (-1 - b2) / a2
            b1 = -2 - a1 * A0

        def truth(A):
            x, y = a1 * A + b1, a2 * A + b2
            if abs(x) > 2 or y > 1 or y < -1:
                return "unstable"
            if x == -2 and y == -1:
                return "unstable"
            if abs(x) == 2 or y == -1:
                return "marginal"
            return "stable"
        brk = sorted(set([(v - b1) / a1 for v in (F(-2), F(2))] + [(v - b2) / a2 for v in (F(-1), F(1))]))
        probes = list(brk)
        probes += [(u + v) / 2 for u, v in zip(brk, brk[1:])] + [brk[0] - 1, brk[-1] + 1]
        text = ("title planted uniform range\nparam A w\nassume w > 0\n"
                "char ((1 + w^2)*lambda - (%s*A + %s)*w)*((1 + w)*lambda - ((%s*A + %s) - w))\n"
                "analyse region A for all [w]\n" % (a1, b1, a2, b2))
        tag = "forall-%d" % k
        rc, doc, err = run(text, ["--time-limit", "30"])
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        reg = find(doc, "region")
        bad = []
        und = []
        for v in probes:
            got = region_status_at(reg, v)
            if got == "undecided":      # honest, not wrong (a root at -1 for every w: see the report)
                und.append(str(v))
                continue
            if got != truth(v):
                bad.append("A=%s: region %s, by hand %s" % (v, got, truth(v)))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:4]), save_failing(text, tag)))
        else:
            ok("%s: %d probes agree (breaks %s)%s" % (tag, len(probes) - len(und), ", ".join(map(str, brk)),
                                                     " undecided at " + ", ".join(und) if und else ""))


# ---------------------------------------------------------------- part qi-region
def part_qi_region(rng, count):
    """region a of p = prod_j (lambda - a m_j u_j) prod_k (lambda - r_k) over Q(i): u_j circle
    points (rational tan), m_j > 0 rational, r_k planted Gaussian rationals.  At a rational
    a every root is a known Gaussian rational: the truth at a probe is planted_truth of
    them (|a m_j u_j| = |a| m_j: crossings at |a| = 1/m_j, coincidences a m_j u_j = r_k
    where r_k/(m_j u_j) is real)."""
    for k in range(count):
        scaled = [(rand_frac(rng, 1, 3, (1, 2, 3)) or F(1), circle_point(rng)) for _ in range(rng.randint(1, 2))]
        fixed = []
        for _ in range(rng.randint(0, 2)):
            c = rng.random()
            fixed.append(inside_point(rng) if c < 0.5 else circle_point(rng) if c < 0.85 else outside_point(rng))
        probes = {F(0)}
        for m, u in scaled:
            probes |= {1 / m, -1 / m}
            for r in fixed:
                q = r / (u * G(m))
                if q.im == 0:
                    probes.add(q.re)
        for m1, u1 in scaled:
            for m2, u2 in scaled:
                pass
        br = sorted(probes)
        probes = br + [(x + y) / 2 for x, y in zip(br, br[1:])] + [br[0] - 1, br[-1] + 1]

        def truth(a):
            return planted_truth([u * G(a * m) for m, u in scaled] + fixed)[0]
        text = ("title planted Q(i) region\nparam a\nchar "
                + "*".join(["(lambda - a*%s*%s)" % (m, u.fmt()) for m, u in scaled] +
                           ["(lambda - %s)" % r.fmt() for r in fixed])
                + "\nanalyse region a\nanalyse hurwitz\nanalyse jury\nanalyse sweep a from -3 to 3 steps 24\n")
        tag = "qi-region-%d" % k
        rc, doc, err = run(text, ["--time-limit", "30"])
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        reg = find(doc, "region")
        bad, und = [], []
        for v in probes:
            got = region_status_at(reg, v)
            if got in ("undecided", None):
                und.append(str(v))
                continue
            if got != truth(v):
                bad.append("a=%s: region %s, planted %s" % (v, got, truth(v)))
        # the sweep's rows (grid -3, -11/4, ..., 3: hits the breakpoints +-1/m for m in {1, 2, 4, 4/3, ...})
        sw = find(doc, "sweep")
        for row in (sw or {}).get("rows", []):
            row = dict(zip(sw["columns"], row)) if isinstance(row, list) else row
            v = F(str(row.get("a_exact") or row.get("a")))
            if row.get("verdict") != truth(v):
                bad.append("sweep a=%s: %s, planted %s" % (v, row.get("verdict"), truth(v)))
        # hurwitz (Bilharz) and jury (complex Schur-Cohn) conditions: stable iff all hold
        for name in ("hurwitz", "jury"):
            h = find(doc, name)
            if h is None or h.get("verdict") != "stable iff the conditions hold":
                if h is not None and h.get("verdict") == "never stable" and any(truth(v) == "stable" for v in probes):
                    bad.append("%s: never stable, but planted stable somewhere" % name)
                continue
            conds = h.get("conditions") or []
            if not all(isinstance(c, str) for c in conds):
                continue
            for v in probes:
                holds = all(ev_cond(c, v, F(0)) for c in conds)
                if holds != (truth(v) == "stable"):
                    bad.append("%s conditions %s at a=%s, planted %s" % (name, holds, v, truth(v)))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:4]), save_failing(text, tag)))
        else:
            ok("%s: %d probes agree%s" % (tag, len(probes) - len(und), " undecided at " + ", ".join(und) if und else ""))


# ---------------------------------------------------------------- part zregion
def part_zregion(rng, count):
    """`region re(z), im(z)` of a one-step map Q(z) lambda - P(z), P and Q random of degree <= 2:
    at a Gaussian rational z (Q(z) != 0) the single root P(z)/Q(z) is exactly known, stable iff
    |P(z)|^2 < |Q(z)|^2, marginal iff equal.  Probes: random Gaussian rationals and, on the
    boundary, z where |P| = |Q| is forced: the roots of P - e Q for circle points e (when rational)."""
    for k in range(count):
        dp, dq = rng.randint(0, 2), rng.randint(1, 2)
        P = [rand_frac(rng, -2, 2, (1, 2, 3)) for _ in range(dp + 1)]
        Q = [rand_frac(rng, -2, 2, (1, 2, 3)) for _ in range(dq + 1)]
        P[0] = P[0] or F(1)
        Q[0] = Q[0] or F(1)
        if Q[-1] == 0:
            Q[-1] = F(1)
        text = ("title planted z-plane region\nparam z complex\nchar (%s)*lambda - (%s)\n"
                "analyse region re(z), im(z)\n" % (ptext(Q, "z"), ptext(P, "z")))
        tag = "zregion-%d" % k
        rc, doc, err = run(text, ["--time-limit", "30"])
        if rc == 2 and err.strip():
            ok("%s: refused (%s)" % (tag, err.strip()[:120]))
            continue
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        reg = find(doc, "region")
        form = reg.get("formula", {})

        def cv(poly, z):
            acc = G(0)
            for c in reversed(poly):
                acc = acc * z + G(c)
            return acc
        pts = [G(rand_frac(rng, -3, 3), rand_frac(rng, -3, 3)) for _ in range(30)]
        # boundary points: degree-1 P - e Q with e = +-1, +-i gives z = -(P0 - e Q0)/(P1 - e Q1)
        for e in (G(1), G(-1), G(0, 1), G(0, -1), circle_point(rng)):
            a0 = G(P[0]) - e * G(Q[0])
            a1 = G(P[1] if len(P) > 1 else 0) - e * G(Q[1])
            a2 = G(P[2] if len(P) > 2 else 0) - e * G(Q[2] if len(Q) > 2 else 0)
            if a2 == G(0) and not a1 == G(0):
                pts.append(-(a0 / a1))
        bad = []
        for z in pts:
            qz, pz = cv(Q, z), cv(P, z)
            if qz.abs2() == 0:
                continue
            st = "stable" if pz.abs2() < qz.abs2() else "marginal" if pz.abs2() == qz.abs2() else "unstable"
            x, y = z.re, z.im
            fs = ev_formula([[c.replace("re(z)", "a").replace("im(z)", "b") for c in cj] for cj in form.get("stable", [])], x, y)
            if fs != (st == "stable"):
                bad.append("z=%s: own %s, formula stable=%s" % (z, st, fs))
            if reg.get("marginal_complete", reg.get("formula_complete")):
                fm = ev_formula([[c.replace("re(z)", "a").replace("im(z)", "b") for c in cj] for cj in form.get("marginal", [])], x, y)
                if fm != (st == "marginal"):
                    bad.append("z=%s: own %s, formula marginal=%s" % (z, st, fm))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:3]), save_failing(text, tag)))
        else:
            ok("%s: %d points agree" % (tag, len(pts)))


# ---------------------------------------------------------------- part claimreg
def part_claimreg(rng, count):
    """claim vs region on random real schemes p(lambda; a) (degree 2-3, coefficients affine in a):
    for each interval of `region a` with rational ends, `claim stable when` its interior must
    not be refuted when the region says stable (and must be refuted when it says unstable);
    the own exact verdict at the interval's midpoint is checked against the region too."""
    for k in range(count):
        deg = rng.choice([2, 3])
        coefs = ["(%s) + (%s)*a" % (rand_frac(rng, -1, 1, (1, 2, 4)), rand_frac(rng, -1, 1, (1, 2, 4)))
                 for _ in range(deg)] + ["1"]
        ptxt = " + ".join("(%s)*lambda^%d" % (cf, i) for i, cf in enumerate(coefs))
        base = "title claim vs region\nparam a\nchar %s\n" % ptxt
        tag = "claimreg-%d" % k
        rc, doc, err = run(base + "analyse region a\n")
        if rc != 0 or doc is None:
            fail("%s: region exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(base, tag)))
            continue
        reg = find(doc, "region")
        claims, bad = [], []
        for x in reg.get("intervals", []):
            lo, hi = x.get("lo"), x.get("hi")
            if isinstance(lo, dict) or isinstance(hi, dict) or x.get("status") not in ("stable", "unstable"):
                continue
            lo = None if lo in (None, "-inf") else F(lo)
            hi = None if hi in (None, "inf") else F(hi)
            if lo is not None and hi is not None and lo == hi:
                continue
            mid = (lo + hi) / 2 if lo is not None and hi is not None else (hi - 1 if lo is None and hi is not None
                                                                          else lo + 1 if lo is not None else F(0))
            own = exact_status([ev(ratify(cf), mid, F(0)) for cf in coefs])
            if own is not None and own != x["status"]:
                bad.append("a=%s: own %s, region %s" % (mid, own, x["status"]))
            cond = " and ".join(([("a > %s" % lo)] if lo is not None else []) + ([("a < %s" % hi)] if hi is not None else []))
            if cond:
                claims.append((x["status"], cond))
        if claims:
            text = base + "".join("claim stable when %s\n" % c for _, c in claims)
            rc2, doc2, err2 = run(text)
            if doc2 is None:
                bad.append("claims exit %d (%s)" % (rc2, err2.strip()[:150]))
            else:
                res = [r for r in doc2["cases"][0]["results"] if r.get("analysis") == "claim"]
                for (st, cond), r in zip(claims, res):
                    if st == "stable" and r.get("status") == "refuted":
                        bad.append("claim stable when %s refuted (%s) on a region-stable interval" % (cond, r.get("counterexample")))
                    if st == "unstable" and r.get("status") != "refuted":
                        bad.append("claim stable when %s %s on a region-unstable interval" % (cond, r.get("status")))
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:3]), save_failing(base + "analyse region a\n", tag)))
        else:
            ok("%s: %d intervals, claims agree" % (tag, len(claims)))


# ---------------------------------------------------------------- part forall5
def part_forall5(rng, count):
    """`region A for all [w]`, w > 0, families that were undecided where decidable (h-forall5);
    x = a A + b (random rationals), truth by hand:
      minus1: p = (lambda + 1)^k ((w + 2) lambda^2 + x w lambda + 1).  Jury for the quadratic
              (|1| < w + 2, |x| w < w + 3 for every w > 0 iff |x| <= 1; R(-1) = (1 - x) w + 3 > 0
              there): k = 1 marginal iff |x| <= 1, else unstable; k = 2 (a double circle root
              of a char line) unstable for every A.
      polya:  p = (c w^2 + e w + c) lambda - x w, c in 8..20, e in {1, 2}: the root's modulus
              |x| w/(c w^2 + e w + c) has its maximum |x|/(2c + e) at w = 1 only: stable iff
              |x| < 2c + e, marginal iff |x| = 2c + e, unstable beyond; conditions near the
              ends need Polya exponents past the cap (the real roots decide them).
      sqrt:   p = (c w^2 + 1) lambda - x w, c non-square: maximum |x|/(2 sqrt c) at
              w = 1/sqrt c: stable iff x^2 < 4c, unstable iff x^2 > 4c (the ends irrational,
              probed only at rationals off their isolating intervals); at the two ends themselves
              |r| = 1 at w = 1/sqrt c only, a simple root (degree 1 in lambda): marginal, and the
              region must say so (two one-point intervals, both marginal).
    Every probe must agree; "undecided" is a failure except at the irrational ends."""
    for k in range(count):
        fam = ["minus1", "polya", "sqrt"][k % 3]
        a = rng.choice([F(1), F(-1), F(1, 2), F(2), F(-3, 2)])
        b = rand_frac(rng, -1, 1, (1, 2))
        if fam == "minus1":
            mult = rng.choice([1, 1, 2])
            charp = "(lambda + 1)^%d*((w + 2)*lambda^2 + (%s*A + %s)*w*lambda + 1)" % (mult, a, b)

            def truth(A, mult=mult, a=a, b=b):
                x = a * A + b
                return "unstable" if mult == 2 or abs(x) > 1 else "marginal"
            ends = [F(-1), F(1)]
        elif fam == "polya":
            c, e = rng.randint(8, 20), rng.choice([1, 2])
            charp = "(%d*w^2 + %d*w + %d)*lambda - (%s*A + %s)*w" % (c, e, c, a, b)

            def truth(A, c=c, e=e, a=a, b=b):
                x = abs(a * A + b)
                return "stable" if x < 2 * c + e else "marginal" if x == 2 * c + e else "unstable"
            ends = [F(-(2 * c + e)), F(2 * c + e), F(-(2 * c + e) + 1), F(2 * c + e - 1)]
        else:
            c = rng.choice([2, 3, 5, 6, 7])
            charp = "(%d*w^2 + 1)*lambda - (%s*A + %s)*w" % (c, a, b)

            def truth(A, c=c, a=a, b=b):
                x = a * A + b
                return "stable" if x * x < 4 * c else "unstable"
            ends = [F(-2 * c), F(2 * c), F(0)]
        # probes: the x values above and around them, mapped to A = (x - b)/a
        xs = sorted(set(ends + [u + d for u in ends for d in (F(-1, 3), F(1, 3))]))
        probes = [(x - b) / a for x in xs]
        text = ("title planted uniform range (h-forall5)\nparam A w\nassume w > 0\nchar %s\n"
                "analyse region A for all [w]\n" % charp)
        tag = "forall5-%s-%d" % (fam, k)
        rc, doc, err = run(text, ["--time-limit", "30"])
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s) case %s" % (tag, rc, err.strip()[:200], save_failing(text, tag)))
            continue
        reg = find(doc, "region")
        bad, und = [], []
        for v in probes:
            got = region_status_at(reg, v)
            if got is None:          # inside an irrational end's isolating interval
                und.append(str(v))
                continue
            if got != truth(v):
                bad.append("A=%s: region %s, by hand %s" % (v, got, truth(v)))
        if fam == "sqrt":
            pts = [x.get("status") for x in reg.get("intervals", [])
                   if isinstance(x.get("lo"), dict) and x.get("lo") == x.get("hi")]
            if pts != ["marginal", "marginal"]:
                bad.append("irrational ends %s, by hand marginal, marginal" % pts)
        if bad:
            fail("%s: %s; case %s" % (tag, "; ".join(bad[:4]), save_failing(text, tag)))
        else:
            ok("%s: %d probes agree%s" % (tag, len(probes) - len(und),
                                          " (not probed, inside isolating intervals: %s)" % ", ".join(und) if und else ""))


PARTS = {"qi": part_qi, "jordan": part_jordan, "jordan-param": part_jordan_param, "pade": part_pade,
         "lmm": part_lmm, "region2": part_region2, "sweep": part_sweep, "forall": part_forall, "qi-region": part_qi_region, "zregion": part_zregion, "claimreg": part_claimreg, "forall5": part_forall5}

if __name__ == "__main__":
    part, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    if len(sys.argv) > 4:
        RS = sys.argv[4]
    rng = random.Random(seed * 1000003 + hash(part) % 1000 if False else seed * 1000003 + sum(map(ord, part)))
    PARTS[part](rng, count)
    sys.exit(1 if NFAIL else 0)

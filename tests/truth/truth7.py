#!/usr/bin/env python3
"""truth7.py -- classes not planted before h-truth7, every route against a truth
derived here independently of recstab (Fractions; closed forms of quadratics;
the bilinear map z -> lambda = (z + 1)/(z - 1) of textbook Routh polynomials):

  lmmfam   the one-parameter family of explicit 2-step methods (Hairer-Norsett-Wanner I,
           III.2: rho = (x - 1)(x - a), sigma = ((3 - a) x - (1 + a))/2, order 2 for every a)
           on y' = mu y: y[n+2] - (1+a) y[n+1] + a y[n] = z ((3-a)/2 y[n+1] - (1+a)/2 y[n]).
           At set a, z the monic quadratic x^2 + b x + c is classified in closed form
           (quad_roots); at z = 0 the roots are 1 and a: zero-stable iff -1 <= a < 1 (a = -1:
           roots +-1, simple, marginal; a = 1: double root 1, unstable), so `region a` must say
           marginal on [-1, 1) and unstable outside, and jury/hurwitz must say never
           (p(1) = 0 for every a).
  builders two scalar subsystems x1' = A x1 + C x2, x2' = B x2 (a cascade: S2 never reads S1),
           each integrated by a one-step method (R(z) in closed form) or a 2-step method
           (AB2, BDF2: a quadratic), any coupling: the lambda-matrix is block triangular, so
           the nonzero roots are those of each subsystem alone (roots at 0 from the
           coupling's delays are not compared: only status, on, outside).
  routh    textbook Routh special cases in z (a zero first-column entry with the rest of the row
           nonzero; a whole zero row from a factor even/odd in z, the auxiliary polynomial;
           repeated imaginary-axis roots) carried to p(lambda) = (lambda + 1)^n q((lambda - 1)/
           (lambda + 1)), whose bilinear image is q again: a root z with Re z < 0 / = 0 / > 0 is
           a root lambda = (1 + z)/(1 - z) inside / on / outside.
  jurysp   Jury's singular cases: reciprocal pairs r, 1/r (real and complex, |p_k(0)| = |lead|
           in a row of the table) beside circle roots and roots inside.
  symsign  planted(lambda) times (lambda^2 - a) (the sign of a decides real or imaginary roots:
           |root|^2 = |a|) or times (a lambda - 1/2) (degree drop at a = 0, root 1/(2a)):
           region a and the point routes at probes, jury/hurwitz never-claims.
  degen    degenerate inputs with hand-derived answers (degree 0 and 1, identically zero p,
           parameters that cancel, zero rows written with zero coefficients).

Usage: truth7.py PART SEED COUNT   prints "ok ..." / "FAIL ..." / "weak ..." lines.
"""
import cmath
import os
import random
import sys
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import truth as T  # noqa: E402
import truth6 as T6  # noqa: E402

# truth6's reporting (its NFAIL counts this script's failures too)
fail = T6.fail
rf = T.rand_frac


# ---------------------------------------------------------------- closed forms
def sqrt_cmp(D, t):
    """sign of sqrt(D) - t for rational D >= 0, t"""
    if t < 0:
        return 1 if D > 0 or t < 0 else 0
    return (D > t * t) - (D < t * t)


def real_root_vs(b, D, sgn, k):
    """sign of r - k for r = (-b + sgn sqrt D)/2 (exact)"""
    # r - k = (-b - 2k + sgn sqrt D)/2 ; compare sgn sqrt D with b + 2k
    t = b + 2 * k
    c = sqrt_cmp(D, sgn * t) if sgn > 0 else -sqrt_cmp(D, -t)
    return c


def quad_roots(b, c):
    """x^2 + b x + c, rational b, c: list of (class, complex value) with class
    'in' / 'on' / 'out', and whether a root on the circle is double"""
    D = b * b - 4 * c
    out = []
    if D < 0:
        cls = "in" if c < 1 else ("on" if c == 1 else "out")
        s = cmath.sqrt(complex(D))
        out = [(cls, (-float(b) + s) / 2), (cls, (-float(b) - s) / 2)]
        return out, False
    s = float(D) ** 0.5
    for sgn in (1, -1):
        lt1 = real_root_vs(b, D, sgn, 1)      # sign of r - 1
        gtm1 = real_root_vs(b, D, sgn, -1)    # sign of r + 1
        cls = "in" if lt1 < 0 and gtm1 > 0 else ("on" if lt1 == 0 or gtm1 == 0 else "out")
        out.append((cls, complex((-float(b) + sgn * s) / 2)))
    return out, D == 0 and out[0][0] == "on"


def classify(roots, defective=False):
    """(status, inside, on, out) of classified roots [(cls, value)]; a repeated circle
    root (by value) or defective=True: unstable"""
    inside = sum(1 for c, _ in roots if c == "in")
    on = sum(1 for c, _ in roots if c == "on")
    out = len(roots) - inside - on
    circ = [v for c, v in roots if c == "on"]
    rep = defective or any(abs(circ[i] - circ[j]) < 1e-12 for i in range(len(circ)) for j in range(i + 1, len(circ)))
    st = "unstable" if out or rep else ("marginal" if on else "stable")
    return st, inside, on, out


def rho2_of(roots):
    return max(abs(v) ** 2 for _, v in roots)


# ---------------------------------------------------------------- part lmmfam
LMM_TEXT = ("title lmm family\nparam a w\nunknown y\n"
            "eq y[n+2] - (1 + a)*y[n+1] + a*y[n] = w*((3 - a)/2*y[n+1] - (1 + a)/2*y[n])\n")


def part_lmmfam(rng, count):
    for k in range(count):
        tag = "lmmfam-%d" % k
        a = rng.choice([F(-1), F(1), F(-1, 2), F(0), F(1, 2), F(9, 10), F(-9, 10), F(3, 2), F(-3, 2),
                        rf(rng, -1, 1), rf(rng, -2, 2)])
        z = rng.choice([F(0), F(0), F(-1, 10), F(-1, 2), F(-1), F(1, 4), F(-3), rf(rng, -2, 1)])
        b = -(1 + a) - z * (3 - a) / 2
        c = a + z * (1 + a) / 2
        roots, double_on = quad_roots(b, c)
        want = classify(roots, double_on)
        text = LMM_TEXT + T6.ANALYSES
        rc, doc, err = T.run(text, ["--time-limit", "30", "--set", "a=%s" % a, "--set", "w=%s" % z])
        if rc not in (0, 1) or doc is None:
            fail("%s: a=%s z=%s: exit %d (%s)" % (tag, a, z, rc, err.strip()[:200]), text, tag)
            continue
        bad = []
        T6.check_point(doc, want, [v for _, v in roots], rho2_of(roots), bad)
        if bad:
            fail("%s: a=%s z=%s: %s" % (tag, a, z, "; ".join(bad)), text + "# --set a=%s --set w=%s\n" % (a, z), tag)
            continue
        # symbolic in a at z = 0 (once every 4 cases: the region is the same family)
        if k % 4 == 0:
            text2 = LMM_TEXT + "analyse jury\nanalyse hurwitz\nanalyse region a\n"
            rc, doc, err = T.run(text2, ["--time-limit", "30", "--set", "w=0"])
            if rc not in (0, 1) or doc is None:
                fail("%s: symbolic: exit %d (%s)" % (tag, rc, err.strip()[:200]), text2, tag + "-sym")
                continue
            reg = T.find(doc, "region")
            for probe in (F(-2), F(-1), F(-1, 2), F(0), F(1, 2), F(1), F(2)):
                w = "marginal" if -1 <= probe < 1 else "unstable"
                got = T.region_status_at(reg, probe) if reg else None
                if got != w:
                    bad.append("region at a = %s %s, truth %s" % (probe, got, w))
            for name in ("jury", "hurwitz"):
                r = T.find(doc, name)
                if r is None or r.get("verdict") != "never stable":
                    bad.append("%s verdict %s, truth never stable (p(1) = 0 for every a)"
                               % (name, r and r.get("verdict")))
            if bad:
                fail("%s: z = 0: %s" % (tag, "; ".join(bad)), text2 + "# --set w=0\n", tag + "-sym")
                continue
        print("ok %s: a=%s z=%s %s" % (tag, a, z, want))


# ---------------------------------------------------------------- part builders
def R_onestep(m, z):
    """the stability function of the one-step method m at rational z, or None at a pole"""
    if m == "euler-forward":
        return 1 + z
    if m in ("rk heun", "rk midpoint"):
        return 1 + z + z * z / 2
    if m == "rk rk4":
        return 1 + z + z ** 2 / 2 + z ** 3 / 6 + z ** 4 / 24
    num, den = {
        "euler-backward": (1, 1 - z),
        "trapezoidal": (1 + z / 2, 1 - z / 2),
        "theta 2/3": (1 + z / 3, 1 - 2 * z / 3),
        "rk gauss2": (1 + z / 2 + z * z / 12, 1 - z / 2 + z * z / 12),      # Pade (2,2)
        "rk radau-iia2": (1 + z / 3, 1 - 2 * z / 3 + z * z / 6),            # Pade (1,2)
    }[m]
    return None if den == 0 else F(num) / den


def sub_roots(m, z):
    """classified roots of one subsystem's scalar scheme at z = h mu, None at a pole"""
    if m == "adams-bashforth 2":      # x^2 - x = z (3/2 x - 1/2)
        return quad_roots(-1 - 3 * z / 2, z / 2)
    if m == "bdf 2":                  # 3/2 x^2 - 2 x + 1/2 = z x^2
        d = F(3, 2) - z
        if d == 0:
            return None
        return quad_roots(F(-2) / d, F(1, 2) / d)
    r = R_onestep(m, z)
    if r is None:
        return None
    cls = "in" if abs(r) < 1 else ("on" if abs(r) == 1 else "out")
    return [(cls, complex(float(r)))], False


METHODS = ["euler-forward", "euler-backward", "trapezoidal", "theta 2/3", "rk heun", "rk midpoint",
           "rk rk4", "rk gauss2", "rk radau-iia2", "adams-bashforth 2", "bdf 2"]
COUPLINGS = ["couple jacobi", "couple gauss-seidel S1 S2", "couple gauss-seidel S2 S1",
             "couple monolithic", "couple jacobi\niterations 1", "couple jacobi\nextrapolate order 1"]


def part_builders(rng, count):
    k = 0
    while k < count:
        A, B = rf(rng, -3, 1), rf(rng, -3, 1)
        C = rf(rng, -2, 2) or F(1)
        h = rng.choice([F(1, 10), F(1, 2), F(1), F(2)])
        m1, m2 = rng.choice(METHODS), rng.choice(METHODS)
        r1, r2 = sub_roots(m1, h * A), sub_roots(m2, h * B)
        if r1 is None or r2 is None:
            continue
        roots = r1[0] + r2[0]
        # a circle root shared by both subsystems: its Jordan structure depends on C and the
        # coupling (not derived here)
        if any(abs(u[1] - v[1]) < 1e-12 for u in r1[0] for v in r2[0] if u[0] == "on" and v[0] == "on"):
            continue
        st, inside, on, out = classify(roots, r1[1] or r2[1])
        cpl = rng.choice(COUPLINGS)
        text = ("title cascade\nparam h\nsubsystem S1 state x1\n  x1' = (%s)*x1 + (%s)*x2\n"
                "subsystem S2 state x2\n  x2' = (%s)*x2\nintegrate S1 %s h\nintegrate S2 %s h\n%s\n%s"
                % (A, C, B, m1, m2, cpl, T6.ANALYSES))
        tag = "builders-%d" % k
        k += 1
        rc, doc, err = T.run(text, ["--time-limit", "30", "--set", "h=%s" % h])
        if rc not in (0, 1) or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text + "# --set h=%s\n" % h, tag)
            continue
        bad = []
        for name in ("stability", "jury", "routh"):
            got = T6.counts(doc, name)
            if got is None or (got[0], got[2], got[3]) != (st, on, out) or got[1] < inside:
                bad.append("%s %s, planted %s (+ roots at 0)" % (name, got, (st, inside, on, out)))
        tmp = []
        T6.check_point(doc, (st, inside, on, out), [v for _, v in roots], rho2_of(roots), tmp)
        # the counts of check_point are compared above without the roots at 0
        bad += [x for x in tmp if not x.startswith(("stability ", "jury ", "routh ", "hurwitz ("))]
        if bad:
            fail("%s: %s %s %s h=%s: %s" % (tag, m1, m2, cpl.replace("\n", "; "), h, "; ".join(bad)),
                 text + "# --set h=%s\n" % h, tag)
        else:
            print("ok %s: %s / %s, %s: %s" % (tag, m1, m2, cpl.split("\n")[0], st))


# ---------------------------------------------------------------- part routh
def pmul(a, b):
    out = [F(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def ppow(a, k):
    r = [F(1)]
    for _ in range(k):
        r = pmul(r, a)
    return r


def to_lambda(q):
    """p(lambda) = (lambda + 1)^n q((lambda - 1)/(lambda + 1)), n = deg q: recstab's own
    bilinear image of p is then q itself (lambda = (1 + z)/(1 - z)), so its Routh array
    meets the textbook special case"""
    n = len(q) - 1
    p = [F(0)] * (n + 1)
    for k, c in enumerate(q):
        t = pmul(ppow([F(-1), F(1)], k), ppow([F(1), F(1)], n - k))
        for i, x in enumerate(t):
            p[i] += c * x
    return p


def ztext(c, var="lambda"):
    return " + ".join("(%s)*%s^%d" % (x, var, i) for i, x in enumerate(c) if x != 0)


# textbook polynomials (coefficients of z^0 .. z^n) with the count of roots in Re z > 0:
# the zero first-column case and its epsilon method.  Values from the sources, each also
# checked below by mpmath's roots (well away from the axis).
TEXTBOOK = [
    # s^4 + s^3 + 2 s^2 + 2 s + 3: row s^2 starts with 0 (Ogata, Modern Control Eng., 5th ed.,
    # ex. 5-13 style; Routh with epsilon: two sign changes, two roots in the RHP)
    ([3, 2, 2, 1, 1], 2),
    # s^5 + 2 s^4 + 2 s^3 + 4 s^2 + 11 s + 10 (Nise, Control Systems Eng., ex. 6.2: two RHP roots)
    ([10, 11, 4, 2, 2, 1], 2),
    # s^5 + s^4 + 2 s^3 + 2 s^2 + 3 s + 5 (zero in the first column at s^3; two RHP roots)
    ([5, 3, 2, 2, 1, 1], 2),
]


def routh_plant(rng):
    """(q coefficients, z roots as (cls, complex)), cls by Re z; repeated axis roots flagged"""
    if rng.random() < 0.3:
        q, nr = rng.choice(TEXTBOOK)
        import mpmath
        zs = mpmath.polyroots([F(x) for x in reversed(q)], maxsteps=200, extraprec=200)
        roots = [("out" if complex(z).real > 0 else "in", complex(z)) for z in zs]
        assert sum(1 for c, _ in roots if c == "out") == nr and all(abs(complex(z).real) > 1e-6 for z in zs)
        q = [F(x) for x in q]
        return q, roots, False
    q = [F(1)]
    roots = []
    for _ in range(rng.randint(1, 3)):
        kind = rng.choice(["lhp", "rhp", "axis", "axis", "sym", "quad", "zero"])
        m = rng.choice([1, 1, 1, 2])
        if kind == "lhp":
            r = F(rng.randint(1, 9), rng.randint(1, 4))
            f, rr = [r, F(1)], [("in", complex(-r))]
        elif kind == "rhp":
            r = F(rng.choice([1, 3, 5, 7]), rng.choice([2, 4]))    # never z = 1 (lambda = inf)
            f, rr = [-r, F(1)], [("out", complex(r))]
        elif kind == "axis":
            w = F(rng.randint(1, 5), rng.randint(1, 3))
            f, rr = [w * w, F(0), F(1)], [("on", complex(0, w)), ("on", complex(0, -w))]
        elif kind == "sym":                # z^2 - r^2: even factor, a zero row
            r = F(rng.choice([1, 3, 5]), rng.choice([2, 4]))     # never 1 (lambda = inf)
            f, rr = [-r * r, F(0), F(1)], [("out", complex(r)), ("in", complex(-r))]
        elif kind == "quad":               # (z^2 + 2uz + s)(z^2 - 2uz + s): quadrantal, a zero row
            u, v = F(rng.randint(1, 3), 2), F(rng.randint(1, 3), 2)
            s = u * u + v * v
            f = [s * s, F(0), 2 * s - 4 * u * u, F(0), F(1)]
            rr = [("in", complex(-u, v)), ("in", complex(-u, -v)), ("out", complex(u, v)), ("out", complex(u, -v))]
        else:                              # z: lambda = -1
            f, rr = [F(0), F(1)], [("on", complex(0))]
        for _ in range(m):
            q = pmul(q, f)
            roots += rr
    circ = [v for c, v in roots if c == "on"]
    rep = any(abs(circ[i] - circ[j]) < 1e-12 for i in range(len(circ)) for j in range(i + 1, len(circ)))
    return q, roots, rep


def part_routh(rng, count):
    for k in range(count):
        q, zroots, rep = routh_plant(rng)
        p = to_lambda(q)
        lroots = [(c, (1 + z) / (1 - z)) for c, z in zroots]
        want = classify(lroots, rep)
        tag = "routh-%d" % k
        text = "title textbook routh\n# q(z) = %s\nchar %s\n%s" % (ztext(q, "z"), ztext(p), T6.ANALYSES)
        rc, doc, err = T.run(text, ["--time-limit", "30"])
        if rc not in (0, 1) or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        bad = []
        T6.check_point(doc, want, [v for _, v in lroots], rho2_of(lroots), bad)
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
        else:
            print("ok %s: %s" % (tag, want))


# ---------------------------------------------------------------- part jurysp
def part_jurysp(rng, count):
    for k in range(count):
        p = [F(1)]
        roots = []
        for _ in range(rng.randint(1, 3)):
            kind = rng.choice(["rpair", "cpair", "circ", "in", "one"])
            if kind == "rpair":                       # r and 1/r
                r = rng.choice([F(2), F(-3), F(3, 2), F(-5, 4), F(7, 3)])
                f = pmul([-r, F(1)], [-1 / r, F(1)])
                rr = [("out", complex(r)), ("in", complex(1 / r))]
            elif kind == "cpair":                     # w, conj w, 1/conj w, 1/w
                u, v = rf(rng, -2, 2), rf(rng, -2, 2) or F(1, 2)
                s = u * u + v * v
                if s == 1:
                    u, v, s = F(1), F(1), F(2)
                f = pmul([s, -2 * u, F(1)], [1 / s, -2 * u / s, F(1)])
                w = complex(u, v)
                rr = [("out" if s > 1 else "in", w), ("out" if s > 1 else "in", w.conjugate()),
                      ("in" if s > 1 else "out", 1 / w.conjugate()), ("in" if s > 1 else "out", 1 / w)]
            elif kind == "circ":
                t = rf(rng, -3, 3)
                c = (1 - t * t) / (1 + t * t)
                if abs(c) == 1:
                    c = F(3, 5)
                f = [F(1), -2 * c, F(1)]
                s2 = (1 - c * c) ** 0.5
                rr = [("on", complex(c, s2)), ("on", complex(c, -s2))]
            elif kind == "in":
                r = rf(rng, -1, 1) * F(9, 10)
                f, rr = [-r, F(1)], [("in", complex(r))]
            else:
                f, rr = [F(-1), F(1)], [("on", complex(1))]
            p = pmul(p, f)
            roots += rr
        want = classify(roots)
        tag = "jurysp-%d" % k
        text = "title jury singular\nchar %s\n%s" % (ztext(p), T6.ANALYSES)
        rc, doc, err = T.run(text, ["--time-limit", "30"])
        if rc not in (0, 1) or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        bad = []
        T6.check_point(doc, want, [v for _, v in roots], rho2_of(roots), bad)
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
        else:
            print("ok %s: %s" % (tag, want))


# ---------------------------------------------------------------- part symsign
def extra_roots(fam, a):
    """classified roots of the parametrised factor at rational a; None at a degree drop"""
    if fam == "sq":            # lambda^2 - a: +-sqrt(a) or +-i sqrt(-a), |.|^2 = |a|
        cls = "in" if abs(a) < 1 else ("on" if abs(a) == 1 else "out")
        s = cmath.sqrt(complex(float(a)))
        rs = [(cls, s), (cls, -s)]
        return rs, a == 0 and False
    if a == 0:
        return None
    r = F(1, 2) / a             # a lambda - 1/2
    return [("in" if abs(r) < 1 else ("on" if abs(r) == 1 else "out"), complex(float(r)))], False


# assumptions on a as intervals (lo, lo_closed, hi, hi_closed); None: unbounded
ASSUME = [("", (None, False, None, False)), ("a >= 1", (F(1), True, None, False)),
          ("a >= 0", (F(0), True, None, False)), ("a <= -1", (None, False, F(-1), True)),
          ("-1 <= a <= 1", (F(-1), True, F(1), True)), ("0 < a < 1/2", (F(0), False, F(1, 2), False)),
          ("a > 1/2", (F(1, 2), False, None, False))]


def admissible(iv, v):
    lo, lc, hi, hc = iv
    return (lo is None or v > lo or (lc and v == lo)) and (hi is None or v < hi or (hc and v == hi))


def meets_open(iv, a, b):
    """does the interval iv meet the open interval (a, b) (None: infinite end)?"""
    lo, _, hi, _ = iv
    left = a if lo is None else (lo if a is None else max(a, lo))
    right = b if hi is None else (hi if b is None else min(b, hi))
    return left is None or right is None or left < right


def part_symsign(rng, count):
    weak = 0
    for k in range(count):
        base = [F(1)]
        broots = []
        for _ in range(rng.randint(1, 2)):
            kind = rng.choice(["in", "in", "circ", "out"])
            if kind == "in":
                r = rf(rng, -1, 1) * F(9, 10)
                base, broots = pmul(base, [-r, F(1)]), broots + [("in", complex(r))]
            elif kind == "out":
                r = rng.choice([F(2), F(-3, 2)])
                base, broots = pmul(base, [-r, F(1)]), broots + [("out", complex(r))]
            else:
                base, broots = pmul(base, [F(1), F(-6, 5), F(1)]), broots + [("on", complex(0.6, 0.8)),
                                                                             ("on", complex(0.6, -0.8))]
        fam = rng.choice(["sq", "lin"])
        factor = "(lambda^2 - a)" if fam == "sq" else "(a*lambda - 1/2)"
        asm, iv = rng.choice(ASSUME)
        tag = "symsign-%d" % k
        text = "title sign of a factor\nparam a\n%schar (%s)*%s\n" % ("assume %s\n" % asm if asm else "",
                                                                     ztext(base), factor)
        bad = []
        probes = [x for x in (F(-2), F(-1), F(-1, 2), F(0), F(1, 3), F(1, 2), F(1), F(3, 2)) if admissible(iv, x)]
        # stable for some admissible a: the factor's own stable set (|a| < 1, or |a| > 1/2) meets it
        some_stable = (meets_open(iv, F(-1), F(1)) if fam == "sq"
                       else meets_open(iv, None, F(-1, 2)) or meets_open(iv, F(1, 2), None))
        for pr in rng.sample(probes, min(2, len(probes))):
            ex = extra_roots(fam, pr)
            if ex is None:
                continue
            roots = broots + ex[0]
            want = classify(roots)
            rc, doc, err = T.run(text + T6.ANALYSES, ["--time-limit", "30", "--set", "a=%s" % pr])
            if rc not in (0, 1) or doc is None:
                bad.append("a = %s: exit %d (%s)" % (pr, rc, err.strip()[:200]))
                continue
            T6.check_point(doc, want, [v for _, v in roots], rho2_of(roots), bad)
        rc, doc, err = T.run(text + "analyse jury\nanalyse hurwitz\nanalyse region a\n", ["--time-limit", "30"])
        if rc not in (0, 1) or doc is None:
            bad.append("symbolic: exit %d (%s)" % (rc, err.strip()[:200]))
        else:
            base_st = classify(broots)[0]
            reg = T.find(doc, "region")
            for pr in probes:
                ex = extra_roots(fam, pr)
                if ex is None or reg is None:
                    continue
                got = T.region_status_at(reg, pr)
                w = classify(broots + ex[0])[0]
                if got is not None and got != w:
                    bad.append("region at a = %s %s, truth %s" % (pr, got, w))
            for name in ("jury", "hurwitz"):
                r = T.find(doc, name)
                v = r and r.get("verdict")
                if v == "never stable" and base_st == "stable" and some_stable:
                    bad.append("%s never stable, but stable for some admissible a" % name)
                if (r or {}).get("sample_check", {}).get("agree") is False:
                    bad.append("%s sample check disagrees" % name)
                if v != "never stable" and (base_st != "stable" or not some_stable):
                    weak += 1
                    print("weak %s: %s says '%s', the planted part is %s" % (tag, name, v, base_st))
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text + T6.ANALYSES, tag)
        else:
            print("ok %s: %s times %s" % (tag, classify(broots)[0], factor))


# ---------------------------------------------------------------- part degen
# (text, exit, status, inside, on, out): each derived by hand in its comment
DEGEN = [
    # p = 1/2: no lambda at all -> an input error, exit 2
    ("char 1/2\nanalyse stability\n", 2, None),
    # p = lambda - lambda = 0 identically -> exit 2
    ("char lambda - lambda\nanalyse stability\n", 2, None),
    # p = lambda: one root at 0, dead-beat, stable
    ("char lambda\n", 0, ("stable", 1, 0, 0)),
    # p = 3 lambda - 1: root 1/3
    ("char 3*lambda - 1\n", 0, ("stable", 1, 0, 0)),
    # a cancels: p = lambda - 1/2 + a - a = lambda - 1/2
    ("param a\nchar lambda - 1/2 + a - a\n", 0, ("stable", 1, 0, 0)),
    # the lambda^2 term cancels: p = lambda - 1/2
    ("param a\nchar (a - a)*lambda^2 + lambda - 1/2\n", 0, ("stable", 1, 0, 0)),
    # lambda^2 (lambda - 2): two roots at 0, one outside
    ("char lambda^3 - 2*lambda^2\n", 1, ("unstable", 2, 0, 1)),
    # x[n+1] = 0 x[n]: M = 0, det(lambda I - M) = lambda, dead-beat
    ("unknown x\neq x[n+1] = 0*x[n]\n", 0, ("stable", 1, 0, 0)),
    # a cancels in M = a - a = 0: the same
    ("param a\nunknown x\neq x[n+1] = a*x[n] - a*x[n]\n", 0, ("stable", 1, 0, 0)),
    # 2 x 2 zero matrix written in full: lambda^2
    ("unknown x y\neq x[n+1] = 0*x[n] + 0*y[n]\neq y[n+1] = 0*x[n] + 0*y[n]\n", 0, ("stable", 2, 0, 0)),
    # M = [[0, 0], [1, 1]]: det = lambda (lambda - 1): one at 0, one on the circle
    ("unknown x y\neq x[n+1] = 0*x[n] + 0*y[n]\neq y[n+1] = x[n] + y[n]\n", 0, ("marginal", 1, 1, 0)),
    # M = [[1, 1], [0, 0]] (zero row 2): det = (lambda - 1) lambda
    ("unknown x y\neq x[n+1] = x[n] + y[n]\neq y[n+1] = 0*x[n]\n", 0, ("marginal", 1, 1, 0)),
    # implicit: 2 x[n+1] = x[n]: root 1/2
    ("unknown x\neq 2*x[n+1] = x[n]\n", 0, ("stable", 1, 0, 0)),
    # implicit E x[n+1] = A x[n], E = [[1, 1], [0, 1]], A = [[0, 0], [0, 1/2]] (A's first row and
    # column zero): det(lambda E - A) = lambda (lambda - 1/2)
    ("unknown x y\neq x[n+1] + y[n+1] = 0*x[n] + 0*y[n]\neq y[n+1] = 0*x[n] + 1/2*y[n]\n", 0, ("stable", 2, 0, 0)),
]


def part_degen(rng, count):
    for k, (body, want_rc, want) in enumerate(DEGEN):
        tag = "degen-%d" % k
        text = "title degenerate\n" + body + (T6.ANALYSES if want is not None else "")
        rc, doc, err = T.run(text, ["--time-limit", "30"])
        bad = []
        if rc != want_rc:
            bad.append("exit %d, expected %d (%s)" % (rc, want_rc, err.strip()[:200]))
        elif want is None:
            if ":" not in err or "c.case:" not in err:
                bad.append("no file:line:col in '%s'" % err.strip()[:200])
        else:
            roots = [("in", 0j)] * want[1]   # every root of these is 0 or as listed below
            nz = {"char 3*lambda - 1\n": [1 / 3], "param a\nchar lambda - 1/2 + a - a\n": [0.5],
                  "param a\nchar (a - a)*lambda^2 + lambda - 1/2\n": [0.5], "unknown x\neq 2*x[n+1] = x[n]\n": [0.5]}
            vals = nz.get(body)
            if vals is not None:
                roots = [("in", complex(v)) for v in vals]
            if want[2]:
                roots = [("in", 0j)] * want[1] + [("on", 1 + 0j)] * want[2]
            if want[3]:
                roots = [("in", 0j)] * want[1] + [("out", 2 + 0j)]
            if "1/2*y[n]" in body:
                roots = [("in", 0j), ("in", 0.5 + 0j)]
            T6.check_point(doc, want, [v for _, v in roots], rho2_of(roots), bad)
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
        else:
            print("ok %s: %s" % (tag, want))


def main():
    part, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = random.Random(seed)
    parts = {"lmmfam": part_lmmfam, "builders": part_builders, "routh": part_routh,
             "jurysp": part_jurysp, "symsign": part_symsign, "degen": part_degen}
    if part not in parts:
        sys.exit("unknown part " + part)
    parts[part](rng, count)
    sys.exit(1 if T.NFAIL or T6.NFAIL else 0)


if __name__ == "__main__":
    main()

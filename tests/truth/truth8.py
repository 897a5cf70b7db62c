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
  astab    `analyse astability` of random rational Butcher tableaux (1-3 stages: explicit,
           diagonally implicit, full; b random or summing to 1) on y' = q y: R(z) =
           det(I - zA + z 1 b^T)/det(I - zA) by SymPy (cases with a common factor of N and D
           skipped); the real and imaginary intervals are the cells around 0 of the exact
           real roots of N^2 - D^2, D (real axis) and |D(iy)|^2 - |N(iy)|^2, |D(iy)|^2
           (imaginary axis), each cell decided at a rational midpoint; a_stable iff
           |D(iy)|^2 - |N(iy)|^2 >= 0 for every y and every pole in Re z > 0 (Hairer-Wanner
           II, IV.3); l_stable iff also deg N < deg D.  Ends compared to 1e-9, closedness too.
  qdcouple S: y' = -a y + c x integrated by sdirk2 / sdirk3 / sdirk3-low (tableaux over
           Q(sqrt 2), Q(sqrt 3): Alexander's / Crouzeix's, the README's), T: x' = -c y - d x by
           euler-backward / euler-forward / trapezoidal, coupled Jacobi or Gauss-Seidel
           (S T or T S), step 1, random rational a, c, d (a sometimes complex): the step
           matrix of (y, x, x_dot) from the tableaux, S with the partner frozen over the step
           (y1 = R(l) y0 + Q(l) k u, R = 1 + l b^T (I - lA)^-1 1, Q = l b^T (I - lA)^-1 A 1
           + b^T 1), T keeping (x, x_dot) as the README's builders do (x_dot[n+1] = -c ys -
           d x[n+1] with the partner at t (Jacobi, first of Gauss-Seidel) or t + h, x[n+1] =
           x[n] + al x_dot[n] + be x_dot[n+1]), its eigenvalues by mpmath at 50 digits: stability and jury's status,
           radius's certified interval must contain the spectral radius.

  lmmz     y' = a y by adams-bashforth K, adams-moulton K, bdf K (K = 1..6) or leapfrog, step 1,
           at random real and complex a (not 0): rho(lambda) - a sigma(lambda) with the
           coefficients derived here from the definitions (SymPy: integrals over [0, 1] of the
           Lagrange basis on the nodes 0, -1, .. (AB), 1, 0, -1, .. (AM); derivative at 1 of
           the basis on 1, 0, -1, .. (BDF); leapfrog y[n+1] - y[n-1] = 2 f[n]), its roots by
           mpmath: stability's status and radius's certified interval.

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


# ---------------------------------------------------------------- part astab
y = sp.symbols("y", real=True)


def rand_tableau(rng):
    n = rng.choice([1, 2, 2, 3, 3])
    kind = rng.choice(["explicit", "dirk", "full"])
    A = [[F(0)] * n for _ in range(n)]
    for i in range(n):
        for j in range(n):
            if (kind == "explicit" and j < i) or (kind == "dirk" and j <= i) or kind == "full":
                A[i][j] = rf(rng, -1, 1) if rng.random() < 0.8 else F(0)
    bb = [rf(rng, -1, 1) for _ in range(n)]
    if rng.random() < 0.7:
        bb[-1] = 1 - sum(bb[:-1])
    return A, bb


def stab_fn(A, bb):
    n = len(A)
    M = sp.Matrix(n, n, lambda i, j: R(A[i][j]))
    e = sp.ones(n, 1)
    bt = sp.Matrix(1, n, [R(v) for v in bb])
    D = sp.expand((sp.eye(n) - z * M).det())
    N = sp.expand((sp.eye(n) - z * M + z * e * bt).det())
    return sp.Poly(N, z), sp.Poly(D, z)


def crit_points(polys, var):
    pts = {}
    for P in polys:
        P = sp.Poly(P, var)
        if P.degree() <= 0:
            continue
        for r in sp.real_roots(P):
            v = sp.N(r, 40)
            if all(abs(v - w) > 1e-25 for w in pts):
                pts[v] = r
    return sorted(pts.items(), key=lambda kv: kv[0])


def interval(bounded_at, is_pole, crit):
    """the bounded cells around 0 (0 is a critical point): (lo, lo_closed, hi, hi_closed),
    ends as floats or +-inf"""
    vals = [v for v, _ in crit]
    if not any(abs(v) < 1e-30 for v in vals):     # |R| = 1 identically on the axis: 0 added
        vals = sorted(vals + [sp.Float(0, 40)])
    i0 = min(range(len(vals)), key=lambda i: abs(vals[i]))
    out = []
    for step in (1, -1):
        j = i0
        while True:
            nxt = j + step
            if 0 <= nxt < len(vals):
                mid = sp.Rational(str(sp.N((vals[j] + vals[nxt]) / 2, 30)))
            else:
                mid = sp.Rational(str(sp.N(vals[j] + step, 30)))
            if not bounded_at(mid):
                out.append((float(vals[j]), not is_pole(vals[j])))
                break
            if not 0 <= nxt < len(vals):
                out.append((step * float("inf"), False))
                break
            if is_pole(vals[nxt]):
                out.append((float(vals[nxt]), False))
                break
            j = nxt
    (hi, hic), (lo, loc) = out
    return lo, loc, hi, hic


def rs_end(e):
    if e == "-inf":
        return float("-inf")
    if e == "inf":
        return float("inf")
    if isinstance(e, dict):
        return float(e["approx"])
    return float(sp.Rational(str(e)))


def same_end(x, yv):
    if x in (float("inf"), float("-inf")) or yv in (float("inf"), float("-inf")):
        return x == yv
    return abs(x - yv) <= 1e-9 * max(1.0, abs(x))


def part_astab(rng, count):
    k = 0
    while k < count:
        A, bb = rand_tableau(rng)
        N, D = stab_fn(A, bb)
        # a common factor (the scheme is singular at its roots), R = 0 or |R| = 1 identically
        if sp.gcd(N, D).degree() > 0 or N.is_zero or (N ** 2 - D ** 2).is_zero:
            continue
        tag = "astab-%d" % k
        k += 1
        n = len(A)
        tab = "; ".join(" ".join(str(A[i][j]) for j in range(n)) for i in range(n)) + " | " + \
            " ".join(str(v) for v in bb)
        text = ("title truth8 astability\nparam q\nsubsystem S state y\n  y' = q*y\n"
                "integrate S rk [%s] 1\nanalyse astability q\n" % tab)
        # real axis
        NpD = (N ** 2 - D ** 2)

        def rb(t):
            dv, nv = D.eval(t), N.eval(t)
            return dv != 0 and abs(nv) <= abs(dv)

        def rpole(v):
            return abs(sp.N(D.as_expr().subs(z, v), 40)) < 1e-25
        real = interval(rb, rpole, crit_points([NpD.as_expr(), D.as_expr()], z))
        # imaginary axis: E(y) = |D(iy)|^2 - |N(iy)|^2
        Di = sp.expand(D.as_expr().subs(z, sp.I * y))
        Ni = sp.expand(N.as_expr().subs(z, sp.I * y))
        D2 = sp.expand(sp.re(Di) ** 2 + sp.im(Di) ** 2)
        N2 = sp.expand(sp.re(Ni) ** 2 + sp.im(Ni) ** 2)
        E = sp.expand(D2 - N2)

        def ib(t):
            d2 = D2.subs(y, t)
            return d2 != 0 and E.subs(y, t) >= 0

        def ipole(v):
            return abs(sp.N(D2.subs(y, v), 40)) < 1e-25
        imag = interval(ib, ipole, crit_points([E, D2], y))
        # A-stability: E >= 0 everywhere and the poles in Re z > 0
        ecrit = crit_points([E], y) if sp.Poly(E, y).degree() > 0 else []
        ev = [v for v, _ in ecrit]
        probes = [sp.Rational(str(sp.N((ev[i] + ev[i + 1]) / 2, 30))) for i in range(len(ev) - 1)]
        probes += [sp.Rational(str(sp.N(ev[0] - 1, 30))), sp.Rational(str(sp.N(ev[-1] + 1, 30)))] if ev else [0]
        e_ok = all(E.subs(y, t) >= 0 for t in probes)
        poles = sp.Poly(D, z).nroots(n=30, maxsteps=2000) if D.degree() > 0 else []
        p_ok = all(sp.re(p) > 1e-20 for p in poles)
        a_st = e_ok and p_ok
        l_st = a_st and N.degree() < D.degree()
        rc, doc, err = T.run(text, ["--time-limit", "60"])
        if rc != 0 or doc is None:
            if rc == 2 and "time" in err:
                print("weak %s: %s" % (tag, err.strip()[:160]))
                continue
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        res = T.find(doc, "astability")
        bad = []
        for name, want in (("real_interval", real), ("imag_interval", imag)):
            got = res.get(name)
            det = res.get(name + "_detail") or {}
            if got is None:
                bad.append("%s null, truth %s" % (name, want))
                continue
            lo, hi = rs_end(got[0]), rs_end(got[1])
            if not (same_end(lo, want[0]) and same_end(hi, want[2])):
                bad.append("%s [%s, %s], truth [%s, %s]" % (name, lo, hi, want[0], want[2]))
            elif det.get("ends_decided"):
                if abs(want[0]) != float("inf") and det.get("lo_closed") != want[1]:
                    bad.append("%s lo_closed %s, truth %s" % (name, det.get("lo_closed"), want[1]))
                if abs(want[2]) != float("inf") and det.get("hi_closed") != want[3]:
                    bad.append("%s hi_closed %s, truth %s" % (name, det.get("hi_closed"), want[3]))
        if res.get("a_stable") != a_st:
            bad.append("a_stable %s, truth %s" % (res.get("a_stable"), a_st))
        if res.get("l_stable") is not None and res.get("l_stable") != l_st:
            bad.append("l_stable %s, truth %s" % (res.get("l_stable"), l_st))
        if bad:
            fail("%s: R = (%s)/(%s): %s" % (tag, N.as_expr(), D.as_expr(), "; ".join(bad)), text, tag)
        else:
            print("ok %s: a_stable %s real [%.6g, %.6g] imag [%.6g, %.6g]" % (tag, a_st, real[0], real[2],
                                                                             imag[0], imag[2]))


# ---------------------------------------------------------------- part qdcouple
S2, S3 = sp.sqrt(2), sp.sqrt(3)
G2 = 1 - S2 / 2
G3 = sp.Rational(1, 2) + S3 / 6
G3L = sp.Rational(1, 2) - S3 / 6
TABLEAUX = {
    "sdirk2": ([[G2, 0], [1 - G2, G2]], [1 - G2, G2]),
    "sdirk3": ([[G3, 0], [-S3 / 3, G3]], [sp.Rational(1, 2), sp.Rational(1, 2)]),
    "sdirk3-low": ([[G3L, 0], [S3 / 3, G3L]], [sp.Rational(1, 2), sp.Rational(1, 2)]),
    "euler-backward": ([[1]], [1]),
    "euler-forward": ([[0]], [1]),
    "trapezoidal": ([[0, 0], [sp.Rational(1, 2), sp.Rational(1, 2)]], [sp.Rational(1, 2), sp.Rational(1, 2)]),
}


def rq(name, lv):
    """R(l), Q(l) of a tableau at l (h = 1), exact"""
    A, bb = TABLEAUX[name]
    n = len(A)
    M = sp.Matrix(A)
    bt = sp.Matrix(1, n, bb)
    one = sp.ones(n, 1)
    Inv = (sp.eye(n) - lv * M).inv()
    Rv = 1 + lv * (bt * Inv * one)[0]
    Qv = lv * (bt * Inv * M * one)[0] + (bt * one)[0]
    return sp.simplify(Rv), sp.simplify(Qv)


def cplx_text(v):
    re_, im_ = sp.re(v), sp.im(v)
    if im_ == 0:
        return str(re_)
    return "%s + %s*i" % (re_, im_)


def part_qdcouple(rng, count):
    for k in range(count):
        ms = rng.choice(["sdirk2", "sdirk3", "sdirk3-low"])
        mt = rng.choice(["euler-backward", "euler-forward", "trapezoidal"])
        cp = rng.choice(["jacobi", "gauss-seidel S T", "gauss-seidel T S"])
        av = R(rf(rng, -1, 4))
        if rng.random() < 0.3:
            av += R(rf(rng, -2, 2)) * sp.I
        cv, dv = R(rf(rng, -2, 2)), R(rf(rng, -1, 3))
        tag = "qdcouple-%d" % k
        Rs, Qs = rq(ms, -av)
        # T keeps (x, x_dot) as the builders do (Olivier et al. 2019): x_dot[n+1] = -c ys -
        # d x[n+1] at t + h with the partner's ys, x[n+1] = x[n] + al x_dot[n] + be x_dot[n+1]
        al, be = {"euler-backward": (0, 1), "euler-forward": (1, 0),
                  "trapezoidal": (sp.Rational(1, 2), sp.Rational(1, 2))}[mt]
        y0, x0, xd0 = sp.symbols("y0 x0 xd0")

        def t_step(ys):
            x1 = (x0 + al * xd0 - be * cv * ys) / (1 + be * dv)
            return x1, -cv * ys - dv * x1
        if cp == "jacobi":
            y1 = Rs * y0 + Qs * cv * x0
            x1, xd1 = t_step(y0)
        elif cp == "gauss-seidel S T":
            y1 = Rs * y0 + Qs * cv * x0
            x1, xd1 = t_step(y1)
        else:
            x1, xd1 = t_step(y0)
            y1 = Rs * y0 + Qs * cv * x1
        M = sp.Matrix([[sp.diff(e, v) for v in (y0, x0, xd0)] for e in (y1, x1, xd1)])
        # det(lambda I - M) exactly (sqrt(d) kept), its roots by mpmath (eig's QR can stall on
        # the zero eigenvalues of x_dot)
        cpoly = sp.Poly(sp.expand((lam * sp.eye(3) - M).det()), lam).all_coeffs()
        ccs = [mpmath.mpc(str(sp.re(sp.N(c, 60))), str(sp.im(sp.N(c, 60)))) for c in cpoly]
        while len(ccs) > 1 and ccs[-1] == 0:
            ccs.pop()
        ev = mpmath.polyroots(ccs, maxsteps=500, extraprec=300) if len(ccs) > 1 else [mpmath.mpf(0)]
        rho = max(abs(e) for e in ev)
        if abs(rho - 1) < mpmath.mpf(10) ** -30:
            continue
        want = "stable" if rho < 1 else "unstable"
        if 1 + be * dv == 0:
            # T's implicit step cannot be solved (x[n+1] (1 + be d) = ...): singular set values
            print("weak %s: d = %s makes T's step singular (not compared)" % ("qdcouple-%d" % k, dv))
            continue
        text = ("title truth8 coupled %s / %s (%s)\nparam a c d\nsubsystem S state y\n  y' = -a*y + c*x\n"
                "subsystem T state x\n  x' = -c*y - d*x\nintegrate S rk %s 1\nintegrate T %s 1\ncouple %s\n"
                "set a = %s, c = %s, d = %s\nanalyse stability\nanalyse jury\nanalyse radius\n"
                % (ms, mt, cp, ms, mt, cp, cplx_text(av), cv, dv))
        rc, doc, err = T.run(text, ["--time-limit", "60"])
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        bad = []
        st = T.find(doc, "stability")
        ju = T.find(doc, "jury")
        ra = T.find(doc, "radius")
        for name, r in (("stability", st), ("jury", ju)):
            got = (r.get("status") or {"stable under the assumptions": "stable", "never stable": "unstable"}.get(
                r.get("verdict"), r.get("verdict"))) if r else None
            if got != want:
                bad.append("%s %s, truth %s (rho %s)" % (name, got, want, mpmath.nstr(rho, 20)))
        if ra is not None and ra.get("lower") is not None:
            lo, hi = mpmath.mpf(ra["lower"]), mpmath.mpf(ra["upper"])
            if not (lo - mpmath.mpf(10) ** -40 <= rho <= hi + mpmath.mpf(10) ** -40):
                bad.append("radius [%s, %s] misses rho %s" % (ra["lower"], ra["upper"], mpmath.nstr(rho, 30)))
        elif ra is None:
            bad.append("no radius result")
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
        else:
            print("ok %s: %s/%s %s a=%s: %s rho %s" % (tag, ms, mt, cp, av, want, mpmath.nstr(rho, 12)))


# ---------------------------------------------------------------- part lmmz
sv = sp.symbols("s")


def lagrange(nodes, j):
    e = sp.Integer(1)
    for m, t in enumerate(nodes):
        if m != j:
            e *= (sv - t) / (nodes[j] - t)
    return e


def lmm_poly(name, K, av):
    """coefficients (highest power first) of rho(lambda) - a sigma(lambda)"""
    if name == "leapfrog":
        return [1, -2 * av, -1]
    if name in ("adams-bashforth", "adams-moulton"):
        nodes = ([sp.Integer(1)] if name == "adams-moulton" else []) + [sp.Integer(-j) for j in range(K)]
        beta = [sp.integrate(lagrange(nodes, j), (sv, 0, 1)) for j in range(len(nodes))]
        # nodes at t[n+1] (AM), t[n], t[n-1], ...: powers lambda^K .. lambda^0
        deg = K
        c = [sp.Integer(0)] * (deg + 1)            # c[m]: coefficient of lambda^(deg - m)
        c[0] += 1
        c[1] -= 1
        off = 0 if name == "adams-moulton" else 1
        for j, bj in enumerate(beta):
            c[j + off] -= av * bj
        return c
    nodes = [sp.Integer(1 - j) for j in range(K + 1)]
    alpha = [sp.diff(lagrange(nodes, j), sv).subs(sv, 1) for j in range(K + 1)]
    c = list(alpha)
    c[0] -= av
    return c


def part_lmmz(rng, count):
    for k in range(count):
        name = rng.choice(["adams-bashforth", "adams-moulton", "bdf", "leapfrog"])
        K = rng.randint(1, 6)
        # mostly small a (near the methods' stability boundaries), some anywhere
        av = R(nzf(rng, -3, 1)) if rng.random() < 0.3 else -abs(R(nzf(rng, -1, 1))) / rng.choice([1, 2, 4])
        if rng.random() < 0.4:
            av += R(nzf(rng, -1, 1)) * sp.I / rng.choice([1, 2, 4])
        cs = lmm_poly(name, K, av)
        ccs = [mpmath.mpc(str(sp.re(sp.N(c, 60))), str(sp.im(sp.N(c, 60)))) for c in cs]
        roots = mpmath.polyroots(ccs, maxsteps=500, extraprec=300)
        rho = max(abs(r) for r in roots)
        if abs(rho - 1) < mpmath.mpf(10) ** -25:
            continue
        want = "stable" if rho < 1 else "unstable"
        meth = name if name == "leapfrog" else "%s %d" % (name, K)
        tag = "lmmz-%d" % k
        text = ("title truth8 %s\nparam a\nsubsystem S state y\n  y' = a*y\nintegrate S %s 1\n"
                "set a = %s\nanalyse stability\nanalyse radius\n" % (meth, meth, cplx_text(av)))
        rc, doc, err = T.run(text, ["--time-limit", "60"])
        if rc != 0 or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        bad = []
        st, ra = T.find(doc, "stability"), T.find(doc, "radius")
        if st is None or st.get("status") != want:
            bad.append("stability %s, truth %s (rho %s)" % (st and st.get("status"), want, mpmath.nstr(rho, 20)))
        if ra is None or ra.get("lower") is None:
            bad.append("no radius interval")
        else:
            lo, hi = mpmath.mpf(ra["lower"]), mpmath.mpf(ra["upper"])
            if not (lo - mpmath.mpf(10) ** -40 <= rho <= hi + mpmath.mpf(10) ** -40):
                bad.append("radius [%s, %s] misses rho %s" % (ra["lower"], ra["upper"], mpmath.nstr(rho, 30)))
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
        else:
            print("ok %s: %s a=%s: %s rho %s" % (tag, meth, av, want, mpmath.nstr(rho, 12)))


def main():
    part, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = random.Random(seed)
    parts = {"rsym": part_rsym, "astab": part_astab, "qdcouple": part_qdcouple, "lmmz": part_lmmz}
    if part not in parts:
        sys.exit("unknown part " + part)
    parts[part](rng, count)
    sys.exit(1 if T.NFAIL or T6.NFAIL else 0)


if __name__ == "__main__":
    main()

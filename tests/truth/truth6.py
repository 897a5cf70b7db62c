#!/usr/bin/env python3
"""truth6.py -- every route recstab has for one question against a planted truth
(h-truth6).  The truth is derived here from the planted roots, independently of
recstab (Fractions / Gaussian rationals; no recstab output feeds an expectation):

  routes   p(lambda) = lead * prod of planted factors: rational roots inside / outside,
           +1, -1, rational unit-circle pairs lambda^2 - 2c lambda + 1, complex
           conjugate pairs off the circle, real pairs u +- v sqrt 2 (a quadratic over Q
           with roots in Q(sqrt 2)), Gaussian rational roots (a char over Q(i)), each with
           multiplicity 1..3.  A scalar recurrence: a repeated circle root is unstable.
           Routes: stability, jury, hurwitz, routh (status and counts), radius (its
           [lower, upper] around rho, compared squared), modes (every planted root inside
           one mode's disc, 1e-12 slack for the 15 printed digits), simulate (its verdict),
           claim bounded; with a parameter a (p times (lambda - a), a set to a planted
           value with --set) the same, and without the set value symbolic jury and
           hurwitz: "never stable" exactly when the planted part is not asymptotically
           stable is the truth (stable iff the planted part is and |a| < 1); a route that
           says never on a stable planted part is wrong; one that cannot prove never is
           counted as "weak" (not a failure: the conditions may still be empty), and its
           sample check and cross_route must agree.
  systems  x[n+1] = M x[n] (eq lines), M = S J S^-1 with J block diagonal: semisimple
           repeated circle eigenvalues (+1, -1, rotations twice: marginal), Jordan blocks on
           the circle (unstable), inside (also Jordan) / outside / complex blocks; the same
           routes as `routes` at the point (a system's counts are det A's).

Usage: truth6.py PART SEED COUNT   (PART: routes, systems)
prints "ok ..." / "FAIL ..." / "weak ..." lines.
"""
import os
import sys
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import truth as T  # noqa: E402

import random  # noqa: E402

NFAIL = 0


def fail(msg, text, tag):
    global NFAIL
    NFAIL += 1
    print("FAIL %s case %s" % (msg, T.save_failing(text, tag)))


def rand_frac(rng, lo, hi):
    return T.rand_frac(rng, lo, hi)


def gpoly_text(c):
    """Gaussian rational coefficients c[k] of lambda^k"""
    terms = []
    for k, x in enumerate(c):
        if x.re == 0 and x.im == 0:
            continue
        terms.append("(%s + (%s)*i)*lambda^%d" % (x.re, x.im, k))
    return " + ".join(terms)


def plant(rng, allow_qi):
    """(coefficients as G, roots as complex, inside, on, out, unstable circle?, rho^2, over_qi)"""
    roots = []          # (G root or None, complex value, multiplicity)
    facs = []           # G coefficient lists with multiplicity
    inside = on = out = 0
    rho2 = F(0)
    circ = {}
    over_qi = allow_qi and rng.random() < 0.3
    nf = rng.randint(1, 4)
    for _ in range(nf):
        kind = rng.choice(["in", "out", "one", "minus", "circ", "cin", "cout", "s2in", "s2out"]
                          + (["gin", "gon", "gout"] if over_qi else []))
        m = rng.choice([1, 1, 1, 2, 3])
        if kind in ("in", "out"):
            r = rand_frac(rng, -1, 1) * F(9, 10) if kind == "in" else rng.choice([F(3, 2), F(-5, 4), F(2), F(-7, 3)])
            f = [G(-r), G(1)]
            vals = [complex(r)]
        elif kind in ("one", "minus"):
            r = F(1) if kind == "one" else F(-1)
            f = [G(-r), G(1)]
            vals = [complex(r)]
        elif kind == "circ":
            t = rand_frac(rng, -3, 3)
            c = (1 - t * t) / (1 + t * t)
            s = 2 * t / (1 + t * t)
            if abs(c) == 1:
                c, s = F(3, 5), F(4, 5)
            f = [G(1), G(-2 * c), G(1)]
            vals = [complex(c, s), complex(c, -s)]
        elif kind in ("cin", "cout"):
            while True:
                a, b = rand_frac(rng, -2, 2), rand_frac(rng, -2, 2)
                n2 = a * a + b * b
                if b != 0 and ((kind == "cin" and n2 < 1) or (kind == "cout" and n2 > 1)):
                    break
            f = [G(n2), G(-2 * a), G(1)]
            vals = [complex(a, b), complex(a, -b)]
        elif kind in ("s2in", "s2out"):
            while True:
                u, v = rand_frac(rng, -2, 2), rand_frac(rng, 0, 2)
                if v == 0:
                    continue
                lo2, hi2 = (u - v * 1.4142135623730951), (u + v * 1.4142135623730951)
                big = max(abs(lo2), abs(hi2))
                small = min(abs(lo2), abs(hi2))
                # u +- v sqrt 2 both inside / one outside; decided exactly below
                if kind == "s2in" and big < 0.999 or kind == "s2out" and small > 1.001:
                    break
            f = [G(u * u - 2 * v * v), G(-2 * u), G(1)]
            vals = [complex(lo2), complex(hi2)]
        else:
            while True:
                z = G(rand_frac(rng, -2, 2), rand_frac(rng, -2, 2))
                n2 = z.abs2()
                if (kind == "gin" and n2 < 1) or (kind == "gout" and n2 > 1):
                    break
                if kind == "gon":
                    t = rand_frac(rng, -3, 3)
                    z = G((1 - t * t) / (1 + t * t), 2 * t / (1 + t * t))
                    z = rng.choice([z, G(0, 1), G(0, -1)])
                    break
            f = [G(0) - z, G(1)]
            vals = [complex(float(z.re), float(z.im))]
        nroots = len(f) - 1
        if kind in ("in", "cin", "s2in", "gin"):
            inside += nroots * m
        elif kind in ("out", "cout", "s2out", "gout"):
            out += nroots * m
        else:
            on += nroots * m
            key = tuple((x.re, x.im) for x in f)
            circ[key] = circ.get(key, 0) + m
        for _ in range(m):
            facs.append(f)
        roots += vals
    # rho^2 exactly: max |root|^2 over the factors (quadratics by their constant term
    # when complex, by the larger root's square for the sqrt 2 pairs via (|u| + v sqrt 2)^2
    # compared through floats only where exact ties are impossible)
    rho2 = max(abs(z) ** 2 for z in roots)
    p = [G(1)]
    for f in facs:
        p = gmul(p, f)
    repeated_circle = any(v > 1 for v in circ.values())
    # two circle factors sharing a root (e.g. lambda^2 + 1 and lambda - i) make it repeated
    circ_roots = [z for z in roots if abs(abs(z) - 1) < 1e-12]
    for i in range(len(circ_roots)):
        for j in range(i + 1, len(circ_roots)):
            if abs(circ_roots[i] - circ_roots[j]) < 1e-12:
                repeated_circle = True
    return p, roots, inside, on, out, repeated_circle, rho2, over_qi


def with_root(a, roots, inside, on, out, rep):
    """status and counts of the planted roots and one more at the rational a"""
    rep2 = rep or (abs(a) == 1 and any(abs(z - complex(a)) < 1e-12 for z in roots))
    if abs(a) < 1:
        inside += 1
    elif abs(a) == 1:
        on += 1
    else:
        out += 1
    return ("unstable" if out > 0 or rep2 else ("marginal" if on > 0 else "stable")), inside, on, out


def gmul(a, b):
    out = [G(0) for _ in range(len(a) + len(b) - 1)]
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] = out[i + j] + x * y
    return out


G = T.G


def counts(doc, name):
    r = T.find(doc, name)
    if r is None:
        return None
    return (r.get("status"), r.get("inside"), r.get("on"), r.get("outside"))


def check_point(doc, want, roots, rho2, bad):
    for a in ("stability", "jury", "routh", "hurwitz"):
        got = counts(doc, a)
        if a == "hurwitz" and got is not None and got[0] is None:
            continue   # real p: hurwitz gives the verdict only (below)
        if got != want:
            bad.append("%s %s, planted %s" % (a, got, want))
    hw = T.find(doc, "hurwitz")
    if hw is not None:
        v = hw.get("verdict")
        if v is not None and (v == "never stable") != (want[0] != "stable"):
            bad.append("hurwitz verdict %s, planted %s" % (v, want[0]))
    rr = T.find(doc, "radius")
    try:
        lo, hi = float(F(rr["lower"])), float(F(rr["upper"]))
        if not (lo * lo <= rho2 * (1 + 1e-12) and rho2 <= hi * hi * (1 + 1e-12)):
            bad.append("radius [%s, %s] misses rho^2 = %s" % (rr["lower"], rr["upper"], rho2))
    except (TypeError, KeyError, ValueError):
        bad.append("radius without bounds: %s" % (rr and rr.get("status")))
    md = T.find(doc, "modes")
    if md is not None and md.get("status") != "singular":
        ms = md.get("modes", [])
        for z in roots:
            if not any(abs(complex(float(m["root"]["re"]), float(m["root"]["im"])) - z)
                       <= float(m["root"].get("radius", 0)) + 1e-12 * max(1, abs(z)) for m in ms):
                bad.append("modes miss planted root %s" % z)
                break
    sm = T.find(doc, "simulate")
    if sm is not None:
        sv = sm.get("verdict")
        st = sv.get("status") if isinstance(sv, dict) else sm.get("status")
        if st != want[0]:
            bad.append("simulate %s, planted %s" % (st, want[0]))
    cl = T.find(doc, "claim")
    want_claim = "refuted" if want[0] == "unstable" else "proved"
    if cl is None or cl.get("status") != want_claim:
        bad.append("claim bounded %s, planted %s" % (cl and cl.get("status"), want_claim))


ANALYSES = "analyse stability\nanalyse jury\nanalyse hurwitz\nanalyse routh\nanalyse radius\n" \
           "analyse modes\nanalyse simulate\nclaim bounded\n"


def part_routes(rng, count):
    weak = 0
    for k in range(count):
        p, roots, inside, on, out, rep, rho2, over_qi = plant(rng, True)
        status = "unstable" if out > 0 or rep else ("marginal" if on > 0 else "stable")
        lead = rng.choice([G(1), G(-2), G(F(3, 7))])
        pc = [lead * x for x in p]
        tag = "routes-%d" % k
        # 1. the planted polynomial alone
        text = "title planted routes\nchar %s\n%s" % (gpoly_text(pc), ANALYSES)
        rc, doc, err = T.run(text, ["--time-limit", "30"])
        bad = []
        if rc not in (0, 1) or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        check_point(doc, (status, inside, on, out), roots, rho2, bad)
        if (rc == 1) != (status == "unstable"):
            bad.append("exit %d" % rc)
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
            continue
        # 2. times (lambda - a), a set to a planted value
        a = rng.choice([rand_frac(rng, -1, 1) * F(9, 10), F(1), F(-1), F(3, 2), F(-5, 3)])
        text2 = "title planted routes with a\nparam a\nchar (%s)*(lambda - a)\n%s" % (gpoly_text(pc), ANALYSES)
        st2, ins, on2, out2 = with_root(a, roots, inside, on, out, rep)
        rho2a = max(rho2, float(a * a))
        rc, doc, err = T.run(text2, ["--time-limit", "30", "--set", "a=%s" % a])
        if rc not in (0, 1) or doc is None:
            fail("%s: --set a=%s: exit %d (%s)" % (tag, a, rc, err.strip()[:200]), text2, tag + "-set")
            continue
        check_point(doc, (st2, ins, on2, out2), roots + [complex(a)], rho2a, bad)
        if bad:
            fail("%s: at a = %s: %s" % (tag, a, "; ".join(bad)), text2, tag + "-set")
            continue
        # 3. symbolic in a: jury, hurwitz (and their cross-checks); region a
        text3 = ("title planted routes symbolic\nparam a\nchar (%s)*(lambda - a)\nanalyse jury\nanalyse hurwitz\n"
                 "analyse region a\n" % gpoly_text(pc))
        rc, doc, err = T.run(text3, ["--time-limit", "30"])
        if rc == 2 and ("limit" in err or "not supported" in err):
            print("ok %s: symbolic refused with a reason (%s)" % (tag, err.strip()[:80]))
            continue
        if rc not in (0, 1) or doc is None:
            fail("%s: symbolic: exit %d (%s)" % (tag, rc, err.strip()[:200]), text3, tag + "-sym")
            continue
        planted_stable = status == "stable"
        for name in ("jury", "hurwitz"):
            r = T.find(doc, name)
            if r is None:
                bad.append("%s missing" % name)
                continue
            v = r.get("verdict")
            never = v == "never stable"
            if never and planted_stable:
                bad.append("%s never stable, but stable for |a| < 1" % name)
            sc = r.get("sample_check", {})
            if sc.get("agree") is False:
                bad.append("%s sample check disagrees" % name)
            cr = r.get("cross_route")
            if cr is not None and cr.get("agree") is False:
                bad.append("%s cross_route disagrees at %s" % (name, cr.get("point")))
            if not never and not planted_stable:
                weak += 1
                print("weak %s: %s says '%s' where the planted part is %s (never stable is the truth) case %s"
                      % (tag, name, v, status, T.save_failing(text3, tag + "-weak")))
        reg = T.find(doc, "region")
        if reg is not None and reg.get("intervals") is not None:
            for probe in (F(0), F(1, 2), F(-1, 2), F(1), F(-1), F(2), F(-3)):
                got = T.region_status_at(reg, probe)
                want = with_root(probe, roots, inside, on, out, rep)[0]
                if got is not None and got != want:
                    bad.append("region at a = %s %s, planted %s" % (probe, got, want))
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text3, tag + "-sym")
        else:
            print("ok %s: %s %d in %d on %d out%s" % (tag, status, inside, on, out, " over Q(i)" if over_qi else ""))
    return weak


def part_systems(rng, count):
    """x[n+1] = M x[n], M = S J S^-1: every route against J's planted eigenvalues"""
    k = 0
    while k < count:
        blocks, roots = [], []
        defective = False
        for kd in rng.sample(["one", "minus", "rot", "in", "in2", "out", "cin"], rng.randint(1, 3)):
            sem = rng.random()
            if kd in ("one", "minus"):
                v = F(1) if kd == "one" else F(-1)
                if sem < 0.5:
                    blocks += [[[v]], [[v]]]                 # semisimple double: marginal
                    roots += [complex(v)] * 2
                elif sem < 0.8:
                    blocks.append([[v]])
                    roots.append(complex(v))
                else:
                    blocks.append([[v, 1], [0, v]])          # Jordan block on the circle
                    roots += [complex(v)] * 2
                    defective = True
            elif kd == "rot":
                t = rand_frac(rng, -3, 3) or F(1, 2)
                c, sn = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
                R = [[c, -sn], [sn, c]]
                reps = 2 if sem < 0.5 else 1
                blocks += [R] * reps
                roots += [complex(c, sn), complex(c, -sn)] * reps
            elif kd in ("in", "in2"):
                v = rand_frac(rng, -1, 1) * F(9, 10)
                blocks.append([[v]] if kd == "in" else [[v, 1], [0, v]])
                roots += [complex(v)] * (1 if kd == "in" else 2)
            elif kd == "cin":
                a, b = rand_frac(rng, -1, 1) * F(1, 2), rand_frac(rng, -1, 1) * F(1, 2) or F(1, 3)
                blocks.append([[a, -b], [b, a]])
                roots += [complex(a, b), complex(a, -b)]
            else:
                v = rng.choice([F(3, 2), F(-5, 4), F(2)])
                blocks.append([[v]])
                roots.append(complex(v))
        rng.shuffle(blocks)
        J = T.block_diag(blocks)
        n = len(J)
        if n > 6:
            continue
        S, Si = T.rand_invertible(rng, n)
        M = T.mat_mul(T.mat_mul(S, J), Si)
        # a zero row or column of M is planted too: every equation writes its [n] terms, zero
        # coefficients included, so det A is det(lambda I - M) with its roots at 0 (h-truth7;
        # h-truth6 skipped these 8 of 400: det A had dropped one root at 0, M = 0 exited 2)
        inside = sum(1 for z in roots if abs(z) < 1 - 1e-12)
        out = sum(1 for z in roots if abs(z) > 1 + 1e-12)
        on = len(roots) - inside - out
        status = "unstable" if out or defective else ("marginal" if on else "stable")
        rho2 = max(abs(z) ** 2 for z in roots)
        names = ["x%d" % (i + 1) for i in range(n)]
        body = "unknown " + " ".join(names) + "\n" + "".join(
            "eq %s[n+1] = %s\n" % (names[i], " + ".join("(%s)*%s[n]" % (M[i][j], names[j]) for j in range(n)))
            for i in range(n))
        text = "title planted system\n%s%s" % (body, ANALYSES)
        tag = "systems-%d" % k
        k += 1
        rc, doc, err = T.run(text, ["--time-limit", "30"])
        if rc not in (0, 1) or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        bad = []
        check_point(doc, (status, inside, on, out), roots, rho2, bad)
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
        else:
            print("ok %s: %s (%d x %d)" % (tag, status, n, n))


def main():
    part, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = random.Random(seed)
    if part == "routes":
        part_routes(rng, count)
    elif part == "systems":
        part_systems(rng, count)
    else:
        sys.exit("unknown part " + part)
    sys.exit(1 if NFAIL or T.NFAIL else 0)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""truth5.py -- planted and literature truths, fifth batch (h-truth5).  Each truth is
derived here or in the literature, independently of recstab (Fractions; the textbook
counts are the books' own, re-derived by hand in the comments):

  textbook continuous-time polynomials of SymPy's Routh tests, Nise's and Ogata's
           special cases (a zero first-column element, a row of zeros), Scilab's
           routh_t regression, mapped to the unit circle by lambda = (1 + s)/(1 - s),
           p(lambda) = (lambda + 1)^n q((lambda - 1)/(lambda + 1)): a root of q with
           Re s < 0, = 0, > 0 is a root of p inside, on, outside the circle.  Plus
           Ogata's Jury example and self-reciprocal polynomials (Jury's singular
           table).  stability, jury and routh must give the literature's counts, also
           for -3/2 p (a negative leading coefficient).
  circle   real polynomials planted from factors: lambda^k, (lambda - r) inside or
           outside, +-1, rational unit-circle pairs lambda^2 - 2c lambda + 1 (c =
           (1 - t^2)/(1 + t^2)) and conjugate pairs off the circle, circle factors with
           multiplicity 1..3: counts with multiplicity; a `char` line is a scalar
           recurrence, so a repeated circle root is unstable, simple ones marginal.
           stability / jury / routh counts and status, radius's printed [lower, upper]
           around rho (compared squared, exactly), `claim bounded`.
  hostile  inputs a fuzzer or a new user would write: deep nesting, long lines, huge
           exponents and coefficients, NUL bytes, non-UTF-8, reserved names, names that
           shadow builtins, values where the scheme is singular or vanishes.  Each must
           end in time with exit 0/1/2 (never a signal or 3), an exit 2 with
           "file:line:col:" on stderr, an exit 0 with valid JSON, and the expected
           verdict where one is planted.

Usage: truth5.py PART SEED COUNT   (PART: textbook, circle (alias circle5), hostile, quick)
prints "ok ..." / "FAIL ..." lines.
"""
import json
import os
import random
import re
import subprocess
import sys
from fractions import Fraction as F

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import truth as T  # noqa: E402

ok = T.ok
NFAIL = 0


def fail(msg, text=None, tag=None):
    global NFAIL
    NFAIL += 1
    if text is not None and tag is not None:
        msg += " case " + T.save_failing(text, tag)
    print("FAIL " + msg)


# ---------------------------------------------------------------- polynomials (Fractions, c[k] of x^k)
pmul, padd = T.pmul, T.padd


def ppow(a, k):
    out = [F(1)]
    for _ in range(k):
        out = pmul(out, a)
    return out


def ptext(c, var="lambda"):
    terms = ["(%s)*%s^%d" % (x, var, k) for k, x in enumerate(c) if x != 0]
    return " + ".join(terms) if terms else "0"


def to_unit_circle(q):
    """p(lambda) = (lambda + 1)^n q((lambda - 1)/(lambda + 1)), n = deg q"""
    n = len(q) - 1
    p = [F(0)]
    for k, a in enumerate(q):
        t = pmul(ppow([F(-1), F(1)], k), ppow([F(1), F(1)], n - k))
        p = padd(p, [a * x for x in t])
    return p


def counts_of(doc, name):
    r = T.find(doc, name)
    if r is None:
        return None
    return (r.get("status"), r.get("inside"), r.get("on"), r.get("outside"))


# ---------------------------------------------------------------- part textbook
# q(s) coefficients from s^0 up; truth (status of p, inside, on, outside) = (LHP, axis, RHP) counts
TEXTBOOK = [
    # SymPy test_routh_table.py p2: first column 1, 1, -3, 4, 3 (zero replaced by epsilon in
    # the third row, sympy's expected table): two sign changes, 2 RHP, 2 LHP
    ("sympy-p2 s^4+s^3+3s^2+3s+3", [3, 3, 3, 1, 1], ("unstable", 2, 0, 2)),
    # SymPy p3: a row of zeros, auxiliary 2s^4 + 12s^2 + 16 = 2(s^2 + 2)(s^2 + 4): four simple
    # roots on the axis; p3 / (s^4 + 6s^2 + 8) = s^2 + 2s + 2, roots -1 +- i: marginal
    ("sympy-p3 s^6+2s^5+8s^4+12s^3+20s^2+16s+16", [16, 16, 20, 12, 8, 2, 1], ("marginal", 2, 4, 0)),
    # Nise, Control Systems Engineering, Example 6.2 (zero only in the first column):
    # s^5 + 2s^4 + 3s^3 + 6s^2 + 5s + 3, two sign changes: 2 RHP, 3 LHP
    ("nise-6.2 s^5+2s^4+3s^3+6s^2+5s+3", [3, 5, 6, 3, 2, 1], ("unstable", 3, 0, 2)),
    # Nise Example 6.4 (row of zeros): s^5 + 7s^4 + 6s^3 + 42s^2 + 8s + 56 = (s + 7)(s^4 + 6s^2 + 8),
    # s^4 + 6s^2 + 8 = (s^2 + 2)(s^2 + 4): 4 simple axis roots, one LHP
    ("nise-6.4 s^5+7s^4+6s^3+42s^2+8s+56", [56, 8, 42, 6, 7, 1], ("marginal", 1, 4, 0)),
    # Ogata, Modern Control Engineering, Routh example s^4 + 2s^3 + 3s^2 + 4s + 5: first column
    # 1, 2, 1, -6, 5, two sign changes: 2 RHP
    ("ogata s^4+2s^3+3s^2+4s+5", [5, 4, 3, 2, 1], ("unstable", 2, 0, 2)),
    # Ogata: s^3 + 2s^2 + s + 2 = (s + 2)(s^2 + 1): row of zeros, +-i simple
    ("ogata s^3+2s^2+s+2", [2, 1, 2, 1], ("marginal", 1, 2, 0)),
    # Scilab bug 12829 (routh_t with a zero first element): 5s^3 - 10s^2 + 7s + 20 has 2 RHP roots
    # (first column 5, -10, 17, 20: two sign changes)
    ("scilab-12829 5s^3-10s^2+7s+20", [20, 7, -10, 5], ("unstable", 1, 0, 2)),
    # a double pair on the axis: (s^2 + 1)^2 (s + 1): repeated axis roots of a scalar
    # recurrence are unstable (t^k growth), the Routh array's repeated auxiliary polynomial
    ("double-axis (s^2+1)^2(s+1)", [1, 1, 2, 2, 1, 1], ("unstable", 1, 4, 0)),
    # s^4 + 1: roots e^{i pi/4 (2k+1)}, 2 LHP and 2 RHP, all first-column trouble (zeros in row 2)
    ("s^4+1", [1, 0, 0, 0, 1], ("unstable", 2, 0, 2)),
]

# polynomials in lambda directly (c[k] of lambda^k)
JURY = [
    # Ogata, Discrete-Time Control Systems, Jury example: z^4 - 1.2z^3 + 0.07z^2 + 0.3z - 0.08
    # = (z - 0.8)(z - 0.5)(z + 0.5)(z - 0.4) (expand by hand): stable
    ("ogata-jury", [F(-8, 100), F(3, 10), F(7, 100), F(-12, 10), 1], ("stable", 4, 0, 0)),
    # self-reciprocal lambda^4 + 5/2 lambda^2 + 1: lambda^2 = -1/2, -2, so +-i/sqrt 2 inside and
    # +-i sqrt 2 outside; p = p* makes Jury's second row vanish (singular table)
    ("self-reciprocal off circle", [1, 0, F(5, 2), 0, 1], ("unstable", 2, 0, 2)),
    # 2 lambda^4 + 5 lambda^3 + 5 lambda + 2: with t = lambda + 1/lambda, 2t^2 + 5t - 4 = 0,
    # t = (-5 +- sqrt 57)/4: |t1| < 2 a circle pair, t2 < -2 a real pair -2.777.., -0.360..
    ("palindromic mixed", [2, 5, 0, 5, 2], ("unstable", 1, 2, 1)),
    # lambda^5 - lambda = lambda (lambda^4 - 1): 0 and four simple circle roots: marginal
    ("lambda^5 - lambda", [0, -1, 0, 0, 0, 1], ("marginal", 1, 4, 0)),
    # (lambda + 1)^3 (lambda - 1/3): a triple root at -1, unstable
    ("triple -1", [F(-1, 3), 0, 2, F(8, 3), 1], ("unstable", 1, 3, 0)),
]


def check_counts(tag, text, want, analyses=("stability", "jury", "routh")):
    rc, doc, err = T.run(text, ["--time-limit", "20"])
    if rc != 0 or doc is None:
        fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
        return
    bad = []
    for a in analyses:
        got = counts_of(doc, a)
        if got != want:
            bad.append("%s %s, expected %s" % (a, got, want))
    if bad:
        fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
    else:
        ok("%s: %s %d in %d on %d out" % ((tag,) + want))


def part_textbook(rng, count):
    del rng, count
    items = [(n, to_unit_circle([F(x) for x in q]), w) for n, q, w in TEXTBOOK]
    items += [(n, [F(x) for x in p], w) for n, p, w in JURY]
    for name, p, want in items:
        for scale in (F(1), F(-3, 2)):
            tag = "textbook-%s%s" % (re.sub(r"[^a-z0-9.]+", "-", name.split()[0].lower()),
                                     "" if scale == 1 else "-neg")
            text = ("title %s\nchar %s\nanalyse stability\nanalyse jury\nanalyse routh\n"
                    % (name, ptext([scale * x for x in p])))
            check_counts(tag, text, want)


# ---------------------------------------------------------------- part circle
def rand_frac(rng, lo, hi):
    return T.rand_frac(rng, lo, hi)


def part_circle(rng, count):
    for k in range(count):
        p = [F(1)]
        inside = on = out = 0
        rho2 = F(0)
        repeated_circle = False
        circ = {}
        nz = rng.choice([0, 0, 1, 2])
        p = pmul(p, ppow([F(0), F(1)], nz))
        inside += nz
        # one or two circle factors with a multiplicity, and some off-circle ones
        for _ in range(rng.randint(1, 2)):
            kind = rng.choice(["one", "minus", "pair", "pair"])
            m = rng.choice([1, 1, 1, 2, 3])
            if kind == "one":
                f = [F(-1), F(1)]
            elif kind == "minus":
                f = [F(1), F(1)]
            else:
                t = rand_frac(rng, -3, 3)
                c = (1 - t * t) / (1 + t * t)
                if abs(c) == 1:
                    c = F(3, 5)
                f = [F(1), -2 * c, F(1)]
            p = pmul(p, ppow(f, m))
            on += (len(f) - 1) * m
            rho2 = max(rho2, F(1))
            # the same factor picked twice adds up (as (lambda + 1)(lambda + 1))
            circ[tuple(f)] = circ.get(tuple(f), 0) + m
            repeated_circle = max(circ.values()) > 1
        for _ in range(rng.randint(0, 3)):
            kind = rng.choice(["in", "out", "cin", "cout"])
            if kind in ("in", "out"):
                r = rand_frac(rng, -1, 1) if kind == "in" else rng.choice([F(3, 2), F(-5, 4), F(2), F(-7, 3)])
                if kind == "in" and (r == 0 or abs(r) == 1):
                    r = F(1, 2)
                p = pmul(p, [-r, F(1)])
                if kind == "in":
                    inside += 1
                else:
                    out += 1
                rho2 = max(rho2, r * r)
            else:
                while True:
                    a, b = rand_frac(rng, -2, 2), rand_frac(rng, -2, 2)
                    n2 = a * a + b * b
                    if b != 0 and ((kind == "cin" and n2 < 1) or (kind == "cout" and n2 > 1)):
                        break
                p = pmul(p, [n2, -2 * a, F(1)])
                if kind == "cin":
                    inside += 2
                else:
                    out += 2
                rho2 = max(rho2, n2)
        status = "unstable" if out > 0 or repeated_circle else "marginal"
        want = (status, inside, on, out)
        scale = rng.choice([F(1), F(-2), F(3, 7)])
        text = ("title planted circle roots\nchar %s\nanalyse stability\nanalyse jury\nanalyse routh\n"
                "analyse radius\nclaim bounded\n" % ptext([scale * x for x in p]))
        tag = "circle-%d" % k
        rc, doc, err = T.run(text, ["--time-limit", "20"])
        if rc not in (0, 1) or doc is None:
            fail("%s: exit %d (%s)" % (tag, rc, err.strip()[:200]), text, tag)
            continue
        bad = []
        for a in ("stability", "jury", "routh"):
            got = counts_of(doc, a)
            if got != want:
                bad.append("%s %s, expected %s" % (a, got, want))
        rr = T.find(doc, "radius")
        try:
            lo, hi = F(rr["lower"]), F(rr["upper"])
            if not (lo >= 0 and lo * lo <= rho2 <= hi * hi):
                bad.append("radius [%s, %s] misses rho^2 = %s" % (rr["lower"], rr["upper"], rho2))
        except (TypeError, KeyError, ValueError):
            bad.append("radius without bounds: %s" % rr)
        cl = T.find(doc, "claim")
        want_claim = "refuted" if status == "unstable" else "proved"
        if cl is None or cl.get("status") != want_claim:
            bad.append("claim bounded %s, expected %s" % (cl and cl.get("status"), want_claim))
        if (rc == 1) != (want_claim == "refuted"):
            bad.append("exit %d" % rc)
        if bad:
            fail("%s: %s" % (tag, "; ".join(bad)), text, tag)
        else:
            ok("%s: %s %d in %d on %d out" % ((tag,) + want))


# ---------------------------------------------------------------- part hostile
LOC = re.compile(r"^recstab: [^:\n]+:\d+:\d+: ", re.M)


def hostile_cases():
    """(tag, bytes of the case, expected exit, jq-like check on the first result or None)"""
    # the limit is 200 levels of parentheses and signs (expr.h): 200 parse (100 failed before)
    deep = b"char " + b"(" * 200 + b"lambda" + b")" * 200 + b" - 1/2\n"
    yield "nest-200", deep + b"analyse stability\n", 0, ("stability", "status", "stable")
    yield "nest-201", b"char " + b"(" * 201 + b"lambda" + b")" * 201 + b"\n", 2, None
    yield "minus-200", b"char lambda - " + b"-" * 199 + b"1/2\nanalyse stability\n", 0, ("stability", "status", "stable")
    yield "nest-5000", b"char " + b"(" * 5000 + b"lambda" + b")" * 5000 + b"\n", 2, None
    # a flat sum is not nesting (h-polish: it was refused past 2000 terms): p = H lambda - 100 with
    # H = sum 1/k, k < 3000, below 1 + ln 2999 < 9.01, so the root 100/H > 11: unstable
    yield "long-sum", ("char " + " + ".join("lambda/%d" % k for k in range(1, 3000)) + " - 100\nanalyse stability\n").encode(), 0, ("stability", "status", "unstable")
    yield "long-title", b"title " + b"x" * 200000 + b"\nchar lambda - 1/2\n", 0, ("stability", "status", "stable")
    # every root of lambda^300 - 1/2 has modulus 2^(-1/300) < 1
    yield "exp-300", b"char lambda^300 - 1/2\nanalyse stability\n", 0, ("stability", "status", "stable")
    yield "exp-huge", b"char lambda^99999999999999999999 - 1\n", 2, None
    yield "exp-negative", b"char lambda^-2 - 1\n", 2, None
    yield "exp-frac", b"char lambda^(1/2) - 1\n", 2, None
    yield "coef-huge", ("char lambda - 1" + "0" * 5000 + "/3\nanalyse stability\n").encode(), 0, \
        ("stability", "status", "unstable")
    yield "coef-tiny", ("char lambda - 1/1" + "0" * 5000 + "\nanalyse stability\n").encode(), 0, \
        ("stability", "status", "stable")
    yield "nul", b"char lambda - 1/2\x00\n", 2, None
    yield "nul-title", b"title a\x00b\nchar lambda - 1/2\n", 2, None
    yield "latin1", b"title caf\xe9\nchar lambda - 1/2\n", 2, None
    yield "overlong-utf8", b"title \xc0\xaf\nchar lambda - 1/2\n", 2, None
    yield "utf8-title", "title café ∑\nchar lambda - 1/2\nanalyse stability\n".encode(), 0, \
        ("stability", "status", "stable")
    yield "bom", b"\xef\xbb\xbfchar lambda - 1/2\n", None, None
    yield "crlf", b"char lambda - 1/2\r\nanalyse stability\r\n", 0, ("stability", "status", "stable")
    yield "reserved-lambda", b"param lambda\nchar lambda - 1/2\n", 2, None
    yield "reserved-n", b"param n\nunknown x\neq x[n+1] = n*x[n]\n", 2, None
    yield "reserved-z", b"param z\nchar lambda - z\n", 2, None
    yield "unknown-lambda", b"unknown lambda\neq lambda[n+1] = lambda[n]/2\n", 2, None
    # a parameter named like a constant or a function is a parameter: lambda - pi/4 at pi = 1
    yield "param-pi", b"param pi\nchar lambda - pi/4\nset pi = 1\nanalyse stability\n", 0, \
        ("stability", "status", "stable")
    yield "unknown-sin", b"unknown sin\neq sin[n+1] = 2*sin[n]\nanalyse stability\n", 0, \
        ("stability", "status", "unstable")
    yield "dup-param", b"param a a\nchar lambda - a\n", 2, None
    yield "set-unknown-name", b"param a\nchar lambda - a\nset b = 1\n", 2, None
    yield "set-twice", b"param a\nchar lambda - a\nset a = 1/2\nset a = 2\nanalyse stability\n", None, None
    yield "div-zero", b"char lambda - 1/0\n", 2, None
    yield "div-zero-set", b"param a\nunknown x\neq x[n+1] = x[n]/(a - 1)\nset a = 1\n", 2, None
    yield "zero-poly", b"char lambda - lambda\n", 2, None
    yield "no-lambda", b"char 1/2\n", 2, None
    # det A = 2 lambda (2 lambda - 1)(1 - a) vanishes at a = 1 (cases/truth/stability-det-vanishes-at-set.case)
    yield "vanishes-set", (b"param a\nunknown x y\neq x[n+1] + y[n+1] = x[n]/2\neq a*x[n+1] + y[n+1] = a*x[n]/2\n"
                           b"set a = 1\nanalyse stability\n"), 0, ("stability", "status", "singular")
    # det A = a^2 lambda^2 - 1/4 drops to -1/4 at a = 0: singular (cases/truth/hurwitz-singular-set-point.case)
    yield "singular-set", (b"param a\nunknown x y\neq a*x[n+1] = y[n]\neq a*y[n+1] = x[n]/4\nset a = 0\n"
                           b"analyse hurwitz\n"), 0, ("hurwitz", "verdict", "never stable")
    yield "empty", b"", 2, None
    yield "only-comments", b"# nothing\n\n", 2, None
    yield "binary", bytes(range(1, 256)) * 4, 2, None
    yield "many-unknowns", ("unknown " + " ".join("x%d" % i for i in range(200)) + "\n" + "".join(
        "eq x%d[n+1] = x%d[n]/2\n" % (i, (i + 1) % 200) for i in range(200))).encode(), None, None
    yield "shift-huge", b"unknown x\neq x[n+100000] = x[n]/2\n", 2, None
    yield "shift-negative", b"unknown x\neq x[n-1] = x[n]/2\nanalyse stability\n", 0, ("stability", "status", "unstable")


def part_hostile(rng, count):
    del rng, count
    path = os.path.join(T.TMP, "hostile.case")
    for tag, data, want_rc, chk in hostile_cases():
        with open(path, "wb") as f:
            f.write(data)
        try:
            p = subprocess.run([T.RS, "--json", "--time-limit", "20", path], capture_output=True, timeout=60)
        except subprocess.TimeoutExpired:
            fail("hostile-%s: no answer in 60 s" % tag)
            continue
        rc = p.returncode
        err = p.stderr.decode("utf-8", "replace")
        bad = []
        if rc < 0 or rc >= 3:
            bad.append("exit %d" % rc)
        if want_rc is not None and rc != want_rc:
            bad.append("exit %d, expected %d" % (rc, want_rc))
        if rc == 2 and not LOC.search(err):
            bad.append("exit 2 without file:line:col: %r" % err[:200])
        if rc in (0, 1):
            try:
                doc = json.loads(p.stdout)
            except ValueError:
                doc = None
                bad.append("exit %d with invalid JSON" % rc)
            if doc is not None and chk is not None:
                r = T.find(doc, chk[0])
                if r is None or r.get(chk[1]) != chk[2]:
                    bad.append("%s.%s = %s, expected %s" % (chk[0], chk[1], r and r.get(chk[1]), chk[2]))
        if bad:
            fail("hostile-%s: %s (stderr %r)" % (tag, "; ".join(bad), err[:160]))
            if len(data) < 4096:
                T.save_failing(data.decode("latin-1"), "hostile-" + tag)
        else:
            ok("hostile-%s: exit %d%s" % (tag, rc, "" if chk is None else ", %s %s" % (chk[0], chk[2])))


def main():
    part, seed, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    rng = random.Random(seed)
    parts = {"textbook": part_textbook, "circle": part_circle, "circle5": part_circle, "hostile": part_hostile}
    if part == "quick":
        for name in ("textbook", "circle", "hostile"):
            parts[name](rng, count)
    else:
        parts[part](rng, count)
    print("# %d failed" % NFAIL)
    return 1 if NFAIL else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""sympy_park.py -- the SymPy peer of `recstab cases/park-staggered.case`.

Does by hand in SymPy what recstab does for the Park (2005) staggered scheme
(cases/park-staggered.case) and times each stage with time.perf_counter:

  matrix    the 4x4 lambda-matrix of the case (unknowns y, x, v, a; params
            m, muh, wh, alpha; yp[n+1] = (1+alpha) y[n] - alpha y[n-1];
            x[n+k] -> lambda^k, every row multiplied by the power of lambda
            that makes its lowest power lambda^0)
  det       Matrix.det(method='bareiss'), then expand; the power of lambda
            that divides it is removed (recstab reports it as
            removed_lambda_power) -> p(lambda)
  bilinear  q(z) = (1-z)^4 p((1+z)/(1-z)), expanded
  hurwitz   the Hurwitz matrix of q and its leading principal minors D1..D4,
            each det(method='bareiss') and expand
  factor    factor() of D1..D4 (skip with --no-factor)

--repeat N runs the timed stages N more times in the same process, SymPy's
cache cleared before each, and prints their median CPU seconds
(sympy_repeat_median_cpu_s): the in-process steady state, the peer of
bench/park_inprocess.c.

Then, outside the timed total, it checks that SymPy's p equals recstab's up to
a constant factor: it runs `build/recstab --json --analyse charpoly
cases/park-staggered.case` (if the binary exists; with --analyse bilinear
--analyse hurwitz added when that recstab knows them), parses "coeffs" (lowest
power first, strings in m, muh, wh, alpha) and prints "agree" when
simplify(p_sympy / p_recstab) is a constant, "DISAGREE" (exit 1) otherwise.
When recstab also gave q(z) and the Hurwitz minors, they are compared the
same way (each up to a constant factor).

Without SymPy it prints why and "skipped", and exits 0.

Output ends with machine-readable lines for bench/run.sh:
  sympy_total_s: <sum of the timed stages>
  sympy_total_cpu_s: <the same stages in CPU seconds (time.process_time)>
  sympy_charpoly_s: <matrix + det>
  check: agree|DISAGREE|skipped (<reason>)
"""
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CASE = os.path.join("cases", "park-staggered.case")

t_start = time.perf_counter()
try:
    import sympy as sp
except ImportError as e:  # pragma: no cover - depends on the machine
    print("sympy_park.py: SymPy is not importable (%s);" % e)
    print("  install it with: apt-get install python3-sympy")
    print("skipped")
    print("check: skipped (no sympy)")
    sys.exit(0)
t_import = time.perf_counter() - t_start


def build_matrix():
    """The lambda-matrix, built from the case's equations term by term."""
    m, muh, wh, alpha, lam = sp.symbols("m muh wh alpha lambda")
    unknowns = ["y", "x", "v", "a"]

    def sh(name, k):
        # x[n+k] -> lambda^k times the unknown's indicator symbol
        return sp.Symbol("U_" + name) * lam**k

    y = lambda k: sh("y", k)
    x = lambda k: sh("x", k)
    v = lambda k: sh("v", k)
    a = lambda k: sh("a", k)
    yp1 = (1 + alpha) * y(0) - alpha * y(-1)  # let yp[n+1] = ...
    eqs = [  # lhs - rhs
        3*y(1) - 4*y(0) + y(-1) + 2*(1 + m)*muh*y(1) + 2*wh**2*x(1),
        x(1) - x(0) - (v(1) + v(0)) / 2,
        v(1) - v(0) - (a(1) + a(0)) / 2,
        a(1) + wh**2*x(1) + m*muh*yp1,
    ]
    rows = []
    for e in eqs:
        e = sp.expand(e)
        row = [e.coeff(sp.Symbol("U_" + u)) for u in unknowns]
        # lowest power of lambda in the row -> multiply it up to lambda^0
        low = min(min(sp.Poly(sp.expand(c * lam**8), lam).monoms())[0] - 8
                  for c in row if c != 0)
        rows.append([sp.expand(c * lam**(-low)) for c in row])
    return sp.Matrix(rows), (m, muh, wh, alpha, lam)


def arg_repeat():
    """--repeat N: N more runs of the timed stages in this process."""
    a = sys.argv[1:]
    if "--repeat" in a:
        i = a.index("--repeat")
        if i + 1 < len(a):
            return max(0, int(a[i + 1]))
    return 0


def main():
    do_factor = "--no-factor" not in sys.argv[1:]
    repeat = arg_repeat()
    stages = []

    cpu = []

    def stage(name, fn):
        t0 = time.perf_counter()
        c0 = time.process_time()
        r = fn()
        stages.append((name, time.perf_counter() - t0))
        cpu.append(time.process_time() - c0)   # CPU seconds: robust to load
        return r

    M, (m, muh, wh, alpha, lam) = stage("matrix", build_matrix)

    def det():
        d = sp.expand(M.det(method="bareiss"))
        P = sp.Poly(d, lam)
        low = min(mon[0] for mon in P.monoms())
        return sp.expand(sp.cancel(d / lam**low)), low
    p, removed = stage("det", det)

    z = sp.Symbol("z")

    def bilinear():
        n = sp.degree(p, lam)
        return sp.expand(sp.cancel((1 - z)**n * p.subs(lam, (1 + z) / (1 - z))))
    q = stage("bilinear", bilinear)

    def hurwitz():
        c = sp.Poly(q, z).all_coeffs()  # a0 (leading) .. an
        n = len(c) - 1
        coef = lambda k: c[k] if 0 <= k <= n else 0
        H = sp.Matrix(n, n, lambda i, j: coef(2*(j + 1) - (i + 1)))
        return H, [sp.expand(H[:k, :k].det(method="bareiss"))
                   for k in range(1, n + 1)]
    H, minors = stage("hurwitz", hurwitz)

    if do_factor:
        factored = stage("factor", lambda: [sp.factor(D) for D in minors])
    total = sum(t for _, t in stages)

    print("SymPy %s, Python %s" % (sp.__version__, sys.version.split()[0]))
    print("lambda-matrix (rows normalised to lowest power lambda^0):")
    for i in range(M.rows):
        print("  [" + ", ".join(str(M[i, j]) for j in range(M.cols)) + "]")
    print("removed_lambda_power: %d" % removed)
    print("p(lambda) =", sp.collect(p, lam))
    print("q(z) =", sp.collect(q, z))
    for k, D in enumerate(minors, 1):
        print("D%d = %s" % (k, D))
        if do_factor:
            print("   = %s" % factored[k - 1])
    print()
    print("%-10s %12s" % ("stage", "seconds"))
    print("%-10s %12.6f   (not in total)" % ("import", t_import))
    for name, t in stages:
        print("%-10s %12.6f" % (name, t))
    print("%-10s %12.6f" % ("total", total))
    print()

    verdict = check_against_recstab(p, q, minors, (m, muh, wh, alpha, lam))
    print("sympy_total_s: %.6f" % total)
    print("sympy_total_cpu_s: %.6f" % sum(cpu))
    if repeat > 0:
        # the same stages again in this process, SymPy's cache cleared before
        # each run (so a run does not reuse the previous run's results): the
        # steady state beside recstab's in-process figure (park_inprocess.c)
        from sympy.core.cache import clear_cache
        runs = []
        for _ in range(repeat):
            clear_cache()
            c0 = time.process_time()
            M2, _syms = build_matrix()
            d = sp.expand(M2.det(method="bareiss"))
            low = min(mon[0] for mon in sp.Poly(d, lam).monoms())
            p2 = sp.expand(sp.cancel(d / lam**low))
            n2 = sp.degree(p2, lam)
            q2 = sp.expand(sp.cancel((1 - z)**n2 * p2.subs(lam, (1 + z) / (1 - z))))
            c = sp.Poly(q2, z).all_coeffs()
            nq = len(c) - 1
            H2 = sp.Matrix(nq, nq, lambda i, j: c[2*(j + 1) - (i + 1)]
                           if 0 <= 2*(j + 1) - (i + 1) <= nq else 0)
            D2 = [sp.expand(H2[:k, :k].det(method="bareiss")) for k in range(1, nq + 1)]
            if do_factor:
                [sp.factor(D) for D in D2]
            runs.append(time.process_time() - c0)
            if sp.expand(p2 - p) != 0:
                print("repeat: a different p(lambda)")
        runs.sort()
        print("sympy_repeat_runs: %d" % len(runs))
        print("sympy_repeat_median_cpu_s: %.6f" % runs[len(runs) // 2])
        print("sympy_repeat_min_cpu_s: %.6f" % runs[0])
    print("sympy_charpoly_s: %.6f" % sum(t for n, t in stages
                                         if n in ("matrix", "det")))
    print("check: %s" % verdict)
    return 1 if verdict.startswith("DISAGREE") else 0


def check_against_recstab(p, q, minors, syms):
    """Compare p (and q, D1..Dn when this recstab has bilinear/hurwitz) with
    recstab's, each up to a constant factor."""
    m, muh, wh, alpha, lam = syms
    z = sp.Symbol("z")
    exe = os.environ.get("RECSTAB", os.path.join(ROOT, "build", "recstab"))
    if not os.access(exe, os.X_OK):
        print("recstab comparison skipped: no executable %s (run make all)" % exe)
        return "skipped (no %s)" % exe
    doc = None
    for extra in (["bilinear", "hurwitz"], []):
        cmd = [exe, "--json", "--analyse", "charpoly"]
        for a in extra:
            cmd += ["--analyse", a]
        r = subprocess.run(cmd + [CASE], cwd=ROOT, capture_output=True, text=True)
        try:
            doc = json.loads(r.stdout)
            if "cases" in doc:   # one document for every case on the command line
                doc = doc["cases"][0]
            results = {x.get("analysis"): x for x in doc["results"]}
            coeffs = results["charpoly"]["coeffs"]
            break
        except (ValueError, KeyError, TypeError):
            doc = None
    if doc is None:
        print("recstab output not understood; exit %d; stderr:\n%s"
              % (r.returncode, r.stderr))
        return "DISAGREE (unreadable recstab output)"
    loc = {"m": m, "muh": muh, "wh": wh, "alpha": alpha}
    parse = lambda t: sp.sympify(t.replace("^", "**"), locals=loc)
    pairs = [("p", p, sum(parse(c) * lam**k for k, c in enumerate(coeffs)))]
    if "bilinear" in results:
        pairs.append(("q", q, sum(parse(c) * z**k for k, c in
                                  enumerate(results["bilinear"]["coeffs"]))))
    if "hurwitz" in results and len(results["hurwitz"].get("minors", [])) == len(minors):
        for k, (mine, theirs) in enumerate(zip(minors, results["hurwitz"]["minors"]), 1):
            pairs.append(("D%d" % k, mine, parse(theirs)))
    bad, ratios = [], []
    for name, mine, theirs in pairs:
        theirs = sp.expand(theirs)
        ratio = sp.simplify(sp.cancel(mine / theirs)) if theirs != 0 else sp.nan
        ok = theirs != 0 and not ratio.free_symbols
        print("%-3s sympy / recstab = %s -> %s" % (name, ratio, "agree" if ok else "DISAGREE"))
        ratios.append("%s %s" % (name, ratio))
        if not ok:
            bad.append(name)
    if bad:
        return "DISAGREE (%s)" % ", ".join(bad)
    return "agree (constant ratios: %s)" % ", ".join(ratios)


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""bench_chain_sympy.py N [RECSTAB_JSON] -- the SymPy peer for the N-mass
trapezoidal chain of issue 17 (bench/make_chain_case.sh).

Builds the same lambda-matrix from the chain's definition (not from recstab):
per mass i the unknowns x_i, v_i, a_i and the equations
    a_i' + c v_i' + (k_i + k_{i+1}) x_i' - k_i x_{i-1}' - k_{i+1} x_{i+1}' = 0
    x_i' - x_i = (v_i' + v_i)/2,   v_i' - v_i = (a_i' + a_i)/2
(' = shift, lambda; the trapezoidal rows times 2), then times, in CPU seconds (time.process_time; the machine is shared):
  det       DomainMatrix over ZZ[c, k, lambda] .det() (fraction-free; 170x
            faster than Matrix.det(method='bareiss') on expressions for N = 2:
            0.14 s against 25 s), divided by lambda^N
            (the first equation of every mass has no unshifted term)
  bilinear  q(z) = (1 - z)^(2N) p((1 + z)/(1 - z)), expanded
  minors    Hurwitz matrix of q and its leading principal minors D_1..D_{2N},
            each DomainMatrix det over ZZ[c, k], unfactored
Prints one line "sympy N det_s bilinear_s minors_s total_s".  With a recstab
--json output file of `analyse hurwitz` on the same case, it also compares
the minors, each up to a constant factor, and prints agree / DISAGREE
(exit 1), untimed.
"""
import json
import sys
import time

import sympy as sp
from sympy.polys.matrices import DomainMatrix

N = int(sys.argv[1])
c = sp.Symbol("c")
k = [sp.Symbol("k%d" % (i + 1)) for i in range(N)]
lam, z = sp.symbols("lambda z")


def kk(i):
    return k[i] if 0 <= i < N else 0


t0 = time.process_time()
M = sp.zeros(3 * N, 3 * N)
for i in range(N):
    x, v, a = 3 * i, 3 * i + 1, 3 * i + 2
    r = 3 * i
    M[r, a] = lam
    M[r, v] = c * lam
    M[r, x] = (kk(i) + kk(i + 1)) * lam
    if i > 0:
        M[r, x - 3] = -kk(i) * lam
    if i + 1 < N:
        M[r, x + 3] = -kk(i + 1) * lam
    # the two trapezoidal rows times 2 (integer entries; p changes by 4^N)
    M[r + 1, x] = 2 * (lam - 1)
    M[r + 1, v] = -(lam + 1)
    M[r + 2, v] = 2 * (lam - 1)
    M[r + 2, a] = -(lam + 1)
dm = DomainMatrix.from_Matrix(M)
p = sp.expand(dm.domain.to_sympy(dm.det()))
p = sp.Poly(p, lam)
p = sp.Poly(sp.div(p, sp.Poly(lam ** N, lam))[0], lam)   # exact: lambda^N | det
t_det = time.process_time() - t0

t0 = time.process_time()
n = 2 * N
# q = sum_j p_j (1 + z)^j (1 - z)^(n - j), polynomial arithmetic only
q = sp.expand(sum(p.coeff_monomial(lam ** j) * (1 + z) ** j * (1 - z) ** (n - j)
                  for j in range(n + 1)))
t_bil = time.process_time() - t0

t0 = time.process_time()
qa = sp.Poly(q, z)
coef = [qa.coeff_monomial(z ** j) for j in range(n + 1)]   # a_0..a_n
H = sp.zeros(n, n)
for i in range(n):
    for j in range(n):
        idx = n - (2 * (j + 1) - (i + 1))
        if 0 <= idx <= n:
            H[i, j] = coef[idx]
D = []
for m in range(1, n + 1):
    dm = DomainMatrix.from_Matrix(H[:m, :m])
    D.append(sp.expand(dm.domain.to_sympy(dm.det())))
t_min = time.process_time() - t0

print("sympy %d %.3f %.3f %.3f %.3f" % (N, t_det, t_bil, t_min,
                                        t_det + t_bil + t_min))
sys.stdout.flush()

if len(sys.argv) > 2:
    d = json.load(open(sys.argv[2]))
    if "cases" in d:   # one document for every case on the command line
        d = d["cases"][0]
    r = [x for x in d["results"] if x["analysis"] == "hurwitz"][0]
    syms = {str(s): s for s in [c] + k}
    ok = len(r["minors"]) == n
    compared = 0
    for m, text in enumerate(r["minors"][:n]):
        if text == "not expanded":   # recstab's per-row share: nothing to compare
            continue
        compared += 1
        ours = sp.sympify(text.replace("^", "**"), locals=syms)
        ratio = sp.cancel(ours / D[m]) if D[m] != 0 else None
        if ratio is None or not ratio.is_number:
            ok = False
            print("D_%d differs: ratio %s" % (m + 1, ratio))
    print(("agree" if ok else "DISAGREE")
          + ("" if compared == n else " (%d of %d minors expanded by recstab)" % (compared, n)))
    sys.exit(0 if ok else 1)

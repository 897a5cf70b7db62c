#!/usr/bin/env python3
"""radius_peers_gen.py -- the polynomials of bench/radius_peers.sh.

Writes, for each polynomial NAME, into DIR: NAME.case (recstab `char` with the
expanded integer coefficients), NAME.expr (the same polynomial in x for PARI),
NAME.pol (the same for MPSolve, its file format) and NAME.rho (the closed-form radius when there is one).
Every tool gets the same integer coefficients.

  random-D     c_0..c_D from bench/results/highdeg-D.case (drawn in [-100, 100])
  cluster-D    (10^12 (10x - 9)^4 - 1) * r(x), r of degree D - 4 with
               coefficients from Python random.Random(D) in [-100, 100]: four
               roots within 10^-4 of 0.9 (a tight cluster inside the circle)
  wilkinson-N  prod_{k=1..N} ((N+1) x - k): roots k/(N+1), rho = N/(N+1)
  pow-N        2 x^N - 1 (lambda^N - 1/2): rho = 2^(-1/N), N roots on a circle
"""
import os
import random
import re
import sys


def mul(a, b):
    r = [0] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x:
            for j, y in enumerate(b):
                r[i + j] += x * y
    return r


def random_coeffs(d):
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "results", "highdeg-%d.case" % d)
    if os.path.exists(path):
        line = [l for l in open(path) if l.startswith("char ")][0][5:]
        c = [0] * (d + 1)
        for term in line.split("+"):
            term = term.strip().replace("(", "").replace(")", "")
            m = re.match(r"^(-?\d+)(?:\*lambda\^(\d+))?$", term)
            c[int(m.group(2) or 0)] = int(m.group(1))
        return c
    g = random.Random(d)
    c = [g.randint(-100, 100) for _ in range(d + 1)]
    c[d] = c[d] or 1
    return c


def write(dirn, name, c, rho=None, title=None):
    d = len(c) - 1
    terms = ["(%d)*lambda^%d" % (x, k) for k, x in enumerate(c) if x]
    with open(os.path.join(dirn, name + ".case"), "w") as f:
        f.write("title %s\nchar %s\n" % (title or name, " + ".join(terms)))
    with open(os.path.join(dirn, name + ".expr"), "w") as f:
        f.write("+".join("(%d)*x^%d" % (x, k) for k, x in enumerate(c) if x) + "\n")
    # MPSolve's own file format (dense, integer, coefficients c_0 .. c_D):
    # `mpsolve -j1 -Ga -o DIGITS NAME.pol`, no expression to parse
    with open(os.path.join(dirn, name + ".pol"), "w") as f:
        f.write("Degree = %d;\nMonomial;\nInteger;\nReal;\n" % d)
        f.write("".join("%d\n" % x for x in c))
    with open(os.path.join(dirn, name + ".rho"), "w") as f:
        f.write((rho or "") + "\n")
    return d


def main():
    dirn, names = sys.argv[1], sys.argv[2:]
    for name in names:
        kind, n = name.rsplit("-", 1)
        n = int(n)
        if kind == "random":
            write(dirn, name, random_coeffs(n))
        elif kind == "cluster":
            g = random.Random(n)
            r = [g.randint(-100, 100) for _ in range(n - 3)]
            r[-1] = r[-1] or 1
            q = [1]
            for _ in range(4):
                q = mul(q, [-9, 10])
            q = [10 ** 12 * x for x in q]
            q[0] -= 1
            write(dirn, name, mul(q, r))
        elif kind == "wilkinson":
            c = [1]
            for k in range(1, n + 1):
                c = mul(c, [-k, n + 1])
            write(dirn, name, c, "%d/%d" % (n, n + 1))
        elif kind == "pow":
            c = [-1] + [0] * (n - 1) + [2]
            write(dirn, name, c, "2^(-1/%d)" % n)
        else:
            sys.exit("radius_peers_gen.py: unknown polynomial " + name)


main()

"""map a, c of cases/complex/sdirk2-coupled-map.case (SDIRK2 Jacobi-coupled
with backward Euler, step 1) against the method's definition, no recstab
arithmetic: rho(M) of the step matrix M from the stage equations in mpmath
(sdirk2_region2.py's step_matrix, 60 digits).  Checks every grid point:
the verdict is stable iff rho < 1 and unstable iff rho > 1 (undecided or
marginal only where |rho - 1| < 1e-40), and `of radius` rows' certified
[radius_lower, radius_upper] contains rho; the boundary overlay lists the
norms of jury's conditions and crosses the column a = 1 where
17 c^4 - 92 c^2 + 124 does (c = 1.6 of the grid lies between its roots
1.5935... and 1.6948...); the column a = 1 is stable exactly for c^2 <
c*^2 = (46 - 2 sqrt 2)/17 (by hand, sdirk2-coupled-conditions.case).
Prints "yes" or "no REASONS".  Usage: sdirk2_map2.py MAP.json"""
import json
import os
import sys
from fractions import Fraction

import mpmath

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sdirk2_region2 import rho  # noqa: E402


def main():
    r = [e for e in json.load(open(sys.argv[1]))["cases"][0]["results"] if e["analysis"] == "map"][0]
    col = {c: k for k, c in enumerate(r["columns"])}
    bad, n = [], 0
    for row in r["rows"]:
        a, c = Fraction(row[col["a_exact"]]), Fraction(row[col["c_exact"]])
        p = rho(a, c)
        near = abs(p - 1) < mpmath.mpf(10) ** -40
        want = "stable" if p < 1 and not near else "unstable" if p > 1 and not near else None
        v = row[col["verdict"]]
        if (want is not None and v != want) or (want is None and v not in ("undecided", "marginal")):
            bad.append("(%s, %s): %s, rho = %s" % (a, c, v, mpmath.nstr(p, 10)))
        if "radius" in col and row[col["radius"]] is not None:
            lo, hi = row[col["radius_lower"]], row[col["radius_upper"]]
            if not (lo <= float(p) * (1 + 1e-15) and float(p) * (1 - 1e-15) <= hi):
                bad.append("(%s, %s): radius [%s, %s], rho = %s" % (a, c, lo, hi, mpmath.nstr(p, 17)))
        if a == 1 and ((mpmath.mpf(c.numerator) ** 2 / c.denominator ** 2 < (46 - 2 * mpmath.sqrt(2)) / 17) != (v == "stable")):
            bad.append("a = 1, c = %s: %s (by hand)" % (c, v))
        n += 1
    if n != r["points"] or r.get("over") != "Q(sqrt 2)" or r.get("rk") != "rk sdirk2":
        bad.append("points/over/rk")
    conds = r.get("boundary", {}).get("conditions", [])
    b17 = [k["index"] for k in conds if k["poly"].replace(" ", "").startswith("4*a^4-4*a^3*c^2+40*a^3")]
    rows = [b for b in r.get("boundary_rows", []) if b[0] in b17 and b[1] == 1 and b[3] == "column"]
    if not conds or not any("jury" in k["origin"] for k in conds) or len(rows) != 4:
        bad.append("boundary at a = 1: %s" % rows)
    print("yes" if not bad else "no " + "; ".join(bad[:5]))


if __name__ == "__main__":
    main()

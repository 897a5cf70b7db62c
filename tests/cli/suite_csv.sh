#!/bin/sh
# suite_csv.sh -- the tables of a run (issue 16): one table per CSV file with
# "# " comments only before its one header line, the map's exact boundary in
# FILE.boundary.csv, later tables in FILE.N.csv; every row in the JSON
# document ("rows", capped by --json-rows), the top level always
# {"cases": [...]}; `sweep ... at NAME=VALUE`; --progress.
# Expected values, derived by hand for x[n+1] = a x[n] + b x[n-1], i.e.
# p = lambda^2 - a lambda - b:
#   a = 0, b = 0: p = lambda^2, radius 0, stable;
#   a = 2, b = -1: p = (lambda - 1)^2, a double root on the circle of a scalar
#     recurrence: unstable (code 2), radius 1;
#   a = -1, b = 1/4: roots (-1 +- sqrt 2)/2, radius (1 + sqrt 2)/2 = 1.2071067811865475.
# Prints "ok ..." or "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$(cd "$BUILD" 2>/dev/null && pwd)/recstab"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }

printf 'param a\nparam b\nunknown x\neq x[n+1] = a*x[n] + b*x[n-1]\n' >"$T/ab.case"
MAP="map a -2 2 5, b -1 1 3"
"$RS" --csv "$T/m.csv" --analyse "$MAP" --analyse "sweep a from -1 to 1 steps 4 at b=1/4" "$T/ab.case" >"$T/out" 2>"$T/err"
rc=$?
[ "$rc" = 0 ] && ok "csv run exit 0" || fail "csv run exit $rc: $(cat "$T/err")"
for f in m.csv m.boundary.csv m.2.csv; do
    if [ ! -f "$T/$f" ]; then fail "$f not written ($(ls "$T"))"; continue; fi
    # comments only before the header, exactly one header line (the first non-comment line)
    if awk 'BEGIN { h = 0 } /^#/ { if (h) bad = 1; next } { h++ } END { exit bad || h < 1 }' "$T/$f"; then
        ok "$f: '# ' comments only before the header"; else fail "$f: a comment after the header"; fi
done
n=$(grep -vc '^#' "$T/m.csv"); [ "$n" = 16 ] && ok "m.csv: header + 15 map rows" || fail "m.csv: $n lines"
n=$(grep -vc '^#' "$T/m.2.csv"); [ "$n" = 6 ] && ok "m.2.csv: header + 5 sweep rows" || fail "m.2.csv: $n lines"
grep -q '^condition,a,b,scan$' "$T/m.boundary.csv" && ok "boundary header" || fail "boundary header"
# the rows of the hand-derived points (columns index,i,j,a,b,a_exact,b_exact,verdict,code,radius,...)
grep -q '^7,2,1,0,0,0,0,stable,0,0,' "$T/m.csv" && ok "a=0,b=0: stable, radius 0" || fail "a=0,b=0 row: $(grep '^7,' "$T/m.csv")"
grep -q '^4,4,0,2,-1,2,-1,unstable,2,1,' "$T/m.csv" && ok "a=2,b=-1: double root at 1, unstable" || fail "a=2,b=-1 row: $(grep '^4,' "$T/m.csv")"
awk -F, '$1 == 0 { d = $4 - 1.2071067811865475; if (d < 0) d = -d; exit !(d < 1e-12 && $5 <= 1.2071067811865475 && $6 >= 1.2071067811865475) }' "$T/m.2.csv" \
    && ok "sweep at b=1/4: radius (1+sqrt 2)/2 at a=-1, inside the certified bounds" || fail "sweep at b=1/4: $(sed -n 3p "$T/m.2.csv")"
grep -q "analysis=sweep a from -1 to 1 steps 4 at b=1/4" "$T/m.2.csv" && ok "m.2.csv comment names the request" || fail "m.2.csv comment"

# JSON: every row, one top-level shape
"$RS" --json --analyse "$MAP" "$T/ab.case" >"$T/one.json" 2>"$T/err"
"$RS" --json --json-rows 2 --analyse "$MAP" "$T/ab.case" "$T/ab.case" >"$T/two.json" 2>"$T/err"
if python3 - "$T/one.json" "$T/two.json" <<'PY'
import json, sys
one = json.load(open(sys.argv[1])); two = json.load(open(sys.argv[2]))
assert list(one) == ["cases"] and len(one["cases"]) == 1, list(one)
assert list(two) == ["cases"] and len(two["cases"]) == 2
m = one["cases"][0]["results"][0]
assert len(m["rows"]) == 15 and len(m["rows"][0]) == len(m["columns"])
assert "table" not in m and "boundary_table" not in m
r = dict(zip(m["columns"], m["rows"][7]))
assert r["verdict"] == "stable" and r["radius"] == 0 and r["a_exact"] == "0", r
assert len(m["boundary_rows"]) >= 1 and m["boundary"]["columns"] == ["condition", "a", "b", "scan"]
c = two["cases"][1]["results"][0]
assert len(c["rows"]) == 2 and c["rows_omitted"] == 13, (len(c["rows"]), c.get("rows_omitted"))
PY
then ok "--json: every row, --json-rows 2 caps them, {\"cases\": [...]} for one and two cases"; else fail "--json rows/shape"; fi

# stdout takes one table: a map with a boundary needs a file name
"$RS" --csv - --analyse "$MAP" "$T/ab.case" >"$T/out" 2>"$T/err"; rc=$?
if [ "$rc" = 2 ] && grep -q 'more than one table' "$T/err"; then ok "--csv - with two tables: exit 2, explained"
else fail "--csv - with two tables: exit $rc $(cat "$T/err")"; fi
"$RS" --analyse "sweep a from 0 to 1 steps 2 at a=1" "$T/ab.case" >"$T/out" 2>"$T/err"; rc=$?
[ "$rc" = 2 ] && grep -q 'swept parameter is also given a value' "$T/err" && ok "at on the swept parameter: exit 2" || fail "at a=: $rc $(cat "$T/err")"

# --progress when stderr is not a terminal: points done and the time it took
"$RS" --progress --analyse "$MAP" "$T/ab.case" >/dev/null 2>"$T/err"
grep -q 'map a,b: 15/15 points done in' "$T/err" && ok "--progress: lines on a non-terminal stderr" || fail "--progress: $(cat "$T/err")"
"$RS" --analyse "$MAP" "$T/ab.case" >/dev/null 2>"$T/err"
[ ! -s "$T/err" ] && ok "no progress without --progress on a non-terminal" || fail "unasked progress: $(cat "$T/err")"
"$RS" --json-rows x "$T/ab.case" >/dev/null 2>&1; rc=$?; [ "$rc" = 2 ] && ok "--json-rows x: exit 2" || fail "--json-rows x: $rc"

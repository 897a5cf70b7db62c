#!/bin/sh
# suite_plot.sh -- plots (issue 16): several --plot options in one run all
# written (.pdf, .png, .svg by their signatures), --plot-size sets the PNG's
# pixels (read from its IHDR header), --plot-script keeps a script that
# redraws the plot on its own, `label` texts reach the axes (LaTeX Greek as
# Unicode), equal axes for a map over Re/Im of one number.
# Prints "ok ..." or "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$(cd "$BUILD" 2>/dev/null && pwd)/recstab"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }
if ! command -v gnuplot >/dev/null 2>&1; then ok "skipped: no gnuplot (Debian: gnuplot-nox)"; exit 0; fi

printf 'param lr1\nparam li1\nunknown x\neq x[n+1] = lr1*x[n] + li1*x[n-1]\nlabel lr1 = "Re \\\\Lambda_1"\nlabel li1 = "Im $\\\\Lambda_1$"\n' >"$T/c.case"
"$RS" --plot "$T/a.png" --plot "$T/a.pdf" --plot "$T/a.svg" --plot-size 640x480 --plot-script "$T/a.gp" \
    --analyse "map lr1 -1 1 4, li1 -1 1 4" "$T/c.case" >"$T/out" 2>"$T/err"; rc=$?
[ "$rc" = 0 ] && ok "three --plot outputs: exit 0" || fail "plot run exit $rc: $(cat "$T/err")"
[ "$(head -c 4 "$T/a.png" | od -An -c | tr -d ' ')" = '211PNG' ] && ok "a.png is a PNG" || fail "a.png: $(head -c 8 "$T/a.png" | od -c)"
[ "$(head -c 4 "$T/a.pdf")" = '%PDF' ] && ok "a.pdf is a PDF" || fail "a.pdf: $(head -c 8 "$T/a.pdf")"
grep -q '<svg' "$T/a.svg" && ok "a.svg is an SVG" || fail "a.svg"
# PNG IHDR: width and height as 4-byte big-endian numbers at offsets 16 and 20
w=$(od -An -tu1 -j16 -N4 "$T/a.png" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4 }')
h=$(od -An -tu1 -j20 -N4 "$T/a.png" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4 }')
[ "$w" = 640 ] && [ "$h" = 480 ] && ok "--plot-size 640x480: the PNG is 640 x 480" || fail "--plot-size: $w x $h"
# the labels (Lambda with subscript 1 as Unicode) on the axes of the SVG
grep -q 'Re Λ₁' "$T/a.svg" && grep -q 'Im Λ₁' "$T/a.svg" && ok "label texts on the axes" || fail "labels not in the SVG"
grep -q '^set size ratio -1$' "$T/a.gp" && ok "complex-plane map (Re, Im): equal axes" || fail "no equal axes"
grep -q '^\$t0 << EOD$' "$T/a.gp" && ok "--plot-script holds the data" || fail "--plot-script data"
# the kept script redraws the plot by itself (the data are in it)
rm -f "$T/a.png"
(cd "$T" && gnuplot a.gp) >/dev/null 2>&1
[ -s "$T/a.png" ] && ok "--plot-script redraws a.png on its own" || fail "--plot-script did not redraw"
# a map over two unrelated parameters keeps its aspect ratio free
printf 'param a\nparam b\nunknown x\neq x[n+1] = a*x[n] + b*x[n-1]\n' >"$T/ab.case"
"$RS" --plot "$T/b.svg" --plot-script "$T/b.gp" --analyse "map a -1 1 3, b -1 1 3" "$T/ab.case" >/dev/null 2>&1
grep -q 'size ratio' "$T/b.gp" && fail "equal axes on a map of a, b" || ok "map of a, b: free aspect ratio"
"$RS" --plot-size 10x10 --plot "$T/c.png" "$T/ab.case" >/dev/null 2>&1; rc=$?
[ "$rc" = 2 ] && ok "--plot-size 10x10: exit 2" || fail "--plot-size 10x10: $rc"
"$RS" --plot-script "$T/d.gp" --analyse "map a -1 1 3, b -1 1 3" "$T/ab.case" >/dev/null 2>&1; rc=$?
[ "$rc" = 2 ] && [ ! -e "$T/d.gp" ] && ok "--plot-script without --plot: exit 2" || fail "--plot-script alone: $rc"
# singular points their own colour and key (they took unstable's clipped colour): backward
# Euler lambda (1 - u) = 1, u = h w, by hand |lambda| = 1/|1 - u|: marginal at u = 0, 2,
# unstable on (0, 2) but u = 1, where the step is singular ((h, w) = (1, 1), (2, 1/2));
# the grid h = 0 .. 2 (5), w = 0, 1/2, 1: marginal 8, unstable 5, singular 2
printf 'param h w\nchar (1 - h*w)*lambda - 1\nanalyse map h 0 2 5, w 0 1 3 of stability\n' >"$T/be.case"
v=$("$RS" --json "$T/be.case" 2>/dev/null | python3 -c 'import json,sys; print(json.load(sys.stdin)["cases"][0]["results"][0]["verdicts"])' 2>/dev/null)
"$RS" --plot "$T/be.svg" --plot-script "$T/be.gp" "$T/be.case" >/dev/null 2>&1; rc=$?
if [ "$rc" = 0 ] && [ "$v" = "{'stable': 0, 'marginal': 8, 'unstable': 5, 'singular': 2}" ] \
   && grep -q "^set cbtics ('stable' 0, 'marginal' 1, 'unstable' 2, 'singular' 3)$" "$T/be.gp" \
   && grep -q "^set cbrange \[-0.5:3.5\]$" "$T/be.gp" && grep -q "2.5 '#7b3294', 3.5 '#7b3294')$" "$T/be.gp"; then
    ok "map with singular points: their own colour and key"
else fail "singular colour: rc=$rc $v $(grep cbtics "$T/be.gp")"; fi

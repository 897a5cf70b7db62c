#!/bin/sh
# suite_sweep.sh -- sweeps and maps through the recstab command: --csv is
# written atomically (a failing run leaves neither the file nor a temporary),
# --plot renders a PNG/SVG with gnuplot (skipped without gnuplot), --shard
# I/N outputs merge (by concatenation, README "Sweeps and maps") into the
# full run's CSV byte for byte, --threads does not change the CSV, the point
# limit exits 2 naming --max-points, the exact-integration map agrees with
# the single-point radius and shards, limits and codes like the others, and, when mpirun and build/recstab-mpi exist, 2
# and 3 MPI ranks write the same CSV as one process.
# Prints "ok ..." or "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$BUILD/recstab"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }
check_exit() { if [ "$2" = "$3" ]; then ok "$1"; else fail "$1: exit $3, expected $2"; fi; }

# the merge recipe documented in README.md (shard files in shard order)
merge() {
    awk '/^# shard /{next}
         /^# recstab table /{t=$4; sub(":", "", t); hdr=1;
             if (!(t in seen)) {seen[t]=1; order[++n]=t; head[t]=$0}; next}
         hdr {hdr=0; if (!(t in colh)) colh[t]=$0; next}
         {rows[t]=rows[t] $0 "\n"}
         END {for (k=1; k<=n; k++) {t=order[k]; print head[t]; print colh[t]; printf "%s", rows[t]}}' "$@"
}

PARK=cases/park-staggered.case
MAP="map alpha 0 3 30, m 1/10 20 25"
SW="sweep w from 0 to 4 steps 40"

# --csv: a map and a sweep of two cases in one file
"$RS" --csv "$T/run.csv" --set muh=1 --set wh=1 --analyse "$MAP" "$PARK" >"$T/out" 2>"$T/err"; rc=$?
check_exit "--csv map exit" 0 "$rc"
# one table per file: the map in run.csv, its exact boundary in run.boundary.csv,
# each with "# " comments and then exactly one header line
n=$(grep -c '^# recstab table ' "$T/run.csv" 2>/dev/null)
hb=$(grep -v '^#' "$T/run.boundary.csv" 2>/dev/null | grep -c '^condition,alpha,m,scan$')
if [ "$n" = 1 ] && [ "$hb" = 1 ]; then ok "--csv: map table in run.csv, its boundary in run.boundary.csv"
else fail "--csv tables: $n in run.csv, boundary header $hb: $(ls "$T")"; fi
# comments only before the header: after the first line not starting with '#', none does
for f in "$T/run.csv" "$T/run.boundary.csv"; do
    if awk 'BEGIN { h = 0 } /^#/ { if (h) bad = 1; next } { h = 1 } END { exit bad }' "$f"; then ok "--csv: comments only before the header ($(basename "$f"))"
    else fail "--csv: a comment after the header in $f"; fi
done
rows=$(grep -v '^#' "$T/run.csv" | grep -c ',fast$\|,prec128$\|,prec256$\|,exact$')
if [ "$rows" = 750 ]; then ok "--csv: 750 map rows"; else fail "--csv map rows: $rows"; fi
if grep -q '^index,i,j,alpha,m,alpha_exact,m_exact,verdict,code,radius,radius_lower,radius_upper,decided_by$' "$T/run.csv"; then
    ok "--csv: map columns"; else fail "--csv: map columns"; fi
if grep -q "csv  *$T/run.csv" "$T/out"; then ok "--csv: report names the file"; else fail "--csv: report: $(grep csv "$T/out")"; fi

"$RS" --json --csv "$T/two.csv" --analyse "$SW" cases/textbook/central-difference.case cases/textbook/trapezoidal.case >"$T/out.json" 2>"$T/err"; rc=$?
check_exit "--csv two cases exit" 0 "$rc"
n=$(cat "$T/two.csv" "$T/two.2.csv" 2>/dev/null | grep -c '^# recstab table ')
if [ "$n" = 2 ] && grep -q 'central-difference' "$T/two.csv" && grep -q 'trapezoidal' "$T/two.2.csv"; then
    ok "--csv: one table per case, the second in two.2.csv"; else fail "--csv two cases: $n tables ($(ls "$T"))"; fi
if grep -q '"table"' "$T/out.json"; then fail "--json with --csv still carries the table"; else ok "--json with --csv: table only in the file"; fi
if grep -q '"points": 41' "$T/out.json" && grep -q '"decided_by": {' "$T/out.json"; then ok "--json sweep element"; else fail "--json sweep element"; fi

# atomic: a run that fails (second case bad) leaves nothing behind
printf 'param w\nunknown x\neq x[n+1] = w*y[n]\n' >"$T/bad.case"
"$RS" --csv "$T/fail.csv" --analyse "$SW" cases/textbook/central-difference.case "$T/bad.case" >"$T/out" 2>"$T/err"; rc=$?
check_exit "--csv failing run exit" 2 "$rc"
if [ ! -e "$T/fail.csv" ] && [ -z "$(ls "$T" | grep 'fail.csv.tmp')" ]; then ok "--csv failing run leaves no file"; else fail "--csv failing run left $(ls "$T")"; fi
# an existing file survives a failing run unchanged
echo keep >"$T/keep.csv"
"$RS" --csv "$T/keep.csv" --analyse "sweep w from 0 to 1 steps 2" "$T/bad.case" >/dev/null 2>&1
if [ "$(cat "$T/keep.csv")" = keep ]; then ok "--csv failing run keeps the old file"; else fail "--csv failing run replaced the old file"; fi
# a failing run (point limit) inside the analysis
"$RS" --csv "$T/lim.csv" --max-points 100 --set muh=1 --set wh=1 --analyse "$MAP" "$PARK" >"$T/out" 2>"$T/err"; rc=$?
check_exit "--max-points limit exit" 2 "$rc"
if grep -q 'more than the limit of 100 points' "$T/err" && grep -q -- '--max-points' "$T/err"; then ok "limit message names --max-points"; else fail "limit message: $(cat "$T/err")"; fi
if [ ! -e "$T/lim.csv" ]; then ok "limit: no csv"; else fail "limit left a csv"; fi
"$RS" --shard 3/2 "$PARK" >/dev/null 2>&1; rc=$?; check_exit "--shard 3/2 is a usage error" 2 "$rc"
"$RS" --threads 0 "$PARK" >/dev/null 2>&1; rc=$?; check_exit "--threads 0 is a usage error" 2 "$rc"

# --threads: the CSV does not depend on the thread count
"$RS" --threads 1 --csv "$T/t1.csv" --set muh=1 --set wh=1 --analyse "$MAP" "$PARK" >/dev/null 2>&1
"$RS" --threads 2 --csv "$T/t2.csv" --set muh=1 --set wh=1 --analyse "$MAP" "$PARK" >/dev/null 2>&1
if cmp -s "$T/t1.csv" "$T/t2.csv" && cmp -s "$T/t1.csv" "$T/run.csv"; then ok "--threads 1 and 2: same CSV"; else fail "--threads changes the CSV"; fi
OMP_NUM_THREADS=1 "$RS" --csv "$T/t3.csv" --set muh=1 --set wh=1 --analyse "$MAP" "$PARK" >/dev/null 2>&1
if cmp -s "$T/t1.csv" "$T/t3.csv"; then ok "OMP_NUM_THREADS=1: same CSV"; else fail "OMP_NUM_THREADS changes the CSV"; fi

# --shard: the merged shards are the full run, byte for byte
for N in 2 3; do
    files=""
    I=1
    while [ $I -le $N ]; do
        "$RS" --shard $I/$N --csv "$T/s$I-$N.csv" --set muh=1 --set wh=1 --analyse "$MAP" --analyse "sweep alpha from 0 to 3 steps 17" --set m=10 "$PARK" >/dev/null 2>"$T/err" \
            || fail "--shard $I/$N: $(cat "$T/err")"
        files="$files $T/s$I-$N.csv"
        I=$((I + 1))
    done
    "$RS" --csv "$T/full.csv" --set muh=1 --set wh=1 --analyse "$MAP" --analyse "sweep alpha from 0 to 3 steps 17" --set m=10 "$PARK" >/dev/null 2>&1
    # shellcheck disable=SC2086
    merge $files >"$T/merged-$N.csv"
    if cmp -s "$T/merged-$N.csv" "$T/full.csv"; then ok "--shard x/$N merge equals the full run"; else fail "--shard x/$N merge differs: $(diff "$T/merged-$N.csv" "$T/full.csv" | head -5)"; fi
    if grep -q "^# shard 2/$N: rows" "$T/s2-$N.csv"; then ok "--shard x/$N header line"; else fail "--shard x/$N header"; fi
done

# --plot (gnuplot): map heatmap + boundary; several cases overlaid
if command -v gnuplot >/dev/null 2>&1; then
    "$RS" --plot "$T/map.png" --set muh=1 --set wh=1 --analyse "$MAP" "$PARK" >/dev/null 2>"$T/err"; rc=$?
    check_exit "--plot map exit" 0 "$rc"
    if [ -s "$T/map.png" ] && head -c 8 "$T/map.png" | od -c | grep -q 'P   N   G'; then ok "--plot writes a PNG"; else fail "--plot PNG: $(cat "$T/err")"; fi
    "$RS" --plot "$T/sw.svg" --analyse "$SW" cases/textbook/central-difference.case cases/textbook/forward-euler.case >/dev/null 2>"$T/err"; rc=$?
    check_exit "--plot overlay exit" 0 "$rc"
    if grep -q '<svg' "$T/sw.svg" && grep -q 'Central difference' "$T/sw.svg" && grep -q 'Forward Euler' "$T/sw.svg"; then
        ok "--plot overlays the cases with their titles"; else fail "--plot overlay legends"; fi
    if grep -q '>w<' "$T/sw.svg"; then ok "--plot axis label names the parameter"; else fail "--plot axis label"; fi
    # a map and a sweep in one plot (the sweep panel used to read the map's
    # missing "param" and crash)
    "$RS" --plot "$T/mix.svg" --set muh=1 --set wh=1 --analyse "map alpha 0 3 4, m 1/10 20 3" \
        --analyse "sweep alpha from 0 to 3 steps 5 of radius" --set m=10 "$PARK" >/dev/null 2>"$T/err"; rc=$?
    check_exit "--plot map and sweep together exit" 0 "$rc"
    if grep -q 'spectral radius' "$T/mix.svg"; then ok "--plot map and sweep: both panels"; else fail "--plot map and sweep: $(cat "$T/err")"; fi
    "$RS" --plot "$T/x.jpg" --analyse "$SW" cases/textbook/central-difference.case >/dev/null 2>&1; rc=$?
    check_exit "--plot unknown extension" 2 "$rc"
    "$RS" --plot "$T/none.png" cases/textbook/central-difference.case >/dev/null 2>&1; rc=$?
    check_exit "--plot without sweep or map" 2 "$rc"
    if [ -z "$(ls "$T" | grep '\.tmp\.')" ]; then ok "--plot leaves no temporary file"; else fail "temporaries left: $(ls "$T")"; fi
else
    echo "skip --plot (gnuplot not installed; Debian: apt-get install gnuplot-nox)"
fi

# exact-integration (co-simulation) map: every grid point is the point the
# single-point `radius` analysis gives when the two values are set by --set
# (its radius inside the map row's certified interval, the same verdict)
LI=cases/li-explicit-k1.case
"$RS" --csv "$T/li.csv" --analyse "map acc1 0 3 4, c1 1/2 2 3" "$LI" >/dev/null 2>"$T/err"; rc=$?
check_exit "cosim map exit" 0 "$rc"
rows=$(grep -vc '^#\|^index' "$T/li.csv")
if [ "$rows" = 12 ]; then ok "cosim map: 12 rows"; else fail "cosim map rows: $rows"; fi
grep -v '^#\|^index' "$T/li.csv" | while IFS=, read -r idx i j x y xe ye verdict code rad lo hi by; do
    "$RS" --json --set "acc1=$xe" --set "c1=$ye" --analyse radius "$LI" >"$T/pt.json" 2>>"$T/err"
    rho=$(sed -n 's/.*"rho": "\(.*\)".*/\1/p' "$T/pt.json" | head -1)
    st=$(sed -n 's/.*"status": "\(.*\)".*/\1/p' "$T/pt.json" | head -1)
    if awk -v r="$rho" -v l="$lo" -v h="$hi" 'BEGIN { exit !(r + 0 >= l * (1 - 1e-15) && r + 0 <= h * (1 + 1e-15)) }' \
        && [ "$st" = "$verdict" ]; then :; else echo "row $idx: map $verdict [$lo, $hi], point $st $rho"; fi
done >"$T/li.diff"
if [ ! -s "$T/li.diff" ]; then ok "cosim map: every point agrees with the single-point radius"; else fail "cosim map: $(cat "$T/li.diff")"; fi

# the co-simulation map runs through the same engine as every map: its
# shards merge (by the README's recipe) into the unsharded CSV byte for byte,
# --max-points refuses it before any point runs, and it has the same columns,
# JSON keys and codes (0 stable, 2 unstable; 4 undecided where the certified
# radius interval contains 1 -- there is no exact side to call it marginal)
LIMAP="map acc1 0 3 5, c1 1/2 2 3"
"$RS" --csv "$T/lifull.csv" --analyse "$LIMAP" "$LI" >/dev/null 2>"$T/err" || fail "cosim map: $(cat "$T/err")"
for N in 2 3; do
    files=""
    I=1
    while [ $I -le $N ]; do
        "$RS" --shard $I/$N --csv "$T/li$I-$N.csv" --analyse "$LIMAP" "$LI" >/dev/null 2>"$T/err" \
            || fail "cosim map --shard $I/$N: $(cat "$T/err")"
        files="$files $T/li$I-$N.csv"
        I=$((I + 1))
    done
    # shellcheck disable=SC2086
    merge $files >"$T/limerged-$N.csv"
    n1=$(grep -vc '^#\|^index' "$T/li1-$N.csv")
    if [ "$n1" -lt 15 ] && cmp -s "$T/limerged-$N.csv" "$T/lifull.csv"; then ok "cosim map --shard x/$N: shards of $n1.. rows merge into the full map"
    else fail "cosim map --shard x/$N: $n1 rows in shard 1, merge differs: $(diff "$T/limerged-$N.csv" "$T/lifull.csv" | head -3)"; fi
done
# the points run in parallel (OpenMP, each thread its own scratch): 1, 2
# and 3 threads write the same CSV byte for byte (rows in index order),
# over a grid with stable and unstable points of the explicit k = 1 scheme
for TH in 1 2 3; do
    "$RS" --threads $TH --csv "$T/lith$TH.csv" --analyse "map acc1 0 3 9, c1 1/2 2 7" "$LI" >/dev/null 2>"$T/err" \
        || fail "cosim map --threads $TH: $(cat "$T/err")"
done
if cmp -s "$T/lith1.csv" "$T/lith2.csv" && cmp -s "$T/lith1.csv" "$T/lith3.csv" \
    && grep -q ',stable,0,' "$T/lith1.csv" && grep -q ',unstable,2,' "$T/lith1.csv"; then
    ok "cosim map: --threads 1, 2, 3 write the same CSV (stable and unstable points)"
else fail "cosim map threads: $(diff "$T/lith1.csv" "$T/lith2.csv" | head -3)"; fi
# `of stability` takes the fast Stein verdict (no eigenvalues, no radius
# cells): on a 15 x 15 grid across the stability boundary every verdict
# equals the one the certified radius gives (the `of radius` map)
"$RS" --csv "$T/lir.csv" --analyse "map acc1 0 3 15, c1 1/2 2 15" "$LI" >/dev/null 2>"$T/err" || fail "cosim map: $(cat "$T/err")"
"$RS" --csv "$T/lis.csv" --analyse "map acc1 0 3 15, c1 1/2 2 15 of stability" "$LI" >/dev/null 2>"$T/err" \
    || fail "cosim map of stability: $(cat "$T/err")"
cut -d, -f1-9 "$T/lir.csv" | sed 1d >"$T/lir.codes"
cut -d, -f1-9 "$T/lis.csv" | sed 1d >"$T/lis.codes"
if cmp -s "$T/lir.codes" "$T/lis.codes" && grep -q ',stable,0,,,,certified' "$T/lis.csv" \
    && grep -q ',unstable,2,,,,certified' "$T/lis.csv"; then
    ok "cosim map of stability: fast Stein verdicts = certified-radius verdicts at all 225 points"
else fail "cosim map of stability differs: $(diff "$T/lir.codes" "$T/lis.codes" | head -3)"; fi
"$RS" --json --shard 2/3 --analyse "$LIMAP" "$LI" >"$T/lis.json" 2>"$T/err"
if grep -q '"shard": "2/3"' "$T/lis.json" && grep -q '"computed": 5' "$T/lis.json"; then ok "cosim map JSON: shard 2/3 computed 5 of 15 points"
else fail "cosim map JSON shard keys: $(grep -E 'shard|computed' "$T/lis.json")"; fi
"$RS" --csv "$T/lilim.csv" --max-points 14 --analyse "$LIMAP" "$LI" >"$T/out" 2>"$T/err"; rc=$?
check_exit "cosim map --max-points 14 (15 points) exit" 2 "$rc"
if grep -q 'the map (5 x 3) has 15 points, more than the limit of 14 points' "$T/err" && [ ! -s "$T/out" ] && [ ! -e "$T/lilim.csv" ]; then
    ok "cosim map: --max-points refused with its message, nothing written"; else fail "cosim map limit: $(cat "$T/err")"; fi
# acc1 = adc1 = d1 = 0 uncouples two undamped oscillators (frequencies
# sqrt(c1), sqrt(2 c1) with ac21 = 2): exp(A H) has every eigenvalue exactly on
# the unit circle, so the certified radius interval contains 1 -> undecided;
# acc1 = 1 is unstable (the single-point radius analysis agrees, above)
DD=cases/li-dd-explicit-k0.case
"$RS" --csv "$T/und.csv" --set d1=0 --set ac21=2 --analyse "map acc1 0 1 2, adc1 0 0 1" "$DD" >/dev/null 2>"$T/err"
codes=$(grep -v '^#\|^index' "$T/und.csv" | cut -d, -f8,9 | tr '\n' ' ')
if [ "$codes" = "undecided,4 unstable,2 " ]; then ok "cosim map codes: undecided 4, unstable 2"; else fail "cosim map codes: '$codes' $(cat "$T/err")"; fi
"$RS" --set d1=0 --set ac21=2 --set acc1=0 --set adc1=0 --analyse radius "$DD" 2>&1 | grep -q 'verdict *undecided' \
    && ok "the single point agrees: undecided" || fail "single point at the undecided map point"

# exact-integration sweep: with the coupling off (acc1 = adc1 = 0) the two
# subsystems are the damped oscillators x'' = -c1 x - d1 x' and
# x'' = -ac21 c1 x - d1 x', whose exact one-step maps have eigenvalues
# exp((-d1/2 +- i sqrt(c c1 - d1^2/4)) H), c = 1, ac21, H = 1.  So the radius
# is exp(-d1/2) by hand (c1 = 101/100 > d1^2/4 for d1 <= 2), checked against
# awk's exp(): inside the certified interval at every d1 of the sweep;
# d1 = 0 lies exactly on the circle: undecided (4), the rest stable.  With
# ac21 = 1 the eigenvalues are double (equal subsystems) and cannot be
# isolated: the enclosure certified so far still decides (not "undefined")
for AC in 2 1; do
    "$RS" --csv "$T/lisw.csv" --set acc1=0 --set adc1=0 --set ac21=$AC --analyse "sweep d1 from 0 to 2 steps 4" "$LI" \
        >/dev/null 2>"$T/err"; rc=$?
    check_exit "cosim sweep ac21=$AC exit" 0 "$rc"
    grep -v '^#\|^index' "$T/lisw.csv" | while IFS=, read -r idx x xe rad lo hi verdict code by; do
        if awk -v x="$x" -v l="$lo" -v h="$hi" 'BEGIN { r = exp(-x / 2); exit !(r >= l * (1 - 1e-15) && r <= h * (1 + 1e-15)) }' \
            && { { [ "$idx" = 0 ] && [ "$code" = 4 ]; } || { [ "$idx" != 0 ] && [ "$code" = 0 ]; }; } && [ "$by" = certified ]; then :
        else echo "row $idx: d1 = $x [$lo, $hi] $verdict $code $by"; fi
    done >"$T/lisw.diff"
    rows=$(grep -vc '^#\|^index' "$T/lisw.csv")
    if [ "$rows" = 5 ] && [ ! -s "$T/lisw.diff" ]; then ok "cosim sweep d1, ac21 = $AC: radius exp(-d1/2) in every certified interval, d1 = 0 undecided"
    else fail "cosim sweep d1, ac21 = $AC ($rows rows): $(cat "$T/lisw.diff" "$T/err")"; fi
done
# coupled (acc1 from 0 to 3): every point is the single-point radius analysis
# at that acc1 (inside the row's interval, same verdict), shards merge into
# the full CSV, `of stability` has the verdicts and no exact counts
SW="sweep acc1 from 0 to 3 steps 6"
"$RS" --csv "$T/lisw2.csv" --analyse "$SW" "$LI" >/dev/null 2>"$T/err" || fail "cosim sweep: $(cat "$T/err")"
grep -v '^#\|^index' "$T/lisw2.csv" | while IFS=, read -r idx x xe rad lo hi verdict code by; do
    "$RS" --json --set "acc1=$xe" --analyse radius "$LI" >"$T/pt.json" 2>>"$T/err"
    rho=$(sed -n 's/.*"rho": "\(.*\)".*/\1/p' "$T/pt.json" | head -1)
    st=$(sed -n 's/.*"status": "\(.*\)".*/\1/p' "$T/pt.json" | head -1)
    if awk -v r="$rho" -v l="$lo" -v h="$hi" 'BEGIN { exit !(r + 0 >= l * (1 - 1e-15) && r + 0 <= h * (1 + 1e-15)) }' \
        && [ "$st" = "$verdict" ]; then :; else echo "row $idx: sweep $verdict [$lo, $hi], point $st $rho"; fi
done >"$T/lisw2.diff"
if [ ! -s "$T/lisw2.diff" ] && grep -q ',stable,0,' "$T/lisw2.csv" && grep -q ',unstable,2,' "$T/lisw2.csv"; then
    ok "cosim sweep acc1: every point agrees with the single-point radius (stable and unstable)"
else fail "cosim sweep acc1: $(cat "$T/lisw2.diff")"; fi
"$RS" --shard 1/2 --csv "$T/lisw-1.csv" --analyse "$SW" "$LI" >/dev/null 2>&1
"$RS" --shard 2/2 --csv "$T/lisw-2.csv" --analyse "$SW" "$LI" >/dev/null 2>&1
merge "$T/lisw-1.csv" "$T/lisw-2.csv" >"$T/lisw-m.csv"
if [ "$(grep -vc '^#\|^index' "$T/lisw-1.csv")" -lt 7 ] && cmp -s "$T/lisw-m.csv" "$T/lisw2.csv"; then ok "cosim sweep --shard 1/2, 2/2 merge into the full sweep"
else fail "cosim sweep shards: $(diff "$T/lisw-m.csv" "$T/lisw2.csv" | head -3)"; fi
"$RS" --csv "$T/lisw3.csv" --analyse "$SW of stability" "$LI" >/dev/null 2>"$T/err"
got=$(grep -v '^#\|^index' "$T/lisw3.csv" | cut -d, -f4-9 | sort | uniq -c | tr -s ' ' | tr '\n' ';')
exp=$(grep -v '^#\|^index' "$T/lisw2.csv" | awk -F, '{print $7 "," $8 ",,,," $9}' | sort | uniq -c | tr -s ' ' | tr '\n' ';')
if [ -n "$got" ] && [ "$got" = "$exp" ]; then ok "cosim sweep of stability: the radius sweep's verdicts, counts empty"
else fail "cosim sweep of stability: '$got' vs '$exp'"; fi
# sweep of modes: Li's symmetric in-phase mode (see the modes check below) is
# lambda_c = -1/10 +- i at every acc1: reference=1 picks it in every row with
# damping ratio 0.1/sqrt(1.01), frequency error sqrt(1.01) - 1, omega 1 (awk);
# the verdict columns are those of the radius sweep and the radius intervals
# meet (the radius sweep takes the interval-double route, the modes sweep Arb)
"$RS" --csv "$T/lisw4.csv" --analyse "$SW of modes reference=1" "$LI" >"$T/out" 2>"$T/err"; rc=$?
check_exit "cosim sweep of modes exit" 0 "$rc"
if [ "$(grep -vc '^#\|^index' "$T/lisw4.csv")" = 7 ] && grep -v '^#\|^index' "$T/lisw4.csv" | awk -F, '
    function ok(a, b) { return (a - b < 1e-12 && b - a < 1e-12) }
    { if (!(ok($10, 0.1 / sqrt(1.01)) && ok($11, sqrt(1.01) - 1) && ok($12, 1))) bad = 1 } END { exit bad }' \
    && [ "$(grep -v '^#\|^index' "$T/lisw4.csv" | cut -d, -f1-3,7-9)" = "$(grep -v '^#\|^index' "$T/lisw2.csv" | cut -d, -f1-3,7-9)" ] \
    && paste -d, "$T/lisw4.csv" "$T/lisw2.csv" | grep -v '^#\|^index' | awk -F, -v n=12 '
        { if (!($5 <= $(n + 6) && $(n + 5) <= $6)) bad = 1 } END { exit bad }'
then ok "cosim sweep of modes: the in-phase mode in every row, the radius sweep's verdicts, radius intervals meet"
else fail "cosim sweep of modes: $(head -3 "$T/lisw4.csv") $(cat "$T/err")"; fi
"$RS" --analyse "$SW of modes" "$LI" >"$T/out" 2>"$T/err"; rc=$?
check_exit "cosim sweep of modes without reference exit" 2 "$rc"

# modes of an exactly integrated co-simulation: in Li's symmetric model the
# in-phase motion x1 = x2, v1 = v2 never loads the coupling (lc = 0 at every
# macro step, extrapolated or not), so it is the uncoupled oscillator's mode
# by hand: lambda_c = -d1/2 +- i sqrt(c1 - d1^2/4) = -1/10 +- i at c1 = 101/100,
# d1 = 1/5; damping ratio 0.1/sqrt(1.01), frequency error sqrt(1.01) - 1 for
# reference=1 (awk), h = the macro step H = 1 by default
"$RS" --json --analyse "modes reference=1" "$LI" >"$T/limodes.json" 2>"$T/err"; rc=$?
check_exit "cosim modes exit" 0 "$rc"
tr -d ' \n' <"$T/limodes.json" | sed 's/.*"modes":\[\(.*\)\],"spurious".*/\1/' | tr '}' '\n' \
    | sed -n 's/.*"sigma":"\([^"]*\)","omega":"\([^"]*\)","damping_ratio":"\([^"]*\)","reference":"1","frequency_error":"\([^"]*\)".*/\1 \2 \3 \4/p' >"$T/limodes.txt"
if [ "$(wc -l <"$T/limodes.txt")" = 2 ] && awk 'function ok(a, b) { return (a - b < 1e-14 && b - a < 1e-14) }
    { if (!(ok($1, -0.1) && ok($2 * $2, 1) && ok($3, 0.1 / sqrt(1.01)) && ok($4, sqrt(1.01) - 1))) bad = 1 }
    END { exit bad }' "$T/limodes.txt" && grep -q '"h": "1"' "$T/limodes.json"; then
    ok "cosim modes: the in-phase mode -1/10 +- i, damping 0.1/sqrt(1.01), frequency error sqrt(1.01) - 1"
else fail "cosim modes: $(cat "$T/limodes.txt" "$T/err")"; fi
"$RS" --analyse "modes h=0" "$LI" >"$T/out" 2>"$T/err"; rc=$?
check_exit "cosim modes h=0 exit" 2 "$rc"
grep -q "expected a time step h > 0, found '0'" "$T/err" && [ ! -s "$T/out" ] && ok "cosim modes h=0: refused" || fail "cosim modes h=0: $(cat "$T/err")"

# MPI: same CSV with 2 and 3 ranks (make mpi builds $BUILD/recstab-mpi)
if command -v mpirun >/dev/null 2>&1 && [ -x "$BUILD/recstab-mpi" ]; then
    MPIOPT="--oversubscribe"
    [ "$(id -u)" = 0 ] && MPIOPT="$MPIOPT --allow-run-as-root"
    for K in 2 3; do
        # shellcheck disable=SC2086
        OMP_NUM_THREADS=1 mpirun $MPIOPT -n $K "$BUILD/recstab-mpi" --csv "$T/mpi$K.csv" --set muh=1 --set wh=1 \
            --analyse "$MAP" --analyse "sweep alpha from 0 to 3 steps 17" --set m=10 "$PARK" >"$T/mpi.out" 2>"$T/mpi.err"; rc=$?
        check_exit "mpirun -n $K exit" 0 "$rc"
        if cmp -s "$T/mpi$K.csv" "$T/full.csv"; then ok "mpirun -n $K: CSV identical to one process"; else fail "mpirun -n $K CSV differs"; fi
        n=$(grep -c '^map$' "$T/mpi.out")
        if [ "$n" = 1 ]; then ok "mpirun -n $K: one report (rank 0)"; else fail "mpirun -n $K: $n reports"; fi
    done
else
    echo "skip MPI (needs mpirun and $BUILD/recstab-mpi: make mpi)"
fi

# The text table never cuts a cell: the outward-rounded bounds of the CSV
# appear whole in the text report (sqrt(1/2) = 0.70710678118654752...: a
# bound cut to 0.707106781186547 would lie below the true radius).
cat >"$T/half.case" <<'EOS'
param h
char lambda^2 - h/2
analyse sweep h from 1 to 2 steps 2 of radius
EOS
"$RS" "$T/half.case" >"$T/half.txt" 2>"$T/err"; rc=$?
check_exit "text table of a sweep exit" 0 "$rc"
"$RS" --csv "$T/half.csv" "$T/half.case" >/dev/null 2>&1
lo=$(awk -F, '$1 == "0" {print $5}' "$T/half.csv"); hi=$(awk -F, '$1 == "0" {print $6}' "$T/half.csv")
if [ -n "$lo" ] && [ -n "$hi" ] && grep -q -- " $lo  *$hi " "$T/half.txt" \
   && awk -v l="$lo" -v h="$hi" 'BEGIN { exit !(l + 0 < 0.7071067811865475 && h + 0 > 0.7071067811865476) }'; then
    ok "text table: the radius bounds whole, as in the CSV ($lo, $hi)"
else fail "text table: bounds '$lo' '$hi' not whole in: $(grep '^    0 ' "$T/half.txt")"; fi

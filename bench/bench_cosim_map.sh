#!/bin/sh
# bench_cosim_map.sh -- the exactly integrated co-simulation map (issue 14
# part 3) side by side with its peers, in one run on the same machine:
#   before   a recstab binary built from an earlier commit (BEFORE=path;
#            skipped when unset; the issue's "original": main at af08382),
#            the same map and threads
#   prev     optionally a second earlier binary (PREV=path, e.g. the Arb
#            fast radius of d8e8f74)
#   after    this tree's build/recstab (of radius, and of stability: the fast Stein verdicts)
#   poly     a polynomial map of the same size (cases/park-staggered.case,
#            degree 4, the certified ladder)
# and checks that before and after give the same verdicts, codes and
# decided_by at every point, and that their radius intervals meet (the fast
# certified radius of maps of radius, src/numeric/cosim_fast.c, prints
# other bounds than the full route (~1e-14 wide), so the cells' last digits differ).
#   usage: BEFORE=/path/recstab sh bench/bench_cosim_map.sh [N] [THREADS]   (default 400, 2)
BUILD=${BUILD:-build}
RS="$BUILD/recstab"
N=${1:-400}
TH=${2:-2}
LI=cases/li-explicit-k1.case
[ -x "$RS" ] || { echo "bench_cosim_map: build $RS first (make all)" >&2; exit 2; }
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

field() { # json-file key -> value of the first "key": number
    sed -n "s/^ *\"$2\": \([0-9.e+-]*\),*$/\1/p" "$1" | head -1
}

# label binary csv case spec [options...]: one line, points/s over the points' time,
# CPU seconds (user + sys of the whole process) and CPU us per point
run() {
    label=$1; bin=$2; csv=$3; case=$4; spec=$5; shift 5
    /usr/bin/env time -f '%e %U %S' -o "$T/time" "$bin" --json --threads "$TH" --max-points 1000000 --csv "$csv" "$@" \
        --analyse "$spec" "$case" >"$T/o.json" 2>"$T/err" || { echo "bench_cosim_map: $label failed: $(cat "$T/err")" >&2; return 1; }
    pts=$(field "$T/o.json" points)
    sp=$(field "$T/o.json" seconds_points)
    set -- $(cat "$T/time")
    cpu=$(echo "$2 + $3" | bc)
    printf '%-16s %7s pts %9.3f s points %8.2f s wall %8.2f s cpu %8.1f us/point cpu %9.0f pts/s\n' "$label" "$pts" "$sp" "$1" \
        "$cpu" "$(echo "$cpu * 1000000 / $pts" | bc -l)" "$(echo "$pts / $sp" | bc -l)"
    echo "$pts / $sp" | bc -l >"$T/rate-$label"
    echo "$cpu * 1000000 / $pts" | bc -l >"$T/us-$label"
}

echo "bench_cosim_map: $N x $N maps, $TH threads ($(nproc) cores; load $(cut -d' ' -f1-3 /proc/loadavg))"
LIMAP="map acc1 0 3 $N, c1 1/2 2 $N"
if [ -n "${BEFORE:-}" ]; then run before "$BEFORE" "$T/before.csv" "$LI" "$LIMAP"; fi
if [ -n "${PREV:-}" ]; then run prev "$PREV" "$T/prev.csv" "$LI" "$LIMAP"; fi
run after "$RS" "$T/after.csv" "$LI" "$LIMAP"
# `of stability`: the fast Stein verdict (no radius cells), every 64th point cross-checked
run after-stability "$RS" "$T/after-stab.csv" "$LI" "$LIMAP of stability"
run poly "$RS" "$T/poly.csv" cases/park-staggered.case "map alpha 0 3 $N, m 1/10 20 $N" --set muh=1 --set wh=1
if [ -n "${BEFORE:-}" ]; then
    # columns index,i,j,acc1,c1,acc1_exact,c1_exact,verdict,code (1-9) and
    # decided_by (13) equal; radius_lower,radius_upper (11, 12) intervals meet
    # (compared as doubles: the cells are 17 digits rounded outward)
    if cmp -s "$T/before.csv" "$T/after.csv"; then echo "CSV before == after (byte for byte)"
    elif [ "$(cut -d, -f1-9,13 "$T/before.csv" | md5sum)" = "$(cut -d, -f1-9,13 "$T/after.csv" | md5sum)" ]; then
        bad=$(paste -d, "$T/before.csv" "$T/after.csv" | awk -F, 'NR > 2 && $11 != "" && $24 != "" && ($24 + 0 > $12 + 0 || $11 + 0 > $25 + 0) { n++ } END { print n + 0 }')
        echo "CSV before/after: same verdicts, codes, decided_by at every point; radius intervals that do not meet: $bad"
    else echo "CSV VERDICTS DIFFER: $(diff "$T/before.csv" "$T/after.csv" | head -3)"; fi
    printf 'after/before speed-up %.2fx (points/s), %.2fx (CPU us/point)\n' "$(echo "$(cat "$T/rate-after") / $(cat "$T/rate-before")" | bc -l)" \
        "$(echo "$(cat "$T/us-before") / $(cat "$T/us-after")" | bc -l)"
fi
if [ -n "${PREV:-}" ]; then
    if [ "$(cut -d, -f1-9,13 "$T/prev.csv" | md5sum)" = "$(cut -d, -f1-9,13 "$T/after.csv" | md5sum)" ]; then
        echo "CSV prev/after: same verdicts, codes, decided_by at every point"
    else echo "CSV PREV/AFTER VERDICTS DIFFER: $(diff "$T/prev.csv" "$T/after.csv" | head -3)"; fi
    printf 'after/prev speed-up %.2fx (CPU us/point)\n' "$(echo "$(cat "$T/us-prev") / $(cat "$T/us-after")" | bc -l)"
fi
printf 'poly/after (polynomial map rate over the co-simulation map rate) %.1fx; CPU us/point after/poly %.1fx\n' \
    "$(echo "$(cat "$T/rate-poly") / $(cat "$T/rate-after")" | bc -l)" "$(echo "$(cat "$T/us-after") / $(cat "$T/us-poly")" | bc -l)"
printf 'poly/after-stability %.1fx; after-stability/after %.2fx\n' \
    "$(echo "$(cat "$T/rate-poly") / $(cat "$T/rate-after-stability")" | bc -l)" \
    "$(echo "$(cat "$T/rate-after-stability") / $(cat "$T/rate-after")" | bc -l)"

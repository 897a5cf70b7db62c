#!/bin/sh
# bench_map.sh -- a certified 400 x 400 stability map of a degree-8 family
# (bench/degree8.case: two BDF2 oscillators, staggered with a predictor) and
# of the Park case (degree 4): points per second at each level of the
# verdict ladder (the ladder started at that level with --sweep-level), the
# whole certified map, the uncertified double-only map (the cost of
# certification), and the exact boundary overlay.
#   usage: sh bench/bench_map.sh [N] [THREADS]     (default 400, 2)
BUILD=${BUILD:-build}
RS="$BUILD/recstab"
N=${1:-400}
TH=${2:-2}
[ -x "$RS" ] || { echo "bench_map: build $RS first (make all)" >&2; exit 2; }
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

field() { # json-file key -> value of the first "key": number
    sed -n "s/^ *\"$2\": \([0-9.e+-]*\),*$/\1/p" "$1" | head -1
}

run() { # label level case map-spec [set...]
    label=$1; level=$2; case=$3; spec=$4; shift 4
    "$RS" --json --threads "$TH" --sweep-level "$level" --csv "$T/m.csv" "$@" --analyse "$spec" "$case" >"$T/o.json" 2>"$T/err" \
        || { echo "bench_map: $label failed: $(cat "$T/err")" >&2; return 1; }
    pts=$(field "$T/o.json" points)
    sp=$(field "$T/o.json" seconds_points)
    st=$(field "$T/o.json" seconds)
    dec=$(tr -d ' \n' <"$T/o.json" | sed -n 's/.*"decided_by":{\([^}]*\)}.*/\1/p')
    rate=$(awk -v p="$pts" -v s="$sp" 'BEGIN { if (s > 0) printf "%.0f", p / s; else print "inf" }')
    printf '%-34s %8s pts  %8.3f s points  %8.3f s total  %9s pts/s  %s\n' "$label" "$pts" "$sp" "$st" "$rate" "$dec"
}

echo "bench_map: $N x $N maps, $TH threads ($(nproc) cores; load $(cut -d' ' -f1-3 /proc/loadavg))"
for c in "degree 8:bench/degree8.case:map w 1/100 3 $N, alpha 0 3 $N" \
         "Park (deg 4):cases/park-staggered.case:map alpha 0 3 $N, m 1/10 20 $N"; do
    name=${c%%:*}; rest=${c#*:}; case=${rest%%:*}; spec=${rest#*:}
    set -- 
    [ "$case" = cases/park-staggered.case ] && set -- --set muh=1 --set wh=1
    run "$name: double only (uncertified)" double "$case" "$spec" "$@"
    run "$name: certified (ladder from fast)" fast "$case" "$spec" "$@"
    run "$name: ladder from prec128" prec128 "$case" "$spec" "$@"
    run "$name: ladder from prec256" prec256 "$case" "$spec" "$@"
done
# the exact level alone is slow: a smaller grid gives its rate
M=$((N / 4))
run "degree 8: exact only (${M}x${M})" exact bench/degree8.case "map w 1/100 3 $M, alpha 0 3 $M"
run "Park: exact only (${M}x${M})" exact cases/park-staggered.case "map alpha 0 3 $M, m 1/10 20 $M" --set muh=1 --set wh=1
# the Schur triangle of lambda^2 - a lambda + b: grid points exactly on its
# edges (roots on the unit circle) need the exact level
printf 'title Schur triangle\nparam a b\nchar lambda^2 - a*lambda + b\n' >"$T/tri.case"
run "triangle (edges exact)" fast "$T/tri.case" "map a -3 3 $((N + 1)), b -2 2 $((N + 1))"

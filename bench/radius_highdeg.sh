#!/bin/sh
# radius_highdeg.sh -- whole-process time of a certified radius at high degree.
#   sh bench/radius_highdeg.sh [BIN] [DEGREES] [DIGITS]
# For each degree d it writes bench/results/highdeg-d.case: `char` with
# coefficients c_0..c_d drawn from [-100, 100] (awk srand(d), c_d != 0, so
# the same polynomial every run; the committed files were drawn by mawk 1.3.4,
# and an existing file is never redrawn, since gawk draws others), then times
#   BIN --analyse 'radius digits=D' CASE
# once (wall seconds from GNU date) and prints degree, digits, seconds, exit.
bin=${1:-build/recstab}
degs=${2:-"12 50 100 200 500"}
digs=${3:-"30 128"}
dir=bench/results
mkdir -p "$dir"
printf 'degree digits seconds exit\n'
for d in $degs; do
    f=$dir/highdeg-$d.case
    [ -f "$f" ] || awk -v d="$d" 'BEGIN { srand(d); s = "";
        for (i = 0; i <= d; i++) { c = int(rand() * 201) - 100;
            if (i == d && c == 0) c = 1;
            s = s (i ? " + (" : "") c (i ? ")*lambda^" i : "") }
        print "title random degree " d; print "char " s }' > "$f"
    for D in $digs; do
        t0=$(date +%s%N)
        "$bin" --analyse "radius digits=$D" "$f" > /dev/null 2>&1
        rc=$?
        t1=$(date +%s%N)
        awk -v d="$d" -v D="$D" -v a="$t0" -v b="$t1" -v rc="$rc" \
            'BEGIN { printf "%d %d %.3f %d\n", d, D, (b - a) / 1e9, rc }'
    done
done

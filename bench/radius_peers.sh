#!/bin/sh
# radius_peers.sh -- certified radius at high degree, recstab beside PARI/GP
# polroots and MPSolve, each a whole process, one thread, in one run.
#   sh bench/radius_peers.sh [BIN] [POLYS] [DIGITS]
# POLYS: names understood by bench/radius_peers_gen.py (default: random,
# clustered and 2x^N - 1 at degree 12, 50, 100, 200, 500; Wilkinson-type at
# 12, 20, 40, 50, 100, 200, 300, 500 (since the 1 MiB statement limit);
# MPSolve reads NAME.pol, its own file format: its -p EXPR mostly parsed
# (2.3 s against 0.7 s at Wilkinson-type 200, bench/README.md "seventh
# step") and from degree ~300 exceeded the 128 KiB argument limit);
# DIGITS default "30 128".  Commands timed:
#   BIN --analyse 'radius digits=D' NAME.case
#   STATIC_BIN (the same; default build/recstab-static when it exists, `make
#   static`: GSL, CBLAS and jansson linked in, FLINT/Arb/GMP shared) -- the
#   start-up share of the small rows
#   gp -q -f -D parisizemax=2G  (realprecision D; polroots; max |root|)
#   mpsolve -j1 -Ga -o D NAME.pol         (guaranteed inclusions; the issue's command)
# Each once, `/usr/bin/time -f '%e %U %S'`: wall s and CPU (user + system)
# s (under 0.3 s CPU: the mean of PEER_REPS more runs, see run());
# PEER_TIMEOUT seconds of CPU each (ulimit -t, default 120; "limit"), and
# ten times that of wall time.  The ratios are of CPU time: on a shared
# machine the wall time measures the other jobs.  A peer
# that is not installed (Debian pari-gp, mpsolve; `make bench` installs
# them) prints "-".  The last columns are recstab / peer CPU ratios (the
# issue's table; below 1: recstab faster), then rho from each tool (first
# 12 digits) so that a wrong answer shows.  Work files: build/radius-peers/.
bin=${1:-build/recstab}
polys=${2:-"random-12 random-50 random-100 random-200 random-500 cluster-12 cluster-50 cluster-100 cluster-200 cluster-500 wilkinson-12 wilkinson-20 wilkinson-40 wilkinson-50 wilkinson-100 wilkinson-200 wilkinson-300 wilkinson-500 pow-12 pow-50 pow-100 pow-200 pow-500"}
digs=${3:-"30 128"}
tmo=${PEER_TIMEOUT:-120}
dir=${PEERS_DIR:-build/radius-peers}
here=$(dirname "$0")
sbin=${STATIC_BIN:-$(dirname "$bin")/recstab-static}
[ -x "$sbin" ] || sbin="" 
mkdir -p "$dir"
python3 "$here/radius_peers_gen.py" "$dir" $polys || exit 1
# PEERS: which peers run (default "gp mpsolve"; "" times recstab alone,
# e.g. to re-measure recstab on rows whose peer times are already known)
peers=" ${PEERS-gp mpsolve} "
have_gp=0; case $peers in *" gp "*) command -v gp > /dev/null 2>&1 && have_gp=1 ;; esac
have_mps=0; case $peers in *" mpsolve "*) command -v mpsolve > /dev/null 2>&1 && have_mps=1 ;; esac

# run OUT CMD...: prints "wall cpu" (or "limit").  A command under 0.3 s
# CPU is run again PEER_REPS times (default 10) in one timed shell loop and
# the mean is printed: /usr/bin/time resolves 0.01 s, the size of the
# small rows themselves.
reps=${PEER_REPS:-10}
run() {
    out=$1; shift
    : > "$dir/time"
    ( ulimit -t "$tmo"; timeout $((10 * tmo)) /usr/bin/time -o "$dir/time" -f '%e %U %S' "$@" > "$out" 2> "$dir/err" )
    rc=$?
    if [ $rc -eq 124 ] || [ $rc -ge 128 ] || grep -q signal "$dir/time"; then echo limit; return; fi
    if [ "$reps" -gt 1 ] && awk '{ exit !($2 + $3 < 0.3) }' "$dir/time"; then
        ( ulimit -t "$tmo"; /usr/bin/time -o "$dir/time" -f '%e %U %S' sh -c \
            'n=$1; shift; i=0; while [ $i -lt $n ]; do "$@" > /dev/null 2>&1; i=$((i + 1)); done' \
            sh "$reps" "$@" )
        awk -v n="$reps" '{ printf "%.4f %.4f\n", $1 / n, ($2 + $3) / n }' "$dir/time" | tail -1
        return
    fi
    awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' "$dir/time" | tail -1
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 > 0 && b + 0 > 0) printf "%.2f", a / b; else printf "-" }'; }

printf '%-14s %6s | %-15s | %-15s | %-15s | %-15s | %8s %8s %8s %8s | %s\n' polynomial digits \
    "recstab wall/cpu" "static wall/cpu" "PARI wall/cpu" "MPSolve wall/cpu" "rs/PARI" "rs/MPS" "st/PARI" "st/MPS" \
    "rho: recstab PARI MPSolve"
for P in $polys; do
    for D in $digs; do
        r=$(run "$dir/rs.out" "$bin" --analyse "radius digits=$D" "$dir/$P.case")
        rrho=$(sed -n 's/^ *rho  *//p' "$dir/rs.out" | head -1 | cut -c1-14)
        s="-"
        if [ -n "$sbin" ]; then
            s=$(run "$dir/st.out" "$sbin" --analyse "radius digits=$D" "$dir/$P.case")
            cmp -s "$dir/rs.out" "$dir/st.out" || s="differs"
        fi
        g="-"; grho="-"
        if [ $have_gp = 1 ]; then
            printf 'default(realprecision,%s);p=%s;r=polroots(p);print(vecmax(abs(r)));\nquit\n' \
                "$D" "$(cat "$dir/$P.expr")" > "$dir/gp.in"
            g=$(run "$dir/gp.out" gp -q -f -D parisizemax=2000000000 "$dir/gp.in")
            grho=$(head -1 "$dir/gp.out" | cut -c1-14)
        fi
        m="-"; mrho="-"
        if [ $have_mps = 1 ]; then
            m=$(run "$dir/mps.out" mpsolve -j1 -Ga -o "$D" "$dir/$P.pol")
            mrho=$(python3 -c '
import sys, re
from decimal import Decimal, getcontext
getcontext().prec = 40
best = Decimal(0)
for line in open(sys.argv[1]):
    m = re.match(r"\s*\(\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*\)", line)
    if m:
        a, b = Decimal(m.group(1)), Decimal(m.group(2))
        best = max(best, (a * a + b * b).sqrt())
print(str(best)[:14])' "$dir/mps.out" 2> /dev/null)
        fi
        rc=$(echo "$r" | awk '{ print $2 }')
        sc=$(echo "$s" | awk '{ print $2 }')
        gc=$(echo "$g" | awk '{ print $2 }')
        mc=$(echo "$m" | awk '{ print $2 }')
        printf '%-14s %6s | %-15s | %-15s | %-15s | %-15s | %8s %8s %8s %8s | %s %s %s\n' "$P" "$D" \
            "$(echo "$r" | tr ' ' /)" "$(echo "$s" | tr ' ' /)" "$(echo "$g" | tr ' ' /)" "$(echo "$m" | tr ' ' /)" \
            "$(ratio "$rc" "$gc")" "$(ratio "$rc" "$mc")" "$(ratio "$sc" "$gc")" "$(ratio "$sc" "$mc")" \
            "$rrho" "$grho" "$mrho"
    done
done

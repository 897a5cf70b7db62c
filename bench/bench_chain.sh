#!/bin/sh
# bench_chain.sh -- `analyse hurwitz` on the N-mass trapezoidal chain of
# issue 17 (bench/make_chain_case.sh), one fresh process per N: wall
# seconds and peak resident MB from /usr/bin/time, or "timeout".
#
#   sh bench/bench_chain.sh [N ...]            # default: 2 3 4 5
# Environment: BIN (default build/recstab; e.g. an older build to compare),
# CHAIN_TIMEOUT (seconds per run, default 600).
set -u
cd "$(dirname "$0")/.." || exit 2
BIN=${BIN:-build/recstab}
LIMIT=${CHAIN_TIMEOUT:-600}
[ $# -gt 0 ] || set -- 2 3 4 5
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT INT TERM
printf '%-3s %10s %8s  %s\n' N seconds MB status
for n in "$@"; do
    sh bench/make_chain_case.sh "$n" "$tmp/chain$n.case"
    timeout "$LIMIT" /usr/bin/time -f '%e %M' -o "$tmp/time" \
        "$BIN" "$tmp/chain$n.case" > "$tmp/out" 2> "$tmp/err"
    rc=$?
    if [ "$rc" -eq 124 ]; then
        printf '%-3s %10s %8s  %s\n' "$n" ">$LIMIT" - timeout
    else
        read -r s kb < "$tmp/time"
        printf '%-3s %10s %8d  exit %d, %s\n' "$n" "$s" $((kb / 1024)) \
            "$rc" "$(grep -m1 '^  verdict' "$tmp/out" | sed 's/^  verdict *//')"
    fi
done

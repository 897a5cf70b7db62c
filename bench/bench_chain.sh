#!/bin/sh
# bench_chain.sh -- `analyse hurwitz` on the N-mass trapezoidal chain of
# issue 17 (bench/make_chain_case.sh), one fresh process per N: wall
# seconds, CPU seconds (user + system) and peak resident MB from
# /usr/bin/time, or "timeout".
#
#   sh bench/bench_chain.sh [N ...]            # default: 2 3 4 5
# Environment: BIN (default build/recstab; e.g. an older build to compare),
# CHAIN_TIMEOUT (seconds per run, default 600), SYMPY=1: also the SymPy peer
# (bench/bench_chain_sympy.py: det, bilinear, Hurwitz minors unfactored; its
# in-process CPU total against recstab's whole-process CPU, ratio = sympy / recstab;
# the minors compared with recstab's --json, untimed), SYMPY_TIMEOUT (600).
set -u
cd "$(dirname "$0")/.." || exit 2
BIN=${BIN:-build/recstab}
LIMIT=${CHAIN_TIMEOUT:-600}
[ $# -gt 0 ] || set -- 2 3 4 5
tmp=$(mktemp -d) || exit 2
trap 'rm -rf "$tmp"' EXIT INT TERM
SYMPY=${SYMPY:-0}
SLIMIT=${SYMPY_TIMEOUT:-600}
PY=${PYTHON:-python3}
printf '%-3s %10s %8s %8s  %s\n' N seconds cpu_s MB status
for n in "$@"; do
    sh bench/make_chain_case.sh "$n" "$tmp/chain$n.case"
    timeout "$LIMIT" /usr/bin/time -f '%e %M %U %S' -o "$tmp/time" \
        "$BIN" "$tmp/chain$n.case" > "$tmp/out" 2> "$tmp/err"
    rc=$?
    if [ "$rc" -eq 124 ]; then
        printf '%-3s %10s %8s %8s  %s\n' "$n" ">$LIMIT" - - timeout
    else
        read -r s kb us ss < "$tmp/time"
        cpu=$(awk -v u="$us" -v s="$ss" 'BEGIN { printf "%.2f", u + s }')
        printf '%-3s %10s %8s %8d  exit %d, %s\n' "$n" "$s" "$cpu" $((kb / 1024)) \
            "$rc" "$(grep -m1 '^  verdict' "$tmp/out" | sed 's/^  verdict *//')"
        if [ "$SYMPY" = 1 ]; then
            "$BIN" --json "$tmp/chain$n.case" > "$tmp/out.json" 2> /dev/null
            if timeout "$SLIMIT" "$PY" bench/bench_chain_sympy.py "$n" \
                   "$tmp/out.json" > "$tmp/sym" 2>&1; then
                read -r _ _ sd sb sm st < "$tmp/sym"
                printf '    sympy %s s (det %s, bilinear %s, minors %s), %s; ratio %s\n' \
                    "$st" "$sd" "$sb" "$sm" "$(tail -1 "$tmp/sym")" \
                    "$(awk -v a="$st" -v b="$cpu" 'BEGIN { if (b > 0) printf "%.0fx", a / b; else print "-" }')"
            elif [ $? -eq 124 ]; then
                printf '    sympy >%s s (timeout)\n' "$SLIMIT"
            else
                printf '    sympy failed: %s\n' "$(tail -1 "$tmp/sym")"
            fi
        fi
    fi
done

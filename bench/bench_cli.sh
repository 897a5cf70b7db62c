#!/bin/sh
# bench_cli.sh -- whole-process wall time of one command line.
#
# usage: bench/bench_cli.sh [-n N] [-w W] [--no-hyperfine] -- COMMAND ARGS...
#
# Runs COMMAND N times (default 200) after W warm-up runs (default 3), with
# stdout and stderr sent to /dev/null, and prints the median, 10th and 90th
# percentile of the wall time in milliseconds:
#
#   command:   build/recstab --analyse charpoly cases/park-staggered.case
#   timer:     hyperfine 1.15.0 (--shell=none)
#   runs:      200
#   exit:      0
#   median_ms: 2.911
#   p10_ms:    2.803
#   p90_ms:    3.120
#   cpu_ms:    2.650 (mean user+system per run)
#
# Timer: hyperfine when installed (Debian package hyperfine), started with
# --shell=none so no shell start-up is counted.  Without it (or with
# --no-hyperfine) a plain sh loop around GNU `date +%s%N`; the time between
# two `date` calls also contains one `date` start-up, so the loop measures
# that overhead first (N back-to-back pairs, median) and subtracts it; it is
# printed as overhead_ms.  With hyperfine, cpu_ms is the mean user+system
# CPU time per run (hyperfine's rusage), which other load on the machine
# disturbs less than wall time.  Percentiles are nearest-rank; the median of an
# even count is the mean of the two middle values.
#
# A command that exits non-zero is still timed (its status is printed as
# exit:) -- recstab exits 1 when an expectation fails, which is a result,
# not a benchmark error.
set -u

n=200
w=3
use_hf=1
usage() {
    echo "usage: $0 [-n N] [-w WARMUP] [--no-hyperfine] -- COMMAND ARGS..." >&2
    exit 2
}
while [ $# -gt 0 ]; do
    case $1 in
        -n) [ $# -ge 2 ] || usage; n=$2; shift 2 ;;
        -w) [ $# -ge 2 ] || usage; w=$2; shift 2 ;;
        --no-hyperfine) use_hf=0; shift ;;
        --) shift; break ;;
        -h|--help) usage ;;
        *) usage ;;
    esac
done
[ $# -ge 1 ] || usage
case $n in ''|*[!0-9]*) usage ;; esac
case $w in ''|*[!0-9]*) usage ;; esac
[ "$n" -ge 1 ] || usage

# One run first: the command must exist, and its exit status is reported.
"$@" >/dev/null 2>&1
status=$?
if [ $status -eq 126 ] || [ $status -eq 127 ]; then
    echo "$0: cannot run: $*" >&2
    exit 2
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/bench_cli.XXXXXX") || exit 2
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

# stats FILE (one value in ms per line) -> "median p10 p90"
stats() {
    sort -g "$1" | awk '
        { v[NR] = $1 }
        END {
            if (NR == 0) { print "nan nan nan"; exit }
            if (NR % 2) med = v[(NR + 1) / 2]
            else med = (v[NR / 2] + v[NR / 2 + 1]) / 2
            i = int(0.10 * NR); if (i < 0.10 * NR) i++; if (i < 1) i = 1
            j = int(0.90 * NR); if (j < 0.90 * NR) j++; if (j < 1) j = 1
            printf "%.3f %.3f %.3f\n", med, v[i], v[j]
        }'
}

# POSIX single-quoting of each argument, for hyperfine's own word splitting
quote_all() {
    out=""
    for a in "$@"; do
        q=$(printf '%s' "$a" | sed "s/'/'\\\\''/g")
        out="$out${out:+ }'$q'"
    done
    printf '%s' "$out"
}

overhead=""
cpu=""
if [ $use_hf -eq 1 ] && command -v hyperfine >/dev/null 2>&1; then
    timer="$(hyperfine --version 2>/dev/null) (--shell=none)"
    cmdline=$(quote_all "$@")
    if ! hyperfine --shell=none --ignore-failure --style none \
            --warmup "$w" --runs "$n" \
            --export-json "$tmp/hf.json" "$cmdline" >"$tmp/hf.out" 2>&1; then
        cat "$tmp/hf.out" >&2
        echo "$0: hyperfine failed" >&2
        exit 2
    fi
    # the "times" array of the JSON export, in seconds, one per line
    tr -d ' \n\t' <"$tmp/hf.json" |
        sed -n 's/.*"times":\[\([^]]*\)\].*/\1/p' | tr ',' '\n' |
        awk 'NF { printf "%.6f\n", $1 * 1000 }' >"$tmp/ms"
    # mean CPU time (user + system) per run: less sensitive to other load
    cpu=$(tr -d ' \n\t' <"$tmp/hf.json" | sed -n \
        's/.*"user":\([-0-9.eE+]*\),"system":\([-0-9.eE+]*\).*/\1 \2/p' |
        awk 'NF == 2 { printf "%.3f", ($1 + $2) * 1000 }')
else
    t=$(date +%s%N)
    case $t in
        *[!0-9]*|'') echo "$0: needs hyperfine or GNU date (+%N)" >&2; exit 2 ;;
    esac
    timer="sh loop, date +%s%N (overhead subtracted)"
    i=0
    while [ $i -lt "$n" ]; do
        t0=$(date +%s%N); t1=$(date +%s%N)
        echo $((t1 - t0)) >>"$tmp/ovh"
        i=$((i + 1))
    done
    overhead=$(awk '{ printf "%.6f\n", $1 / 1e6 }' "$tmp/ovh" >"$tmp/ovh_ms";
               stats "$tmp/ovh_ms" | cut -d' ' -f1)
    i=0
    while [ $i -lt "$w" ]; do "$@" >/dev/null 2>&1; i=$((i + 1)); done
    i=0
    while [ $i -lt "$n" ]; do
        t0=$(date +%s%N)
        "$@" >/dev/null 2>&1
        t1=$(date +%s%N)
        echo $((t1 - t0)) >>"$tmp/ns"
        i=$((i + 1))
    done
    awk -v o="$overhead" '{ x = $1 / 1e6 - o; if (x < 0) x = 0; printf "%.6f\n", x }' \
        "$tmp/ns" >"$tmp/ms"
fi

got=$(wc -l <"$tmp/ms" | tr -d ' ')
if [ "$got" -ne "$n" ]; then
    echo "$0: expected $n timings, got $got" >&2
    exit 2
fi
printf 'command:   %s\n' "$*"
printf 'timer:     %s\n' "$timer"
printf 'runs:      %s\n' "$n"
printf 'exit:      %s\n' "$status"
[ -n "$overhead" ] && printf 'overhead_ms: %s\n' "$overhead"
stats "$tmp/ms" | awk '{ printf "median_ms: %s\np10_ms:    %s\np90_ms:    %s\n", $1, $2, $3 }'
[ -n "$cpu" ] && printf 'cpu_ms:    %s (mean user+system per run)\n' "$cpu"
exit 0

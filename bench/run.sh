#!/bin/sh
# run.sh -- recstab's benchmarks, peers side by side (`make bench` runs this).
#
#   (0) whole-process time of  build/recstab --version  (the start-up floor:
#       exec, dynamic linking of FLINT/Arb/GSL/jansson, no case read)
#   (a) whole-process time of  build/recstab --analyse charpoly cases/park-staggered.case
#       (target: median under 5 ms)
#   (b) whole-process time of  build/recstab cases/park-staggered.case
#       (every analysis the case lists)
#   (c) build/recstab --analyse charpoly --analyse bilinear --analyse hurwitz
#       on the same case -- the work SymPy does in (d) -- when this build of
#       recstab knows those analyses (skipped otherwise)
#   (d) bench/sympy_park.py, the SymPy peer, SYMPY_RUNS fresh processes
#   (e) build/bench_radius (compiled from bench/bench_radius.c when present)
#   (f) in-process: build/park_inprocess (the one-call API, N calls, CPU per
#       call) beside bench/sympy_park.py --repeat SYMPY_REPEAT (default 5)
#   (g) build/recstab-static --version (make static: GSL, CBLAS, jansson static)
#   and a summary line: recstab median ms vs SymPy total seconds, ratio.
#
# Environment: BENCH_N (runs per command line, default 200), SYMPY_RUNS
# (default 3; the median total is used), BENCH_RADIUS=0 skips (e),
# BENCH_RADIUS_TIMEOUT (seconds, default 120, 0 = none) bounds (e),
# CC (default cc), PYTHON (default python3).
set -u
cd "$(dirname "$0")/.." || exit 2

N=${BENCH_N:-200}
SYMPY_RUNS=${SYMPY_RUNS:-3}
PY=${PYTHON:-python3}
CASE=cases/park-staggered.case
BIN=build/recstab

if [ ! -x "$BIN" ]; then
    echo "run.sh: $BIN not found; run 'make all' first" >&2
    exit 2
fi

# Benchmark a private copy: other people may rebuild build/recstab while
# this runs (a half-linked binary would fail or mix two versions).
snap=$(mktemp -d "${TMPDIR:-/tmp}/recstab_bench.XXXXXX") || exit 2
trap 'rm -rf "$snap"' EXIT
trap 'exit 130' INT TERM
cp "$BIN" "$snap/recstab" || exit 2
BIN=$snap/recstab
export RECSTAB="$BIN"   # sympy_park.py compares against the same binary

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if [ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ]; then
    commit="$commit (working tree has uncommitted changes)"
fi
echo "== recstab benchmarks"
echo "date:    $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "commit:  $commit"
echo "binary:  build/recstab, copied to $BIN"
echo "machine: $(uname -sm), $(getconf _NPROCESSORS_ONLN 2>/dev/null || echo '?') cores," \
     "load average $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')"
echo

median_of() { sed -n 's/^median_ms: *//p'; }
cpu_of() { sed -n 's/^cpu_ms: *\([^ ]*\).*/, cpu \1 ms/p'; }

echo "== (0) start-up floor: recstab --version"
out_0=$(sh bench/bench_cli.sh -n "$N" -- "$BIN" --version)
echo "$out_0"
med_0=$(echo "$out_0" | median_of)
cpu_0=$(echo "$out_0" | cpu_of)
echo

echo "== (a) charpoly only (target: median < 5 ms)"
out_a=$(sh bench/bench_cli.sh -n "$N" -- "$BIN" --analyse charpoly "$CASE")
echo "$out_a"
med_a=$(echo "$out_a" | median_of)
cpu_a=$(echo "$out_a" | cpu_of)
echo

echo "== (b) every analysis the case lists"
out_b=$(sh bench/bench_cli.sh -n "$N" -- "$BIN" "$CASE")
echo "$out_b"
med_b=$(echo "$out_b" | median_of)
cpu_b=$(echo "$out_b" | cpu_of)
echo

echo "== (c) charpoly + bilinear + hurwitz (what the SymPy peer computes)"
med_c=""; cpu_c=""
if "$BIN" --analyse charpoly --analyse bilinear --analyse hurwitz "$CASE" \
        >/dev/null 2>&1; then
    out_c=$(sh bench/bench_cli.sh -n "$N" -- "$BIN" --analyse charpoly \
            --analyse bilinear --analyse hurwitz "$CASE")
    echo "$out_c"
    med_c=$(echo "$out_c" | median_of)
cpu_c=$(echo "$out_c" | cpu_of)
else
    echo "skipped: this build of recstab does not run those analyses on $CASE"
fi
echo

echo "== (d) SymPy peer: bench/sympy_park.py ($SYMPY_RUNS fresh processes)"
sym_tot=""; sym_cp=""; sym_wall=""; sym_check=""
if ! command -v "$PY" >/dev/null 2>&1; then
    echo "skipped: $PY not found"
else
    i=1
    runs=$(mktemp "${TMPDIR:-/tmp}/sympy_runs.XXXXXX") || exit 2
    while [ "$i" -le "$SYMPY_RUNS" ]; do
        t0=$(date +%s%N)
        out_d=$("$PY" bench/sympy_park.py)
        rc=$?
        t1=$(date +%s%N)
        [ "$i" -eq 1 ] && echo "$out_d"
        tot=$(echo "$out_d" | sed -n 's/^sympy_total_s: *//p')
        cp=$(echo "$out_d" | sed -n 's/^sympy_charpoly_s: *//p')
        c=$(echo "$out_d" | sed -n 's/^check: *//p')
        # keep the most telling verdict over the runs: DISAGREE > agree > skipped
        case $sym_check:$c in
            DISAGREE*:*) ;;
            *:DISAGREE*|:*|skipped*:agree*) sym_check=$c ;;
        esac
        [ $rc -eq 0 ] || echo "sympy_park.py exited $rc"
        [ -n "$tot" ] || break
        echo "$tot $cp $(( (t1 - t0) / 1000000 ))" >>"$runs"
        i=$((i + 1))
    done
    if [ -s "$runs" ]; then
        # median of each column
        col_median() {
            cut -d' ' -f"$1" "$runs" | sort -g | awk '
                { v[NR] = $1 }
                END { if (NR % 2) print v[(NR + 1) / 2];
                      else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
        }
        sym_tot=$(col_median 1); sym_cp=$(col_median 2); sym_wall=$(col_median 3)
        echo
        echo "SymPy over $(wc -l <"$runs" | tr -d ' ') runs (median):" \
             "timed stages ${sym_tot} s, matrix+det ${sym_cp} s," \
             "whole process (with import) ${sym_wall} ms"
    fi
    rm -f "$runs"
fi
echo

echo "== (f) in-process: charpoly + bilinear + hurwitz through rs_analyse_json_with, beside SymPy's"
echo "   stages repeated in one Python process (issue 17: no exec, no dynamic loading, no import)"
ip_first=""; ip_med=""; sym_rep=""
if [ -x build/park_inprocess ]; then
    out_f=$(build/park_inprocess -n "$N" "$CASE")
    echo "$out_f"
    ip_first=$(echo "$out_f" | sed -n 's/^inprocess_first_cpu_ms: *//p')
    ip_med=$(echo "$out_f" | sed -n 's/^inprocess_median_cpu_ms: *//p')
else
    echo "skipped: no build/park_inprocess (make build/park_inprocess)"
fi
if command -v "$PY" >/dev/null 2>&1; then
    out_r=$("$PY" bench/sympy_park.py --repeat "${SYMPY_REPEAT:-5}" | grep '^sympy_')
    echo "$out_r"
    sym_first_cpu=$(echo "$out_r" | sed -n 's/^sympy_total_cpu_s: *//p')
    sym_rep=$(echo "$out_r" | sed -n 's/^sympy_repeat_median_cpu_s: *//p')
fi
echo

echo "== (g) start-up with GSL, CBLAS and jansson linked statically (make static)"
med_s=""; cpu_s=""
if [ -x build/recstab-static ]; then
    cp build/recstab-static "$snap/recstab-static" || exit 2
    out_s=$(sh bench/bench_cli.sh -n "$N" -- "$snap/recstab-static" --version)
    echo "$out_s"
    med_s=$(echo "$out_s" | median_of)
    cpu_s=$(echo "$out_s" | cpu_of)
else
    echo "skipped: no build/recstab-static (make static)"
fi
echo

echo "== (e) bench_radius"
if [ "${BENCH_RADIUS:-1}" = 0 ]; then
    echo "skipped (BENCH_RADIUS=0)"
else
    radius_ok=1
    if [ -f bench/bench_radius.c ]; then
        if ! ${CC:-cc} -std=c11 -D_POSIX_C_SOURCE=200809L -O2 -Iinclude \
                -I/usr/include/flint bench/bench_radius.c build/librecstab.a \
                -o build/bench_radius -lflint-arb -lflint -lgsl -lgslcblas \
                -ljansson -lmpfr -lgmp -lm; then
            echo "bench_radius.c did not compile; skipping it (not running a stale build/bench_radius)"
            radius_ok=0
        fi
    fi
    if [ $radius_ok -eq 1 ] && [ -x build/bench_radius ]; then
        rt=${BENCH_RADIUS_TIMEOUT:-120}
        if command -v timeout >/dev/null 2>&1 && [ "$rt" != 0 ]; then
            timeout "$rt" build/bench_radius
            rc=$?
            if [ $rc -eq 124 ]; then
                echo
                echo "build/bench_radius stopped after ${rt} s (BENCH_RADIUS_TIMEOUT=$rt; 0 = no limit)"
            elif [ $rc -ne 0 ]; then
                echo "build/bench_radius exited $rc"
            fi
        else
            build/bench_radius || echo "build/bench_radius exited $?"
        fi
    elif [ $radius_ok -eq 1 ]; then
        echo "skipped: no bench/bench_radius.c and no build/bench_radius"
    fi
fi
echo

echo "== summary (park-staggered, whole-process medians)"
ratio() { awk -v s="$1" -v r="$2" 'BEGIN { if (r > 0) printf "%.0f", s * 1000 / r; else print "?" }'; }
[ -n "$med_0" ] && echo "recstab --version (start-up):  ${med_0} ms${cpu_0}"
[ -n "$med_a" ] && echo "recstab charpoly only:        ${med_a} ms${cpu_a} (target < 5 ms:" \
    "$(awk -v m="$med_a" 'BEGIN { print (m < 5) ? "met" : "NOT met" }'))"
[ -n "$med_b" ] && echo "recstab case's analyses:      ${med_b} ms${cpu_b}"
[ -n "$med_c" ] && echo "recstab charpoly+bilinear+hurwitz: ${med_c} ms${cpu_c}"
if [ -n "$sym_tot" ]; then
    echo "SymPy charpoly (matrix+det):  ${sym_cp} s   -> recstab (a) is $(ratio "$sym_cp" "$med_a")x faster"
    if [ -n "$med_c" ]; then
        echo "SymPy total (det, bilinear, Hurwitz minors, factor): ${sym_tot} s" \
             "-> recstab (c) is $(ratio "$sym_tot" "$med_c")x faster"
    elif [ -n "$med_b" ]; then
        echo "SymPy total (det, bilinear, Hurwitz minors, factor): ${sym_tot} s" \
             "vs recstab (b) ${med_b} ms: ratio $(ratio "$sym_tot" "$med_b")x" \
             "(not the same work)"
    fi
    echo "SymPy process wall time incl. Python start-up and import: ${sym_wall} ms"
    echo "SymPy vs recstab p(lambda): ${sym_check}"
else
    echo "SymPy: skipped"
fi
[ -n "$med_s" ] && echo "recstab-static --version (start-up): ${med_s} ms${cpu_s}"
if [ -n "$ip_med" ] && [ -n "$sym_rep" ]; then
    echo "in-process, CPU per call: recstab ${ip_med} ms (first call ${ip_first} ms)," \
         "SymPy ${sym_rep} s (first run ${sym_first_cpu} s)" \
         "-> $(ratio "$sym_rep" "$ip_med")x (first calls: $(ratio "$sym_first_cpu" "$ip_first")x; goal >= 700x)"
fi
case $sym_check in DISAGREE*) exit 1 ;; esac
exit 0

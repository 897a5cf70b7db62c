#!/bin/sh
# bench_accuracy.sh -- what accuracy costs in time (issue "what accuracy costs
# in time"): recstab's certified spectral radius vs PARI/GP polroots, MPSolve
# and the GSL double baseline, at 15, 38, 77, 154, 308 and 1233 digits
# (53 ... 4096 bits), side by side in one run.
#
#   sh bench/bench_accuracy.sh
#
# 1. builds build/bench_radius from bench/bench_radius.c against a private
#    copy of build/librecstab.a (run 'make all' first) with the Makefile's
#    LIBS;
# 2. runs  build/bench_radius --accuracy bench/results  with --gp / --mpsolve
#    when the commands are installed (Debian pari-gp, mpsolve; skipped with a
#    message otherwise).  What is timed and how: see the comment above
#    acc_main in bench/bench_radius.c and bench/README.md;
# 3. writes bench/results/accuracy-vs-time.txt (table), .csv (one row per
#    polynomial x digits x method), .dat (plot data) and, with gnuplot,
#    accuracy-vs-time.png (bench/accuracy.gp).
#
# Environment: ACC_BUDGET (seconds of repeated calls per measurement, default
# 0.1), ACC_OUT (default bench/results), GP (default gp), MPSOLVE (default
# mpsolve), CC (default cc).  Takes about 1.5-2 minutes on 2 cores.
set -u
cd "$(dirname "$0")/.." || exit 2

OUT=${ACC_OUT:-bench/results}
WORK=build/accuracy
BUDGET=${ACC_BUDGET:-0.1}
GP=${GP:-gp}
MPSOLVE=${MPSOLVE:-mpsolve}

if [ ! -f build/librecstab.a ]; then
    echo "bench_accuracy.sh: build/librecstab.a not found; run 'make all' first" >&2
    exit 2
fi
mkdir -p "$OUT" "$WORK" || exit 2

# link against a snapshot: other people may rebuild the library meanwhile
snap=$(mktemp -d "${TMPDIR:-/tmp}/recstab_acc.XXXXXX") || exit 2
trap 'rm -rf "$snap"' EXIT
trap 'exit 130' INT TERM
cp build/librecstab.a "$snap/librecstab.a" || exit 2

LIBS=$(sed -n 's/^LIBS *:= *//p' Makefile 2>/dev/null)
# the Makefile's LIBS may be made of other variables ($(DEP_LIBS)): then the list
case "$LIBS" in ''|*'$('*) LIBS="-fopenmp -lflint-arb -lflint -lgsl -lgslcblas -ljansson -lmpfr -lgmp -lm" ;; esac
# shellcheck disable=SC2086
if ! ${CC:-cc} -std=c11 -D_POSIX_C_SOURCE=200809L -O2 -Iinclude \
        -I/usr/include/flint bench/bench_radius.c "$snap/librecstab.a" \
        -o build/bench_radius $LIBS; then
    echo "bench_accuracy.sh: bench/bench_radius.c did not compile" >&2
    exit 1
fi

peers=""
if command -v "$GP" >/dev/null 2>&1; then
    peers="$peers --gp $GP"
    gpv=$(echo 'print(Strexpand("PARI/GP ", version()))' | "$GP" -q 2>/dev/null)
else
    echo "PARI/GP: skipped ($GP not found; Debian package pari-gp)"
    gpv="PARI/GP: not installed"
fi
if command -v "$MPSOLVE" >/dev/null 2>&1; then
    peers="$peers --mpsolve $MPSOLVE"
    mpv=$("$MPSOLVE" -v 2>&1 | head -n 1)
else
    echo "MPSolve: skipped ($MPSOLVE not found; Debian package mpsolve)"
    mpv="MPSolve: not installed"
fi

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if [ -n "$(git status --porcelain --untracked-files=no 2>/dev/null)" ]; then
    commit="$commit (working tree has uncommitted changes)"
fi
head="== accuracy vs time ($(date -u '+%Y-%m-%d %H:%M UTC'), commit $commit)
machine: $(uname -sm), $(getconf _NPROCESSORS_ONLN 2>/dev/null || echo '?') cores, load average at start $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')
peers: $gpv; $mpv; GSL $(gsl-config --version 2>/dev/null || echo '?'); budget ${BUDGET} s per measurement"
echo "$head"
echo

# shellcheck disable=SC2086
build/bench_radius --accuracy "$OUT" --work "$WORK" --budget "$BUDGET" $peers
rc=$?
if [ $rc -ne 0 ]; then
    echo "build/bench_radius --accuracy exited $rc" >&2
    exit $rc
fi
{ echo "$head"
  echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')"
  echo
  cat "$OUT/accuracy-vs-time.txt"; } >"$snap/t.txt" && cp "$snap/t.txt" "$OUT/accuracy-vs-time.txt"

if command -v gnuplot >/dev/null 2>&1; then
    if gnuplot -e "dat='$OUT/accuracy-vs-time.dat'; out='$OUT/accuracy-vs-time.png'" \
            bench/accuracy.gp; then
        echo "plot: $OUT/accuracy-vs-time.png"
    else
        echo "gnuplot failed; no plot" >&2
    fi
else
    echo "plot: skipped (gnuplot not found; Debian package gnuplot-nox)"
fi

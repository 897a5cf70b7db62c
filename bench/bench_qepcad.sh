#!/bin/sh
# bench_qepcad.sh -- recstab against QEPCAD B (Debian `qepcad`) on the
# question of issue 13: for which values of one parameter is the scheme
# stable for EVERY admissible value of another?
#
# Side by side, in one run, per case:
#   recstab: the whole process, case file -> conditions -> uniform range with
#            evidence (certificates re-checked, counterexamples):
#              recstab --analyse "region P for all [Q]" CASE
#   QEPCAD B: quantifier elimination of the same question from recstab's own
#            Routh-Hurwitz conditions, the input recstab writes itself
#            (`region P, Q` -> "qepcad_input_for_all"; not timed);
#            qepcad $QE_OPTS < INPUT
# Times: median of BENCH_RUNS (default 5) fresh processes each; CPU (user +
# sys of the child, robust when the machine is shared) and wall seconds;
# ratio = QEPCAD / recstab.  Both answers are printed, to be compared.
# Goal (issue 13): recstab at least 2x faster on Park and on HHT-alpha.
set -u
cd "$(dirname "$0")/.." || exit 2
BIN=${RECSTAB:-build/recstab}   # RECSTAB=path: another build, side by side
# the documented `make static` product (fully static since h-static13: FLINT
# and Arb built from Debian's sources, GMP, MPFR, GSL, jansson, libgomp and
# glibc from Debian's lib*.a), timed beside the shipped build/recstab when it
# exists (issue 13: both ratios printed, side by side)
SBIN=${RECSTAB_STATIC:-$(dirname "$BIN")/recstab-static}
RUNS=${BENCH_RUNS:-5}
# QEPCAD's default garbage-collected space (+N1000000 cells); a larger +N costs
# start-up time (100M cells: about 1.8 s) and none of these cases needs it
QE_OPTS=${QE_OPTS:-+N1000000}
PY=${PYTHON:-python3}
if [ ! -x "$BIN" ]; then echo "bench_qepcad.sh: $BIN not found; run 'make all' first" >&2; exit 2; fi
if ! command -v qepcad >/dev/null 2>&1; then
    echo "bench_qepcad.sh: qepcad not installed (Debian package qepcad; `make bench` installs it); skipped"
    exit 0
fi
T=$(mktemp -d "${TMPDIR:-/tmp}/recstab_qe.XXXXXX") || exit 2
trap 'rm -rf "$T"' EXIT
cp "$BIN" "$T/recstab" || exit 2
if [ -x "$SBIN" ]; then cp "$SBIN" "$T/recstab-static" || exit 2; else SBIN=; fi

# HHT-alpha with the range of alpha left open (the case assumes -1/3 <= alpha <= 0)
sed 's/^assume w > 0, -1\/3 <= alpha <= 0/assume w > 0/' cases/textbook/hht-alpha.case >"$T/hht-free.case"

# median CPU and wall seconds of RUNS runs of a command (stdin from $2)
timeit() { # name stdin-file command...
    name=$1; in=$2; shift 2
    "$PY" - "$RUNS" "$in" "$@" <<'PYEOF'
import resource, subprocess, sys, time, statistics
runs, stdin = int(sys.argv[1]), sys.argv[2]
cmd = sys.argv[3:]
cpu, wall = [], []
for _ in range(runs):
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    with open(stdin) as f:
        subprocess.run(cmd, stdin=f, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    wall.append(time.monotonic() - t0)
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu.append(r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)
print("%.4f %.4f" % (statistics.median(cpu), statistics.median(wall)))
PYEOF
}

# The fixed cost of each process, measured the same way: recstab --version
# (dynamic loading of FLINT, Arb, NTL, libstdc++: no analysis) and QEPCAD B
# on a trivial input (its start-up, Saclib's space).  Both programs' times on
# these small cases are mostly this; "work" = total - start-up, its ratio
# printed as work_x (a difference of medians: rough).
printf '[ trivial ]\n(x)\n1\n[ x > 0 ].\nfinish\n' >"$T/trivial.qe"
rs0=$(timeit recstab /dev/null "$T/recstab" --version)
qe0=$(timeit qepcad "$T/trivial.qe" qepcad $QE_OPTS)
echo "$rs0 $qe0" | awk '{ printf "start-up: recstab %.4f s CPU (%.4f wall), QEPCAD %.4f s CPU (%.4f wall)\n", $1, $2, $3, $4 }'
if [ -n "$SBIN" ]; then
    st0=$(timeit recstab-static /dev/null "$T/recstab-static" --version)
    kind=dynamic; file -L "$SBIN" 2>/dev/null | grep -q 'statically linked' && kind="fully static"
    echo "$st0" | awk -v k="$kind" '{ printf "start-up: recstab-static (make static, %s) %.4f s CPU (%.4f wall)\n", k, $1, $2 }'
fi
printf '%-34s %10s %10s %10s %10s %8s %8s %8s\n' case rs_cpu_s rs_wall_s qe_cpu_s qe_wall_s cpu_x wall_x work_x
run_case() { # label case P Q sets...
    label=$1; case=$2; p=$3; q=$4; shift 4
    "$T/recstab" --json "$@" --analyse "region $p, $q" "$case" >"$T/r2.json" 2>/dev/null
    # the JSON document: {"cases": [{"results": [...]}]} (one case)
    "$PY" -c "import json,sys; d=json.load(open(sys.argv[1])); d=d['cases'][0] if 'cases' in d else d; print(d['results'][0]['qepcad_input_for_all'])" \
        "$T/r2.json" >"$T/in.qe" || { echo "$label: no QEPCAD input"; return; }
    rs=$(timeit recstab /dev/null "$T/recstab" "$@" --analyse "region $p for all [$q]" "$case")
    qe=$(timeit qepcad "$T/in.qe" qepcad $QE_OPTS)
    echo "$rs $qe $rs0 $qe0" | awk -v l="$label" '{ w1 = $1 - $5; w2 = $3 - $7;
        printf "%-34s %10.4f %10.4f %10.4f %10.4f %8.2f %8.2f %8s\n", l, $1, $2, $3, $4, $3 / $1, $4 / $2,
               (w1 > 0 && w2 > 0) ? sprintf("%.1f", w2 / w1) : "n/a" }'
    if [ -n "$SBIN" ]; then
        st=$(timeit recstab-static /dev/null "$T/recstab-static" "$@" --analyse "region $p for all [$q]" "$case")
        echo "$st $qe $rs" | awk '{ printf "    make static: %.4f s CPU (%.4f wall), cpu_x %.2f, wall_x %.2f (build/recstab: cpu_x %.2f, wall_x %.2f)\n",
                                        $1, $2, $3 / $1, $4 / $2, $3 / $5, $4 / $6 }'
    fi
    ans_rs=$("$T/recstab" "$@" --analyse "region $p for all [$q]" "$case" 2>&1 | grep -E '^  (stable|marginal|unstable|singular|undecided) ' | tr -s ' ' | tr '\n' ';')
    ans_qe=$(qepcad $QE_OPTS <"$T/in.qe" 2>&1 | sed -n '/equivalent quantifier-free/{n;n;p}')
    echo "    recstab: $ans_rs"
    echo "    QEPCAD (stable): $ans_qe"
}
run_case "theta, for all w" cases/forall/theta-oscillator.case th w
run_case "HHT-alpha, for all w" "$T/hht-free.case" alpha w
run_case "Park m=muh=1, for all wh" cases/park-staggered.case alpha wh --set m=1 --set muh=1

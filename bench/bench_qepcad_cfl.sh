#!/bin/sh
# bench_qepcad_cfl.sh -- `region nu for all` on the complex CFL cases
# (issue 15 part 1) against QEPCAD B on the same question.  recstab runs
# the whole process (case file with its complex char line -> p's own
# conditions over Q(i) -> uniform range with certificates and
# counterexamples); QEPCAD B eliminates the quantifier from the condition
# derived BY HAND for each scheme (t = tan(theta/2)):
#   leapfrog: bounded iff the roots -i a +- sqrt(1 - a^2), a = nu sin theta,
#             are distinct on the circle: (1 + t^2)^2 - 4 nu^2 t^2 > 0;
#   upwind:   1 - |g|^2 = 2 nu (1 - nu)(1 - cos theta) >= 0, i.e.
#             nu (1 - nu) t^2 >= 0 (a simple root: degree 1);
#   Lax-Wendroff: 1 - |g|^2 = nu^2 (1 - nu^2)(1 - cos theta)^2 >= 0, i.e.
#             nu^2 (1 - nu^2) t^4 >= 0.
# (QEPCAD answers a smaller question: the hand derivation did the
# scheme-specific work.)  Median of BENCH_RUNS (5) fresh processes; CPU
# (user + sys of the child) and wall seconds; ratio = QEPCAD / recstab.
set -u
cd "$(dirname "$0")/.." || exit 2
BIN=build/recstab
RUNS=${BENCH_RUNS:-5}
QE_OPTS=${QE_OPTS:-+N1000000}
PY=${PYTHON:-python3}
if [ ! -x "$BIN" ]; then echo "bench_qepcad_cfl.sh: $BIN not found; run 'make all' first" >&2; exit 2; fi
if ! command -v qepcad >/dev/null 2>&1; then echo "bench_qepcad_cfl.sh: qepcad not installed; skipped"; exit 0; fi
T=$(mktemp -d "${TMPDIR:-/tmp}/recstab_qecfl.XXXXXX") || exit 2
trap 'rm -rf "$T"' EXIT
timeit() { # stdin-file command...
    in=$1; shift
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
printf '%-16s %10s %10s %10s %10s %8s %8s\n' case rs_cpu_s rs_wall_s qe_cpu_s qe_wall_s cpu_x wall_x
run_case() { # label case-file qepcad-formula
    printf '[ %s ]\n(nu,t)\n1\n(A t)[ nu > 0 /\\ %s ].\nfinish\n' "$1" "$3" >"$T/in.qe"
    rs=$(timeit /dev/null "$BIN" --analyse "region nu for all" "$2")
    qe=$(timeit "$T/in.qe" qepcad $QE_OPTS)
    echo "$rs $qe" | awk -v l="$1" '{ printf "%-16s %10.4f %10.4f %10.4f %10.4f %8.1f %8.1f\n", l, $1, $2, $3, $4, $3 / $1, $4 / $2 }'
    echo "    recstab: $("$BIN" --analyse "region nu for all" "$2" 2>&1 | grep -E '^  (stable|marginal|unstable|singular|undecided) ' | tr -s ' ' | tr '\n' ';')"
    echo "    QEPCAD (bounded): $(qepcad $QE_OPTS <"$T/in.qe" 2>&1 | sed -n '/equivalent quantifier-free/{n;n;p}')"
}
run_case leapfrog cases/complex/leapfrog-cfl.case "(1 + t^2)^2 - 4 nu^2 t^2 > 0"
run_case upwind cases/complex/upwind-cfl.case "nu (1 - nu) t^2 >= 0"
run_case lax-wendroff cases/complex/lax-wendroff-cfl.case "nu^2 (1 - nu^2) t^4 >= 0"

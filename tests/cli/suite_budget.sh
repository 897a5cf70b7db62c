#!/bin/sh
# suite_budget.sh -- the resource budget of the command (issue 11): a run
# that passes --time-limit stops within about a second of it with exit 2, a
# message naming the limit and nothing on stdout; --memory-limit likewise;
# bad values of the options are usage errors.  The exact messages of the
# up-front estimates are pinned in tests/bad (sweep-huge, simulate-huge, ...).
# Prints "ok ..." or "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$(cd "$BUILD" 2>/dev/null && pwd)/recstab"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }

now() { date +%s.%N; }

# check LABEL MAX_SECONDS PATTERN -- ARGS: exit 2, no stdout, stderr matches
# PATTERN (grep -E), done within MAX_SECONDS
check() {
    label=$1; max=$2; pat=$3; shift 4
    t0=$(now)
    timeout 60 "$RS" "$@" >"$T/out" 2>"$T/err"; rc=$?
    t=$(awk -v a="$t0" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }')
    if [ "$rc" != 2 ]; then fail "$label: exit $rc, expected 2"; head -c 500 "$T/err"; return; fi
    if [ -s "$T/out" ]; then fail "$label: printed on stdout"; return; fi
    if ! grep -Eq "$pat" "$T/err"; then fail "$label: stderr '$(head -c 300 "$T/err")' does not match '$pat'"; return; fi
    # The limit is wall time; on a machine loaded beyond its cores the work
    # between two cooperative checks takes longer in wall time, so the
    # allowance grows with the load per core (1x on an idle machine).
    m=$(awk -v m="$max" -v l="$(cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo 0)" -v c="$(nproc 2>/dev/null || echo 1)" \
        'BEGIN { f = l / c; if (f < 1) f = 1; printf "%.2f", m * f }')
    if awk -v t="$t" -v m="$m" 'BEGIN { exit !(t > m) }'; then fail "$label: took $t s, more than $m s ($max s x load per core)"; return; fi
    ok "$label ($t s)"
}

# A sweep estimated below the limit (1 us per point) that takes about 30 s:
# stopped by the cooperative checks of the points (before the budget:
# nothing stopped it).
cat >"$T/sweep.case" <<'EOF'
param h
unknown x y
eq x[n+1] = x[n] + h*y[n]
eq y[n+1] = y[n] - h*x[n+1] - h*h*y[n]
analyse sweep h from 0 to 3 steps 900000
EOF
check "time limit during a sweep" 3.5 '^recstab: .*sweep.case:5:9: time limit of 1 s reached during .*; raise it with --time-limit$' \
    -- --time-limit 1 "$T/sweep.case"
check "time limit during a sweep (json)" 3.5 'time limit of 1 s reached during .*; raise it with --time-limit$' \
    -- --json --time-limit 1 --csv "$T/never.csv" "$T/sweep.case"
[ -e "$T/never.csv" ] && fail "time limit: --csv file written" || ok "time limit: no --csv file written"
# (a streamed sweep counts 32 bytes per point, its value and the model's
# numbers, not a row of results: 900001 x 32 bytes = 28.8 MB > 20 MB)
check "memory limit estimated before a sweep" 1 'the sweep would need about [0-9.]+ MB \(estimated\), more than the memory limit of 20 MB allows; raise it with --memory-limit$' \
    -- --memory-limit 20 "$T/sweep.case"

# --set c1=0 on a Li case: eigenvalues that cannot be isolated drive the
# precision to the 65536-bit ceiling, where an MPFR square root needed more
# than the usual 8 MB of stack (SIGSEGV after 0.5 s before the fix).  The
# run is cut by the time limit (13 s otherwise).
check "li --set c1=0 (stack at 65536 bits)" 4.5 'time limit of 2 s reached' \
    -- --set c1=0 --time-limit 2 cases/li-explicit-k0.case

# region k1 at m1 = 10^-1000 on an Olivier case (issue 11: "runs for hours"):
# Arb's complex root finder isolating the critical values' real roots raises
# its own precision and is one library call; the command's backstop ends it
# one second past the limit, with the limit's message.
check "region at m1=10^-1000 (Olivier)" 4.5 'time limit of 2 s reached' \
    -- --time-limit 2 --analyse 'region k1 at m1=10^-1000' cases/olivier2019-J-ee-ee.case

# options
for bad in "--time-limit" "--time-limit -1" "--time-limit 1.5" "--memory-limit x" "--memory-limit 100000000000"; do
    # shellcheck disable=SC2086
    check "usage: $bad" 1 "^recstab: --(time|memory)-limit expects a whole number" -- $bad cases/park-staggered.case
done
# 0 means no limit
if "$RS" --time-limit 0 --memory-limit 0 cases/recurrence-forward-euler.case >/dev/null 2>&1; then
    ok "--time-limit 0 --memory-limit 0 run"
else fail "--time-limit 0 --memory-limit 0 run"; fi

# --row-share SECONDS (issue 17): the per-row share of hurwitz's not-expanded
# mode.  With 0 every row from D_2 on is over its share; by default the
# 3-mass chain (bench/make_chain_case.sh) expands every minor (0.06 s).
for bad in "--row-share" "--row-share -1" "--row-share x" "--row-share nan" "--row-share 1e9"; do
    # shellcheck disable=SC2086
    check "usage: $bad" 1 "^recstab: --row-share expects seconds between 0 and 100000000" -- $bad cases/park-staggered.case
done
sh "$(dirname "$0")/../../bench/make_chain_case.sh" 3 "$T/chain3.case"
"$RS" --row-share 0 "$T/chain3.case" >"$T/rs0" 2>&1; rc0=$?
"$RS" --row-share 0.5 "$T/chain3.case" >"$T/rs1" 2>&1; rc1=$?
if [ "$rc0" = 0 ] && grep -q 'D_5 > 0 (not expanded)' "$T/rs0" && [ "$rc1" = 0 ] && ! grep -q 'not expanded' "$T/rs1" \
   && grep -q '^  stopped at .*over the row share of 0 s (--row-share)' "$T/rs0"; then
    ok "--row-share 0 leaves the chain's minors not expanded (the step that stopped named), 0.5 expands them"
else fail "--row-share: exit $rc0/$rc1, $(grep -c 'not expanded' "$T/rs0")/$(grep -c 'not expanded' "$T/rs1") not-expanded lines"; fi

# --expand-seconds SECONDS (issue 17, h-chain13): the budget of all expansion
# steps together.  0 admits no step (D_2's row is the first); the default
# (6) expands the 3-mass chain; given with --row-share both apply.
for bad in "--expand-seconds" "--expand-seconds -1" "--expand-seconds x"; do
    # shellcheck disable=SC2086
    check "usage: $bad" 1 "^recstab: --expand-seconds expects seconds between 0 and 100000000" -- $bad cases/park-staggered.case
done
"$RS" --expand-seconds 0 "$T/chain3.case" >"$T/es0" 2>&1; rc0=$?
"$RS" "$T/chain3.case" >"$T/es1" 2>&1; rc1=$?
"$RS" --row-share 10 --expand-seconds 0 "$T/chain3.case" >"$T/es2" 2>&1; rc2=$?
if [ "$rc0" = 0 ] && grep -q 'D_5 > 0 (not expanded)' "$T/es0" && [ "$rc1" = 0 ] && ! grep -q 'not expanded' "$T/es1" \
   && grep -q '^  stopped at .*over the expansion budget of 0 s (--expand-seconds)' "$T/es0" \
   && [ "$rc2" = 0 ] && grep -q 'over the expansion budget of 0 s' "$T/es2"; then
    ok "--expand-seconds 0 leaves the chain's minors not expanded (the budget named), also beside --row-share; the default expands them"
else fail "--expand-seconds: exit $rc0/$rc1/$rc2, $(grep -c 'not expanded' "$T/es0")/$(grep -c 'not expanded' "$T/es1") not-expanded lines"; fi

# the determinant's uninterruptible products are estimated first (CI's fuzz_case
# found p = P + i Q of degree 59 in four variables: P^2 + Q^2 multiplies two
# 34 220-term polynomials, C(60, 3) terms each, seconds per product): with 5 s
# left the run stops at once, naming the estimate, instead of overrunning.
printf 'param a b c\nchar (a+b+c+lambda)^56 + (a+b+c+lambda)^56 + (a+b+c+lambda)^57 + (i+b+lambda)^59\n' >"$T/big-complex.case"
"$RS" --time-limit 5 --analyse charpoly "$T/big-complex.case" >"$T/bc.out" 2>&1; rc=$?
if [ "$rc" = 2 ] && grep -q 'the products of the determinant would take about .* more than the time limit of 5 s' "$T/bc.out"; then
    ok "charpoly: a determinant product over the time limit is refused by its estimate"
else fail "charpoly big complex: exit $rc, $(head -c 300 "$T/bc.out")"; fi

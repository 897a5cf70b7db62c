#!/bin/sh
# Runs every cmocka suite in $BUILD/tests and every shell suite tests/cli/suite_*.sh,
# and the dependency rule tests/check_deps.sh, then prints one summary line "N passed, N failed".
BUILD=${BUILD:-build}
export BUILD
pass=0; fail=0; failed_suites=""
log=$(mktemp)
for t in "$BUILD"/tests/test_*; do
    [ -x "$t" ] || continue
    name=$(basename "$t")
    "$t" >"$log" 2>&1
    rc=$?
    p=$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -1)
    f=$(sed -n 's/^\[  FAILED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -1)
    p=${p:-0}; f=${f:-0}
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi   # crashed suite
    pass=$((pass + p)); fail=$((fail + f))
    if [ "$f" -ne 0 ]; then
        failed_suites="$failed_suites $name"
        echo "---- $name FAILED ----"; cat "$log"
    else
        echo "$name: $p passed"
    fi
done
for s in tests/cli/suite_*.sh tests/check_deps.sh; do
    [ -f "$s" ] || continue
    name=$(basename "$s" .sh)
    sh "$s" >"$log" 2>&1
    p=$(grep -c '^ok ' "$log"); f=$(grep -c '^FAIL ' "$log")
    pass=$((pass + p)); fail=$((fail + f))
    if [ "$f" -ne 0 ]; then
        failed_suites="$failed_suites $name"
        echo "---- $name FAILED ----"; grep -A3 '^FAIL ' "$log"
    else
        echo "$name: $p passed"
    fi
done
rm -f "$log"
[ -n "$failed_suites" ] && echo "failed suites:$failed_suites"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]

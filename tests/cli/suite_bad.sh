#!/bin/sh
# suite_bad.sh -- malformed input never crashes or hangs recstab.  Every
# tests/bad/NAME.case (plus the gen-* cases generated below: binary data and
# huge inputs are not committed) must, in text and --json mode, within 20 s:
# exit with status 2, print nothing on stdout, and print exactly
# tests/bad/NAME.expected on stderr.  NAME.args holds extra options.  Inputs
# the fuzzer found (tests/fuzz/regress/*) must finish within 20 s with a
# status below 3 (no crash, no timeout, no sanitizer report), under the
# fuzzers' budget (--time-limit 5, FUZZ_TIME_LIMIT of tests/fuzz/fuzz_common.h).
# Prints "ok ..." or "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$(cd "$BUILD" 2>/dev/null && pwd)/recstab"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }

# ---- generated cases (written under $T/tests/bad, run from $T) ----------
G="$T/tests/bad"
mkdir -p "$G"
printf 'param h\000x\nunknown x\n' >"$G/gen-nul.case"
printf '\177ELF\002\001\001\000\000\000\000\000\003\000>\000' >"$G/gen-binary.case"
printf 'param h\nunknown x\377\n' >"$G/gen-non-utf8.case"
printf 'param h\nunknown x\303\n' >"$G/gen-non-utf8-truncated.case"
printf 'param h\300\257\n' >"$G/gen-non-utf8-overlong.case"
awk 'BEGIN { printf "param h\nunknown x\neq x[n+1] = ";
             for (i = 0; i < 100000; i++) printf "("; printf "x[n]";
             for (i = 0; i < 100000; i++) printf ")"; printf "\n" }' >"$G/gen-deep-nesting-100k.case"
awk 'BEGIN { printf "param h\nunknown x\neq x[n+1] = ";
             for (i = 0; i < 30000; i++) printf "("; printf "x[n]";
             for (i = 0; i < 30000; i++) printf ")"; printf "\n" }' >"$G/gen-deep-nesting-30k.case"
awk 'BEGIN { printf "param h\nunknown x\neq x[n+1] = ";
             for (i = 0; i < 30000; i++) printf "-"; printf "x[n]\n" }' >"$G/gen-deep-minus.case"
awk 'BEGIN { printf "param h\nunknown x\neq x[n+1] = ";
             for (i = 0; i < 30000; i++) printf "h*"; printf "x[n]\n" }' >"$G/gen-long-product.case"
# a flat 12000-term sum parses (suite_cli), but not inside 201 parentheses
awk 'BEGIN { printf "param h\nunknown x\neq x[n+1] = ";
             for (i = 0; i < 201; i++) printf "("; printf "x[n]";
             for (i = 0; i < 12000; i++) printf "+x[n]";
             for (i = 0; i < 201; i++) printf ")"; printf "\n" }' >"$G/gen-long-sum.case"
{ printf 'param '; head -c 10485760 /dev/zero | tr '\000' a; printf '\n'; } >"$G/gen-10mb-line.case"
awk 'BEGIN { printf "param"; for (i = 0; i < 1000; i++) printf " p%d", i; printf "\n" }' >"$G/gen-1000-params.case"
awk 'BEGIN { for (i = 0; i < 1000; i++) printf "param p%d\n", i }' >"$G/gen-1000-param-lines.case"
{ printf 'param h\n'; head -c 17000000 /dev/zero | tr '\000' '\n'; } >"$G/gen-17mb-file.case"
awk 'BEGIN { printf "param h\nunknown x\neq x[n+1] = ";
             for (i = 0; i < 60000; i++) printf "1"; printf "*x[n] +\n" }' >"$G/gen-long-number.case"

run_bad() { # dir name  (runs from dir; the case is tests/bad/name.case)
    dir=$1; name=$2; case=tests/bad/$name.case
    exp=tests/bad/$name.expected
    if [ ! -f "$exp" ]; then fail "bad $name: no $exp"; return; fi
    args=""
    [ -f "tests/bad/$name.args" ] && args=$(cat "tests/bad/$name.args")
    for mode in text json; do
        j=""; [ $mode = json ] && j=--json
        # shellcheck disable=SC2086
        (cd "$dir" && timeout 20 "$RS" $j $args "$case") >"$T/out" 2>"$T/err"
        rc=$?
        label="bad $name ($mode)"
        if [ "$rc" -ge 124 ]; then
            fail "$label: exit $rc (crash or timeout)"; head -c 2000 "$T/err"; continue
        fi
        if [ "$rc" != 2 ]; then fail "$label: exit $rc, expected 2"; head -c 2000 "$T/err"; continue; fi
        if [ -s "$T/out" ]; then fail "$label: printed on stdout"; head -c 500 "$T/out"; continue; fi
        if ! cmp -s "$T/err" "$exp"; then
            fail "$label: stderr differs"
            echo "  expected: $(head -c 500 "$exp")"; echo "  got:      $(head -c 500 "$T/err")"
            continue
        fi
        ok "$label"
    done
}

for f in tests/bad/*.case; do
    [ -f "$f" ] || continue
    run_bad . "$(basename "$f" .case)"
done
for f in "$G"/gen-*.case; do
    name=$(basename "$f" .case)
    # the expectation lives in the source tree, the input in $T
    mkdir -p "$T/tests/bad"
    [ -f "tests/bad/$name.expected" ] && cp "tests/bad/$name.expected" "$T/tests/bad/"
    [ -f "tests/bad/$name.args" ] && cp "tests/bad/$name.args" "$T/tests/bad/"
    (cd "$T" && run_bad . "$name")
done
for f in tests/bad/*.expected; do
    name=$(basename "$f" .expected)
    [ -f "tests/bad/$name.case" ] || [ -f "$G/$name.case" ] || fail "bad $name: $f has no case"
done

# ---- fuzzer regressions: must not crash or hang ---------------------------
for f in tests/fuzz/regress/*; do
    [ -f "$f" ] || continue
    for j in "" --json; do
        # shellcheck disable=SC2086
        timeout 20 "$RS" --time-limit 5 $j "$f" >"$T/out" 2>"$T/err"; rc=$?
        if [ "$rc" -le 2 ]; then ok "fuzz regression $j $f"
        else fail "fuzz regression $j $f: exit $rc"; head -c 2000 "$T/err"; fi
    done
done

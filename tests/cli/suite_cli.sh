#!/bin/sh
# suite_cli.sh -- the recstab command end to end: every bundled case runs with
# its expected exit status (a case may say "# expect-exit: N"; default 0) in
# text and JSON mode, bad input gives file:line:col and exit 2 with nothing
# on stdout, and the options behave as documented.  Prints "ok ..." or
# "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$BUILD/recstab"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }

check_exit() { # name expected actual
    if [ "$2" = "$3" ]; then ok "$1"; else fail "$1: exit $3, expected $2"; fi
}

for f in $(find cases -name '*.case' | sort); do
    want=$(sed -n 's/^# expect-exit: *\([0-9]\).*/\1/p' "$f" | head -1)
    want=${want:-0}
    "$RS" "$f" >"$T/out" 2>"$T/err"; rc=$?
    check_exit "case $f" "$want" "$rc"
    [ "$rc" = "$want" ] || { head -5 "$T/err"; }
    "$RS" --json "$f" >"$T/out.json" 2>"$T/err"; rc=$?
    check_exit "case --json $f" "$want" "$rc"
    if [ "$rc" -le 1 ] && ! grep -q '"results"' "$T/out.json"; then fail "json $f: no results"; fi
done

# bad input: message with file:line:col, exit 2, no stdout
printf 'param w\nunknown x\neq x[n+1] = w*y[n]\n' >"$T/bad.case"
"$RS" "$T/bad.case" >"$T/out" 2>"$T/err"; rc=$?
check_exit "bad case exit" 2 "$rc"
if grep -q "bad.case:3:15: unknown name 'y'" "$T/err"; then ok "bad case message"; else fail "bad case message: $(cat "$T/err")"; fi
if [ ! -s "$T/out" ]; then ok "bad case: nothing on stdout"; else fail "bad case printed output"; fi

# a good case followed by a bad one: still no partial output
"$RS" cases/textbook/forward-euler.case "$T/bad.case" >"$T/out" 2>"$T/err"; rc=$?
check_exit "good+bad exit" 2 "$rc"
if [ ! -s "$T/out" ]; then ok "good+bad: no partial output"; else fail "good+bad printed partial output"; fi

# --set of a name that is not a parameter
"$RS" --set q=1 cases/textbook/forward-euler.case >"$T/out" 2>"$T/err"; rc=$?
check_exit "--set non-parameter" 2 "$rc"
if grep -q "'q' is not a parameter" "$T/err"; then ok "--set message"; else fail "--set message: $(cat "$T/err")"; fi

# --set substitutes before elimination: p = lambda^2 - 2 lambda + 5/4 at w = 1/2 -> 4l^2 - 8l + 5
"$RS" --json --set w=0.5 cases/textbook/forward-euler.case >"$T/out" 2>&1
if tr -d ' \n' <"$T/out" | grep -q '"coeffs":\["5","-8","4"\]'; then ok "--set substitution"; else fail "--set substitution: $(cat "$T/out")"; fi

# --analyse replaces the case's analyses
"$RS" --json --analyse charpoly cases/park-staggered.case >"$T/out" 2>&1
n=$(grep -c '"analysis"' "$T/out")
if [ "$n" = 1 ]; then ok "--analyse replaces"; else fail "--analyse replaces: $n results"; fi
"$RS" --analyse "expect charpoly lambda^2 + 1" cases/textbook/forward-euler.case >"$T/out" 2>&1; rc=$?
check_exit "--analyse expect different -> exit 1" 1 "$rc"

# stdin
"$RS" - <cases/textbook/central-difference.case >"$T/out" 2>&1; rc=$?
check_exit "stdin" 0 "$rc"

# usage errors
"$RS" >"$T/out" 2>&1; rc=$?;               check_exit "no case" 2 "$rc"
"$RS" --bogus x.case >"$T/out" 2>&1; rc=$?; check_exit "unknown option" 2 "$rc"
"$RS" --help >"$T/out" 2>&1; rc=$?;         check_exit "--help" 0 "$rc"
"$RS" --version >"$T/out" 2>&1; rc=$?;      check_exit "--version" 0 "$rc"
"$RS" /nonexistent.case >"$T/out" 2>"$T/err"; rc=$?; check_exit "missing file" 2 "$rc"

# derivations: Markdown always; LaTeX compiled when pdflatex is installed
# (Debian: apt-get install texlive-latex-base)
"$RS" --markdown cases/park-staggered.case >"$T/d.md" 2>"$T/err"; rc=$?
check_exit "--markdown" 1 "$rc"
if grep -q "### Routh array\|### Hurwitz minors" "$T/d.md" && grep -q "### The lambda-matrix" "$T/d.md"; then
    ok "markdown derivation sections"; else fail "markdown derivation sections"; fi
"$RS" --latex cases/park-staggered.case cases/textbook/central-difference.case cases/textbook/trapezoidal.case >"$T/d.tex" 2>"$T/err"; rc=$?
check_exit "--latex" 1 "$rc"
if command -v pdflatex >/dev/null 2>&1; then
    if (cd "$T" && timeout 120 pdflatex -interaction=nonstopmode -halt-on-error d.tex >/dev/null 2>&1) && [ -s "$T/d.pdf" ]; then
        ok "latex derivation compiles with pdflatex"
    else
        fail "latex derivation does not compile: $(grep '^!' "$T/d.log" | head -3)"
    fi
else
    echo "skip latex compile (pdflatex not installed)"
fi
"$RS" --json --latex cases/textbook/trapezoidal.case >"$T/out" 2>&1; rc=$?
check_exit "--json with --latex is a usage error" 2 "$rc"

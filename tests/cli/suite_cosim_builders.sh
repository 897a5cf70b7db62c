#!/bin/sh
# suite_cosim_builders.sh -- couplings written with the builders against the
# same schemes written as equations by hand (cases/cosim/*-by-hand.case):
# Gauss-Seidel over three subsystems in a given order, and Jacobi with one
# iteration of Newmark subsystems, couple explicit|implicit order K with
# integrators (backward Euler + trapezoidal; midpoint rule + backward Euler).
# The characteristic polynomials must be
# identical.  Plus the extension couplings' case files run and decide.
# Prints "ok ..." or "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$BUILD/recstab"

ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }

poly() { "$RS" --analyse charpoly "$1" 2>&1 | sed -n 's/^  p(lambda) *//p' | head -1; }

for pair in gs3 newmark-iter li-explicit-integrator li-implicit-integrator; do
    a=$(poly cases/cosim/$pair-builder.case); b=$(poly cases/cosim/$pair-by-hand.case)
    if [ -n "$a" ] && [ "$a" = "$b" ]; then ok "$pair: builder = by hand ($a)"
    else fail "$pair: builder '$a' vs by hand '$b'"; fi
done

# the swapped Gauss-Seidel order is a different scheme (not the same polynomial)
sed 's/^couple gauss-seidel S2 S1 S3/couple gauss-seidel S1 S2 S3/' cases/cosim/gs3-builder.case > "${TMPDIR:-/tmp}/gs3-swap.$$.case"
c=$(poly "${TMPDIR:-/tmp}/gs3-swap.$$.case"); rm -f "${TMPDIR:-/tmp}/gs3-swap.$$.case"
if [ -n "$c" ] && [ "$c" != "$a" ]; then ok "gs3: the order matters"; else fail "gs3 order S1 S2 S3 gives '$c'"; fi

# the extension couplings: a certified verdict at the case's point
for f in cases/cosim/li-ext-d-k1-sym.case cases/cosim/li-ext-i-k1-a1_4-unsym.case; do
    if "$RS" "$f" 2>&1 | grep -q "verdict .*certified by the radius interval"; then ok "verdict $f"
    else fail "no certified verdict: $f"; fi
done

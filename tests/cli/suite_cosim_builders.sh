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

for pair in gs3 newmark-iter cd-iter li-explicit-integrator li-implicit-integrator; do
    a=$(poly cases/cosim/$pair-builder.case); b=$(poly cases/cosim/$pair-by-hand.case)
    if [ -n "$a" ] && [ "$a" = "$b" ]; then ok "$pair: builder = by hand ($a)"
    else fail "$pair: builder '$a' vs by hand '$b'"; fi
done

# iterations with central difference (cd-iter-*.case): `iterations 2` and
# Gauss-Seidel against their hand derivations; with the velocity coupling e the iterates
# differ (iterations 1 != 2), with position coupling only (e = 0) every
# iterate after the first reads the partner's final position y[n], so
# iterations 1, 2 and 3 give monolithic central difference.  Closed form
# of that (independent): the modes w^2 = 1, 3 of x'' = -2x + y - c x',
# y'' = x - 2y - c y' each give (1 + ch/2) l^2 - (2 - h^2 w^2) l + 1 - ch/2;
# at c = 1/5, h = 1/10 times 100: (101 l^2 - 199 l + 99)(101 l^2 - 197 l + 99),
# at c = 0: (100 l^2 - 199 l + 100)(100 l^2 - 197 l + 100).
CDT="${TMPDIR:-/tmp}/cd-iter.$$"
mkdir -p "$CDT"
for k in 1 2 3; do sed "s/^iterations 1/iterations $k/" cases/cosim/cd-iter-builder.case > "$CDT/k$k.case"; done
a=$(poly "$CDT/k2.case"); b=$(poly cases/cosim/cd-iter2-by-hand.case)
if [ -n "$a" ] && [ "$a" = "$b" ]; then ok "cd-iter2: builder = by hand ($a)"
else fail "cd-iter2: builder '$a' vs by hand '$b'"; fi
sed 's/^couple jacobi/couple gauss-seidel S1 S2/' "$CDT/k1.case" > "$CDT/gs.case"
g=$(poly "$CDT/gs.case"); b=$(poly cases/cosim/cd-iter-gs-by-hand.case)
if [ -n "$g" ] && [ "$g" = "$b" ]; then ok "cd-iter-gs: builder = by hand ($g)"
else fail "cd-iter-gs: builder '$g' vs by hand '$b'"; fi
a1=$(poly "$CDT/k1.case")
if [ -n "$a1" ] && [ -n "$a" ] && [ "$a1" != "$a" ]; then ok "cd-iter: velocity coupling, iterations 1 != 2"
else fail "cd-iter: iterations 1 '$a1' vs 2 '$a'"; fi
polyset() { "$RS" --analyse charpoly --set "$2" --set "$3" "$1" 2>&1 | sed -n 's/^  p(lambda) *//p' | head -1; }
for cs in "c=1/5|10201*lambda^4 - 39996*lambda^3 + 59201*lambda^2 - 39204*lambda + 9801" \
          "c=0|10000*lambda^4 - 39600*lambda^3 + 59203*lambda^2 - 39600*lambda + 10000"; do
    c=${cs%%|*}; want=${cs#*|}
    for k in 1 2 3; do
        got=$(polyset "$CDT/k$k.case" e=0 "$c")
        if [ "$got" = "$want" ]; then ok "cd-iter: e=0 $c iterations $k = monolithic closed form"
        else fail "cd-iter: e=0 $c iterations $k gives '$got', closed form '$want'"; fi
    done
done
rm -rf "$CDT"

# the swapped Gauss-Seidel order is a different scheme (not the same polynomial)
sed 's/^couple gauss-seidel S2 S1 S3/couple gauss-seidel S1 S2 S3/' cases/cosim/gs3-builder.case > "${TMPDIR:-/tmp}/gs3-swap.$$.case"
c=$(poly "${TMPDIR:-/tmp}/gs3-swap.$$.case"); rm -f "${TMPDIR:-/tmp}/gs3-swap.$$.case"
if [ -n "$c" ] && [ "$c" != "$a" ]; then ok "gs3: the order matters"; else fail "gs3 order S1 S2 S3 gives '$c'"; fi

# the extension couplings: a certified verdict at the case's point
for f in cases/cosim/li-ext-d-k1-sym.case cases/cosim/li-ext-i-k1-a1_4-unsym.case; do
    if "$RS" "$f" 2>&1 | grep -q "verdict .*certified by the radius interval"; then ok "verdict $f"
    else fail "no certified verdict: $f"; fi
done

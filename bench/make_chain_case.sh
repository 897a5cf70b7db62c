#!/bin/sh
# make_chain_case.sh N [out.case] -- the N-mass chain of issue 17: unit masses
# in a line, mass 1 tied to a wall, spring i (stiffness k_i, scaled by h^2)
# between masses i-1 and i, one damping c (scaled by h) from every mass to
# ground, the trapezoidal rule on x' = v, v' = a.  Degree 2N in lambda,
# N + 1 parameters; `analyse hurwitz` on it.
set -eu
N=${1:?usage: make_chain_case.sh N [out.case]}
out=${2:-/dev/stdout}
{
    printf '# %s-mass trapezoidal chain (bench/make_chain_case.sh %s)\n' "$N" "$N"
    params="c"; assume="c > 0"; unknowns=""
    i=1
    while [ "$i" -le "$N" ]; do
        params="$params k$i"; assume="$assume, k$i > 0"
        unknowns="$unknowns x$i v$i a$i"
        i=$((i + 1))
    done
    printf 'param%s\n' " $params"
    printf 'assume %s\n' "$assume"
    printf 'unknown%s\n' "$unknowns"
    i=1
    while [ "$i" -le "$N" ]; do
        f="c*v$i[n+1] + k$i*x$i[n+1]"
        [ "$i" -gt 1 ] && f="$f - k$i*x$((i - 1))[n+1]"
        if [ "$i" -lt "$N" ]; then
            f="$f + k$((i + 1))*x$i[n+1] - k$((i + 1))*x$((i + 1))[n+1]"
        fi
        printf 'eq a%s[n+1] + %s = 0\n' "$i" "$f"
        printf 'eq x%s[n+1] - x%s[n] = (v%s[n+1] + v%s[n])/2\n' "$i" "$i" "$i" "$i"
        printf 'eq v%s[n+1] - v%s[n] = (a%s[n+1] + a%s[n])/2\n' "$i" "$i" "$i" "$i"
        i=$((i + 1))
    done
    printf 'analyse hurwitz\n'
} > "$out"

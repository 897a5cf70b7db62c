#!/bin/sh
# suite_truth.sh -- planted truths against the newest verdicts (h-truth):
# random cases whose verdicts are known by construction (tests/truth/truth.py
# derives each independently, in exact rational / Gaussian rational
# arithmetic) and the regressions found that way (cases/truth/*.case, each
# expected value derived by hand in the case's comment).  Fixed seeds, small
# counts (each part well under 2 s CPU); larger runs: tests/truth/run_big.sh.
# Prints "ok ..." or "FAIL ..." per check.
BUILD=${BUILD:-build}
RS="$BUILD/recstab"
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT

ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }

# field of the n-th result (0-based) of a case, compact JSON
jfield() { # case index filter
    "$RS" --json "$1" 2>/dev/null | jq -c ".cases[0].results[$2]$3" 2>/dev/null
}
check() { # name want got
    if [ "$2" = "$3" ]; then ok "$1: $2"; else fail "$1: got '$3', expected '$2'"; fi
}

if command -v jq >/dev/null 2>&1; then
    # semisimple double root -1 of a system: stability, jury and routh all marginal
    C=cases/truth/jury-semisimple-minus-one.case
    check "semisimple -1: stability" '"marginal"' "$(jfield $C 0 .status)"
    check "semisimple -1: jury (was unstable)" '"marginal"' "$(jfield $C 1 .status)"
    check "semisimple -1: routh (was unstable)" '"marginal"' "$(jfield $C 2 .status)"
    check "semisimple -1: jury kernel" '2' "$(jfield $C 1 '.circle_roots[0].kernel_dim')"
    # the same det with a Jordan block: unstable everywhere
    C=cases/truth/jury-jordan-minus-one.case
    check "Jordan -1: stability" '"unstable"' "$(jfield $C 0 .status)"
    check "Jordan -1: jury" '"unstable"' "$(jfield $C 1 .status)"
    check "Jordan -1: routh" '"unstable"' "$(jfield $C 2 .status)"
    # modes over Q(i) with a root at 0 and a double root (was exit 2)
    C=cases/truth/modes-zero-and-double-root.case
    check "modes Q(i) 0 and double root: roots" \
        '[["0","0"],["0.333333333333333","0.142857142857143"],["-0.857142857142857","0"],["-0.857142857142857","0"]]' \
        "$(jfield $C 1 '.modes | map([.root.re, .root.im])')"
    check "modes Q(i) 0 and double root: exact check" '"stable"' "$(jfield $C 1 .exact_check.status)"
    # dead-beat modes (was exit 2): the two roots at 0 of det = lambda^2, no continuous
    # equivalent (h-truth3: listed, as over Q(i); before, no mode)
    C=cases/truth/modes-dead-beat.case
    check "modes dead-beat" '[["0","0"],["0","0"]]' "$(jfield $C 1 '.modes | map([.root.re, .root.im])')"
    check "modes dead-beat: note" '"root at 0: no continuous equivalent"' "$(jfield $C 1 '.modes[0].note')"
    # roots at 0 divided out of p counted (h-truth3; by hand in the cases' comments)
    C=cases/truth/counts-roots-at-zero.case
    for k in 0 1 2; do
        check "roots at 0: $(jfield $C $k .analysis) counts (was 1 inside)" '["unstable",4,3,0,1,2]' \
            "$(jfield $C $k '| [.status, .degree, .inside, .on, .outside, .at_zero]')"
    done
    check "roots at 0: modes lists them" '[["0","0"],["0","0"],["0.5","0"],["3","0"]]' \
        "$(jfield $C 3 '| [.modes[], .spurious[]] | map([.root.re, .root.im]) | sort_by(.[0] | tonumber)')"
    C=cases/truth/routh-roots-at-zero.case
    check "roots at 0: routh (was 1 inside)" '["unstable",3,0,1]' "$(jfield $C 0 '| [.status, .inside, .on, .outside]')"
    check "roots at 0: jury" '["unstable",3,0,1]' "$(jfield $C 1 '| [.status, .inside, .on, .outside]')"
    # a char line over Q(i): p's own counts, not its real block form's (by hand in the case)
    C=cases/truth/complex-char-counts.case
    check "char over Q(i): stability, routh, jury count p's roots (were the block form's 2, 4, 0 of 6)" \
        '[["marginal",3,1,2,0],["marginal",3,1,2,0],["marginal",3,1,2,0]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map([.status, .degree, .inside, .on, .outside])')"
    check "char over Q(i): the block form's counts kept, twice p's" '[6,2,4,0]' \
        "$(jfield $C 0 '.block_form | [.degree, .inside, .on, .outside]')"
    C=cases/truth/complex-dead-beat.case
    check "dead-beat over Q(i): stability, jury, hurwitz, radius, modes (were exit 2)" \
        '["stable",2,"stable under the assumptions","stable under the assumptions","0",2]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].status, .[0].inside, .[1].verdict, .[2].verdict, .[3].upper, (.[4].modes | length)]')"
    C=cases/truth/limit-roots-at-zero.case
    check "limit keeps the roots at 0" '[[["0",4]],[["0",2],["inf",2]]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map(.roots | map([.value, .multiplicity]))')"
    C=cases/truth/claim-thin-algebraic-sliver.case
    check "claim false on a sliver beyond sqrt 5: refuted by the region's sample (was undecided)" \
        '["proved","refuted","unstable"]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[1].status, .[2].status, .[2].at_counterexample.status]')"
    # the sample itself depends on the isolating intervals: check it lies in the
    # failing sliver, sqrt 5 < a < 559267/250000 (exactly, a^2 > 5)
    a=$(jfield $C 2 '.counterexample.a' | tr -d '"')
    check "claim sliver: counterexample inside (sqrt 5, 559267/250000)" 'True' \
        "$(python3 -c "from fractions import Fraction as F; a = F('$a'); print(a * a > 5 and a < F(559267, 250000))")"
    check "claim sliver: explanation's interval (was (~0, ...))" 'true' \
        "$(jfield $C 2 '.explanation.summary | contains("unstable on (~2.23607, 559267/250000)")')"
    # uniform range of a planted family (by hand in the case's comment)
    C=cases/truth/forall-planted-double-minus-one.case
    check "forall planted: intervals" \
        '[["unstable",null,"-2",false,true],["stable","-2","2",false,false],["marginal","2","2",true,true],["unstable","2",null,false,false]]' \
        "$(jfield $C 0 '.intervals | map([.status, .lo, .hi, .lo_closed, .hi_closed])')"
    # issue 13 undecided-where-decidable (h-forall5), each expected value by hand in the case's comment
    IV='.intervals | map([.status, (.lo|if type=="object" then .minpoly else . end), (.hi|if type=="object" then .minpoly else . end), .lo_closed, .hi_closed])'
    C=cases/truth/forall-minus-one-every-w.case
    check "forall -1 for every w: intervals (was undecided on [-1, 1])" \
        '[["unstable",null,"-1",false,false],["marginal","-1","1",true,true],["unstable","1",null,false,false]]' \
        "$(jfield $C 0 "$IV")"
    check "forall -1 for every w: claim bounded (was undecided)" '"proved"' "$(jfield $C 1 .status)"
    C=cases/truth/forall-double-minus-one-every-w.case
    check "forall double -1: unstable everywhere" '[["unstable",null,null,false,false]]' "$(jfield $C 0 "$IV")"
    C=cases/truth/forall-polya-cap.case
    check "forall past Polya's cap: intervals (was undecided on (31/32, 33/32))" \
        '[["unstable",null,"-33/32",false,false],["marginal","-33/32","-33/32",true,true],["stable","-33/32","33/32",false,false],["marginal","33/32","33/32",true,true],["unstable","33/32",null,false,false]]' \
        "$(jfield $C 0 "$IV")"
    check "forall past Polya's cap: claim at A = 1 by real roots" '["proved",true]' \
        "$(jfield $C 2 '| [.status, (.certificate | map(.no_real_root_on_range == true) | any)]')"
    C=cases/truth/forall-sqrt8-edge.case
    check "forall +-sqrt 8: unstable sides (were undecided), the points marginal over Q(sqrt 8) (were undecided)" \
        '[["unstable","marginal","stable","marginal","unstable"],0,"A^2 - 8"]' \
        "$(jfield $C 0 '| [(.intervals | map(.status)), (.undecided_points | length), .intervals[1].lo.minpoly]')"
    # the second method at the two marginal points (h-review): certified roots at w = 1 and at the w
    # where lambda = -1 is a root, none outside the circle.  By hand at A = -+sqrt 8, w = 1:
    # p = 3 lambda +- sqrt 8, |lambda| = sqrt 8/3 = 0.94280904158...; at w = 1/sqrt 2: 2 lambda +- 2, |lambda| = 1
    check "forall +-sqrt 8: the marginal points cross-checked by certified roots" \
        '[["agree","agree"],[["1",0,true],["1",0,true]],[true,true]]' \
        "$(jfield $C 0 '| [.intervals[] | select(.status == "marginal") | .evidence[0].cross_check] | [map(.result), map([.samples[0].value, .samples[0].roots_outside_circle, (.samples | length == 2)]), map(.samples[0].abs_root_max_upper | . >= 0.9428090415 and . < 0.9428090416)]')"
    # symbolic Routh array with q's leading coefficient negative where stable (h-truth2):
    # the column by hand (3a + 6, 4a + 2, 4a^2 + 2a); the note's criterion was "one sign"
    C=cases/truth/routh-negative-lead.case
    check "routh negative lead: column" '["3*a + 6","4*a + 2","4*a^2 + 2*a"]' "$(jfield $C 0 '.rows | map(.[0])')"
    check "routh negative lead: note (was: one sign)" 'true' \
        "$(jfield $C 0 '.note | contains("sign f_k = (sign f_0)^k")')"
    check "routh negative lead: stable at a = -3" '"stable"' \
        "$("$RS" --json --set a=-3 --analyse stability $C 2>/dev/null | jq -c '.cases[0].results[0].status')"
    # RK tableau whose det has the factor q - 1 (h-truth2): astability exited 2 at q = 1
    C=cases/truth/rk-common-factor-astability.case
    check "rk common factor: astability (was exit 2)" '[true,true,["-inf",0],["-inf","inf"]]' \
        "$(jfield $C 1 ' | [.a_stable, .l_stable, .real_interval, .imag_interval]')"
    # a negative real root found as a ball across the axis (h-truth2): omega was "0e+1", damping nan
    C=cases/truth/modes-negative-real-root.case
    check "modes negative real root (was 0e+1, nan)" '["-1.09861228866811","3.14159265358979","0.330097420439083"]' \
        "$(jfield $C 0 '.modes[0] | [.sigma, .omega, .damping_ratio]')"
    # a root at 1: lambda_c = 0, damping ratio 0/0 (by hand in the case; was "damping nan")
    C=cases/truth/modes-root-at-one.case
    check "modes root at 1: damping undefined (was nan)" '[["-0.693147180559945","1.00000000000000"],["0",null,"undefined: lambda = 1, so lambda_c = 0"]]' \
        "$(jfield $C 0 '.modes | [[.[0].sigma, .[0].damping_ratio], [.[1].sigma, .[1].damping_ratio, .[1].damping_note]]')"
    check "modes root at 1: text" '1' "$("$RS" $C 2>/dev/null | grep -c 'sigma 0 omega 0 damping undefined$')"
    # co-simulation with a double eigenvalue (h-truth2): the enclosure excludes 1 (was exit 2)
    C=cases/truth/cosim-double-eigenvalue.case
    # the enclosure's verdict and its second method (Schur on T's ball characteristic polynomial)
    check "cosim double eigenvalue: stable from the enclosure (was exit 2), cross-checked" '["stable",true,"every root inside",true]' \
        "$("$RS" --json --max-prec 2048 $C 2>/dev/null | jq -c '.cases[0].results[0] | [.status, (.upper | tonumber) < 1, .cross_check.result, .cross_check.agree]')"
    # det = a lambda^2 (h-truth4, by hand in the case): a = 0 its own singular point
    # (was exit 2), the conditions a != 0 (were "none left")
    C=cases/truth/lead-zero-polynomial.case
    check "p = 0 at a = 0: region (was exit 2)" \
        '[["stable",null,"0",null],["singular","0","0",true],["stable","0",null,null]]' \
        "$(jfield $C 0 '.intervals | map([.status, .lo, .hi, .vanishes])')"
    check "p = 0 at a = 0: hurwitz and jury say a != 0 (said none)" '[["a != 0"],["a != 0"]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[1].conditions, .[2].conditions]')"
    C=cases/truth/lead-degree-drop.case
    check "degree drop at a = 0: region" \
        '[["stable",null,"-5/4",null],["marginal","-5/4","-5/4",null],["unstable","-5/4","0",null],["singular","0","0",false],["unstable","0","3/4",null],["marginal","3/4","3/4",null],["stable","3/4",null,null]]' \
        "$(jfield $C 0 '.intervals | map([.status, .lo, .hi, .vanishes])')"
    check "degree drop at a = 0: hurwitz agrees at its samples" 'true' "$(jfield $C 1 '.sample_check.agree')"
    # radius roots (h-truth4, by hand in the cases): the roots at 0 listed with their
    # multiplicity; over Q(i) p's own roots, not p conj(p)'s (coordinates x 1e9, rounded)
    RJ='.cases[0].results[0] | [(.roots | map([(.re | tonumber * 1e9 | round + 0), (.im | tonumber * 1e9 | round + 0), .multiplicity]) | sort), .upper]'
    check "radius lists the roots at 0 (were left off)" '[[[-250000000,0,1],[0,0,2],[0,0,2],[500000000,0,1]],"0.5"]' \
        "$("$RS" --json cases/truth/radius-roots-at-zero.case 2>/dev/null | jq -c "$RJ")"
    check "radius over Q(i): p's roots (were p conj(p)'s)" '[[[-333333333,0,1],[0,0,1],[0,500000000,1]],"0.5"]' \
        "$("$RS" --json cases/truth/radius-complex-char.case 2>/dev/null | jq -c "$RJ")"
    # two-parameter claim false on a thin sliver (h-truth4, by hand in the case): refuted
    # by a cell sample of the plane's decomposition (was undecided); the true one stays undecided
    C=cases/truth/claim-thin-sliver-two-params.case
    check "claim 2-param sliver: refuted by the plane's cell sample (was undecided)" '["refuted","unstable","undecided"]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].status, .[0].at_counterexample.status, .[1].status]')"
    ab=$(jfield $C 0 '.counterexample | "\(.a) \(.b)"' | tr -d '"')
    check "claim 2-param sliver: counterexample in the set, a^2 + b^2 < 1" 'True' \
        "$(python3 -c "from fractions import Fraction as F; a, b = map(F, '$ab'.split()); print(F(1001001, 10**6) < a + b < F(2236, 1000) and 0 < b < F(1, 100) and a * a + b * b < 1)")"
    # det A = 0 at the set value (h-truth5, by hand in the case): singular as region says (was exit 2)
    C=cases/truth/stability-det-vanishes-at-set.case
    "$RS" $C >/dev/null 2>&1
    check "det vanishes at set a = 1: exit (the claim refuted)" 1 $?
    check "det vanishes at set a = 1: stability (was exit 2)" '["singular",true,{"a":"1"}]' \
        "$(jfield $C 0 '| [.status, .vanishes, .substituted]')"
    check "det vanishes at set a = 1: jury, routh, hurwitz, radius (were exit 2)" \
        '[["jury","singular",true],["routh","singular",true],["hurwitz","singular",true],["radius","singular",true]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results[1:5] | map([.analysis, .status, .vanishes])')"
    check "det vanishes at set a = 1: claim bounded refuted (was exit 2)" '["refuted","singular",true]' \
        "$(jfield $C 5 '| [.status, .at_counterexample.status, .at_counterexample.vanishes]')"
    check "det vanishes at a = 1: region agrees" '["singular",true]' \
        "$("$RS" --json --analyse 'region a' $C 2>/dev/null | jq -c '.cases[0].results[0].intervals | map(select(.lo == "1" and .hi == "1"))[0] | [.status, .vanishes]')"
    # p = a lambda^2 with a unset (h-truth5, by hand in the case): rho 0 only where a != 0
    C=cases/truth/radius-content-only.case
    check "content-only parameter: valid_if" '[["radius","0",["a != 0"]],["stability","stable",["a != 0"]]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map([.analysis, (.upper // .status), .valid_if])')"
    # hurwitz at a singular set point (h-truth5, by hand in the cases): never stable, as jury says singular
    for C in cases/truth/hurwitz-singular-set-point.case cases/truth/hurwitz-singular-degree-drop.case; do
        check "$(basename $C .case): hurwitz (was stable under the assumptions)" '["never stable",true,"singular"]' \
            "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].verdict, .[0].sample_check.agree, .[1].status]')"
    done
    # condition sets that can never all hold (h-never; each expectation by hand in its case):
    # verdict, the sample check agreeing and confirming no admissible sample satisfies them
    for C in cases/truth/never-disjoint-roots.case cases/truth/never-one-param-bound.case; do
        check "$(basename $C .case): hurwitz and jury never stable" \
            '[["never stable",true,true,"conditions"],["never stable",true,true,"conditions"]]' \
            "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map([.verdict, .sample_check.agree, .sample_check.never_confirmed, .never_from])')"
    done
    C=cases/truth/never-sympy-p6.case
    check "SymPy p6: hurwitz never stable, b0 > 0 against -b0 > 0 in both branches" '["never stable",true,true,2,true]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results[0] | [.verdict, .sample_check.agree, .sample_check.never_confirmed, (.branches | length), (.never | test("branch 1: the conditions b0 > 0 and -b0 > 0 contradict.*branch 2: the conditions -b0 > 0 and b0 > 0 contradict"))]')"
    # jury on p6 (h-truth6): the table's conditions hide D_2 = 0 from rs_conds_never; the
    # bilinear image's never (hurwitz's route, same p) is jury's answer, and its conditions
    # agree with the table's at every sample point (was "stable iff" an empty set)
    check "SymPy p6: jury never stable through the bilinear image, the two routes agree" \
        '["never stable","bilinear","hurwitz",true,true,true]' \
        "$(jfield $C 1 '| [.verdict, .never_from, .cross_route.never_proved_by, .cross_route.agree, .sample_check.agree, .sample_check.never_confirmed]')"
    # conditions reduced to constants name their coefficient (h-truth6, by hand in the case)
    C=cases/truth/hurwitz-stripped-constant.case
    check "hurwitz: 1 > 0 / -1 > 0 said with a_2 = (a + 1)^2, a_0 = -(a - 1)^2" \
        '["never stable",true,true,"0 > 0"]' \
        "$(jfield $C 0 '| [.verdict, (.conditions[0] | startswith("a_2 = a^2 + 2*a + 1 > 0, i.e. 1 > 0 once (a + 1)^2")), (.conditions[1] | startswith("a_0 = -a^2 + 2*a - 1 > 0, i.e. -1 > 0 once (a - 1)^2")), .conditions[2]]')"
    # det A drops a degree at the set value (h-truth6, by hand in the case): every route singular
    C=cases/truth/degree-drop-charpoly-modes.case
    check "degree drop: stability, charpoly, modes, simulate singular (charpoly and modes said nothing)" \
        '["singular","singular","singular","singular"]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].status, .[1].status, .[2].status, .[3].verdict.status]')"
    C=cases/truth/simulate-dead-beat.case
    check "dead-beat p = lambda: simulate gives the exact verdict stable (was growth undefined, no verdict)" \
        '["stable","stable",null]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].status, .[1].verdict.status, .[1].growth]')"
    # a fixed root outside over Q(i) times (lambda - a) (h-truth6, by hand in the case): never
    C=cases/truth/complex-never-root-outside.case
    check "Q(i), root 2i outside: jury and hurwitz never stable, samples agree (was stable iff)" \
        '[["never stable",true,"conditions"],["never stable",true,"conditions"]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map([.verdict, .sample_check.agree, .never_from])')"
    C=cases/truth/never-sympy-p4-nonpositive.case
    check "SymPy p4, a <= 0: hurwitz never stable, a > 0 impossible" '["never stable",true,true,["b0 > 0","a > 0"],true]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results[0] | [.verdict, .sample_check.agree, .sample_check.never_confirmed, .conditions, (.never | startswith("no value with a <= 0 satisfies a > 0"))]')"
    # det A = 0 at the set values (h-polish, by hand in the cases): charpoly, modes,
    # simulate and limit say singular with the reason and "vanishes" as stability (were exit 2)
    C=cases/truth/det-vanishes-charpoly-modes-simulate-limit.case
    check "det vanishes: charpoly, modes, simulate, stability, radius singular (were exit 2)" \
        '[["charpoly","singular",true],["modes","singular",true],["simulate","singular",true],["stability","singular",true],["radius","singular",true]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map([.analysis, .status, .vanishes])')"
    C=cases/truth/det-vanishes-limit.case
    check "det vanishes for every b: limit b -> 0 singular (was exit 2)" '[["limit","singular",true,{"a":"1"}]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map([.analysis, .status, .vanishes, .substituted])')"
    # radius where the implicit step is singular (h-polish, by hand in the case): singular
    # wins, no rho (it printed the reduced polynomial's rho 1/2, or "rho 0" when dead-beat)
    C=cases/truth/radius-singular-step.case
    check "singular step: stability singular, radius singular without rho" '["singular","singular",null,null]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].status, .[1].status, .[1].rho, .[1].roots]')"
    C=cases/truth/hurwitz-singular-set-point.case
    check "singular dead-beat step: radius singular without rho" '["singular",null]' \
        "$("$RS" --json --analyse radius $C 2>/dev/null | jq -c '.cases[0].results[0] | [.status, .rho]')"
    # never-stable reasons (h-polish, by hand in the cases): the wording for a parameter
    # without an assumption, and a pair of conditions with a negative sum (jury said "stable iff")
    C=cases/truth/never-unbounded-param-wording.case
    check "never, a unbounded: hurwitz and jury say 'no real value of a'" '["never stable","never stable",true,true]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].verdict, .[1].verdict, (.[0].never | startswith("no real value of a satisfies")), (.[1].never | startswith("no real value of a satisfies"))]')"
    C=cases/truth/never-sympy-p6-positive.case
    check "SymPy p6, b0 b1 b3 > 0: jury never stable by a negative sum, the samples agree" '["never stable",true,true]' \
        "$(jfield $C 1 '| [.verdict, (.never | contains("their sum is negative")), .sample_check.agree]')"
    # never over Q(sqrt 2) (issue 15; by hand in the case: z = 1 + c^2 in [1, 2], |R| > 1 there):
    # jury, hurwitz and routh said "stable iff" a condition holding nowhere on 0 <= c <= 1
    C=cases/truth/sdirk2-never-qd.case
    check "sdirk2 z = 1 + c^2, 0 <= c <= 1: never stable over Q(sqrt 2), samples agree" \
        '[["never stable","conditions",true],["never stable","conditions",true],["never stable","conditions",true]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '[.cases[0].results[] | [.verdict, .never_from, .sample_check.agree]]')"
    # the control: 0 <= c <= 4 reaches z = 17 > 6 + 4 sqrt 2, where |R| < 1: not never
    sed 's/assume 0 <= c <= 1/assume 0 <= c <= 4/' $C >"$T/never4.case"
    check "sdirk2 z = 1 + c^2, 0 <= c <= 4: stable iff (z > 6 + 4 sqrt 2 reached)" \
        '["stable iff the conditions hold",null]' \
        "$("$RS" --json --analyse jury "$T/never4.case" 2>/dev/null | jq -c '.cases[0].results[0] | [.verdict, .never]')"
    # a zero row of x[n+1] = M x[n] (h-truth7, by hand in the case): det(lambda I - M) =
    # lambda (lambda - 1/2)(lambda + 2), the root at 0 counted (was 1 inside)
    C=cases/truth/zero-row-system.case
    check "zero row: stability, jury, routh count the root at 0 (was 1 inside)" \
        '[["unstable",2,0,1],["unstable",2,0,1],["unstable",2,0,1]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results[0:3] | map([.status, .inside, .on, .outside])')"
    check "zero row: modes list the root at 0" '[["-2","0"],["0","0"],["0.5","0"]]' \
        "$(jfield $C 3 '| [.modes[], (.spurious // [])[]] | map([.root.re, .root.im]) | sort_by(.[0] | tonumber)')"
    # M = 0 (h-truth7, by hand in the case): dead-beat, stable, radius 0 (was exit 2)
    C=cases/truth/dead-beat-zero-matrix.case
    check "x[n+1] = 0*x[n]: stable dead-beat on every route (was exit 2 'no dynamics')" \
        '["stable",1,"stable","stable under the assumptions (dead-beat: every root is 0)","0","stable","proved"]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].status, .[0].inside, .[1].status, .[2].verdict, .[3].upper, .[4].verdict.status, .[5].status]')"
    check "claim without a free parameter: the certificate names no empty point (was 'at : stable')" \
        '"stable (the exact point verdict)"' "$(jfield $C 5 '.certificate[0].text')"
    printf 'title x is zero\nunknown x\neq x[n+1] = 0\nanalyse stability\n' >"$T/zero.case"
    "$RS" "$T/zero.case" >"$T/out" 2>"$T/err"; rc=$?
    check "x[n+1] = 0 alone (x = 0 from n = 0): exit 2 with the dead-beat spelling" "2 1" \
        "$rc $(grep -c 'zero.case:3:4: .*no dynamics.*written x\[n+1\] = 0\*x\[n\]' "$T/err")"
    # never reasons over 1000 characters (h-truth7, by hand in the case): whole, not cut
    C=cases/truth/never-long-reason.case
    check "long never reasons end as written (were cut at 1000 characters mid-number)" \
        '[["never stable",true,true],["never stable",true,true]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map([.verdict, (.never | length > 1000), (.never | test("(interval\\)|allow \\(.*\\)|both|never holds|proves it: .*); never asymptotically stable$"))])')"
    # a dead-beat simulate has no "check" object (h-truth7: it was built and dropped)
    C=cases/truth/simulate-dead-beat.case
    check "dead-beat simulate: the exact verdict decides, no check object" '["exact",null]' \
        "$(jfield $C 1 '| [.verdict.decided_by, .check]')"
    # symbolic Routh arrays singular for every value (h-truth8, by hand in the cases): routh
    # decides never (was: no verdict; a zero pivot was exit 1), hurwitz on the same q agrees
    C=cases/truth/routh-zero-row-symbolic.case
    check "routh zero row: never, A(z) divides q, hurwitz and the samples agree (was no verdict)" \
        '["never stable","16*a + 16*z^2",true,true,"never stable",true]' \
        "$(jfield $C 0 '| [.verdict, .auxiliary, .auxiliary_divides_q, .sample_check.agree, .cross_route.hurwitz_verdict, .cross_route.agree]')"
    C=cases/truth/routh-zero-pivot-symbolic.case
    check "routh zero pivot D_2 = 0: never, rows up to the z^2 row (was exit 1)" \
        '["never stable",[4,3,2],true,["never stable","never stable"]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | [.[0].verdict, .[0].powers, .[0].cross_route.agree, [.[1].verdict, .[2].verdict]]')"
    C=cases/truth/routh-last-row-symbolic.case
    check "routh last row 0 (q(0) = 0): never, lambda = 1 named (was no verdict)" \
        '["never stable",true]' "$(jfield $C 0 '| [.verdict, (.never | test("lambda = 1"))]')"
    # a root 10^-199998 off the circle (h-truth8, by hand in the case): stability and jury
    # decide (were exit 2 with no file:line:col), and inside with z = i (1 - 10^-99999)
    C=cases/truth/complex-near-circle-root.case
    check "root 10^-199998 outside the circle: stability, jury, modes' exact check (were exit 2)" \
        '[["unstable",1],["unstable",1],["unstable",1]]' \
        "$("$RS" --json $C 2>/dev/null | jq -c '.cases[0].results | map([(.status // .exact_check.status), (.outside // .exact_check.outside)])')"
    sed 's/^set z = .*/set z = i*(1 - 10^-99999)/' $C >"$T/near.case"
    check "root 10^-199998 inside the circle: stability, jury" '[["stable",0],["stable",0]]' \
        "$("$RS" --json "$T/near.case" 2>/dev/null | jq -c '.cases[0].results[0:2] | map([.status, .outside])')"
else
    ok "skipped the cases/truth field checks: no jq"
fi

# the random planted parts (tests/truth/truth.py PART SEED COUNT)
if command -v python3 >/dev/null 2>&1; then
    for spec in "qi 1 20" "jordan 1 12" "jordan-param 1 3" "pade 1 24" "lmm 1 6" \
                "region2 1 6" "sweep 1 6" "forall 1 8" "qi-region 1 10" "zregion 1 8" "claimreg 1 8" "forall5 1 9"; do
        # shellcheck disable=SC2086
        RS="$RS" TRUTH_KEEP="$T/failures" python3 tests/truth/truth.py $spec 2>&1 | sed -n '/^ok /p; /^FAIL /p; /Traceback/,$s/^/FAIL /p'
    done
    # second batch (tests/truth/truth2.py, h-truth2)
    for spec in "quick 1 4"; do
        # shellcheck disable=SC2086
        RS="$RS" TRUTH_KEEP="$T/failures" python3 tests/truth/truth2.py $spec 2>&1 | sed -n '/^ok /p; /^FAIL /p; /Traceback/,$s/^/FAIL /p'
    done
    # third batch (tests/truth/truth3.py, h-truth3): roots at 0, circle multiplicities,
    # literature LMMs, algebraic claim ends, simulate and limit
    for spec in "quick 1 8" "lmm 1 11"; do
        # shellcheck disable=SC2086
        RS="$RS" TRUTH_KEEP="$T/failures" python3 tests/truth/truth3.py $spec 2>&1 | sed -n '/^ok /p; /^FAIL /p; /Traceback/,$s/^/FAIL /p'
    done
    # fourth batch (tests/truth/truth4.py, h-truth4): radius roots (zeros, Q(i)) and outward
    # rounding against mpmath, vanishing leading coefficients, singular implicit steps
    for spec in "quick 1 5"; do
        # shellcheck disable=SC2086
        RS="$RS" TRUTH_KEEP="$T/failures" python3 tests/truth/truth4.py $spec 2>&1 | sed -n '/^ok /p; /^FAIL /p; /Traceback/,$s/^/FAIL /p'
    done
    # fifth batch (tests/truth/truth5.py, h-truth5): SymPy's / Nise's / Ogata's Routh and Jury
    # special cases through the bilinear map, planted real circle roots with multiplicity,
    # hostile inputs
    for spec in "quick 1 6"; do
        # shellcheck disable=SC2086
        RS="$RS" TRUTH_KEEP="$T/failures" python3 tests/truth/truth5.py $spec 2>&1 | sed -n '/^ok /p; /^FAIL /p; /Traceback/,$s/^/FAIL /p'
    done
    # sixth batch (tests/truth/truth6.py, h-truth6): planted roots (rational, +-1, circle
    # pairs, conjugate pairs, u +- v sqrt 2, over Q(i)) against stability, jury, hurwitz,
    # routh, radius, modes, simulate, claim, at a set parameter and symbolic, and region
    for spec in "routes 2 3" "systems 2 4"; do
        # shellcheck disable=SC2086
        RS="$RS" TRUTH_KEEP="$T/failures" python3 tests/truth/truth6.py $spec 2>&1 | sed -n '/^ok /p; /^FAIL /p; /Traceback/,$s/^/FAIL /p'
    done
    # seventh batch (tests/truth/truth7.py, h-truth7): the 2-step family (1 + a, a) with its
    # zero-stability boundary, integrators in a cascade under every coupling, textbook Routh
    # special cases through the bilinear map, Jury's reciprocal pairs, a factor whose sign is
    # free, degenerate inputs (all of them)
    for spec in "lmmfam 3 4" "builders 3 3" "routh 3 3" "jurysp 3 3" "symsign 3 2" "degen 3 1"; do
        # shellcheck disable=SC2086
        RS="$RS" TRUTH_KEEP="$T/failures" python3 tests/truth/truth7.py $spec 2>&1 | sed -n '/^ok /p; /^FAIL /p; /Traceback/,$s/^/FAIL /p'
    done
    # eighth batch (tests/truth/truth8.py, h-truth8): symbolic Routh arrays singular for every
    # value (zero row, zero pivot, last row 0) and a control, against mpmath roots; astability
    # of random rational tableaux; sdirk2/3 couplings over Q(sqrt d) at real and complex values
    # against the step matrix's eigenvalues; multistep builders at complex a
    for spec in "rsym 8 8" "astab 8 4" "qdcouple 8 2" "lmmz 8 4"; do
        # shellcheck disable=SC2086
        RS="$RS" TRUTH_KEEP="$T/failures" python3 tests/truth/truth8.py $spec 2>&1 | sed -n '/^ok /p; /^FAIL /p; /Traceback/,$s/^/FAIL /p'
    done
else
    ok "skipped the random planted truths: no python3"
fi

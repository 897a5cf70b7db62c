#!/bin/sh
# run_big.sh -- the planted-truth parts of tests/truth/truth.py at scale
# (opt-in, not part of make check).  Usage, from the repository root:
#   sh tests/truth/run_big.sh [COUNT] [SEEDS]      (defaults: 200 per part, seeds 101 102 103)
# Prints one summary line per part and every FAIL line; failing cases are kept
# in ${TRUTH_KEEP:-/tmp/truth-failures}.
# Measured 2026-11-26 (2 shared cores, loaded): `sh tests/truth/run_big.sh 100 "101 102"`
# ran 1833 planted cases, 0 failed, 94.2 s user + 45.5 s sys CPU (jordan skips
# matrices above 6 x 6; pade has 24 distinct (m, n) per seed).
# truth3.py (h-truth3, 2026-11-27, loaded): `python3 tests/truth/truth3.py zeros S 1500` for
# S = 201, 202: 3000 planted cases, 0 failed, 27.8 + 26.1 s and 24.3 + 21.4 s (user + sys) CPU;
# `circle 201 500`: 500, 0 failed, 9.3 + 8.4 s; algclaim, simlimit 40 and lmm (11 methods) for
# both seeds: 0 failed (the first algclaim run, seed 1, found the claim fixed in bf1b474).
# truth4.py (h-truth4, 2026-11-27, loaded): radius 3 200, lead 3 150, implicit 3 150: 500 planted
# cases, 0 failed; at 3548634 (before): radius 53 of 60 (seed 2) failed (roots at 0 missing, Q(i)
# listed p conj(p)'s roots), lead 24 of 40 (seed 1) exited 2 at a zero of p's content.
# truth5.py (h-truth5, 2026-11-27, loaded): textbook (14 literature polynomials x 2 scalings),
# circle 1 300 and hostile (41 inputs): 369 cases, 0 failed after the fixes; before them nest-200
# (100 parentheses rejected as "over 200") failed, and the hunt's hand probes found hurwitz
# "stable" at singular set points and exit 2 where det A vanishes at set values.
# truth6.py (h-truth6, 2026-11-27, 2 cores shared with 4 other jobs): `truth6.py routes S 120` for
# S = 11, 12 and 106 of seed 13 (at 9800f11's parent d21816e, before the Q(i) fix): 347 planted
# cases, 4 with jury and hurwitz over Q(i) saying "stable iff" an empty condition set in a
# (fixed in 9800f11), 4 with simulate giving no verdict on a dead-beat p = lambda (fixed in
# d21816e), 2 planting bugs of the script (fixed); 441 + 536 s wall per seed.  After the
# fixes: routes 31 and 32 (100 each) and 23 of seed 33: 223 cases, 0 failed, 0 weak (466 s
# wall for seed 31); `truth6.py systems S 100` for S = 51..54: 400 cases, 8 failed, all with
# a zero row or column of M (det A drops that root at 0: counts only, the verdicts agree;
# now skipped by the script); truth.py's jordan through truth6 (seeds 41..43): 352, 0 failed.
# Then routes 61, 62 (100 each) and 57 of seed 63 at 9800f11 (nice 19, beside make check): 257,
# 0 failed, 0 weak.  CPU (/usr/bin/time, user + sys): routes 109, 89, 68, 50, 37, 157 s for
# seeds 11, 12, 31, 32, 61, 62; systems about 5 s per 100 (small numeric cases): about 9 CPU
# minutes in all, short of the hour asked for (the session ended first; the machine was loaded).
# truth7.py (h-truth7, 2026-11-28, 2 cores at load 7-10 from other jobs; CPU by /usr/bin/time -v,
# user + sys, children included): `truth7.py P S 60` for P = lmmfam builders routh jurysp symsign,
# S = 711..716: 1693 ok, 0 failed (116 s); `truth7.py P S 200`, S = 721..728: 8000 ok, 0 failed,
# 0 weak (442 s); `truth6.py systems|routes S 100`, S = 81..86 (systems without the zero-row skip,
# fixed in this session): 1100 ok, 0 failed (356 s); `run_big.sh 60 "701 702"` (every part
# before truth7): 3208 ok and 17 failed (400 s), none of them recstab's: symcond/symmat 4 (truth2
# could not parse h-truth6's 'a_0 = ..., i.e. -1 > 0' wording; fixed), implicit 3 (truth4 still
# wanted exit 2 where h-polish says singular; fixed), cosim 8 (the 20 s wall time limit under
# load: each case takes about 3 s CPU).  About 22 CPU minutes in all, short of the hour asked for
# (the machine ran 8-10 jobs on its 2 cores).  Found before the big runs: truth6 systems' 8
# skipped zero-row cases (det A lost a root at 0; M = 0 exited 2), fixed in scheme.c.
# truth8.py (h-truth8, 2026-11-28, 2 shared cores; CPU by /usr/bin/time, user + sys, children
# excluded): `truth8.py rsym 81 40` 40 ok (9.5 + 2.5 s; recstab's share is in the 297 s wall),
# `astab 82 40` 40 ok (3.5 + 1.3 s), `qdcouple 83 30` 27 ok (14.2 + 1.1 s), `lmmz 84 40` 40 ok
# (3.5 + 1.3 s).  Other seeds: rsym 11..15 x 40: 200 ok (at the parent every non-control case would
# fail: routh gave no verdict, or exit 1 on a zero pivot, by hand probes); astab 21..27, 41..47: 603 ok;
# qdcouple 31..36: 266 ok, 5 singular set values (T's step at d = -1: jury over Q(sqrt d)
# exits 2 there, the other fields say "singular" over Q); lmmz 51..53: 120 ok.  Failures seen
# were the script's own (nsimplify rounding R, mpmath QR stalls; fixed).
COUNT=${1:-200}
SEEDS=${2:-"101 102 103"}
RS=${RS:-build/recstab}
export RS
total_fail=0
for part in qi jordan jordan-param pade lmm region2 sweep forall qi-region zregion claimreg \
            symcond symmat rk builders limit radmat map cosim zeros circle lmm3 algclaim simlimit \
            radius lead implicit textbook circle5 hostile routes systems \
            lmmfam builders routh jurysp symsign degen; do
    n=$COUNT
    [ "$part" = jordan-param ] && n=$((COUNT / 10 + 1))
    script=tests/truth/truth.py
    case $part in symcond|symmat|rk|builders|limit|radmat|map|cosim) script=tests/truth/truth2.py ;; esac
    case $part in zeros|circle|lmm3|algclaim|simlimit) script=tests/truth/truth3.py ;; esac
    case $part in radius|lead|implicit) script=tests/truth/truth4.py ;; esac
    case $part in textbook|circle5|hostile) script=tests/truth/truth5.py ;; esac
    case $part in routes|systems) script=tests/truth/truth6.py ;; esac
    case $part in lmmfam|builders|routh|jurysp|symsign|degen) script=tests/truth/truth7.py ;; esac
    okc=0; fc=0
    for s in $SEEDS; do
        out=$(python3 "$script" "$part" "$s" "$n" 2>&1)
        okc=$((okc + $(printf '%s\n' "$out" | grep -c '^ok ')))
        f=$(printf '%s\n' "$out" | grep -c '^FAIL \|Traceback')
        fc=$((fc + f))
        [ "$f" -gt 0 ] && printf '%s\n' "$out" | grep '^FAIL \|Traceback\|Error'
    done
    echo "$part: $okc ok, $fc failed"
    total_fail=$((total_fail + fc))
done
[ "$total_fail" -eq 0 ]

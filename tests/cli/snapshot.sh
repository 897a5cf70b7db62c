#!/bin/sh
# Safety net for refactoring (issue 12): record what the command prints for
# every case in cases/, then compare two recordings byte for byte.
#   sh tests/cli/snapshot.sh record DIR [BIN]   # DIR outside the repository
#   sh tests/cli/snapshot.sh compare DIR1 DIR2  # exit 1 and a diff if they differ
# For each case: --json output, the text report, --emit equations output,
# the --markdown and --latex derivations, and their exit statuses; then a few
# --analyse runs (extra-*) of analyses no case requests, in all four formats,
# so that every renderer path is recorded. Keys that vary from run to run ("seconds", "threads", times in
# the text) are normalised. SNAP_TIMEOUT (default 120 s) bounds each run.
set -u
cmd=${1:-}
case "$cmd" in
record)
    out=${2:?usage: snapshot.sh record DIR [BIN]}
    bin=${3:-build/recstab}
    to=${SNAP_TIMEOUT:-120}
    mkdir -p "$out"
    for f in $(find cases -name '*.case' | sort); do
        name=$(echo "$f" | tr / _)
        # the run's own directory (include files are relative to the case)
        timeout "$to" "$bin" --json --threads 1 "$f" >"$out/$name.json" 2>"$out/$name.json.err"
        echo "exit $?" >>"$out/$name.json.err"
        timeout "$to" "$bin" --threads 1 "$f" >"$out/$name.txt" 2>"$out/$name.txt.err"
        echo "exit $?" >>"$out/$name.txt.err"
        timeout "$to" "$bin" --emit equations "$f" >"$out/$name.eq" 2>"$out/$name.eq.err"
        echo "exit $?" >>"$out/$name.eq.err"
        timeout "$to" "$bin" --markdown --threads 1 "$f" >"$out/$name.md" 2>"$out/$name.md.err"
        echo "exit $?" >>"$out/$name.md.err"
        timeout "$to" "$bin" --latex --threads 1 "$f" >"$out/$name.tex" 2>"$out/$name.tex.err"
        echo "exit $?" >>"$out/$name.tex.err"
        sed -i -e 's/"seconds": *[-0-9.eE+]*/"seconds": S/g' \
               -e 's/"seconds_points": *[-0-9.eE+]*/"seconds_points": S/g' \
               -e 's/"threads": *[0-9]*/"threads": T/g' "$out/$name.json"
        # the reports' timings ("computed N points in X s")
        sed -i -e 's/points in [0-9.]* s/points in S s/' "$out/$name.txt" "$out/$name.md" "$out/$name.tex"
    done
    # analyses no case requests: NAME|CASE|SET|ANALYSIS (SET: --set values
    # separated by spaces, or empty; the text report's "computed ... s" is normalised)
    cd_=cases/textbook/central-difference.case
    while IFS='|' read -r name f set req; do
        sets=
        for v in $set; do sets="$sets --set $v"; done
        for fmt in json txt md tex; do
            case $fmt in json) opt=--json ;; txt) opt= ;; md) opt=--markdown ;; tex) opt=--latex ;; esac
            timeout "$to" "$bin" $opt --threads 1 $sets --analyse "$req" "$f" \
                >"$out/extra-$name.$fmt" 2>"$out/extra-$name.$fmt.err"
            echo "exit $?" >>"$out/extra-$name.$fmt.err"
        done
        sed -i -e 's/"seconds": *[-0-9.eE+]*/"seconds": S/g' \
               -e 's/"seconds_points": *[-0-9.eE+]*/"seconds_points": S/g' \
               -e 's/"threads": *[0-9]*/"threads": T/g' "$out/extra-$name.json"
        sed -i -e 's/points in [0-9.]* s/points in S s/' "$out/extra-$name.txt" "$out/extra-$name.md" "$out/extra-$name.tex"
    done <<EXTRA
sweep|$cd_||sweep w from 0 to 4 steps 8
sweep-long|$cd_||sweep w from 0 to 4 steps 70
sweep-modes|$cd_||sweep w from 1/2 to 3 steps 5 of modes reference=w
map|cases/park-staggered.case|muh=1 wh=1|map alpha 0 3 4, m 1/10 20 3
map-exact|cases/li-explicit-k1.case||map acc1 0 3 3, c1 1/2 2 2
simulate|$cd_|w=1|simulate steps=200 seed=3
modes|$cd_|w=1|modes
limit|$cd_||limit w -> inf
claim-refuted|$cd_||claim stable when w < 3
claim-proved|cases/textbook/forward-euler.case||claim unstable
region-symbolic|cases/park-staggered.case||region alpha
jury|$cd_|w=1|jury
jury-symbolic|$cd_||jury
routh-symbolic|$cd_||routh
stability|$cd_|w=1|stability
stability-cosim|cases/li-explicit-k1.case||stability
radius|$cd_|w=1|radius
expect-different|$cd_||expect charpoly lambda^2 + 1
not-in-p|cases/textbook/jordan-vs-identity.case||stability
jury-regular|cases/textbook/bdf2.case|w=1|jury
hurwitz-numeric|cases/textbook/bdf2.case|w=1|hurwitz
EXTRA
    echo "recorded $(ls "$out" | grep -c '\.json$') cases in $out"
    ;;
compare)
    a=${2:?usage: snapshot.sh compare DIR1 DIR2}; b=${3:?usage: snapshot.sh compare DIR1 DIR2}
    if diff -r "$a" "$b"; then echo "snapshot: identical ($(ls "$a" | grep -c '\.json$') cases)"
    else echo "snapshot: DIFFERENT"; exit 1; fi
    ;;
*) echo "usage: snapshot.sh record DIR [BIN] | compare DIR1 DIR2" >&2; exit 2 ;;
esac

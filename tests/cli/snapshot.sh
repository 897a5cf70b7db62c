#!/bin/sh
# Safety net for refactoring (issue 12): record what the command prints for
# every case in cases/, then compare two recordings byte for byte.
#   sh tests/cli/snapshot.sh record DIR [BIN]   # DIR outside the repository
#   sh tests/cli/snapshot.sh compare DIR1 DIR2  # exit 1 and a diff if they differ
# For each case: --json output, the text report, --emit equations output,
# and their exit statuses. Keys that vary from run to run ("seconds", "threads", times in
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
        sed -i -e 's/"seconds": *[-0-9.eE+]*/"seconds": S/g' \
               -e 's/"threads": *[0-9]*/"threads": T/g' "$out/$name.json"
    done
    echo "recorded $(ls "$out" | grep -c '\.json$') cases in $out"
    ;;
compare)
    a=${2:?usage: snapshot.sh compare DIR1 DIR2}; b=${3:?usage: snapshot.sh compare DIR1 DIR2}
    if diff -r "$a" "$b"; then echo "snapshot: identical ($(ls "$a" | grep -c '\.json$') cases)"
    else echo "snapshot: DIFFERENT"; exit 1; fi
    ;;
*) echo "usage: snapshot.sh record DIR [BIN] | compare DIR1 DIR2" >&2; exit 2 ;;
esac

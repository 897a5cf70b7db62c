#!/bin/sh
# check_deps.sh -- the dependency rule of docs/architecture.md:
#
#     util <- lang <- lower <- algebra <- numeric <- stability <- analysis <- render <- cli
#
# A file may include headers of its own stage and of earlier stages only.
# Inside the kernel {algebra, numeric, stability} the order is algebra (exact
# polynomials, conditions and the parameter signs) <- numeric (certified
# isolation, radius, the verdict ladder with its exact rung passed in) <-
# stability (the exact counts, which check themselves against certified
# isolation, and the semisimplicity verdict over them).
# Every #include "..." of src/*/*.[ch] and include/recstab/*.h is checked:
#   "recstab/NAME.h"   a public header, its stage from the table below
#   "STAGE/NAME.h"     a private header of that stage (src/STAGE/NAME.h)
#   "NAME.h"           a header next to the file (same stage)
# Public headers may include public headers only.  Exceptions would be
# listed in KNOWN; the list can only shrink: a new violation fails, and so
# does a listed one that is gone.
# Prints "ok deps ..." / "FAIL deps ..." lines (tests/run.sh counts them).
cd "$(dirname "$0")/.." || exit 1

rank() {
    case $1 in
    util) echo 0 ;; lang) echo 1 ;; lower) echo 2 ;;
    algebra) echo 3 ;; numeric) echo 4 ;; stability) echo 5 ;;
    analysis) echo 6 ;; render) echo 7 ;; cli) echo 8 ;;
    *) echo x ;;
    esac
}

# the stage of each public header (where its functions are defined)
public_stage() {
    case $1 in
    error|budget|str) echo util ;;
    expr|casefile) echo lang ;;
    model|scheme) echo lower ;;
    charpoly|cond) echo algebra ;;
    bilinear|routh|hurwitz|jury|rootcount|semisimple|positivity) echo stability ;;
    radius|cosim|ladder) echo numeric ;;
    analysis|sweep|api) echo analysis ;;     # sweep.h: src/analysis/analysis_sweep.c
    report|derivation|recstab) echo render ;;
    *) echo unknown ;;
    esac
}

# "FILE -> HEADER" allowed for now; each removed by a phase-B item (issue 12)
KNOWN='
'

fails=0
seen=$(mktemp)
trap 'rm -f "$seen"' EXIT

check_file() { # file stage
    f=$1; st=$2; r=$(rank "$st"); bad=0
    for inc in $(sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p' "$f"); do
        case $inc in
        recstab/*.h) n=${inc#recstab/}; tst=$(public_stage "${n%.h}") ;;
        */*.h)       tst=${inc%%/*}
                     [ -f "src/$inc" ] || tst=unknown
                     case $f in include/*) tst=private ;; esac ;;
        *.h)         [ -f "$(dirname "$f")/$inc" ] && tst=$st || tst=unknown ;;
        *)           tst=unknown ;;
        esac
        case $tst in
        unknown) echo "FAIL deps $f: includes \"$inc\", neither a public header in public_stage nor an existing src/STAGE/NAME.h"
                 bad=1; continue ;;
        private) echo "FAIL deps $f: a public header includes the private \"$inc\""
                 bad=1; continue ;;
        esac
        tr=$(rank "$tst")
        if [ "$tst" = "$st" ] || [ "$tr" -lt "$r" ]; then continue; fi
        if printf '%s\n' "$KNOWN" | grep -qxF "$f -> $inc"; then
            echo "$f -> $inc" >>"$seen"; continue
        fi
        echo "FAIL deps $f ($st) includes \"$inc\" ($tst): against util <- lang <- lower <- algebra <- numeric <- stability <- analysis <- render <- cli"
        bad=1
    done
    return $bad
}

for d in src/*/; do
    st=$(basename "$d")
    if [ "$(rank "$st")" = x ]; then echo "FAIL deps $d: not a stage folder"; fails=1; continue; fi
    ok=1
    for f in "$d"*.c "$d"*.h; do
        [ -f "$f" ] || continue
        check_file "$f" "$st" || ok=0
    done
    [ $ok = 1 ] && echo "ok deps $d"
done
ok=1
for f in include/recstab/*.h; do
    n=$(basename "$f" .h); st=$(public_stage "$n")
    if [ "$st" = unknown ]; then echo "FAIL deps $f: a public header of no stage (add it to public_stage)"; ok=0; continue; fi
    check_file "$f" "$st" || ok=0
done
[ $ok = 1 ] && echo "ok deps include/recstab/"

# every known exception must still be needed (the list only shrinks)
ok=1
printf '%s\n' "$KNOWN" | while IFS= read -r e; do
    [ -n "$e" ] || continue
    grep -qxF "$e" "$seen" || { echo "FAIL deps known exception no longer occurs, remove it from KNOWN: $e"; }
done | grep . && ok=0
[ $ok = 1 ] && echo "ok deps known exceptions all still needed ($(printf '%s\n' "$KNOWN" | grep -c .))"
exit 0

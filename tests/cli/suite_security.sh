#!/bin/sh
# suite_security.sh -- untrusted names and hostile output targets (issue 11,
# "Security"): text that reaches gnuplot runs nothing; --csv/--plot never
# replace a device, FIFO, symbolic link or folder; a failure after staging
# (stdout, a rename) or SIGINT/SIGTERM leaves no committed file, no
# temporary and no gnuplot; include reads each file once, refuses
# non-regular files and caps files and bytes; a non-UTF-8 case path prints
# escaped.  Every expectation follows from the documented behaviour (README
# "Output files", "include"), not from a recorded run.
# Prints "ok ..." or "FAIL ..." per check ("skip ..." without gnuplot).
BUILD=${BUILD:-build}
RS="$(cd "$BUILD" 2>/dev/null && pwd)/recstab"
SRC=$(pwd)
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"     # the plot's private folder and through-stages go here
mkdir -p "$TMPDIR"

ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }
check_exit() { if [ "$2" = "$3" ]; then ok "$1"; else fail "$1: exit $3, expected $2"; head -c 600 "$T/err"; fi; }
# no PATH.tmp.* staged file and nothing in TMPDIR
no_leftovers() { # label dir
    left=$(find "$2" "$TMPDIR" -mindepth 1 \( -name '*.tmp.*' -o -path "$TMPDIR/*" \) 2>/dev/null | head -3)
    if [ -z "$left" ]; then ok "$1: no temporaries left"; else fail "$1: left $left"; fi
}

CD="$SRC/cases/textbook/central-difference.case"
SW="sweep w from 0 to 4 steps 8"
# central difference with the frequency split w^2 = a*w^2: two parameters for a map
TWO='param w a
assume w > 0
unknown x
eq x[n+1] - 2*x[n] + x[n-1] + a*w^2*x[n] = 0
'
HAVE_GP=0; command -v gnuplot >/dev/null 2>&1 && HAVE_GP=1

# ---- 1. nothing user-supplied executes inside gnuplot ------------------------
if [ $HAVE_GP = 1 ]; then
    D="$T/inj"; mkdir -p "$D"
    # a file name with newlines, both quotes, backquotes, @, a backslash and
    # system(...) on a line of its own; no title, so the name is the legend
    NAME=$(printf 'x\nsystem("touch SENTINEL1")\n`touch SENTINEL2` '"'"'q" \\ @x @ARG0\n.case')
    printf '%s' "$TWO" >"$D/$NAME"
    # a title that closes a quote and calls system() (a title is one line)
    printf 'title t" . system("touch SENTINEL3") . "'"'"' `touch SENTINEL4` \\ @ARG0 end\n%s' "$TWO" >"$D/titled.case"
    (cd "$D" && "$RS" --plot "o.0.png" --set a=1 --analyse "$SW" "$NAME" titled.case) >"$T/out" 2>"$T/err"
    check_exit "--plot hostile file name and title: exit" 0 $?
    (cd "$D" && "$RS" --plot "m'\`touch SENTINEL5\`\".7.svg" --analyse "map w 0 3 5, a 0 2 4" "$NAME") >"$T/out" 2>"$T/err"
    check_exit "--plot hostile map and output name: exit" 0 $?
    # gnuplot runs "|cmd" given as an output file name
    (cd "$D" && "$RS" --plot "|touch SENTINEL6.png" --analyse "$SW" "$CD") >"$T/out" 2>"$T/err"
    check_exit "--plot '|command' output name: exit" 0 $?
    if [ -s "$D/|touch SENTINEL6.png" ]; then ok "--plot '|command': a file of that name"
    else fail "--plot '|command': $(ls "$D" | tr '\n' ' ')"; fi
    # a relative TMPDIR that reads as a gnuplot option or an input pipe
    for td in '-e system("touch SENTINEL7")' '<touch SENTINEL8'; do
        mkdir -p "$D/$td"
        (cd "$D" && TMPDIR="$td" "$RS" --plot t.png --analyse "$SW" "$CD") >"$T/out" 2>"$T/err"
        check_exit "--plot TMPDIR='$td': exit" 0 $?
        rmdir "$D/$td"
    done
    if head -c 8 "$D/o.0.png" | od -c | grep -q 'P   N   G' && [ -s "$D/m'\`touch SENTINEL5\`\".7.svg" ]; then
        ok "--plot hostile names: the PNG and the SVG are written"
    else fail "--plot hostile names: no plot ($(ls "$D" | tr '\n' ' '))"; fi
    if [ -z "$(find "$T" -name 'SENTINEL*')" ]; then ok "--plot hostile names: gnuplot ran nothing"
    else fail "--plot hostile names: gnuplot ran $(find "$T" -name 'SENTINEL*')"; fi
    no_leftovers "--plot hostile names" "$D"
else
    echo "skip gnuplot injection checks (gnuplot not installed: make deps)"
fi

# ---- 2. output targets that are not regular files ----------------------------
D="$T/targets"; mkdir -p "$D"
# a FIFO is written through and stays a FIFO
mkfifo "$D/fifo.csv"
timeout 10 cat "$D/fifo.csv" >"$D/from-fifo" &
reader=$!
timeout 20 "$RS" --csv "$D/fifo.csv" --analyse "$SW" "$CD" >"$T/out" 2>"$T/err"
check_exit "--csv FIFO: exit" 0 $?
wait $reader
if [ -p "$D/fifo.csv" ] && grep -q '^# recstab table 1: ' "$D/from-fifo"; then ok "--csv FIFO: written through, still a FIFO"
else fail "--csv FIFO: $(ls -l "$D/fifo.csv")"; fi
# a character device (a null device of our own when we may create one;
# /dev/null itself is never put at risk)
if mknod "$D/null.csv" c 1 3 2>/dev/null; then
    "$RS" --csv "$D/null.csv" --analyse "$SW" "$CD" >"$T/out" 2>"$T/err"
    check_exit "--csv character device: exit" 0 $?
    if [ -c "$D/null.csv" ]; then ok "--csv character device: still a device"; else fail "--csv device replaced: $(ls -l "$D/null.csv")"; fi
else
    echo "skip --csv character device (mknod needs root)"
fi
# "-" is stdout for --csv; the report moves to stderr
(cd "$D" && "$RS" --csv - --analyse "$SW" "$CD") >"$T/out" 2>"$T/err"   # in $D: a file "-" must not land in the tree
check_exit "--csv -: exit" 0 $?
if head -1 "$T/out" | grep -q '^# recstab table 1: ' && grep -q '^case ' "$T/err" && ! grep -q '^case ' "$T/out"; then
    ok "--csv -: the CSV on stdout, the report on stderr"
else fail "--csv -: stdout $(head -c 200 "$T/out")"; fi
# a symbolic link is refused before any work; link and target untouched
echo old >"$D/target.csv"
ln -s target.csv "$D/link.csv"
"$RS" --csv "$D/link.csv" --analyse "$SW" "$CD" >"$T/out" 2>"$T/err"
check_exit "--csv symbolic link: exit" 2 $?
if [ -L "$D/link.csv" ] && [ "$(cat "$D/target.csv")" = old ] && [ ! -s "$T/out" ] \
   && grep -q "recstab: --csv: '$D/link.csv' is a symbolic link" "$T/err"; then
    ok "--csv symbolic link: refused, nothing on stdout, link and target unchanged"
else fail "--csv symbolic link: $(cat "$T/err")"; fi
mkdir "$D/dir.png"
"$RS" --plot "$D/dir.png" --analyse "$SW" "$CD" >"$T/out" 2>"$T/err"
check_exit "--plot folder: exit" 2 $?
if [ "$(cat "$T/err")" = "recstab: --plot: '$D/dir.png' is a folder: expected a file name" ]; then ok "--plot folder: message"
else fail "--plot folder: $(cat "$T/err")"; fi
no_leftovers "refused targets" "$D"

# ---- 4. nothing committed unless everything succeeded ------------------------
D="$T/commit"; mkdir -p "$D"
echo keep >"$D/keep.csv"
"$RS" --csv "$D/keep.csv" --analyse "$SW" "$CD" >/dev/full 2>"$T/err"
check_exit "stdout /dev/full: exit" 2 $?
if [ "$(cat "$D/keep.csv")" = keep ]; then ok "stdout /dev/full: the old CSV is back"; else fail "stdout /dev/full: CSV replaced"; fi
"$RS" --csv "$D/new.csv" --analyse "$SW" "$CD" >/dev/full 2>"$T/err"
if [ ! -e "$D/new.csv" ]; then ok "stdout /dev/full: no new CSV"; else fail "stdout /dev/full: new.csv committed"; fi
no_leftovers "stdout /dev/full" "$D"
# stdout a pipe whose reader is gone: EPIPE, not a SIGPIPE death after the commit
"$RS" --csv "$D/keep.csv" --analyse "$SW" "$CD" 2>"$T/err" | :
if [ "$(cat "$D/keep.csv")" = keep ] && grep -q 'cannot write output' "$T/err"; then ok "stdout closed pipe: the old CSV is back"
else fail "stdout closed pipe: $(cat "$T/err")"; fi
no_leftovers "stdout closed pipe" "$D"
if [ $HAVE_GP = 1 ]; then
    # a gnuplot that puts a folder where the plot goes, then plots: the plot
    # cannot be renamed, so the CSV renamed before it must be undone
    mkdir -p "$T/bin-dir"
    printf '#!/bin/sh\nmkdir "%s"\nexec %s "$@"\n' "$D/p.png" "$(command -v gnuplot)" >"$T/bin-dir/gnuplot"
    chmod +x "$T/bin-dir/gnuplot"
    PATH="$T/bin-dir:$PATH" "$RS" --csv "$D/keep.csv" --plot "$D/p.png" --analyse "$SW" "$CD" >"$T/out" 2>"$T/err"
    check_exit "failed plot rename: exit" 2 $?
    if [ "$(cat "$D/keep.csv")" = keep ] && [ -d "$D/p.png" ] && [ ! -s "$T/out" ]; then
        ok "failed plot rename: the CSV is put back, nothing on stdout"
    else fail "failed plot rename: $(cat "$T/err")"; fi
    no_leftovers "failed plot rename" "$D"
    rmdir "$D/p.png"
fi

# ---- 4. SIGINT / SIGTERM: 130 / 143, no temporaries, no gnuplot --------------
# a gnuplot that ignores both signals and never finishes: only recstab's
# SIGKILL ends it
mkdir -p "$T/bin-hang"
printf '#!/bin/sh\ntrap "" INT TERM\necho $$ >"%s"\nexec sleep 60\n' "$T/gp.pid" >"$T/bin-hang/gnuplot"
chmod +x "$T/bin-hang/gnuplot"
for sig in INT TERM; do
    want=130; [ $sig = TERM ] && want=143
    rm -f "$T/gp.pid"
    PATH="$T/bin-hang:$PATH" timeout --preserve-status -s $sig 1 \
        "$RS" --csv "$D/s.csv" --plot "$D/s.png" --analyse "$SW" "$CD" >"$T/out" 2>"$T/err"
    check_exit "SIG$sig during gnuplot: exit" $want $?
    pid=$(cat "$T/gp.pid" 2>/dev/null)
    if [ -n "$pid" ] && ! kill -0 "$pid" 2>/dev/null; then ok "SIG$sig during gnuplot: gnuplot stopped"
    else fail "SIG$sig during gnuplot: gnuplot ${pid:-never started} still runs"; [ -n "$pid" ] && kill -9 "$pid"; fi
    if [ ! -e "$D/s.csv" ] && [ ! -e "$D/s.png" ]; then ok "SIG$sig during gnuplot: nothing committed"
    else fail "SIG$sig during gnuplot: committed $(ls "$D")"; fi
    no_leftovers "SIG$sig during gnuplot" "$D"
done
# during a long map (400,000 points on one thread: several seconds)
timeout --preserve-status -s INT 1 "$RS" --threads 1 --csv "$D/m.csv" --plot "$D/m.png" --set muh=1 --set wh=1 \
    --analyse "map alpha 0 3 1000, m 1/10 20 400" "$SRC/cases/park-staggered.case" >"$T/out" 2>"$T/err"
check_exit "SIGINT during a map: exit" 130 $?
if [ ! -e "$D/m.csv" ] && [ ! -e "$D/m.png" ] && [ ! -s "$T/out" ]; then ok "SIGINT during a map: nothing written"
else fail "SIGINT during a map: $(ls "$D")"; fi
no_leftovers "SIGINT during a map" "$D"

# ---- 3. include ---------------------------------------------------------------
D="$T/inc"; mkdir -p "$D/frag"
# 16 files, each including the next three times: 3^15 reads before (days), 16 now
k=0
while [ $k -lt 15 ]; do
    n=$((k + 1)); printf 'include f%d.inc\ninclude f%d.inc\ninclude f%d.inc\n' $n $n $n >"$D/frag/f$k.inc"; k=$n
done
printf '# the leaf\n' >"$D/frag/f15.inc"
printf 'param w\ninclude frag/f0.inc\nunknown x\neq x[n+1] - 2*x[n] + x[n-1] + w^2*x[n] = 0\nanalyse charpoly\n' >"$D/triple.case"
timeout 2 "$RS" "$D/triple.case" >"$T/out" 2>"$T/err"
check_exit "include three times at depth 15: exit (within 2 s)" 0 $?
# the same fragment (a declaration) reached twice, as a diamond: applied once
printf 'param w\nassume w > 0\n' >"$D/frag/common.inc"
printf 'include common.inc\n' >"$D/frag/left.inc"
printf 'include ../frag/common.inc\n' >"$D/frag/right.inc"
printf 'include frag/left.inc\ninclude frag/right.inc\nunknown x\neq x[n+1] - 2*x[n] + x[n-1] + w^2*x[n] = 0\nanalyse charpoly\n' >"$D/diamond.case"
"$RS" "$D/diamond.case" >"$T/out" 2>"$T/err"
check_exit "include diamond: exit" 0 $?
# the Hughes closed form of central-difference.case
if grep -q 'p(lambda)    lambda^2 + (w^2 - 2)\*lambda + 1' "$T/out"; then ok "include diamond: the fragment applies once"
else fail "include diamond: $(grep 'p(lambda)' "$T/out")"; fi
# a FIFO is refused at once (it would block the parse), as /dev/zero and folders (tests/bad)
mkfifo "$D/frag/pipe.inc"
printf 'param w\ninclude frag/pipe.inc\n' >"$D/fifo.case"
timeout 10 "$RS" "$D/fifo.case" >"$T/out" 2>"$T/err"
check_exit "include FIFO: exit" 2 $?
if [ "$(cat "$T/err")" = "recstab: $D/fifo.case:2:9: cannot include '$D/frag/pipe.inc': expected a regular file, found a FIFO" ]; then
    ok "include FIFO: message"; else fail "include FIFO: $(cat "$T/err")"; fi
# 257 distinct files: over the limit of 256, reported at the 257th include
k=1; : >"$D/many.case"
while [ $k -le 257 ]; do : >"$D/frag/e$k.inc"; echo "include frag/e$k.inc" >>"$D/many.case"; k=$((k + 1)); done
"$RS" "$D/many.case" >"$T/out" 2>"$T/err"
check_exit "include 257 files: exit" 2 $?
if [ "$(cat "$T/err")" = "recstab: $D/many.case:257:9: more than 256 files included" ]; then ok "include 257 files: message"
else fail "include 257 files: $(cat "$T/err")"; fi
# two 8.4 MB fragments: each under the 16 MiB of one file, together over the 16 MiB of all includes
head -c 8400000 /dev/zero | tr '\000' '\n' >"$D/frag/big1.inc"
cp "$D/frag/big1.inc" "$D/frag/big2.inc"
printf 'include frag/big1.inc\ninclude frag/big2.inc\n' >"$D/bytes.case"
"$RS" "$D/bytes.case" >"$T/out" 2>"$T/err"
check_exit "include 16.8 MB: exit" 2 $?
if [ "$(cat "$T/err")" = "recstab: $D/bytes.case:2:9: included files over 16 MiB in all (the limit)" ]; then ok "include 16.8 MB: message"
else fail "include 16.8 MB: $(cat "$T/err")"; fi

# ---- 5. a case path that is not UTF-8 -------------------------------------------
D="$T/utf"; mkdir -p "$D"
BAD=$(printf 'bad\377name.case')
cp "$CD" "$D/$BAD"
(cd "$D" && "$RS" --analyse charpoly "$BAD") >"$T/out" 2>"$T/err"
check_exit "non-UTF-8 path: exit" 0 $?
if [ "$(head -1 "$T/out")" = 'case bad\xffname.case: Central difference, undamped oscillator' ]; then ok "non-UTF-8 path: text escapes the byte"
else fail "non-UTF-8 path: $(head -1 "$T/out")"; fi
(cd "$D" && "$RS" --json --analyse charpoly "$BAD") >"$T/out" 2>"$T/err"
if grep -q '"case": "bad\\\\xffname.case"' "$T/out"; then ok "non-UTF-8 path: JSON escapes the byte"
else fail "non-UTF-8 path JSON: $(grep case "$T/out" | head -2)"; fi
(cd "$D" && "$RS" --csv "$(printf 'o\377.csv')" --analyse "$SW" "$BAD") >"$T/out" 2>"$T/err"
if grep -q '^  csv          o\\xff\.csv$' "$T/out"; then ok "non-UTF-8 --csv path: the report names it escaped"
else fail "non-UTF-8 --csv path: $(grep csv "$T/out")"; fi

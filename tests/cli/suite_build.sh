#!/bin/sh
# suite_build.sh -- the Makefile's choice of FLINT (issue 16), with fake
# pkg-config programs (PKG_CONFIG=...): FLINT 3 found by pkg-config (Arb is
# part of it: its cflags plus INCLUDEDIR/flint for <arb.h>, its libs, no
# Arb library), a FLINT 2 .pc (not 3: Debian's pair), no flint.pc, and no
# pkg-config at all (both: Debian's FLINT 2.9 + Arb 2.23, -lflint-arb).
# The expected flags follow from the layouts: FLINT 3 installs every header
# in PREFIX/include/flint/ and one library libflint; Debian's libflint-dev
# has /usr/include/flint/, libflint-arb-dev /usr/include/arb.h and
# libflint-arb.so.  Only the choice is tested here; `make check-flint3`
# (tests/flint3.sh, run by CI) builds and tests against a real FLINT 3.
# Prints "ok ..." or "FAIL ..." per check.
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
ok()   { echo "ok $*"; }
fail() { echo "FAIL $*"; }

# fake pkg-config VERSION PREFIX: a flint.pc of that version at PREFIX
fake() {
    cat >"$T/$1" <<EOS
#!/bin/sh
for a in "\$@"; do
    case \$a in
    --atleast-version=*) v=\${a#--atleast-version=}; [ "\${2:-}" = flint ] || exit 1
        [ "\$(printf '%s\n%s\n' "\$v" "$2" | sort -V | head -1)" = "\$v" ] && exit 0 || exit 1 ;;
    --cflags) echo "-I$3/include" ; exit 0 ;;
    --libs) echo "-L$3/lib -lflint" ; exit 0 ;;
    --variable=includedir) echo "$3/include" ; exit 0 ;;
    esac
done
exit 1
EOS
    chmod +x "$T/$1"
}
fake pc3 3.1.2 /opt/flint3
fake pc2 2.9.0 /opt/flint2
printf '#!/bin/sh\nexit 1\n' >"$T/pcnone"; chmod +x "$T/pcnone"

flags() { make -s --no-print-directory print-flint PKG_CONFIG="$1" 2>/dev/null; }

out=$(flags "$T/pc3")
echo "$out" | grep -qx 'FLINT3=yes' && ok "build: FLINT 3 found by pkg-config" || fail "build: FLINT 3 not chosen: $out"
echo "$out" | grep -qx 'FLINT_CFLAGS=-I/opt/flint3/include -I/opt/flint3/include/flint' \
    && ok "build: FLINT 3 cflags (its include dir and include/flint for <arb.h>)" || fail "build: FLINT 3 cflags: $out"
echo "$out" | grep -qx 'FLINT_LIBS=-L/opt/flint3/lib -lflint' \
    && ok "build: FLINT 3 libs, no Arb library" || fail "build: FLINT 3 libs: $out"
for pc in pc2 pcnone /nonexistent/pkg-config; do
    case $pc in /*) p=$pc ;; *) p=$T/$pc ;; esac
    out=$(flags "$p")
    if echo "$out" | grep -qx 'FLINT3=' && echo "$out" | grep -qx 'FLINT_CFLAGS=-I/usr/include/flint' \
        && echo "$out" | grep -qx 'FLINT_LIBS=-lflint-arb -lflint'; then ok "build: $pc: Debian's FLINT 2.9 + Arb"
    else fail "build: $pc: $out"; fi
done
# the real machine: what is installed links (the build of `make all` did)
out=$(flags pkg-config)
if pkg-config --atleast-version=3 flint 2>/dev/null; then want=yes; else want=; fi
echo "$out" | grep -qx "FLINT3=$want" && ok "build: this machine's FLINT (${want:-2.9 + Arb}) chosen" || fail "build: this machine: $out"

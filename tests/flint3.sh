#!/bin/sh
# flint3.sh -- build recstab against a real FLINT 3 (Arb merged into FLINT,
# one library libflint, headers in include/flint/) and run the whole test
# suite on it (issue 16: "FLINT 3 untested").  This machine is Debian
# bookworm, whose FLINT is 2.9 + Arb 2.23; Debian trixie's libflint-dev and
# libflint19 (FLINT 3.1) need only glibc 2.34, GMP and MPFR, which bookworm
# has.  The two packages are fetched from Debian's archive, checked against
# the SHA256 sums of the archive's Packages index, unpacked (dpkg -x, no
# installation) under $OUT, and found by the Makefile through pkg-config
# (PKG_CONFIG_PATH) exactly as an installed FLINT 3 would be.
#
#   sh tests/flint3.sh            (make check-flint3; run by .ci/run)
#
# Exits non-zero if the archive cannot be reached, a checksum differs, the
# build fails or any test fails.
set -eu
cd "$(dirname "$0")/.."
OUT=${OUT:-build-flint3}
MIRROR=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
SUITE=${FLINT3_SUITE:-trixie}
ROOT="$(pwd)/$OUT/root"
mkdir -p "$OUT/deb" "$OUT/pc"

fetch() { # URL FILE: three tries, then fail
    for i in 1 2 3; do
        curl -fsS --retry 2 -o "$2" "$1" && return 0
        sleep 2
    done
    echo "flint3: cannot fetch $1" >&2
    return 1
}

fetch "$MIRROR/dists/$SUITE/main/binary-amd64/Packages.xz" "$OUT/deb/Packages.xz"
xz -dc "$OUT/deb/Packages.xz" >"$OUT/deb/Packages"
for pkg in libflint-dev libflint19; do
    fields=$(awk -v p="$pkg" '
        /^Package: / { on = ($2 == p) }
        on && /^Filename: / { f = $2 }
        on && /^SHA256: / { s = $2 }
        on && /^$/ { if (f != "") { print f, s; exit } }' "$OUT/deb/Packages")
    file=${fields% *}; sum=${fields#* }
    [ -n "$file" ] || { echo "flint3: $pkg not in $SUITE's index" >&2; exit 1; }
    deb="$OUT/deb/$(basename "$file")"
    [ -f "$deb" ] || fetch "$MIRROR/$file" "$deb"
    echo "$sum  $deb" | sha256sum -c --quiet - || { rm -f "$deb"; echo "flint3: checksum of $deb" >&2; exit 1; }
    dpkg -x "$deb" "$ROOT"
done

LIBDIR="$ROOT/usr/lib/x86_64-linux-gnu"
sed "s|^prefix=/usr\$|prefix=$ROOT/usr|" "$LIBDIR/pkgconfig/flint.pc" >"$OUT/pc/flint.pc"
export PKG_CONFIG_PATH="$(pwd)/$OUT/pc"
export LD_LIBRARY_PATH="$LIBDIR${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

echo "flint3: $(pkg-config --modversion flint) from $SUITE"
make --no-print-directory -s print-flint BUILD="$OUT/b" | grep -qx 'FLINT3=yes' \
    || { echo "flint3: the Makefile did not choose FLINT 3" >&2; exit 1; }
make --no-print-directory -j2 BUILD="$OUT/b" all
ldd "$OUT/b/recstab" | grep -q "$LIBDIR/libflint.so" \
    || { echo "flint3: recstab is not linked with the fetched FLINT 3" >&2; exit 1; }
make --no-print-directory BUILD="$OUT/b" test

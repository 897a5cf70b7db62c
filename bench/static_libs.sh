#!/bin/sh
# static_libs.sh -- static FLINT and Arb for `make static` (issue 13: the
# start-up of build/recstab, ld.so relocating libflint, libflint-arb, NTL
# and libstdc++, is about 2/3 of its run on the QEPCAD B cases).  Debian
# ships no libflint.a or libflint-arb.a, but its source packages are in the
# archive: this script fetches the sources of the very versions installed
# (libflint-dev, libflint-arb-dev: same code as build/recstab's shared
# libraries, so the same outputs), checks each tarball against the SHA256
# sum of its .dsc, and builds static libraries once into $OUT
# (build/static-libs/root/{include,lib}); a later run finds the stamp and
# does nothing, an interrupted one goes on where it stopped.  Configured as
# Debian's rules do (its CFLAGS from dpkg-buildflags, less -g; Arb against
# the installed FLINT headers, --with-flint=/usr) but --disable-shared and
# without NTL (FLINT's NTL interface is C++, which recstab does not use).
# FLINT and Arb compile side by side (Arb needs only FLINT's headers).
# Debian's patches of these versions touch only tests, docs and rpaths, so
# they are not applied.
#
#   sh bench/static_libs.sh        (run by `make static`; a few minutes)
#
# Exits non-zero if the archive cannot be reached, a checksum differs or a
# build fails; prints the library folder on success.
set -eu
cd "$(dirname "$0")/.."
OUT=${OUT:-build/static-libs}
MIRROR=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
case $OUT in /*) ROOT="$OUT/root" ;; *) ROOT="$(pwd)/$OUT/root" ;; esac
STAMP="$ROOT/.done"
JOBS=${JOBS:-2}

# the source versions of the installed packages (epoch dropped: not in file names)
srcver() { dpkg-query -W -f='${source:Version}' "$1" | sed 's/^[0-9]*://'; }
FLINT_V=$(srcver libflint-dev)
ARB_V=$(srcver libflint-arb-dev)
want="flint $FLINT_V, flint-arb $ARB_V"
if [ -f "$STAMP" ] && [ "$(cat "$STAMP")" = "$want" ]; then
    echo "$ROOT/lib"
    exit 0
fi
rm -rf "$ROOT"
mkdir -p "$OUT/dl" "$OUT/src" "$ROOT"

fetch() { # URL FILE: three tries, then fail
    for i in 1 2 3; do
        curl -fsS --retry 2 -o "$2" "$1" && return 0
        sleep 2
    done
    echo "static_libs: cannot fetch $1" >&2
    return 1
}

# get SOURCE VERSION: the .dsc, then its upstream tarball checked against
# the .dsc's SHA256 line; unpacked under $OUT/src (once), prints the folder
get() {
    pool="$MIRROR/pool/main/$(printf %s "$1" | cut -c1)/$1"
    dsc="$OUT/dl/$1_$2.dsc"
    [ -f "$dsc" ] || fetch "$pool/$1_$2.dsc" "$dsc"
    line=$(awk '/^Checksums-Sha256:/ { on = 1; next } /^[^ ]/ { on = 0 }
                on && $3 ~ /\.orig\.tar\./ { print $1, $3; exit }' "$dsc")
    sum=${line% *}; tarball=${line#* }
    [ -n "$tarball" ] || { echo "static_libs: no tarball in $dsc" >&2; exit 1; }
    [ -f "$OUT/dl/$tarball" ] || fetch "$pool/$tarball" "$OUT/dl/$tarball"
    echo "$sum  $OUT/dl/$tarball" | sha256sum -c --quiet - \
        || { rm -f "$OUT/dl/$tarball"; echo "static_libs: checksum of $tarball" >&2; exit 1; }
    dir=$(tar tf "$OUT/dl/$tarball" | head -1 | cut -d/ -f1)
    if [ ! -f "$OUT/src/$dir/.unpacked" ]; then
        rm -rf "$OUT/src/$dir"
        tar xf "$OUT/dl/$tarball" -C "$OUT/src" && touch "$OUT/src/$dir/.unpacked"
    fi
    echo "$OUT/src/$dir"
}

DEB_BUILD_MAINT_OPTIONS=hardening=+all; export DEB_BUILD_MAINT_OPTIONS
CF="$(dpkg-buildflags --get CPPFLAGS) $(dpkg-buildflags --get CFLAGS | sed 's/-g //; s/-ffile-prefix-map=[^ ]*//')"

echo "static_libs: building static $want into $ROOT"
fl=$(get flint "$FLINT_V")
ar=$(get flint-arb "$ARB_V")
# build DIR CONFIGURE-ARGS...: configure, make the library, install into $ROOT
build() {
    d=$1; shift
    # configured once: a second configure rewrites flint-config.h, and
    # every object would be compiled again
    (cd "$d" && { [ -f .configured ] || { ./configure --prefix="$ROOT" --disable-shared --enable-static \
        --with-gmp=/usr --with-mpfr=/usr CFLAGS="$CF" "$@" >configure.log && touch .configured; }; } \
      && make -j"$JOBS" AT= QUIET_CC= QUIET_AR= library >build.log 2>&1 \
      && make install >install.log 2>&1) || { echo "static_libs: build failed (see $d/*.log)" >&2; return 1; }
}
build "$fl" --without-ntl & fpid=$!
build "$ar" --with-flint=/usr & apid=$!
frc=0; arc=0
wait $fpid || frc=1
wait $apid || arc=1
[ $frc = 0 ] && [ $arc = 0 ] || exit 1
ls "$ROOT"/lib*/libflint.a "$ROOT"/lib*/libarb.a >/dev/null
echo "$want" >"$STAMP"
echo "$ROOT/lib"

#!/bin/sh
# suite_api.sh -- the library as others use it (issue 16):
#  - the C examples (examples/*.c, linked against build/librecstab.so) run
#    and exit 0; each checks its own expected values (see their comments);
#  - librecstab.so has the soname librecstab.so.0;
#  - the library never exits, aborts, prints on stdout or installs signal
#    handlers: none of those symbols is called from librecstab.a's objects
#    (flint_abort is allowed only in jury.o, where it comes from an inline
#    FLINT header function, not from recstab's code);
#  - every function declared in include/recstab/*.h is named in docs/api.md
#    and the man page recstab.1 names every option of `recstab --help`;
#  - make install (PREFIX in a temporary folder, and DESTDIR) installs the
#    public headers only, both libraries, recstab.pc, the man page and the
#    Python module, and a program builds with plain
#    `pkg-config --cflags --libs recstab` and runs against the installed
#    library;
#  - the Python package's tests (tests/python, pytest from Debian).
BUILD=${BUILD:-build}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
ok()   { echo "ok $*"; }
# a sanitizer build (make check-sanitize): programs linked against it need
# the sanitizer flags, and Python cannot load it (the ASan runtime must come
# first), so the Python tests are skipped there
SANFLAGS=
readelf -d "$BUILD/librecstab.so" 2>/dev/null | grep -q 'libasan' && SANFLAGS="-fsanitize=address,undefined"
fail() { echo "FAIL $*"; }

for e in "$BUILD"/examples/*; do
    [ -x "$e" ] || continue
    if "$e" >"$T/ex.out" 2>&1; then ok "example $(basename "$e")"; else fail "example $(basename "$e")"; cat "$T/ex.out"; fi
done
[ -x "$BUILD/examples/one_call" ] && [ -x "$BUILD/examples/typed_roots" ] && ok "examples built" || fail "examples not built"

if readelf -d "$BUILD/librecstab.so" | grep -q 'SONAME.*\[librecstab\.so\.0\]'; then ok "soname librecstab.so.0"
else fail "soname of $BUILD/librecstab.so"; fi

bad=$(nm -A -u "$BUILD/librecstab.a" 2>/dev/null | awk '{print $1, $NF}' |
      grep -E ' (exit|_exit|_Exit|abort|quick_exit|signal|sigaction|alarm|raise|printf|puts|putchar|vprintf|__printf_chk|stdout|flint_printf|flint_abort)$' |
      grep -vE '^[^ ]*:jury\.o: (flint_abort|flint_printf)$')
if [ -z "$bad" ]; then ok "library: no exit/abort/stdout/signal calls"
else fail "library calls: $bad"; fi

missing=""
for fn in $(grep -hoE '\brs_[a-z0-9_]+ *\(' include/recstab/*.h | tr -d ' (' | sort -u); do
    grep -q "$fn" docs/api.md || missing="$missing $fn"
done
if [ -z "$missing" ]; then ok "docs/api.md names every public function"; else fail "docs/api.md lacks:$missing"; fi

missing=""
for o in $("$BUILD/recstab" --help | grep -oE -- '--[a-z][a-z-]*' | sort -u); do
    grep -q -- "$(echo "$o" | sed 's/-/\\\\-/g')" recstab.1 || missing="$missing $o"
done
if [ -z "$missing" ]; then ok "recstab.1 names every option"; else fail "recstab.1 lacks:$missing"; fi

P="$T/prefix"
if make --no-print-directory -s -o all install PREFIX="$P" >"$T/install.log" 2>&1; then ok "make install PREFIX"
else fail "make install PREFIX"; cat "$T/install.log"; fi
inst=$(cd "$P/include/recstab" && ls | sort | tr '\n' ' ')
want=$(make --no-print-directory -s print-public-headers | tr ' ' '\n' | sed 's|include/recstab/||' | sort | tr '\n' ' ')
[ "$inst" = "$want" ] && ok "installed headers are the public ones" || fail "installed headers: $inst (want $want)"
for f in lib/librecstab.a lib/librecstab.so lib/librecstab.so.0 lib/pkgconfig/recstab.pc share/man/man1/recstab.1 bin/recstab; do
    [ -e "$P/$f" ] && ok "installed $f" || fail "not installed: $f"
done
ls "$P"/lib/python3*/dist-packages/recstab/__init__.py >/dev/null 2>&1 && ok "installed the Python module" || fail "Python module not installed"
if cc $SANFLAGS $(PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config --cflags recstab) -o "$T/one_call" examples/one_call.c \
      $(PKG_CONFIG_PATH="$P/lib/pkgconfig" pkg-config --libs recstab) 2>"$T/cc.log" \
   && LD_LIBRARY_PATH="$P/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" "$T/one_call" >/dev/null 2>&1; then
    ok "an example links with pkg-config --cflags --libs recstab and runs"
else fail "pkg-config link"; cat "$T/cc.log"; fi
if LD_LIBRARY_PATH="$P/lib" ldd "$T/one_call" 2>/dev/null | grep -q "$P/lib/librecstab.so.0"; then ok "the program uses the installed librecstab.so.0"
else fail "the program does not use $P/lib/librecstab.so.0"; fi
D="$T/dest"
if make --no-print-directory -s -o all install DESTDIR="$D" PREFIX=/opt/rs >"$T/install2.log" 2>&1 \
   && [ -f "$D/opt/rs/include/recstab/recstab.h" ] && grep -q '^prefix=/opt/rs$' "$D/opt/rs/lib/pkgconfig/recstab.pc"; then
    ok "make install DESTDIR stages under DESTDIR with PREFIX in recstab.pc"
else fail "make install DESTDIR"; cat "$T/install2.log"; fi

PY=/usr/bin/python3
if [ -n "$SANFLAGS" ]; then
    echo "skip python: a sanitizer build of librecstab.so cannot be loaded by python3"
elif [ -x "$PY" ] && "$PY" -c 'import pytest' 2>/dev/null; then
    pyd=$(ls -d "$P"/lib/python3*/dist-packages | head -1)
    got=$(cd "$T" && PYTHONPATH="$pyd" "$PY" -c 'import recstab; d = recstab.analyse("unknown x\neq x[n+1] = x[n]/2\n"); print(recstab.library_path, d["cases"][0]["unknowns"])' 2>&1)
    if [ "$got" = "$P/lib/librecstab.so.0 ['x']" ]; then ok "the installed Python module loads the installed library"
    else fail "installed Python module: $got"; fi
    if RECSTAB_LIBRARY="$(pwd)/$BUILD/librecstab.so" PYTHONPATH="$(pwd)/python" "$PY" -m pytest -q -p no:cacheprovider \
        tests/python >"$T/py.log" 2>&1; then
        ok "python: $(tail -1 "$T/py.log")"
    else fail "python tests"; tail -30 "$T/py.log"; fi
else fail "python3-pytest missing (make deps installs it)"; fi

#!/bin/sh
# suite_headers.sh -- the public API (issue 12): every header in
# include/recstab/ compiles on its own, with only include/ on the path (so it
# names no private header), under the project's warnings; and `make install`
# installs exactly these headers (the Makefile's PUBLIC_HDRS list).
CC=${CC:-cc}
FLAGS="-std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror -Wmissing-prototypes -Wstrict-prototypes -Wshadow"
for h in include/recstab/*.h; do
    n=$(basename "$h")
    if out=$(printf '#include "recstab/%s"\n' "$n" |
             $CC $FLAGS -Iinclude -I/usr/include/flint -fsyntax-only -x c - 2>&1); then
        echo "ok header $n compiles alone"
    else
        echo "FAIL header $n does not compile alone:"; echo "$out" | head -5
    fi
done
# the install list against the folder
list=$(make -s --no-print-directory -f Makefile print-public-headers 2>/dev/null | tr ' ' '\n' | sed '/^$/d' | sort)
have=$(ls include/recstab/*.h | sort)
if [ -n "$list" ] && [ "$list" = "$have" ]; then
    echo "ok header install list = include/recstab/*.h ($(echo "$have" | wc -l) headers)"
else
    echo "FAIL header install list (PUBLIC_HDRS) differs from include/recstab/*.h:"
    printf '%s\n' "$list" >/tmp/rs-hdr-list.$$; printf '%s\n' "$have" | diff /tmp/rs-hdr-list.$$ - ; rm -f /tmp/rs-hdr-list.$$
fi
# the umbrella header includes every other public header
missing=""
for h in include/recstab/*.h; do
    n=$(basename "$h"); [ "$n" = recstab.h ] && continue
    grep -q "^#include \"recstab/$n\"" include/recstab/recstab.h || missing="$missing $n"
done
if [ -z "$missing" ]; then echo "ok header umbrella recstab.h includes every public header"
else echo "FAIL header recstab.h does not include$missing"; fi

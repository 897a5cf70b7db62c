#!/bin/sh
# bench_routes.sh N [ROW_LIMIT_S] -- issue 17: Hurwitz minors of the N-mass
# chain by the fraction-free Routh recursion over Z, one modular image, and
# one interpolation probe (bench/bench_routh_routes.c; builds it).
set -eu
cd "$(dirname "$0")/.."
N=${1:?usage: bench_routes.sh N [row limit seconds]}
CC=${CC:-cc}
[ -x build/recstab ] || { echo "make all first" >&2; exit 2; }
$CC -O2 -Iinclude -Isrc -I/usr/include/flint bench/bench_routh_routes.c \
    src/util/budget.c src/util/error.c -o build/bench_routh_routes -lflint -lgmp -lm
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
sh bench/make_chain_case.sh "$N" "$tmp/chain.case"
build/recstab --json --analyse bilinear "$tmp/chain.case" > "$tmp/q.json"
python3 - "$tmp/q.json" > "$tmp/q.txt" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d = d["cases"][0] if "cases" in d else d
r = [x for x in d["results"] if x["analysis"] == "bilinear"][0]
print(" ".join(d["params"]))
for c in r["coeffs"]:
    print(c)
PY
build/bench_routh_routes "${2:-60}" < "$tmp/q.txt"

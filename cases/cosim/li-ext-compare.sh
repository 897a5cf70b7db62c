#!/bin/sh
# Measures Li et al.'s statements (sect. 4) under recstab's reading of the
# extension couplings: the number of certified-stable points of the 40 x 40
# grid lr1 in [-2, -1/100], li1 in [1/100, 2] (their Fig. 6-8 axes) for the
# direct implicit method (cases/figures/li-implicit-k*.case), the D- and the
# I-Extension (cases/cosim/li-ext-*.case), k = 0, 1, 2, both test models, and
# the I-Extension k = 1 at alpha_T = 1/4, 1/2, 3/4.  Run from the repository
# root after `make`; about a minute on one core.
RS=${RS:-build/recstab}
grid="map lr1 -2 -1/100 40, li1 1/100 2 40 of stability"
count() { # case -> stable/undecided counts
  "$RS" --json --analyse "$grid" "$1" 2>/dev/null | python3 -c '
import json, sys
d = json.load(sys.stdin)
m = [r for r in d["results"] if r.get("analysis") == "map"][0]
v = m["verdicts"]
print("%d stable, %d unstable, other %d" % (v.get("stable", 0), v.get("unstable", 0),
      m["points"] - v.get("stable", 0) - v.get("unstable", 0)))'
}
for model in sym unsym; do
  for K in 0 1 2; do
    echo "$model k=$K direct implicit: $(count cases/figures/li-implicit-k$K-$model.case)"
    echo "$model k=$K D-Extension:     $(count cases/cosim/li-ext-d-k$K-$model.case)"
    echo "$model k=$K I-Extension:     $(count cases/cosim/li-ext-i-k$K-$model.case)"
  done
  for a in 1_4 3_4; do
    echo "$model k=1 I-Extension alpha_T=$a: $(count cases/cosim/li-ext-i-k1-a$a-$model.case)"
  done
done

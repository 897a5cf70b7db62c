#!/bin/sh
# make figures: recstab's versions of the source documents' figures, into
# docs/figures/ (PNG via gnuplot).  Every curve and map point is certified
# (see README, "Sweeps and maps").  Run from the repository root after make all.
set -e
RS=${RS:-build/recstab}
OUT=docs/figures
mkdir -p "$OUT"
O=cases/olivier2019

# Olivier et al. (2019) Fig. 12.3: spectral radius vs time step, k2/k1 = m2/m1 = 1, dc = 0,
# kc/k1 = 1 (a, b) and 10 (c, d); forward Euler (a, c), backward Euler (b, d).
for kc in 1 10; do
  for i in ee ei; do
    tag=$( [ $kc = 1 ] && { [ $i = ee ] && echo a || echo b; } || { [ $i = ee ] && echo c || echo d; } )
    $RS --plot "$OUT/olivier-fig12-3$tag.png" --set kc=$kc --set dc=0 \
        --analyse "sweep h from 1/1000 to 1 steps 160 log of radius" \
        $O-mono-$i-$i.case $O-J-$i-$i.case $O-GS12-$i-$i.case $O-J-$i-$i-iter1.case $O-GS12-$i-$i-iter1.case \
        > /dev/null || [ $? -le 1 ]
  done
done

# Fig. 12.4: frequency error and damping ratio of both modes (omega1 = 1,
# omega2 = sqrt(21) for kc/k1 = 10), mixed schemes (backward Euler on subsystem 2)
# against GS12 with forward / backward Euler on both; dc = 0.2.
$RS --plot "$OUT/olivier-fig12-4.png" --set kc=10 --set dc=1/5 \
    --analyse "sweep h from 1/1000 to 1/5 steps 120 log of modes h=h reference=1,4.58257569495584" \
    $O-GS12-ee-ei.case $O-J-ee-ei.case $O-GS12-ee-ee.case $O-GS12-ei-ei.case > /dev/null || [ $? -le 1 ]

# Fig. 12.5: stability over (h, dc) with kc/k1 = 10: GS12 (a, b) and J (c, d),
# forward Euler on both (a, c) or forward/backward (b, d).
for c in GS12 J; do
  for p in ee-ee ee-ei; do
    $RS --plot "$OUT/olivier-fig12-5-$c-$p.png" --set kc=10 \
        --analyse "map h 1/200 1/2 120, dc 0 4 120 of stability" $O-$c-$p.case > /dev/null || [ $? -le 1 ]
  done
done

# Li et al. Fig. 6 (symmetric model, explicit and implicit, k = 0, 1, 2) and
# Fig. 7 (unsymmetric, implicit): spectral radius over (Lambda_r1, Lambda_i1).
for model in sym unsym; do
  for m in explicit implicit; do
    for K in 0 1 2; do
      $RS --plot "$OUT/li-$m-k$K-$model.png" \
          --analyse "map lr1 -2 -1/100 80, li1 1/100 2 80 of radius" cases/figures/li-$m-k$K-$model.case \
          > /dev/null || [ $? -le 1 ]
    done
  done
done
# Li et al. Fig. 8: I-Extension, k = 1, alpha_T = 1/4, 1/2, 3/4, symmetric and
# unsymmetric models (recstab's reading of the extension: src/numeric/cosim_ext.h).
for model in sym unsym; do
  for a in 1_4 "" 3_4; do
    f=cases/cosim/li-ext-i-k1${a:+-a$a}-$model.case
    $RS --plot "$OUT/li-fig8-ext-i-k1-a${a:-1_2}-$model.png" \
        --analyse "map lr1 -2 -1/100 80, li1 1/100 2 80 of radius" "$f" > /dev/null || [ $? -le 1 ]
  done
done
ls -1 "$OUT"

#!/bin/sh
# Writes cases/figures/li-<explicit|implicit>-k<K>-<sym|unsym>.case: the Li et al.
# force/force schemes parametrised by the first subsystem's eigenvalue
# Lambda_1 = lr1 + i li1 (their eq. 24): c1 = lr1^2 + li1^2, d1 = -2 lr1.
# Their five ratios alpha_m21, alpha_Lr21, alpha_Li21, alpha_Lrc1, alpha_Lic1
# all 1 (symmetric) or all 10 (unsymmetric) translate, inverting eq. (24), into
#   symmetric:    am21 = ac21 = ad21 = acc1 = adc1 = 1
#   unsymmetric:  am21 = 10, ad21 = 100, ac21 = 1000, adc1 = 200/11, acc1 = 2000/11
# (alpha*_m = 2 am21/(1 + am21) = 20/11; the square roots of eq. (24) cancel
# because 4 c1 - d1^2 = 4 li1^2).  Run from the repository root.
set -e
for m in explicit implicit; do
  for K in 0 1 2; do
    for model in sym unsym; do
      if [ $model = sym ]; then vals="am21 = 1, ac21 = 1, ad21 = 1, acc1 = 1, adc1 = 1"; mt="symmetric"
      else vals="am21 = 10, ac21 = 1000, ad21 = 100, acc1 = 2000/11, adc1 = 200/11"; mt="unsymmetric"; fi
      cat > cases/figures/li-$m-k$K-$model.case <<EOC
# Li et al., $m co-simulation, k = $K, $mt test model, over (Lambda_r1, Lambda_i1).
title Li et al. $m k=$K, $mt
param lr1 li1 am21 ac21 ad21 acc1 adc1
assume lr1 < 0, li1 > 0
let c1 = lr1^2 + li1^2
let d1 = -2*lr1
include ../include/li2016-two-mass.inc
couple $m order $K
set $vals
set lr1 = -1/10, li1 = 1
analyse radius digits=15
EOC
    done
  done
done

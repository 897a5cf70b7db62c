#!/bin/sh
# Writes cases/cosim/li-ext-<d|i>-k<K>-<sym|unsym>.case and the Fig. 8 cases
# li-ext-i-k1-a<alpha>-<sym|unsym>.case: Li et al.'s extended implicit
# co-simulation (sect. 3.2, Fig. 5, 8), force/force, over (Lambda_r1,
# Lambda_i1) as in cases/figures/make-li-figure-cases.sh (same parameter
# translation of their eq. 24).  Run from the repository root.
set -e
reading='# READING (the paper does not print the extended polynomials; recstab chooses,
# src/numeric/cosim_ext.h): per macro step the coupling force is sampled at
# T_N, T_{N+a}, T_{N+1} (a = alpha_T; D: a = 1/2); u(t) is the piecewise
# degree-K interpolant of the three samples (K = 0 hold from the right, K = 1
# broken line, K = 2 the quadratic); u_N = the previous corrected value; the
# two unknowns u_{N+a}, u_{N+1} satisfy g = 0 at T_{N+1} and, for D, dg/dt = 0
# at T_{N+1} (z'' from the subsystem equations), for I, the integral of g over
# the macro step = 0.  The conditions are affine, so the linearised Newton step
# of eq. (21) solves them exactly and the predictor drops out; the corrector
# gives z_{N+1} = M z_N (tests/unit/numeric/test_cosim_ext.c checks M against
# a literal predictor/corrector time loop).'
one() { # file ext K alpha model
  f=$1; ext=$2; K=$3; a=$4; model=$5
  if [ $model = sym ]; then vals="am21 = 1, ac21 = 1, ad21 = 1, acc1 = 1, adc1 = 1"; mt="symmetric"
  else vals="am21 = 10, ac21 = 1000, ad21 = 100, acc1 = 2000/11, adc1 = 200/11"; mt="unsymmetric"; fi
  if [ "$ext" = D ]; then couple="couple implicit order $K extension D"; what="D-Extension"
  elif [ -z "$a" ]; then couple="couple implicit order $K extension I"; what="I-Extension, alpha_T = 1/2"
  else couple="couple implicit order $K extension I alpha_T = $a"; what="I-Extension, alpha_T = $a"; fi
  cat > "$f" <<EOC
# Li et al., $what, k = $K, $mt test model, force/force, over (Lambda_r1, Lambda_i1).
$reading
title Li et al. $what k=$K, $mt
param lr1 li1 am21 ac21 ad21 acc1 adc1
assume lr1 < 0, li1 > 0
let c1 = lr1^2 + li1^2
let d1 = -2*lr1
include ../include/li2016-two-mass.inc
$couple
set $vals
set lr1 = -1/10, li1 = 1
analyse radius digits=15
EOC
}
for model in sym unsym; do
  for K in 0 1 2; do
    one cases/cosim/li-ext-d-k$K-$model.case D $K "" $model
    one cases/cosim/li-ext-i-k$K-$model.case I $K "" $model
  done
  for a in 1/4 3/4; do
    one cases/cosim/li-ext-i-k1-a$(echo $a | tr / _)-$model.case I 1 $a $model
  done
done

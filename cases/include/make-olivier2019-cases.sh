#!/bin/sh
# Writes cases/olivier2019-<coupling>-<int1>-<int2>[-iterK].case, the schemes of
# Olivier, Verlinden & Kouroussis (2019), sections 12.2-12.3, from one system
# file and the builders.  Run from the repository root.
set -e
for cpl in J GS12 GS21 mono; do
  for pair in ee-ee ei-ei ee-ei; do
    for it in 0 1; do
      [ "$cpl" = mono ] && [ "$it" = 1 ] && continue
      i1=${pair%-*}; i2=${pair#*-}
      m1=euler-forward; [ "$i1" = ei ] && m1=euler-backward
      m2=euler-forward; [ "$i2" = ei ] && m2=euler-backward
      case $cpl in
        J) couple="couple jacobi"; cname="Jacobi" ;;
        GS12) couple="couple gauss-seidel S1 S2"; cname="Gauss-Seidel, subsystem 1 first" ;;
        GS21) couple="couple gauss-seidel S2 S1"; cname="Gauss-Seidel, subsystem 2 first" ;;
        mono) couple="couple monolithic"; cname="monolithic" ;;
      esac
      name=olivier2019-$cpl-$pair; [ "$it" = 1 ] && name=$name-iter1
      f=cases/$name.case
      {
        echo "# Olivier et al. (2019), eq. 12.3-12.19: $cname coupling, subsystem 1 $m1,"
        echo "# subsystem 2 $m2$( [ "$it" = 1 ] && echo ", one iteration (eq. 12.19)")."
        echo "# The equations of motion are imposed at t+h with the partner's state at t"
        echo "# or t+h as the coupling order says (their U matrices); the one-step formula"
        echo "# links y, y' at t and t+h.  Values: the ratios of their Fig. 12.3 (kc/k1 = 10)."
        echo "title Olivier 2019: $cpl coupling, $i1 / $i2$( [ "$it" = 1 ] && echo ", 1 iteration")"
        echo "include include/olivier2019-oscillator.inc"
        echo "integrate S1 $m1 h"
        echo "integrate S2 $m2 h"
        echo "$couple"
        [ "$it" = 1 ] && echo "iterations 1"
        echo "set m1 = 1, m2 = 1, k1 = 1, k2 = 1, kc = 10, dc = 0, h = 1/10"
        echo "analyse charpoly"
        echo "analyse stability"
        echo "analyse radius digits=30"
        echo "analyse region h"
      } > "$f"
    done
  done
done

# accuracy.gp -- plot of bench_radius --accuracy output (bench/bench_accuracy.sh).
#   gnuplot -e "dat='bench/results/accuracy-vs-time.dat'; out='bench/results/accuracy-vs-time.png'" bench/accuracy.gp
# Data blocks (index): 0 geometric mean over all polynomials, 1-4 single
# polynomials (titles from the '# panel' comments), 5 digits right.
# Columns: digits recstab_ms pari_ms mpsolve_proc_ms mpsolve_minus_start_ms gsl_ms
if (!exists("dat")) dat = 'bench/results/accuracy-vs-time.dat'
if (!exists("out")) out = 'bench/results/accuracy-vs-time.png'
set terminal pngcairo size 1500,950 font ",10"
set output out
set datafile missing "?"
set logscale xy
set xrange [12:1600]
set xtics (15, 38, 77, 154, 308, 1233)
set grid
set format y "%g"
set xlabel "digits requested"
set ylabel "CPU ms per call (log)"

# panel titles from the data file's comments
title(i) = system(sprintf("sed -n 's/^# panel %d: //p' '%s'", i, dat))

set multiplot layout 2,3 title "What accuracy costs in time: recstab certified radius vs PARI polroots, MPSolve, GSL double (uncertified)"
do for [i=0:4] {
    set title title(i)
    # one legend, in the first panel's empty lower right corner
    if (i == 0) { set key bottom right font ",9" box opaque; set yrange [1e-5:100] } else { unset key; set yrange [*:*] }
    plot dat index i using 1:2 with linespoints lw 2 pt 7 lc rgb "#1f77b4" title "recstab rs\\_radius\\_fmpz\\_poly (certified)", \
         ''  index i using 1:3 with linespoints lw 2 pt 5 lc rgb "#d62728" title "PARI polroots (in gp, start-up excluded)", \
         ''  index i using 1:4 with linespoints lw 2 pt 9 lc rgb "#2ca02c" title "MPSolve, whole process", \
         ''  index i using 1:5 with linespoints lw 1 dt 2 pt 8 lc rgb "#2ca02c" title "MPSolve minus start-up floor", \
         ''  index i using 1:6 with points pt 13 ps 2 lc rgb "#000000" title "GSL double (15 digits at best)"
}
set title "digits right for rho (minimum over the polynomials)"
set ylabel "digits (recstab: certified; others: vs certified value)"
set yrange [0.3:3000]
set key top left nobox
plot dat index 5 using 1:2 with linespoints lw 2 pt 7 lc rgb "#1f77b4" title "recstab (certified)", \
     ''  index 5 using 1:3 with linespoints lw 2 pt 5 lc rgb "#d62728" title "PARI polroots", \
     ''  index 5 using 1:4 with linespoints lw 2 pt 9 lc rgb "#2ca02c" title "MPSolve", \
     ''  index 5 using 1:5 with points pt 13 ps 2 lc rgb "#000000" title "GSL double", \
     x with lines dt 3 lc rgb "#888888" title "requested"
unset multiplot

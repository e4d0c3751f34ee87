# Work-precision figure, paper's law: largest relative error over the five quantities
# against the right-hand-side evaluations and against the CPU time of one impact.
#   gnuplot -d -c work_precision.gp OUT   (reads OUT/work_precision.csv)
out = ARG1
here = system('dirname '.ARG0)
load here.'/../style.gnuplot'
data = out.'/work_precision.csv'

set style line 11 lc rgb '#e67e22' lw 1.6 dt 1 pt 7 ps 0.5   # euler, located
set style line 12 lc rgb '#e67e22' lw 1.6 dt 2 pt 6 ps 0.5   # euler, unlocated
set style line 13 lc rgb '#27ae60' lw 1.6 dt 1 pt 5 ps 0.5   # rk4, located
set style line 14 lc rgb '#27ae60' lw 1.6 dt 2 pt 4 ps 0.5   # rk4, unlocated
set style line 15 lc rgb '#0b3c8c' lw 2.0 dt 1 pt 9 ps 0.6   # rk4, regularised
set style line 16 lc rgb '#8e44ad' lw 1.6 dt 1 pt 7 ps 0.5   # cvode adams
set style line 17 lc rgb '#c0392b' lw 1.6 dt 1 pt 5 ps 0.5   # cvode bdf

sel(i, l) = (strcol(1) eq i && strcol(2) eq l)
col(i, l, c) = sel(i, l) ? column(c) : NaN

set logscale xy
set format x '10^{%T}'
set format y '10^{%T}'
set ylabel 'largest relative error (5 quantities)'
set yrange [1e-13:1]
set key bottom left

do for [kind in 'pdf png'] {
  if (kind eq 'pdf') { set terminal pdfcairo size 7in,3in font 'Helvetica,9' enhanced }
  else { set terminal pngcairo size 1400,600 font 'Helvetica,11' enhanced }
  set output out.'/work_precision.'.kind
  set multiplot layout 1,2
  do for [panel in 'rhs cpu'] {
    if (panel eq 'rhs') {
      c = 4; set xlabel 'right-hand-side evaluations per impact'; set title "(a) paper's law: error against work"
    } else {
      c = 5; set xlabel 'CPU time per impact [s]'; set title "(b) paper's law: error against CPU time"
    }
    plot data u (col('euler','located',c)):6 w lp ls 11 t 'Euler, located', \
         data u (col('euler','unlocated',c)):6 w lp ls 12 t 'Euler, unlocated', \
         data u (col('rk4','located',c)):6 w lp ls 13 t 'RK4, located', \
         data u (col('rk4','unlocated',c)):6 w lp ls 14 t 'RK4, unlocated', \
         data u (col('rk4-regularized','located',c)):6 w lp ls 15 t 'RK4, regularised', \
         data u (col('cvode-adams','located',c)):6 w lp ls 16 t 'CVODE Adams', \
         data u (col('cvode-bdf','located',c)):6 w lp ls 17 t 'CVODE BDF'
  }
  unset multiplot
  set output
}

# Work-precision figure, paper's law: largest relative error over the five quantities
# against the right-hand-side evaluations and against the CPU time of one impact (both per
# impact).
#   gnuplot -d -c work_precision.gp OUT   (reads OUT/work_precision.csv)
out = ARG1
here = system('dirname '.ARG0)
data = out.'/work_precision.csv'
sel(i, l) = (strcol(1) eq i && strcol(2) eq l)
col(i, l, c) = sel(i, l) ? column(c) : NaN

do for [kind in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  # The series styles of the convergence figure (convergence.gp).
  set style line 11 lc rgb '#e67e22' lw 1.6 dt 1 pt 7 ps 0.5   # euler, located
  set style line 12 lc rgb '#e67e22' lw 1.6 dt 2 pt 6 ps 0.5   # euler, unlocated
  set style line 13 lc rgb '#27ae60' lw 1.6 dt 1 pt 5 ps 0.5   # rk4, located
  set style line 14 lc rgb '#27ae60' lw 1.6 dt 2 pt 4 ps 0.5   # rk4, unlocated
  set style line 15 lc rgb '#0b3c8c' lw 2.0 dt 1 pt 9 ps 0.6   # rk4, regularised
  set style line 16 lc rgb '#8e44ad' lw 1.6 dt 1 pt 7 ps 0.5   # cvode adams
  set style line 17 lc rgb '#c0392b' lw 1.6 dt 1 pt 5 ps 0.5   # cvode bdf
  call here.'/../output.gnuplot' out.'/work_precision' kind full_width_in 3.2
  set logscale xy
  set format x '10^{%T}'
  set format y '10^{%T}'
  set ytics 1e4
  set xtics 100
  set ylabel 'largest relative error'
  set yrange [1e-13:1]
  set key off
  set multiplot
  do for [panel in 'rhs cpu'] {
    if (panel eq 'rhs') {
      c = 4; set xlabel 'RHS evaluations'; set title '(a) against work'; eval two_panels_a
    } else {
      c = 5; set xlabel 'CPU time [s]'; set title '(b) against CPU time'; eval two_panels_b
      unset ylabel
    }
    plot data u (col('euler','located',c)):6 w lp ls 11 notitle, \
         data u (col('euler','unlocated',c)):6 w lp ls 12 notitle, \
         data u (col('rk4','located',c)):6 w lp ls 13 notitle, \
         data u (col('rk4','unlocated',c)):6 w lp ls 14 notitle, \
         data u (col('rk4-regularized','located',c)):6 w lp ls 15 notitle, \
         data u (col('cvode-adams','located',c)):6 w lp ls 16 notitle, \
         data u (col('cvode-bdf','located',c)):6 w lp ls 17 notitle
  }
  eval two_panels_key
  eval key_panel
  plot NaN w lp ls 11 t 'Euler, located', NaN w lp ls 12 t 'Euler, unlocated', NaN w lp ls 13 t 'RK4, located', \
       NaN w lp ls 14 t 'RK4, unlocated', NaN w lp ls 15 t 'RK4, regularised', NaN w lp ls 16 t 'CVODE Adams', \
       NaN w lp ls 17 t 'CVODE BDF'
  unset multiplot
  set output
}

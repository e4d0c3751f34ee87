# Convergence figure: relative error against the step (fixed-step methods) and
# against the tolerance (CVODE), with reference slopes.
#   gnuplot -d -c convergence.gp OUT   (reads OUT/convergence.csv, OUT/convergence_undamped.csv)
# (a) undamped Hertz law, state at t*; (b) paper's law, state at t*; (c) undamped law,
# RK4 without event location: each quantity; (d) CVODE, state at t*, both laws.
out = ARG1
here = system('dirname '.ARG0)
do for [kind in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  paper = out.'/convergence.csv'
  hertz = out.'/convergence_undamped.csv'

  # Series styles: colour per integrator; located solid with filled points, unlocated dashed with open points.
  set style line 11 lc rgb '#e67e22' lw 1.6 dt 1 pt 7 ps 0.5   # euler, located
  set style line 12 lc rgb '#e67e22' lw 1.6 dt 2 pt 6 ps 0.5   # euler, unlocated
  set style line 13 lc rgb '#27ae60' lw 1.6 dt 1 pt 5 ps 0.5   # rk4, located
  set style line 14 lc rgb '#27ae60' lw 1.6 dt 2 pt 4 ps 0.5   # rk4, unlocated
  set style line 15 lc rgb '#0b3c8c' lw 2.0 dt 1 pt 9 ps 0.6   # rk4, regularised
  set style line 16 lc rgb '#8e44ad' lw 1.6 dt 1 pt 7 ps 0.5   # cvode adams
  set style line 17 lc rgb '#c0392b' lw 1.6 dt 1 pt 5 ps 0.5   # cvode bdf
  set style line 18 lc rgb '#8e44ad' lw 1.6 dt 2 pt 6 ps 0.5   # cvode adams, other law
  set style line 19 lc rgb '#c0392b' lw 1.6 dt 2 pt 4 ps 0.5   # cvode bdf, other law
  set style line 20 lc rgb '#777777' lw 1.0 dt 3               # reference slopes

  sel(i, l, q) = (strcol(1) eq i && strcol(2) eq l && strcol(3) eq q)
  col(i, l, q, c) = sel(i, l, q) ? column(c) : NaN
  # Reference slope p through (x0, y0): y = y0 (x/x0)^p.
  slope(x, x0, y0, p) = y0 * (x / x0)**p

  set logscale xy
  set format x '10^{%T}'
  set format y '10^{%T}'
  set mytics 10
  set xtics 10
  set ytics 1e4
  set yrange [1e-13:1]

  call here.'/../output.gnuplot' out.'/convergence' kind full_width_in 7.6
  set multiplot

  # (a) and (b): their legend is the row at the bottom; (c) and (d) each have theirs below.
  set key off
  set xlabel 'time step h [s]'
  set ylabel 'error of the state at t^*'
  set title '(a) undamped Hertz law (exact reference)'
  set xrange [1e-7:2e-4]
  eval quad_panel(1)
  plot hertz u (col('euler','located','state_at_t_star',4)):5 w lp ls 11 notitle, \
       hertz u (col('euler','unlocated','state_at_t_star',4)):5 w lp ls 12 notitle, \
       hertz u (col('rk4','located','state_at_t_star',4)):5 w lp ls 13 notitle, \
       hertz u (col('rk4','unlocated','state_at_t_star',4)):5 w lp ls 14 notitle, \
       hertz u (col('rk4-regularized','located','state_at_t_star',4)):5 w lp ls 15 notitle, \
       slope(x, 1e-4, 3e-2, 1) ls 20 notitle, slope(x, 1e-4, 1e-5, 2.5) ls 20 notitle, \
       slope(x, 1e-4, 3e-5, 4) ls 20 notitle

  set title "(b) paper's law"
  eval quad_panel(2)
  plot paper u (col('euler','located','state_at_t_star',4)):5 w lp ls 11 notitle, \
       paper u (col('euler','unlocated','state_at_t_star',4)):5 w lp ls 12 notitle, \
       paper u (col('rk4','located','state_at_t_star',4)):5 w lp ls 13 notitle, \
       paper u (col('rk4','unlocated','state_at_t_star',4)):5 w lp ls 14 notitle, \
       paper u (col('rk4-regularized','located','state_at_t_star',4)):5 w lp ls 15 notitle, \
       slope(x, 1e-4, 3e-2, 1) ls 20 notitle, slope(x, 1e-4, 3e-4, 1.5) ls 20 notitle, \
       slope(x, 1e-4, 3e-5, 4) ls 20 notitle

  set title '(c) undamped law, RK4 unlocated'
  set ylabel 'relative error'
  set key below font ',8' samplen 2 nobox noopaque maxrows 3 width -2
  eval quad_panel(3)
  plot hertz u (col('rk4','unlocated','e_effective',4)):5 w lp ls 13 t 'restitution', \
       hertz u (col('rk4','unlocated','peak_force',4)):5 w lp ls 16 t 'peak force', \
       hertz u (col('rk4','unlocated','max_deformation',4)):5 w lp ls 19 t 'max. deformation', \
       hertz u (col('rk4','unlocated','contact_time',4)):5 w lp ls 11 t 'contact time', \
       hertz u (col('rk4','unlocated','state_at_t_star',4)):5 w lp ls 14 t 'state at t^*', \
       slope(x, 1e-4, 3e-2, 1) ls 20 t 'slopes 1, 2, 2.5', slope(x, 1e-4, 1e-3, 2) ls 20 notitle, \
       slope(x, 1e-4, 1e-4, 2.5) ls 20 notitle

  set title '(d) CVODE'
  set xlabel 'relative tolerance rtol'
  set ylabel 'error at t^*'
  set xrange [1e-13:1e-3]
  set xtics 1e3
  set yrange [1e-13:1]
  set key below font ',8' samplen 2 nobox noopaque maxrows 3 width -2
  eval quad_panel(4)
  plot paper u (col('cvode-adams','located','state_at_t_star',4)):5 w lp ls 16 t "Adams, paper's law", \
       paper u (col('cvode-bdf','located','state_at_t_star',4)):5 w lp ls 17 t "BDF, paper's law", \
       hertz u (col('cvode-adams','located','state_at_t_star',4)):5 w lp ls 18 t 'Adams, undamped', \
       hertz u (col('cvode-bdf','located','state_at_t_star',4)):5 w lp ls 19 t 'BDF, undamped', \
       slope(x, 1e-4, 1e-4, 1) ls 20 t 'error = rtol'

  eval quad_key_row
  eval key_panel
  eval key_row
  plot NaN w lp ls 11 t '(a), (b): Euler, located', NaN w lp ls 12 t 'Euler, unlocated', \
       NaN w lp ls 13 t 'RK4, located', NaN w lp ls 14 t 'RK4, unlocated', \
       NaN w lp ls 15 t 'RK4, regularised (mean h)', NaN ls 20 t 'reference slopes (caption)'
  unset multiplot
  set output
}

# Work precision of hertzdash's integrators against the peer libraries.
#   gnuplot -d -c work_precision_peers.gp OUT
# reads OUT/work_precision_peers.csv (contact phase) and OUT/work_precision_peers_drop.csv
# (full drop); writes OUT/work_precision_peers.pdf and .png.
# Top: |e_eff error| against wall time per impact (lower left is better).
# Bottom: |e_eff error| against the tolerance for the adaptive solvers, with error = tolerance.
out = ARG1
here = system('dirname '.ARG0)
do for [kind in 'pdf png'] {
  reset
  load here.'/../../validation/style.gnuplot'
  contact = out.'/work_precision_peers.csv'
  drop = out.'/work_precision_peers_drop.csv'

  # One colour per solver; hertzdash solid with filled points, peers dashed with open points.
  # Style 20 + i for the i-th word of `solvers`; word 7 is a placeholder (27 is the error line).
  set style line 21 lc rgb '#0b3c8c' lw 2.0 dt 1 pt 7 ps 0.55   # hertzdash-dopri5
  set style line 22 lc rgb '#8e44ad' lw 1.6 dt 1 pt 5 ps 0.5    # hertzdash-cvode
  set style line 23 lc rgb '#27ae60' lw 1.6 dt 1 pt 9 ps 0.55   # hertzdash-rk4
  set style line 24 lc rgb '#e67e22' lw 1.6 dt 2 pt 6 ps 0.55   # odeint-dopri5
  set style line 25 lc rgb '#c0392b' lw 1.6 dt 2 pt 4 ps 0.5    # gsl-rk8pd
  set style line 26 lc rgb '#555555' lw 1.6 dt 2 pt 8 ps 0.55   # cvode-fresh
  set style line 27 lc rgb '#999999' lw 1.0 dt 3                # error = tolerance
  set style line 28 lc rgb '#5dade2' lw 2.0 dt 1 pt 11 ps 0.6   # hertzdash-dopri5-regularized
  set style line 29 lc rgb '#bb8fce' lw 1.6 dt 1 pt 13 ps 0.6   # hertzdash-cvode-regularized
  set style line 30 lc rgb '#000000' lw 2.2 dt 1 pt 15 ps 0.6   # hertzdash-gbs8-regularized
  # Peers on the regularised contact: dotted-dashed, open points.
  set style line 31 lc rgb '#d35400' lw 1.6 dt 4 pt 10 ps 0.6   # odeint-bs-regularized
  set style line 32 lc rgb '#f5b041' lw 1.6 dt 4 pt 12 ps 0.6   # odeint-bs-dense-regularized
  set style line 33 lc rgb '#e67e22' lw 1.6 dt 4 pt 14 ps 0.6   # odeint-dopri5-regularized
  set style line 34 lc rgb '#922b21' lw 1.6 dt 4 pt 4 ps 0.5    # gsl-rk8pd-regularized
  set style line 35 lc rgb '#007c91' lw 2.4 dt 1 pt 5 ps 0.6    # hertzdash-taylor-regularized

  solvers = 'hertzdash-dopri5 hertzdash-cvode hertzdash-rk4 odeint-dopri5 gsl-rk8pd cvode-fresh 27 hertzdash-dopri5-regularized hertzdash-cvode-regularized hertzdash-gbs8-regularized odeint-bs-regularized odeint-bs-dense-regularized odeint-dopri5-regularized gsl-rk8pd-regularized hertzdash-taylor-regularized'
  # Legend titles: '-regularized' shortened to '-reg'.
  short(s) = strstrt(s, '-regularized') > 0 ? s[1:strstrt(s, '-regularized') - 1].'-reg' : s
  pick(s, c) = (strcol(1) eq s) ? column(c) : NaN

  set logscale xy
  set format x '10^{%T}'
  set format y '10^{%T}'
  set yrange [1e-12:1e-2]

  call here.'/../../validation/output.gnuplot' out.'/work_precision_peers' kind full_width_in 7.4
  set multiplot

  # One legend for all four panels, the row at the bottom.
  set key off
  set xlabel 'wall time per impact [{/Symbol m}s]'
  set ylabel '|e_{eff} - e_{ref}|'
  set xrange [0.3:1e4]
  set xtics 10
  set title '(a) contact phase, steel, h = 20 mm'
  eval quad_panel(1)
  plot for [i in '15 10 8 1 2 3 4 5 6 9 11 12 13 14'] contact using (pick(word(solvers, i+0), 5)):(pick(word(solvers, i+0), 3)) \
       with linespoints ls 20 + i notitle
  set title '(b) full drop'
  eval quad_panel(2)
  plot for [i in '15 10 8 1 2 3 4 5 6 9 11 12 13 14'] drop using (pick(word(solvers, i+0), 5)):(pick(word(solvers, i+0), 3)) \
       with linespoints ls 20 + i notitle

  set xlabel 'rtol (atol = 10^{-4} rtol)'
  set xrange [1e-11:1e-3]
  set xtics 100
  set title '(c) contact phase'
  eval quad_panel(3)
  plot for [i in '15 10 8 1 9 2 4 5 6 11 12 13 14'] contact using (pick(word(solvers, i+0), 2)):(pick(word(solvers, i+0), 3)) \
       with linespoints ls 20 + i notitle, \
       x with lines ls 27 notitle
  set title '(d) full drop'
  eval quad_panel(4)
  plot for [i in '15 10 8 1 9 2 4 5 6 11 12 13 14'] drop using (pick(word(solvers, i+0), 2)):(pick(word(solvers, i+0), 3)) \
       with linespoints ls 20 + i notitle, \
       x with lines ls 27 notitle
  eval quad_key_row
  eval key_panel
  eval key_row
  set key maxrows 5 width -3 at graph 0.02, 0.5
  plot for [i in '15 10 8 1 2 3 4 5 6 9 11 12 13 14'] NaN with linespoints ls 20 + i title short(word(solvers, i+0)), \
       NaN with lines ls 27 title 'error = tolerance'
  unset multiplot
}

# `hertzdash fit --figure FILE` (issue 46), embedded in the program (cli/CMakeLists.txt) with
# style.gnuplot and output.gnuplot beside it:
#   gnuplot -c fit_figure.gp KIND OUT_BASE FORMAT TITLE EXTRA POINTS [CURVE]
# KIND 'e' (a restitution table, a bounce recording; simulation/reports/fit_curves.hpp):
# (a) e against the impact speed: the data's e (EXTRA says what: a table's rows, or a
# recording's e per bounce, drag-corrected) and the fitted law at the data's impacts with its
# 1-sigma band (CURVE); (b) the residuals e_measured - e_model.
# KIND 'trace' (`fit --curves` columns, write_fit_curves): per channel (EXTRA: their names,
# space-separated) the trace and the fitted model against time, and below it the residuals.
# Draws OUT_BASE.FORMAT (png, pdf or svg), in a temporary directory the program copies it from.
here = system('dirname "'.ARG0.'"')
kind = ARG1
title_text = ARG4
extra = ARG5
points = ARG6
curve = ARG7
load here.'/style.gnuplot'
if (kind eq 'e') {
  call here.'/output.gnuplot' ARG2 ARG3 full_width_in 4.2
  stats points using 'speed_measured_mps' nooutput
  lo = STATS_min
  hi = STATS_max
  stats curve using 'impact_speed_mps' nooutput
  lo = STATS_min < lo ? STATS_min : lo
  hi = STATS_max > hi ? STATS_max : hi
  pad = hi > lo ? 0.05 * (hi - lo) : 0.05 * hi
  set xrange [lo - pad : hi + pad]
  stats points using 'e_measured' nooutput
  e_lo = STATS_min
  e_hi = STATS_max
  stats curve using 'e_model' nooutput
  e_lo = STATS_min < e_lo ? STATS_min : e_lo
  e_hi = STATS_max > e_hi ? STATS_max : e_hi
  set ytics nice_step(e_hi - e_lo)
  set multiplot
  # The two panels share their x axis: the same margins, the key to the right of the upper one.
  set lmargin at screen 0.18
  set rmargin at screen 0.57
  set tmargin at screen 0.88
  set bmargin at screen 0.45
  set label 1 title_text at screen 0.02, 0.955 left noenhanced
  set format x ''
  set ylabel 'Coefficient of restitution'
  set key at screen 0.585, 0.88 left top Left reverse samplen 1.2 width -2 font ',8' nobox noopaque
  plot curve using 'impact_speed_mps':'e_low':'e_high' with filledcurves ls 11 title 'fitted law, 1-sigma band', \
       curve using 'impact_speed_mps':'e_model' with lines ls 1 title 'fitted law', \
       points using 'speed_measured_mps':'e_measured' with points ls 3 ps 0.6 title extra
  unset label 1
  set tmargin at screen 0.41
  set bmargin at screen 0.16
  stats points using 'residual_e' nooutput
  set ytics nice_step(STATS_max - STATS_min)
  set format x '%g'
  set xlabel 'Impact speed (m/s)'
  set ylabel 'Residual' offset 0, 0
  set key off
  plot 0 with lines ls 2, points using 'speed_measured_mps':'residual_e' with points ls 3 ps 0.6
  unset multiplot
} else {
  n = words(extra)
  height_in = 2.6 * n + 0.6
  call here.'/output.gnuplot' ARG2 ARG3 full_width_in height_in
  ms(c) = 1e3 * column(c)
  # A channel's label from its column name (the trace format's names, data/measurements/README.md).
  channel_label(c) = c eq 'force_N' ? 'Force (N)' : c eq 'accel_mps2' ? 'Acceleration (m/s^2)' : \
                     c eq 'displacement_m' ? 'Displacement (m)' : c eq 'velocity_mps' ? 'Velocity (m/s)' : c
  set multiplot
  set lmargin at screen 0.2
  set rmargin at screen 0.97
  set autoscale xfix
  set format y '%g'
  set key off
  block = 0.86 / n   # each channel's share of the canvas above the key row, its overlay above its residuals
  do for [k = 1:n] {
    channel = word(extra, k)
    bottom = 0.1 + (n - k) * block
    set tmargin at screen bottom + 0.97 * block
    set bmargin at screen bottom + 0.47 * block
    set format x ''
    unset xlabel
    stats points using channel.'_measured' nooutput
    set ytics nice_step(STATS_max - STATS_min)
    set ylabel channel_label(channel) noenhanced
    unset label 2
    plot points using (ms('t_s')):channel.'_measured' with points ls 3 ps 0.25, \
         points using (ms('t_s')):channel.'_model' with lines ls 1
    set tmargin at screen bottom + 0.36 * block
    set bmargin at screen bottom + 0.08 * block
    set format x (k == n ? '%g' : '')
    set xlabel k == n ? 'Time (ms)' : ''
    stats points using channel.'_residual' nooutput
    set ytics nice_step(STATS_max - STATS_min)
    unset ylabel
    set label 2 'residual' at graph 0.01, 0.85 left front font ',8'
    plot 0 with lines ls 2, points using (ms('t_s')):channel.'_residual' with lines ls 3 lw 0.8
  }
  eval quad_key_row
  set size 1, 0.06
  eval key_panel
  eval key_row
  plot NaN with points ls 3 ps 0.5 title 'trace', NaN with lines ls 1 title title_text
  unset multiplot
}

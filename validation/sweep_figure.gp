# `hertzdash sweep CASE --figure FILE` (issue 46), embedded in the program (cli/CMakeLists.txt)
# with style.gnuplot and output.gnuplot beside it:
#   gnuplot -c sweep_figure.gp rig  OUT_BASE FORMAT TITLE KEY IMPACTS_CSV
#   gnuplot -c sweep_figure.gp rows OUT_BASE FORMAT TITLE KEY OUTPUTS ROWS_CSV
# rig: the bifurcation diagram of a rig's sweep over KEY, from its per-impact table
# (CSV.impacts.csv, docs/sweep.md): (a) every kept impact's phase of the drive, (b) its impact
# speed, against KEY. rows: each of OUTPUTS (space-separated columns of the rows) against KEY.
# Draws OUT_BASE.FORMAT (png, pdf or svg), in a temporary directory the program copies it from.
here = system('dirname "'.ARG0.'"')
load here.'/style.gnuplot'
key_column = ARG5
if (ARG1 eq 'rig') {
  impacts = ARG6
  call here.'/output.gnuplot' ARG2 ARG3 full_width_in 5.0
  set multiplot
  set lmargin at screen 0.15
  set rmargin at screen 0.97
  set autoscale xfix
  set key off
  set label 1 ARG4 at screen 0.02, 0.965 left noenhanced
  set tmargin at screen 0.9
  set bmargin at screen 0.54
  set format x ''
  set yrange [0:1]
  set ytics 0.25
  set ylabel 'Impact phase (cycles)'
  plot impacts using key_column:'impact_phase' with points ls 1 pt 7 ps 0.25
  unset label 1
  set tmargin at screen 0.51
  set bmargin at screen 0.16
  set format x '%g'
  set xlabel key_column noenhanced
  set autoscale y
  set ytics autofreq
  set ylabel 'Impact speed (m/s)'
  plot impacts using key_column:'impact_speed_mps' with points ls 1 pt 7 ps 0.25
  unset multiplot
} else {
  rows = ARG7
  n = words(ARG6)
  height_in = 1.8 * n + 0.8
  call here.'/output.gnuplot' ARG2 ARG3 full_width_in height_in
  set multiplot
  set lmargin at screen 0.17
  set rmargin at screen 0.97
  set autoscale xfix
  set format y '%g'
  set key off
  set label 1 ARG4 at screen 0.02, 1 - 0.25 / height_in left noenhanced
  top = 1 - 0.5 / height_in
  bottom = 0.7 / height_in
  panel = (top - bottom) / n
  do for [k = 1:n] {
    output = word(ARG6, k)
    set tmargin at screen top - (k - 1) * panel
    set bmargin at screen top - k * panel + 0.04
    set format x (k == n ? '%g' : '')
    set xlabel (k == n ? key_column : '') noenhanced
    set ylabel output noenhanced
    stats rows using output nooutput
    set ytics nice_step(STATS_max - STATS_min)
    plot rows using key_column:output with linespoints ls 1 pt 7 ps 0.4
    unset label 1
  }
  unset multiplot
}

# The basins of the bouncing ball's attractors where they coexist: gnuplot -d -c shaker_basins.gp OUT
# -> OUT/shaker_basins.pdf, .png from OUT/shaker_basins.csv (validation/shaker_basins). Each start at
# the section (position, velocity) coloured by the attractor it reaches; the period-1 orbit found by
# shooting marked.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/shaker_basins.csv'
orbit_y = real(system(sprintf("sed -n 's/^# orbit: position \\([-0-9.e]*\\) m.*/\\1/p' '%s'", data)))
orbit_u = real(system(sprintf("sed -n 's/^# orbit: position .* m, velocity \\([-0-9.e]*\\) m\\/s.*/\\1/p' '%s'", data)))
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/shaker_basins' format full_width_in 3.0
  set multiplot
  set origin 0, 0
  set size 0.68, 1
  set xlabel 'Position at the section (mm)'
  set ylabel 'Velocity at the section (m/s)'
  set xrange [0:20]
  set yrange [-0.5:0.5]
  unset grid
  unset colorbox
  unset key
  set palette defined (-1 '#cccccc', 0 '#0b3c8c', 1 '#c0392b', 2 '#27ae60')
  set cbrange [-1:2]
  plot data using (1000 * column('position_m')):'velocity_mps':'attractor' with image notitle, \
       '+' using (1000 * orbit_y):(orbit_u) every ::0::0 with points pt 3 ps 1.2 lw 2 lc rgb '#ffffff' notitle
  eval two_panels_key
  eval key_panel
  plot NaN with boxes fs solid 1.0 lc rgb '#0b3c8c' title 'period-1 orbit', \
       NaN with boxes fs solid 1.0 lc rgb '#c0392b' title 'at rest on the table', \
       NaN with boxes fs solid 1.0 lc rgb '#27ae60' title 'another attractor', \
       NaN with points pt 3 ps 1.2 lw 2 lc rgb '#000000' title 'the orbit (shooting)'
  unset multiplot
}

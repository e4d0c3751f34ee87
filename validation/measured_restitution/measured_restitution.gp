# Gugan's measured restitution and every law's fit: gnuplot -d -c measured_restitution.gp OUT ->
# OUT/measured_restitution.pdf, .png from OUT/measured_restitution_curves.csv and
# OUT/measured_restitution_points.csv (validation/measured_restitution). (a) The croquet ball's
# measured e against the impact speed (points) and each law's best fit (lines); the laws whose e
# does not depend on the speed coincide, and the paper's law is drawn last, on top of them.
# (b) The residuals, measured minus fitted e, at the table's speeds (the CSV's rows in order of speed).
out = ARG1
here = system('dirname '.ARG0)
curves = out.'/measured_restitution_curves.csv'
points = out.'/measured_restitution_points.csv'
paper_law = 'hongo'
pick(law, value) = strcol('law') eq law ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/../damping_laws/law_styles.gnuplot'
  laws = law_names(curves)
  first = word(laws, 1)
  call here.'/../output.gnuplot' out.'/measured_restitution' format full_width_in 4.4
  set multiplot
  set key off
  set xlabel 'Impact speed U (m/s)'
  set xrange [0:7.2]
  set xtics 1
  # (a) e(U): the other laws first, the paper's law on top, the measured points over all.
  set origin 0, 0.3
  set size 0.5, 0.7
  set ylabel 'Coefficient of restitution e'
  set yrange [0.74:0.89]
  set ytics 0.02
  set format y '%.2f'
  set label 1 '(a) fits' at graph 0.96, 0.07 right front
  plot for [i=1:words(laws)] curves using (word(laws, i) eq paper_law ? NaN : pick(word(laws, i), column('impact_speed_mps'))):'e_effective' \
         with lines lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i)), \
       curves using (pick(paper_law, column('impact_speed_mps'))):'e_effective' \
         with lines lw law_lw(paper_law) lc rgb law_lc(paper_law) dt law_dt(paper_law), \
       points using (pick(first, column('impact_speed_mps'))):'e_measured' with points pt 7 ps 0.7 lc rgb '#000000'
  # (b) residuals at the table's speeds.
  set origin 0.5, 0.3
  set size 0.5, 0.7
  set ylabel 'Measured - fitted e'
  set yrange [-0.08:0.10]
  set ytics 0.04
  set label 1 '(b) residuals' at graph 0.96, 0.93 right front
  set arrow 1 from graph 0, first 0 to graph 1, first 0 nohead lc rgb '#555555' dt 3 lw 1.0
  plot for [i=1:words(laws)] points using (word(laws, i) eq paper_law ? NaN : pick(word(laws, i), column('impact_speed_mps'))):'residual' \
         with linespoints pt 7 ps 0.35 lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i)), \
       points using (pick(paper_law, column('impact_speed_mps'))):'residual' \
         with linespoints pt 7 ps 0.35 lw law_lw(paper_law) lc rgb law_lc(paper_law) dt law_dt(paper_law)
  unset arrow 1
  # The legend, in a row of its own below the panels: it covers no data.
  set origin 0, 0.01
  set size 1, 0.27
  set margins 0, 0, 0, 0
  eval key_panel
  eval key_row
  set key maxrows 5 width -3
  plot NaN with points pt 7 ps 0.7 lc rgb '#000000' title 'measured (Gugan)', \
       for [i=1:words(laws)] NaN with lines lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i)) title word(laws, i)
  unset multiplot
}

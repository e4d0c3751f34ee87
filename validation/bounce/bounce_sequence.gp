# A drop and its bounces: gnuplot -d -c bounce_sequence.gp OUT -> OUT/bounce_sequence.pdf, .png
# from OUT/bounce_sequence.csv and OUT/bounce_restitutions.csv (validation/bounce). Steel rod
# from 20 mm. (a) the gap between the rod's face and the ball (the paper's law; contacts last
# ~1 ms, too short to see); (b) per impact, the restitution from the intervals between impacts
# (the paper's measurement, solid) and from the velocities (dashed), for the paper's law and
# the viscoelastic law with the same force at the first impact.
out = ARG1
here = system('dirname '.ARG0)
gaps = out.'/bounce_sequence.csv'
data = out.'/bounce_restitutions.csv'
pick(law, value) = strcol('damping') eq law ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/../damping_laws/law_styles.gnuplot'
  call here.'/../output.gnuplot' out.'/bounce_sequence' format full_width_in 3.4
  set multiplot
  set key off
  set label 1 at graph 0.04, 0.92 front
  set origin 0, 0.25
  set size 0.5, 0.75
  set label 1 '(a)'
  set xlabel 'Time from release (s)'
  set ylabel 'Gap (mm)'
  set yrange [0:22]
  set autoscale xfix
  set xtics 0.1  # the default 0.05 steps ran their labels together
  plot gaps using 't_s':(1e3*column('gap_m')) with lines ls 1
  set origin 0.5, 0.25
  set size 0.5, 0.75
  set label 1 '(b)'
  set xlabel 'Impact'
  set ylabel 'Restitution'
  set xtics 1
  set xrange [0.5:*]
  set autoscale y
  set offsets 0, 0.5, graph 0.08, graph 0.08
  plot for [law in 'hongo kuwabara-kono'] data using (pick(law, column('impact'))):'e_from_intervals' \
         with linespoints lc rgb law_lc(law) lw 1.6 pt 7 ps 0.5, \
       for [law in 'hongo kuwabara-kono'] data using (pick(law, column('impact'))):'e_velocity_ratio' \
         with linespoints lc rgb law_lc(law) lw 1.2 dt 2 pt 6 ps 0.5
  set origin 0, 0.01
  set size 1, 0.16
  set margins 0, 0, 0, 0
  eval key_panel
  eval key_row
  set key maxrows 2
  plot NaN with linespoints lc rgb law_lc('hongo') lw 1.6 pt 7 ps 0.5 title 'hongo (the paper): intervals', \
       NaN with linespoints lc rgb law_lc('hongo') lw 1.2 dt 2 pt 6 ps 0.5 title 'hongo: velocities', \
       NaN with linespoints lc rgb law_lc('kuwabara-kono') lw 1.6 pt 7 ps 0.5 title 'kuwabara-kono: intervals', \
       NaN with linespoints lc rgb law_lc('kuwabara-kono') lw 1.2 dt 2 pt 6 ps 0.5 title 'kuwabara-kono: velocities'
  unset multiplot
}

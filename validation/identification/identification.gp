# Identification on virtual experiments: gnuplot -d -c identification.gp OUT -> OUT/identification.pdf, .png
# from OUT/identification_draws.csv and OUT/identification_bias.csv (validation/identification).
# All traces SYNTHETIC. Small points: the rigid model fitted to its own traces, one per noise draw
# (the scatter the error bars must describe); filled diamonds: the rigid model fitted to the
# elastic rod's trace (the bias the paper's model would have had); open circles: the elastic
# model fitted to the same trace. Colour: the rod.
out = ARG1
here = system('dirname '.ARG0)
draws = out.'/identification_draws.csv'
bias = out.'/identification_bias.csv'
rods = 'steel duralumin-a duralumin-b duralumin-c'
pick(rod, value) = strcol('rod') eq rod ? value : NaN
pick_model(rod, model, value) = strcol('rod') eq rod && strcol('model') eq model ? value : NaN
E_err(c) = 100 * (column(c) / 1.7e9 - 1)
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/identification' format full_width_in 3.2
  set multiplot
  set origin 0, 0
  set size 0.62, 1
  set key off
  set xlabel 'Estimated E / true E - 1 (%)'
  set ylabel 'Estimated e - true e'
  set xzeroaxis lt -1 lw 0.6
  set yzeroaxis lt -1 lw 0.6
  set format y '%.3f'
  plot for [rod in rods] draws using (pick(rod, E_err('E_estimate_Pa'))):(column('e_estimate') - column('e_truth')) \
         with points pt 7 ps 0.25 lc rgb rod_tint(rod), \
       for [rod in rods] bias using (pick_model(rod, 'rigid', E_err('E_estimate_Pa'))):(column('e_estimate') - column('e_truth')) \
         with points pt 13 ps 1.1 lc rgb rod_colour(rod), \
       for [rod in rods] bias using (pick_model(rod, 'elastic', E_err('E_estimate_Pa'))):(column('e_estimate') - column('e_truth')) \
         with points pt 6 ps 1.0 lw 1.2 lc rgb rod_colour(rod)
  set origin 0.63, 0
  set size 0.37, 1
  unset xzeroaxis
  unset yzeroaxis
  eval key_panel
  plot for [rod in rods] NaN with points pt 7 ps 0.6 lc rgb rod_colour(rod) title rod_label(rod), \
       NaN with points pt 7 ps 0.4 lc rgb '#999999' title 'rigid on rigid (draws)', \
       NaN with points pt 13 ps 1.0 lc rgb '#555555' title 'rigid on elastic rod', \
       NaN with points pt 6 ps 1.0 lw 1.2 lc rgb '#555555' title 'elastic on elastic rod'
  unset multiplot
}

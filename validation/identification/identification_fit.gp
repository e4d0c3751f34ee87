# A fit and its residuals: gnuplot -d -c identification_fit.gp OUT -> OUT/identification_fit.pdf, .png
# from OUT/identification_fit_{rigid,elastic}.csv (validation/identification; `hertzdash fit
# --curves` writes the same columns for any trace). The steel rod's virtual experiment
# (SYNTHETIC: the elastic rod on the load cell, 500 kHz, 100 kHz anti-alias, 1 % noise) with the
# rigid model's fit (grey dashed, as in the elastic-rod figures) and the elastic rod's (the rod's
# colour); below each channel, the residuals of both fits.
out = ARG1
here = system('dirname '.ARG0)
rigid = out.'/identification_fit_rigid.csv'
elastic = out.'/identification_fit_elastic.csv'
ms(c) = 1e3 * column(c)
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/identification_fit' format full_width_in 5.2
  set multiplot
  set key off
  set label 1 at graph 0.04, 0.9 front
  set autoscale xfix
  set offsets 0, 0, graph 0.05, graph 0.05
  set xlabel 'Time (ms)'
  set xtics 0.5
  # (a), (b): the force and the acceleration with both fits.
  eval quad_panel(1)
  set label 1 '(a)'
  set ylabel 'Load cell force (N)'
  plot rigid using (ms('t_s')):'force_N_measured' with points ls 3 ps 0.12, \
       rigid using (ms('t_s')):'force_N_model' with lines ls 2, \
       elastic using (ms('t_s')):'force_N_model' with lines lc rgb rod_colour('steel') lw 1.0
  eval quad_panel(2)
  set label 1 '(b)'
  set ylabel 'Acceleration (m/s^2)'
  plot rigid using (ms('t_s')):'accel_mps2_measured' with points ls 3 ps 0.12, \
       elastic using (ms('t_s')):'accel_mps2_model' with lines lc rgb rod_colour('steel') lw 0.8, \
       rigid using (ms('t_s')):'accel_mps2_model' with lines ls 2
  # (c), (d): residuals, trace minus model.
  eval quad_panel(3)
  set label 1 '(c)'
  set ylabel 'Force residual (N)'
  plot rigid using (ms('t_s')):'force_N_residual' with lines ls 2 lw 0.8, \
       elastic using (ms('t_s')):'force_N_residual' with lines lc rgb rod_colour('steel') lw 0.6
  eval quad_panel(4)
  set label 1 '(d)'
  set ylabel 'Acceleration residual (m/s^2)'
  plot elastic using (ms('t_s')):'accel_mps2_residual' with lines lc rgb rod_colour('steel') lw 0.6, \
       rigid using (ms('t_s')):'accel_mps2_residual' with lines ls 2 lw 0.8
  eval quad_key_row
  eval key_panel
  eval key_row
  plot NaN with points ls 3 ps 0.5 title 'virtual experiment, elastic steel rod (synthetic)', \
       NaN with lines ls 2 title 'fit: rigid model (the paper''s)', \
       NaN with lines lc rgb rod_colour('steel') lw 1.2 title 'fit: elastic rod on the load cell'
  unset multiplot
}

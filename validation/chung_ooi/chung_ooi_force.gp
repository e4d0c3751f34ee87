# Chung & Ooi (2011) benchmark tests 1 and 2: gnuplot -d -c chung_ooi_force.gp OUT
# -> OUT/chung_ooi_force.pdf, .png from OUT/chung_ooi_force_model.csv (the simulated undamped
# Hertz contact), OUT/chung_ooi_force_overlap.csv and OUT/chung_ooi_force_time.csv (the points
# digitised from Chung & Ooi's figures) (validation/chung_ooi). (a), (b) test 1, two glass
# spheres at 20 m/s; (c), (d) test 2, an aluminium sphere on a rigid flat at 0.2 m/s. The
# simulated curve is the closed form to within 1e-9 of the peak force; the digitised points
# carry ~1 % of full scale in both columns.
out = ARG1
here = system('dirname '.ARG0)
model = out.'/chung_ooi_force_model.csv'
overlap = out.'/chung_ooi_force_overlap.csv'
time = out.'/chung_ooi_force_time.csv'
pick(test, value) = strcol('test') eq test ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/chung_ooi_force' format full_width_in 5.2
  set multiplot
  set key off
  set label 1 at graph 0.04, 0.90 front
  set ylabel 'Contact force (kN)'
  set yrange [0:13.5]
  set ytics 2
  set autoscale xfix
  set offsets 0, graph 0.03, 0, 0
  do for [k=1:4] {
    eval quad_panel(k)
    test = k <= 2 ? 'test1' : 'test2'
    name = k <= 2 ? 'Test 1' : 'Test 2'
    set xtics word('50 10 10 200', k) + 0
    if (k % 2 == 1) {
      set label 1 sprintf('(%s) %s', word('a b c d', k), name)
      set xlabel 'Overlap ({/Symbol m}m)'
      plot model using (pick(test, 1e6*column('x_m'))):(1e-3*column('force_N')) with lines ls 1, \
           overlap using (pick(test, 1e6*column('x_m'))):(1e-3*column('force_N')) with points ls 3 pt 6 ps 0.8 lw 1.2
    } else {
      set label 1 sprintf('(%s) %s', word('a b c d', k), name)
      set xlabel 'Time from first contact ({/Symbol m}s)'
      plot model using (pick(test, 1e6*column('t_s'))):(1e-3*column('force_N')) with lines ls 1, \
           time using (pick(test, 1e6*column('t_s'))):(1e-3*column('force_N')) with points ls 3 pt 6 ps 0.8 lw 1.2
    }
  }
  eval quad_key_row
  eval key_panel
  eval key_row
  plot NaN with lines ls 1 title 'hertzdash: undamped Hertz, simulated (= closed form)', \
       NaN with points ls 3 pt 6 ps 0.8 lw 1.2 title 'digitised, Chung \& Ooi 2011 (about 1 % of full scale)'
  unset multiplot
}

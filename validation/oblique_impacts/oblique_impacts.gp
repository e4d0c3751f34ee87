# Chung and Ooi's test 4 with each tangential model: gnuplot -d -c oblique_impacts.gp OUT
# -> OUT/oblique_impacts.pdf, .png from OUT/oblique_impacts.csv and OUT/oblique_impacts_reference.csv
# (validation/oblique_impacts). Against the incident angle: (a) the tangential restitution of the
# centre e_t = w_1/w_0, (b) the rebound spin omega_1, (c) the rebound angle of the contact point, with the reference
# curve's digitised points (circles) and the experiment's rebound angles (triangles), (d) the
# fraction of the contact spent sliding. One colour and dash per model (style.gnuplot).
out = ARG1
here = system('dirname '.ARG0)
data = out.'/oblique_impacts.csv'
ref = out.'/oblique_impacts_reference.csv'
pick(m, value) = strcol('model') eq m ? value : NaN
curve(name, value) = strcol('curve') eq name ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  models = csv_parameter(data, 'tangential_models')  # the registered models, in the registry's order
  call here.'/../output.gnuplot' out.'/oblique_impacts' format full_width_in 4.6
  set multiplot
  set key off
  set xrange [0:90]
  set xtics 15
  set xlabel 'incident angle (deg)'
  eval quad_panel(1)
  set ylabel 'e_t = w_1 / w_0'
  set yrange [0.4:1.1]
  set ytics 0.2
  set label 1 '(a)' at graph 0.9, 0.12 font ',10'
  plot for [m in models] data using 'angle_deg':(pick(m, column('tangential_restitution'))) with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m), \
       ref using 'angle_deg':(curve('tangential_restitution', column('value'))) with points pt 6 ps 0.6 lc rgb 'black'
  eval quad_panel(2)
  set ylabel '{/Symbol w}_1 (rad/s)'
  set yrange [-800:0]
  set ytics 200
  set label 1 '(b)'
  plot for [m in models] data using 'angle_deg':(pick(m, column('rebound_angular_velocity_rad_per_s'))) with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m), \
       ref using 'angle_deg':(curve('rebound_angular_velocity_rad_per_s', column('value'))) with points pt 6 ps 0.6 lc rgb 'black'
  eval quad_panel(3)
  set ylabel 'rebound angle (deg)'
  set yrange [-20:90]
  set ytics 20
  set label 1 '(c)'
  plot for [m in models] data using 'angle_deg':(pick(m, column('rebound_angle_deg'))) with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m), \
       ref using 'angle_deg':(curve('rebound_angle_deg', column('value'))) with points pt 6 ps 0.6 lc rgb 'black', \
       ref using 'angle_deg':(curve('rebound_angle_deg_experiment', column('value'))) with points pt 9 ps 0.7 lc rgb '#777777'
  eval quad_panel(4)
  set ylabel 'sliding fraction'
  set yrange [0:1.05]
  set ytics 0.25
  set label 1 '(d)'
  plot for [m in models] data using 'angle_deg':(pick(m, column('sliding_fraction'))) with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m)
  eval quad_key_row
  eval key_panel
  eval key_row
  plot for [m in models] NaN with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m) title m, \
       NaN with points pt 6 ps 0.6 lc rgb 'black' title 'Chung and Ooi, test 4', \
       NaN with points pt 9 ps 0.7 lc rgb '#777777' title 'experiment (c)'
  unset multiplot
}

# Height sweep: gnuplot -d -c height_sweep.gp OUT -> OUT/height_sweep.pdf, OUT/height_sweep.png
# from OUT/height_sweep.csv (validation/height_sweep). Solid: the paper's model, one
# colour per rod; dashed, same colour: undamped Hertz closed forms (v0^{6/5}, v0^{4/5}, v0^{-1/5}).
out = ARG1
here = system('dirname '.ARG0)
data = out.'/height_sweep.csv'
rods = 'steel duralumin-a duralumin-b duralumin-c'
pick(r, value) = strcol('rod') eq r ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/height_sweep' format full_width_in 5.8
  set multiplot
  set logscale x
  set xlabel 'Impact velocity v_0 (m/s)'
  set mxtics 10
  set autoscale xfix
  set xtics (0.2, 0.3, 0.5, 0.7, 1, 1.5)
  set autoscale yfix
  set offsets 0, 0, graph 0.08, graph 0.08
  set key off
  set label 1 at graph 0.04, 0.90 front

  set logscale y
  eval quad_panel(1)
  set label 1 '(a)'
  set ytics (100, 200, 500, 1000, 2000, 5000)
  set ylabel 'Peak force (N)'
  plot for [i=1:4] data using (pick(word(rods,i), column('impact_velocity_mps'))):'peak_force_hertz_N' with lines lc rgb rod_colour(word(rods,i)) dt 2 lw 1.2, \
       for [i=1:4] data using (pick(word(rods,i), column('impact_velocity_mps'))):'peak_force_N' with lines lc rgb rod_colour(word(rods,i)) lw 1.6 dt 1
  eval quad_panel(2)
  set label 1 '(b)'
  set ytics (20, 50, 100, 200, 500)
  set ylabel 'x_{max} ({/Symbol m}m)'
  plot for [i=1:4] data using (pick(word(rods,i), column('impact_velocity_mps'))):(1e6*column('max_deformation_hertz_m')) with lines lc rgb rod_colour(word(rods,i)) dt 2 lw 1.2, \
       for [i=1:4] data using (pick(word(rods,i), column('impact_velocity_mps'))):(1e6*column('max_deformation_m')) with lines lc rgb rod_colour(word(rods,i)) lw 1.6 dt 1
  eval quad_panel(3)
  set label 1 '(c)' at graph 0.96, 0.90 right
  set ytics (0.3, 0.5, 0.7, 1, 1.5, 2, 3)
  set ylabel 'Contact time (ms)'
  plot for [i=1:4] data using (pick(word(rods,i), column('impact_velocity_mps'))):(1e3*column('contact_time_hertz_s')) with lines lc rgb rod_colour(word(rods,i)) dt 2 lw 1.2, \
       for [i=1:4] data using (pick(word(rods,i), column('impact_velocity_mps'))):(1e3*column('contact_time_s')) with lines lc rgb rod_colour(word(rods,i)) lw 1.6 dt 1
  unset logscale y
  eval quad_panel(4)
  set label 1 '(d)' at graph 0.04, 0.90 left
  set ytics autofreq
  set ylabel 'Restitution e_{eff}'
  set yrange [0.78:0.89]
  set offsets 0, 0, 0, 0
  # Duralumin A and C have the same Table 2 e (0.828): their curves lie on each other.
  set label 2 'A and C coincide' at graph 0.96, 0.28 right font ',8'
  plot for [i=1:4] data using (pick(word(rods,i), column('impact_velocity_mps'))):'e_input' with lines lc rgb rod_colour(word(rods,i)) dt 3 lw 1.2 notitle, \
       for [i=1:4] data using (pick(word(rods,i), column('impact_velocity_mps'))):'e_effective' with lines lc rgb rod_colour(word(rods,i)) lw 1.6 dt 1 notitle
  eval quad_key_row
  eval key_panel
  eval key_row
  plot for [i=1:4] NaN with lines lc rgb rod_colour(word(rods,i)) lw 1.6 dt 1 title rod_label(word(rods,i)), \
       NaN with lines lc rgb '#555555' dt 2 lw 1.2 title 'undamped Hertz (a-c)', \
       NaN with lines lc rgb '#555555' dt 3 lw 1.2 title 'input e, Table 2 (d)'
  unset multiplot
}

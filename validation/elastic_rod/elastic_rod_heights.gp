# Rigid model against the elastic rig over drop heights: gnuplot -d -c elastic_rod_heights.gp OUT
# -> OUT/elastic_rod_heights.pdf, .png from OUT/elastic_rod_heights.csv (validation/elastic_rod).
# One colour per rod; (a) dashed: rigid model, solid: elastic rod on the load cell (virtual
# experiment); (b) the energy left in rod vibration at separation; (c), (d) the departures of
# the peak force and the contact time, with the 1 % line.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/elastic_rod_heights.csv'
rods = 'steel duralumin-a duralumin-b duralumin-c'
pick(r, value) = strcol('rod') eq r ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/elastic_rod_heights' format full_width_in 5.6
  set multiplot
  set logscale x
  set xlabel 'Drop height h (mm)'
  set xtics (2, 5, 10, 20, 50, 100)
  set autoscale xfix
  set key off
  set label 1 at graph 0.04, 0.90 front
  set offsets 0, 0, graph 0.08, graph 0.08

  eval quad_panel(1)
  set label 1 '(a)'
  set ylabel 'Restitution e_{eff}'
  plot for [i=1:4] data using (pick(word(rods,i), 1e3*column('height_m'))):'e_rigid' with lines lc rgb rod_colour(word(rods,i)) dt 2 lw 1.2, \
       for [i=1:4] data using (pick(word(rods,i), 1e3*column('height_m'))):'e_elastic' with lines lc rgb rod_colour(word(rods,i)) lw 1.6
  eval quad_panel(2)
  set label 1 '(b)'
  set logscale y
  set format y '10^{%L}'
  set ylabel 'Vibration / energy in'
  plot for [i=1:4] data using (pick(word(rods,i), 1e3*column('height_m'))):'wave_energy_share' with lines lc rgb rod_colour(word(rods,i)) lw 1.6
  unset logscale y
  set format y '% g'
  eval quad_panel(3)
  set label 1 '(c)' at graph 0.04, 0.08
  set ylabel 'Peak force departure (%)'
  set yrange [0:1.3]
  plot for [i=1:4] data using (pick(word(rods,i), 1e3*column('height_m'))):(100*column('peak_force_departure')) with lines lc rgb rod_colour(word(rods,i)) lw 1.6, \
       1 with lines ls 2
  eval quad_panel(4)
  set label 1 '(d)'
  set ylabel 'Contact time departure (%)'
  plot for [i=1:4] data using (pick(word(rods,i), 1e3*column('height_m'))):(100*column('contact_time_departure')) with lines lc rgb rod_colour(word(rods,i)) lw 1.6, \
       1 with lines ls 2
  eval quad_key_row
  eval key_panel
  eval key_row
  set key maxrows 3
  plot for [i=1:4] NaN with lines lc rgb rod_colour(word(rods,i)) lw 1.6 title rod_label(word(rods,i)), \
       NaN with lines lc rgb '#555555' lw 1.6 title 'solid: virtual experiment', \
       NaN with lines lc rgb '#555555' dt 2 lw 1.2 title 'dashed: rigid model; 1 %'
  unset multiplot
}

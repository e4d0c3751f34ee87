# What the instruments would have recorded: gnuplot -d -c elastic_rod_instruments.gp OUT ->
# OUT/elastic_rod_instruments.pdf, .png from OUT/elastic_rod_traces.csv (validation/elastic_rod).
# Virtual experiment (synthetic). Grey dashed: the rigid model's contact force and rod
# acceleration (Figs. 5 and 6, panels a and d); solid, the rod's colour: the elastic rod on
# the load cell as the load cell and the top-face accelerometer would read it.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/elastic_rod_traces.csv'
pick(rod, model, value) = (strcol('rod') eq rod && strcol('model') eq model) ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/elastic_rod_instruments' format full_width_in 5.6
  set multiplot
  set key off
  set xlabel 'Time from onset (ms)'
  set label 1 at graph 0.04, 0.90 front
  set offsets 0, 0, graph 0.06, graph 0.06
  do for [k=1:4] {
    rod = k <= 2 ? 'steel' : 'duralumin-c'
    eval quad_panel(k)
    xstep = k <= 2 ? 0.5 : 0.2
    set xtics xstep
    set label 1 sprintf('(%s)', k == 1 ? 'a' : k == 2 ? 'b' : k == 3 ? 'c' : 'd')
    if (k % 2 == 1) {
      set ylabel 'Force (N)'
      plot data using (pick(rod, 'rigid', 1e3*column('t_s'))):'contact_force_N' with lines ls 2, \
           data using (pick(rod, 'elastic', 1e3*column('t_s'))):'load_cell_force_N' with lines lc rgb rod_colour(rod) lw 1.4
    } else {
      set ylabel 'Acceleration (m/s^2)'
      plot data using (pick(rod, 'rigid', 1e3*column('t_s'))):'accelerometer_mps2' with lines ls 2, \
           data using (pick(rod, 'elastic', 1e3*column('t_s'))):'accelerometer_mps2' with lines lc rgb rod_colour(rod) lw 1.0
    }
  }
  eval quad_key_row
  eval key_panel
  eval key_row
  plot NaN with lines ls 2 title 'rigid model: contact force (a, c), rod acceleration (b, d)', \
       NaN with lines lc rgb rod_colour('steel') lw 1.4 title 'virtual experiment, steel (a, b): load cell, top-face accelerometer', \
       NaN with lines lc rgb rod_colour('duralumin-c') lw 1.4 title 'virtual experiment, duralumin C (c, d): the same'
  unset multiplot
}

# Effective against input restitution of every damping law, rigid-wall contact phase:
#   gnuplot -d -c restitution_map.gp OUT -> OUT/restitution_map.pdf, OUT/restitution_map.png
# from OUT/restitution_map.csv (validation/damping_laws). (a) tension allowed, (b) the
# force clamped at zero (--no-tension). The dotted diagonal is e_effective = e.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/restitution_map.csv'
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/law_styles.gnuplot'
  eval set_terminal(format, out.'/restitution_map', 7.0, 3.0)
  laws = law_names(data)
  set multiplot
  set xrange [0:1]
  set yrange [0:1.03]
  set xtics 0.2
  set ytics 0.2
  set xlabel 'input restitution e'
  set ylabel 'effective restitution e_{eff}'
  set label 1 at graph 0.04, 0.93 left front font ',9'
  do for [panel in 'allowed clamped'] {
    if (panel eq 'allowed') { eval panel_a; set key off; set label 1 '(a) tension allowed' } \
    else { eval panel_b; eval side_key; set label 1 '(b) tension clamped' }
    plot x with lines lc rgb '#999999' lw 1 dt 3 notitle, \
         for [i=1:words(laws)] data using (strcol('model') eq word(laws, i) && strcol('tension') eq panel ? \
           column('e_input') : NaN):'e_effective' with lines \
           lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i), i) dt law_dt(word(laws, i), i) title word(laws, i)
  }
  unset multiplot
}

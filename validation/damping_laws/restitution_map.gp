# Effective against input restitution of every damping law, rigid-wall contact phase:
#   gnuplot -d -c restitution_map.gp OUT -> OUT/restitution_map.pdf, OUT/restitution_map.png
# from OUT/restitution_map.csv (validation/damping_laws). (a) tension allowed, (b) the
# force clamped at zero (--no-tension). The dotted diagonal is e_effective = e. The legend
# has a panel of its own, so no law covers another's curve however many are registered.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/restitution_map.csv'
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/law_styles.gnuplot'
  call here.'/../output.gnuplot' out.'/restitution_map' format full_width_in 3.2
  laws = law_names(data)
  set multiplot
  set xrange [0:1]
  set yrange [0:1.03]
  set xtics 0.5
  set mxtics 5
  set ytics 0.2
  set key off
  set xlabel 'input restitution e'
  do for [panel in 'allowed clamped'] {
    if (panel eq 'allowed') { set ylabel 'effective restitution e_{eff}'; set title '(a) tension allowed'; eval two_panels_a } \
    else { unset ylabel; set title '(b) tension clamped'; eval two_panels_b }
    plot x with lines lc rgb '#999999' lw 1 dt 3 notitle, \
         for [i=1:words(laws)] data using (strcol('model') eq word(laws, i) && strcol('tension') eq panel ? \
           column('e_input') : NaN):'e_effective' with lines \
           lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i)) notitle
  }
  eval two_panels_key
  eval key_panel
  eval law_key
  unset multiplot
}

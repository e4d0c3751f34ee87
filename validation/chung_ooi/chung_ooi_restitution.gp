# Test 3's restitution map: gnuplot -d -c chung_ooi_restitution.gp OUT
# -> OUT/chung_ooi_restitution.pdf, .png from OUT/chung_ooi_restitution.csv (validation/chung_ooi).
# (a) the effective restitution of every registered law against its input e, Chung & Ooi's
# test 3 (alumina sphere on a rigid flat at 3.9 m/s, tension allowed); the dotted diagonal is
# e_eff = e. (b) how far that map lies from the same law's map in the paper's steel contact
# phase: e_eff depends on e alone, so only the solver's error remains. Colours as in
# restitution_map (damping_laws/law_styles.gnuplot); the legend has a panel of its own.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/chung_ooi_restitution.csv'
pick(law, value) = strcol('model') eq law && strcol('tension') eq 'allowed' ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/../damping_laws/law_styles.gnuplot'
  call here.'/../output.gnuplot' out.'/chung_ooi_restitution' format full_width_in 3.2
  laws = law_names(data)
  set multiplot
  set key off
  set xrange [0:1]
  set xtics 0.5
  set mxtics 5
  set xlabel 'input restitution e'
  eval two_panels_a
  set title '(a) test 3'
  set ylabel 'effective restitution e_{eff}'
  set yrange [0:1.03]
  set ytics 0.2
  plot x with lines lc rgb '#999999' lw 1 dt 3 notitle, \
       for [i=1:words(laws)] data using (pick(word(laws, i), column('e_input'))):'e_effective' with lines \
         lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i))
  eval two_panels_b
  set title '(b) test 3 vs steel'
  set ylabel 'difference in e_{eff}' offset 1, 0
  set logscale y
  set format y '10^{%L}'
  set yrange [1e-12:1e-6]
  set ytics 100
  plot for [i=1:words(laws)] data using (pick(word(laws, i), column('e_input'))): \
         (abs(column('e_effective') - column('e_effective_paper_setup'))) with lines \
         lw 1.2 lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i))
  eval two_panels_key
  eval key_panel
  eval law_key
  unset multiplot
}

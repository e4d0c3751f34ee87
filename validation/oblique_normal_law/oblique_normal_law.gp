# Where the normal law matters: gnuplot -d -c oblique_normal_law.gp OUT
# -> OUT/oblique_normal_law.pdf, .png from OUT/oblique_normal_law.csv and
# OUT/oblique_normal_law_reference.csv (validation/oblique_normal_law). Chung and Ooi's test 6
# (a spinning sphere on a rigid flat, e = 0.5, mindlin-no-slip) under each law whose e_eff is e:
# (a) beta = -s1/s0 against x = 3.5 mu (1 + e) V_cn / V_st (the axis labelled x), with the sliding closed form x - 1 and
# the digitised test-6 curve of the same aluminium alloy (for orientation); (b) each law's departure
# from x - 1 below x = 1. Colours as in restitution_map (damping_laws/law_styles.gnuplot).
out = ARG1
here = system('dirname '.ARG0)
data = out.'/oblique_normal_law.csv'
ref = out.'/oblique_normal_law_reference.csv'
pick(law, value) = strcol('model') eq law ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/../damping_laws/law_styles.gnuplot'
  call here.'/../output.gnuplot' out.'/oblique_normal_law' format full_width_in 3.2
  laws = law_names(data)
  set multiplot
  set key off
  set logscale x
  set xlabel 'x'
  eval two_panels_a
  set title '(a) rebound slip ratio'
  set ylabel '{/Symbol b} = -s_1 / s_0'
  set xrange [0.15:40]
  set yrange [-1:0.6]
  set ytics 0.5
  plot (x < 1 ? x - 1 : NaN) with lines lc rgb '#999999' lw 1 dt 3, \
       for [i=1:words(laws)] data using 'x':(pick(word(laws, i), column('beta'))) with lines \
         lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i)), \
       ref using 'x':'beta' with points pt 6 ps 0.6 lc rgb 'black'
  eval two_panels_b
  set title '(b) departure from x - 1'
  set ylabel '|{/Symbol b} - (x - 1)|' offset 1, 0
  set xrange [0.15:1]
  set xtics (0.2, 0.5, 1)
  set logscale y
  set format y '10^{%L}'
  set yrange [1e-4:0.1]
  set ytics 10
  plot for [i=1:words(laws)] data using 'x':(column('x') < 1 ? pick(word(laws, i), abs(column('beta') - column('x') + 1)) : NaN) \
         with lines lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i))
  eval two_panels_key
  eval key_panel
  plot for [i=1:words(laws)] NaN with lines lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) \
         dt law_dt(word(laws, i)) title word(laws, i), \
       NaN with lines lc rgb '#999999' lw 1 dt 3 title 'sliding: x - 1', \
       NaN with points pt 6 ps 0.6 lc rgb 'black' title 'test 6, digitised'
  unset multiplot
}

# Hysteresis loops (force against deformation) of every damping law, the paper's steel
# drop from h = 20 mm: gnuplot -d -c hysteresis_models.gp OUT -> OUT/hysteresis_models.pdf,
# OUT/hysteresis_models.png from OUT/hysteresis_models.csv (validation/damping_laws).
# (a) every law at the paper's input e = 0.795; (b) each law at the input e that gives it
# an effective restitution of 0.795 (undamped Hertz cannot, and is absent from (b)).
out = ARG1
here = system('dirname '.ARG0)
data = out.'/hysteresis_models.csv'
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/law_styles.gnuplot'
  eval set_terminal(format, out.'/hysteresis_models', 7.0, 3.0)
  laws = law_names(data)
  set multiplot
  set xlabel 'deformation x ({/Symbol m}m)'
  set ylabel 'contact force F (kN)'
  set xrange [0:*]
  set label 1 at graph 0.04, 0.93 left front font ',9'
  do for [panel in 'equal_input equal_effective'] {
    if (panel eq 'equal_input') { eval panel_a; set key off; set label 1 '(a) equal input e = 0.795' } \
    else { eval panel_b; eval side_key; set label 1 '(b) equal e_{eff} = 0.795' }
    plot for [i=1:words(laws)] data using (strcol('model') eq word(laws, i) && strcol('comparison') eq panel ? \
           1e6*column('x_m') : NaN):(1e-3*column('force_N')) with lines \
           lw (word(laws, i) eq 'hongo' ? 2.4 : 1.3) lc rgb law_lc(word(laws, i), i) dt law_dt(word(laws, i), i) \
           title word(laws, i)
  }
  unset multiplot
}

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
  call here.'/../output.gnuplot' out.'/hysteresis_models' format full_width_in 3.2
  laws = law_names(data)
  set multiplot
  set xlabel 'deformation x ({/Symbol m}m)'
  set xrange [0:*]
  set xtics 200
  set mxtics 2
  set key off
  do for [panel in 'equal_input equal_effective'] {
    if (panel eq 'equal_input') { set ylabel 'contact force F (kN)'; set title '(a) input e = 0.795'; eval two_panels_a } \
    else { unset ylabel; set title '(b) e_{eff} = 0.795'; eval two_panels_b }
    plot for [i=1:words(laws)] data using (strcol('model') eq word(laws, i) && strcol('comparison') eq panel ? \
           1e6*column('x_m') : NaN):(1e-3*column('force_N')) with lines \
           lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i)) notitle
  }
  eval two_panels_key
  eval key_panel
  eval law_key
  unset multiplot
}

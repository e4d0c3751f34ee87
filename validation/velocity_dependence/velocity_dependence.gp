# e_effective against the impact speed: gnuplot -d -c velocity_dependence.gp OUT ->
# OUT/velocity_dependence.pdf, .png from OUT/velocity_dependence.csv (validation/velocity_dependence).
# Steel rod, gravity on, every law fed Table 2's e; (a) the rigid model, (b) the elastic rod on
# the load cell (virtual experiment). The viscoelastic law (kuwabara-kono, A fixed) is the
# paper's force at the 20 mm drop (dotted line) and falls as v0^{1/5} away from it.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/velocity_dependence.csv'
pick(law, model, value) = (strcol('damping') eq law && strcol('rod_model') eq model) ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/../damping_laws/law_styles.gnuplot'
  laws = law_names(data)
  v20 = sqrt(2 * real(csv_parameter(data, 'gravity_mps2')) * 0.02)
  call here.'/../output.gnuplot' out.'/velocity_dependence' format full_width_in 4.8
  set multiplot
  set logscale x
  set xlabel 'Impact speed v_0 (m/s)'
  set xtics (0.05, 0.2, 0.5, 1, 3)
  set xrange [0.05:3]
  set yrange [0.6:1.02]
  set ylabel 'Restitution e_{eff}'
  set key off
  set label 1 at graph 0.95, 0.07 right front
  set arrow 1 from v20, graph 0 to v20, graph 1 nohead lc rgb '#555555' dt 3 lw 1.0
  do for [k=1:2] {
    model = k == 1 ? 'rigid' : 'elastic'
    set origin (k - 1) * 0.5, 0.34
    set size 0.5, 0.66
    set label 1 sprintf('(%s) %s', k == 1 ? 'a' : 'b', k == 1 ? 'rigid model' : 'elastic rod')
    plot for [i=1:words(laws)] data using (pick(word(laws, i), model, column('impact_velocity_mps'))):'e_effective' \
         with lines lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i))
  }
  unset arrow 1
  unset arrow 1
  set origin 0, 0.01
  set size 1, 0.31
  set margins 0, 0, 0, 0
  eval key_panel
  eval key_row
  set key maxrows 6
  plot for [i=1:words(laws)] NaN with lines lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) dt law_dt(word(laws, i)) title word(laws, i), \
       NaN with lines lc rgb '#555555' dt 3 lw 1.0 title 'drop from 20 mm'
  unset multiplot
}

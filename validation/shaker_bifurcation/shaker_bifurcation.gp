# Bifurcation diagrams of the bouncing body: gnuplot -d -c shaker_bifurcation.gp OUT ->
# OUT/shaker_bifurcation.pdf, .png from OUT/shaker_bifurcation_steel.csv and _nylon.csv
# (validation/shaker_bifurcation). The impact phase of every kept impact against Gamma; columns:
# the stiff pair (steel rod on a steel hemisphere), the paper's pair (steel rod on nylon); rows:
# the paper's law (hongo), the viscoelastic law (kuwabara-kono), each a soft contact in its law
# colour over the instantaneous map with that law's own e_effective (black dots:
# law_styles.gnuplot's colour for a model not in its table). The dashed line is the map's
# period-doubling threshold Gamma_2(e).
out = ARG1
here = system('dirname '.ARG0)
pick(model, law, value) = (strcol('model') eq model && strcol('law') eq law) ? value : NaN
gamma_2(e) = sqrt((pi * (1 - e) / (1 + e))**2 + (2 * (1 + e**2) / (1 + e)**2)**2)
laws = 'hongo kuwabara-kono'
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/../damping_laws/law_styles.gnuplot'
  call here.'/../output.gnuplot' out.'/shaker_bifurcation' format full_width_in 5.4
  set multiplot
  set xlabel '{/Symbol G} = A (2{/Symbol p} f)^2 / g'
  set ylabel 'Phase (cycles)'
  set xrange [1.2:2.0]
  set yrange [0:1]
  set xtics 0.2
  set ytics 0.25
  set tmargin 1.6
  set key off
  set label 1 at graph 0, 1.08 left front font ',8'
  do for [k=1:4] {
    pair = k % 2 == 1 ? 'steel' : 'nylon'
    law = word(laws, (k + 1) / 2)
    data = out.'/shaker_bifurcation_'.pair.'.csv'
    e_map = real(csv_parameter(data, 'map_restitution_'.law))
    eval quad_panel(k)
    set label 1 sprintf('(%s) %s, %s', word('a b c d', k), law, pair)
    set arrow 1 from gamma_2(e_map), graph 0 to gamma_2(e_map), graph 1 nohead lc rgb '#555555' dt 2 lw 1.0
    plot data using (pick('instantaneous', law, column('gamma'))):'impact_phase' with points pt 7 ps 0.28 lc rgb '#000000', \
         data using (pick(law, law, column('gamma'))):'impact_phase' with points pt 6 ps 0.4 lw 0.8 lc rgb law_lc(law)
  }
  unset arrow 1
  eval quad_key_row
  eval key_panel
  eval key_row
  set key maxrows 2
  plot for [i=1:words(laws)] NaN with points pt 6 ps 1.0 lc rgb law_lc(word(laws, i)) title word(laws, i).' (soft)', \
       NaN with points pt 7 ps 0.8 lc rgb '#000000' title 'map, e = the law''s e_{eff}', \
       NaN with lines lc rgb '#555555' dt 2 lw 1.0 title 'map threshold {/Symbol G}_2(e)'
  unset multiplot
}

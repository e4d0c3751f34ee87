# The paper's results under the joint input uncertainty, per rod:
#   gnuplot -d -c uncertainty_outputs.gp OUT  ->  OUT/uncertainty_outputs.pdf, .png
# from OUT/uncertainty_outputs.csv (validation/uncertainty). For each result and rod: the 5-95 %
# range over the joint draws (bar) and the median (filled circle), relative to the value at the assumed inputs
# (the zero line), in per cent of the value at the assumed inputs.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/uncertainty_outputs.csv'
rods = 'steel duralumin-a duralumin-b duralumin-c'
results = 'e_effective peak_force_N contact_time_s'
rel(v) = 100*(v/column('assumed_value') - 1)
at(i) = strcol('rod') eq word(rods, i) ? (strcol('output') eq 'e_effective' ? 0 : strcol('output') eq 'peak_force_N' ? 1 : 2) + (i - 2.5)*0.18 : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/uncertainty_outputs' format narrow_width_in 3.3
  set xrange [-0.5:2.5]
  set xtics ('e_{eff}' 0, 'P_{max}' 1, 't_c' 2)
  set yrange [-20:32]
  set ytics -20, 10, 20
  set grid noxtics ytics
  set ylabel 'Change from assumed inputs (%)' offset 0.5, -0.3
  set key top center Left reverse noopaque nobox font ',8' samplen 1.5 spacing 1.0 maxrows 2 width 1
  plot 0 with lines ls 2 notitle, \
       for [i=1:4] data using (at(i)):(rel(column('q50'))):(rel(column('q05'))):(rel(column('q95'))) \
         with yerrorbars lc rgb rod_colour(word(rods, i)) pt 7 ps 0.6 lw 1.5 title rod_label(word(rods, i))
}

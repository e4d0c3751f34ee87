# Sobol indices of the paper's results under the joint input uncertainty, beside the variance
# shares of the linearisation:  gnuplot -d -c uncertainty_sobol.gp OUT  ->  OUT/uncertainty_sobol.pdf, .png
# from OUT/uncertainty_sobol.csv (validation/uncertainty). One panel per result, log scale: for
# each input one column per rod in its colour: the total index S_T (filled circle, 95 % bootstrap
# interval) and the linearised share el^2 CV^2 / sum (open square). The first-order indices,
# whose intervals reach below zero for every input but the dominant one, are in the table and
# the CSV; where the inputs do not interact S = S_T.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/uncertainty_sobol.csv'
rods = 'steel duralumin-a duralumin-b duralumin-c'
results = 'e_effective peak_force_N contact_time_s'
# The CSV lists, per rod and result, the d inputs in design order: row r is input r % d.
d = 8
slot(row) = int(row) % d
# x of rod i's column of an input row, NaN on the other rods' and results' rows.
at(i, result) = strcol('rod') eq word(rods, i) && strcol('output') eq result ? slot(column(0)) + (i - 2.5)*0.19 : NaN
floor_value = 1e-12  # below every index here: none is clipped
shown(v) = v > floor_value ? v : floor_value
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/uncertainty_sobol' format full_width_in 7.0
  set multiplot
  set logscale y
  set xrange [-0.6:d - 0.4]
  set yrange [floor_value:3]
  set ytics 1e-12, 100, 1 format '10^{%L}'
  set mytics 10
  set grid noxtics ytics
  set key off
  set label 1 at graph 0.99, 0.86 right front
  set xtics ('E_{nylon}' 0, '{/Symbol n}_{nylon}' 1, '{/Symbol n}_{rod}' 2, 'e' 3, 'R' 4, 'h' 5, 'm' 6, 'E_{rod}' 7)
  set ylabel 'Index'
  do for [k=1:3] {
    eval stack_panel(k, 3)
    set label 1 k == 1 ? '(a) e_{eff}' : k == 2 ? '(b) peak force' : '(c) contact time'
    if (k < 3) { set format x ''; unset xlabel } else { set format x; set xlabel 'Input' }
    r = word(results, k)
    plot for [i=1:4] data using (at(i, r)):(shown(column('ST'))):(shown(column('ST_lower'))):(shown(column('ST_upper'))) \
           with yerrorbars lc rgb rod_colour(word(rods, i)) pt 7 ps 0.8 lw 1, \
         for [i=1:4] data using (at(i, r)):(shown(column('linear_share'))) with points lc rgb rod_colour(word(rods, i)) pt 4 ps 1.4 lw 1
  }
  eval quad_key_row
  eval key_panel
  eval key_row
  set key maxrows 3
  plot for [i=1:4] NaN with points lc rgb rod_colour(word(rods, i)) pt 7 ps 0.8 title rod_label(word(rods, i)), \
       NaN with points lc rgb '#555555' pt 7 ps 0.8 title 'total index S_T (95 % interval)', \
       NaN with points lc rgb '#555555' pt 4 ps 1.4 title 'linearised share'
  unset multiplot
}

# How the omega_n assumptions behave across drop heights, steel rod, Table 2 e, zeta eq. (6):
# (a) e_effective (dashed: the input e), (b) peak force and (c) contact time relative to the
# paper's variant (Delta, in per cent). as-printed is left out (its -12 % / +27 % would flatten the others; see
# sensitivity_omega_n_table.tex).
#   gnuplot -d -c omega_n_height.gp OUT   (reads OUT/omega_n_height.csv)
out = ARG1
here = system('dirname '.ARG0)
data = out.'/omega_n_height.csv'
sel(v, col) = (strcol(1) eq v && strcol(2) eq 'paper' && strcol(3) eq 'steel') ? column(col) : NaN
variants = 'paper impact-energy rebound-energy self-consistent contact-time'
style(i) = i == 1 ? 1 : i + 2
e_steel = 0.795  # Table 2, nylon-steel (data/table2_restitution.csv)

# Three stacked panels above a legend row, automatic margins.
stacked(k) = sprintf('set origin 0, %g; set size 1, %g', k == 3 ? 0.13 : 0.13 + 0.33 + (2 - k) * 0.26, k == 3 ? 0.33 : 0.26)
do for [fmt in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/omega_n_height' fmt narrow_width_in 6.2
  set multiplot
  set logscale x
  set xrange [1.8:110]
  set format x '%g'
  set key off
  set label 1 at graph 0.03, 0.85 left front
  eval stacked(1)
  set label 1 '(a)'
  set format x ''
  set ylabel 'e_{eff}'
  set yrange [0.79:*]
  set ytics 0.02
  plot e_steel ls 2 lw 1 notitle, \
       for [i=1:words(variants)] data using (1e3*$4):(sel(word(variants,i), 5)) \
         with linespoints ls style(i) pt 7 ps 0.35 notitle
  eval stacked(2)
  set label 1 '(b)'
  set yrange [*:*]
  set offsets 0, 0, graph 0.25, graph 0.1  # room for the panel letter above the curves
  set ytics 0.2
  set ylabel '{/Symbol D}P_{max} [%]'
  plot for [i=1:words(variants)] data using (1e3*$4):(100*sel(word(variants,i), 6)) \
         with linespoints ls style(i) pt 7 ps 0.35 notitle
  eval stacked(3)
  set label 1 '(c)'
  set format x '%g'
  set xlabel 'drop height h [mm]'
  set ytics 0.05
  set ylabel '{/Symbol D}t_c [%]'
  plot for [i=1:words(variants)] data using (1e3*$4):(100*sel(word(variants,i), 7)) \
         with linespoints ls style(i) pt 7 ps 0.35 notitle
  eval quad_key_row
  eval key_panel
  eval key_row
  plot NaN ls 2 lw 1 title 'input e (a)', \
       for [i=1:words(variants)] NaN with linespoints ls style(i) pt 7 ps 0.35 title word(variants,i)
  unset multiplot
}

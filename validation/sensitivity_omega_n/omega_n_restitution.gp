# Does any omega_n assumption give back the restitution it was given?
# e_effective - e_input against e_input at h = 20 mm, zeta by eq. (6) (solid) and, for the
# paper's variant, by the exact relation (dashed). as-printed is left out: its deviation
# (-0.5 and below) would flatten the others; it is in sensitivity_omega_n_table.tex.
#   gnuplot -d -c omega_n_restitution.gp OUT   (reads OUT/omega_n_restitution.csv)
out = ARG1
here = system('dirname '.ARG0)
data = out.'/omega_n_restitution.csv'
sel(v, z, r) = (strcol(1) eq v && strcol(2) eq z && strcol(3) eq r) ? $5 : NaN
variants = 'paper impact-energy rebound-energy self-consistent contact-time'
style(i) = i == 1 ? 1 : i + 2
rods = 'steel duralumin-c'

do for [fmt in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/omega_n_restitution' fmt narrow_width_in 5.6
  set multiplot
  set key off
  set xrange [0.05:1.0]
  set ytics 0.04
  set xtics 0.2
  set ylabel 'e_{eff} - e'
  do for [k=1:2] {
    eval stack_panel(k, 2)
    set title sprintf('(%s) %s rod, h = 20 mm', word('a b', k), word('Steel Duralumin-C', k))
    if (k == 2) { set xlabel 'input restitution e' }
    plot 0 ls 2 lw 1 notitle, \
         for [i=1:words(variants)] data using 4:(sel(word(variants,i), 'paper', word(rods,k))) \
           with linespoints ls style(i) pt 7 ps 0.35 notitle, \
         data using 4:(sel('paper', 'exact', word(rods,k))) with lines ls 1 dt 2 notitle
  }
  eval quad_key_row
  eval key_panel
  eval key_row
  plot for [i=1:words(variants)] NaN with linespoints ls style(i) pt 7 ps 0.35 title word(variants,i), \
       NaN with lines ls 1 dt 2 title 'paper, exact {/Symbol z}'
  unset multiplot
}

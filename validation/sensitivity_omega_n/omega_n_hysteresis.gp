# Force-deformation loops of the paper's law under each omega_n assumption, h = 20 mm,
# Table 2 e, zeta eq. (6): (a) steel rod, (b) duralumin rod C (cf. Figs. 5c and 6c of the paper).
#   gnuplot -d -c omega_n_hysteresis.gp OUT   (reads OUT/omega_n_hysteresis.csv)
out = ARG1
here = system('dirname '.ARG0)
data = out.'/omega_n_hysteresis.csv'
sel(v, r, col) = (strcol(1) eq v && strcol(2) eq r) ? column(col) : NaN
variants = 'paper impact-energy rebound-energy self-consistent contact-time as-printed'
style(i) = i == 1 ? 1 : i + 2
rods = 'steel duralumin-c'

do for [fmt in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/omega_n_hysteresis' fmt narrow_width_in 5.6
  set multiplot
  set key off
  set ylabel 'contact force P [N]'
  set xrange [-5:*]
  do for [k=1:2] {
    eval stack_panel(k, 2)
    set title sprintf('(%s) %s rod, h = 20 mm', word('a b', k), word('Steel Duralumin-C', k))
    if (k == 2) { set xlabel 'deformation x [{/Symbol m}m]' }
    set ytics (k == 1 ? 400 : 200)
    plot for [i=1:words(variants)] data using (1e6*$3):(sel(word(variants,i), word(rods,k), 4)) \
           with lines ls style(i) notitle
  }
  eval quad_key_row
  eval key_panel
  eval key_row
  plot for [i=1:words(variants)] NaN with lines ls style(i) title word(variants,i)
  unset multiplot
}

# How the omega_n assumptions behave across drop heights, steel rod, Table 2 e, zeta eq. (6):
# (a) e_effective (dotted: the input e), (b) peak force and (c) contact time relative to the
# paper's variant. as-printed is left out (its -12 % / +27 % would flatten the others; see
# sensitivity_omega_n_table.tex).
#   gnuplot -d -c omega_n_height.gp OUT   (reads OUT/omega_n_height.csv)
out = ARG1
here = system('dirname '.ARG0)
load here.'/../style.gnuplot'
data = out.'/omega_n_height.csv'
sel(v, col) = (strcol(1) eq v && strcol(2) eq 'paper' && strcol(3) eq 'steel') ? column(col) : NaN
variants = 'paper impact-energy rebound-energy self-consistent contact-time'
style(i) = i == 1 ? 1 : i + 2
e_steel = 0.795  # Table 2, nylon-steel (data/table2_restitution.csv)

do for [fmt in 'pdf png'] {
  if (fmt eq 'pdf') { set terminal pdfcairo size 3.5in,5.2in font 'Helvetica,9' } \
  else { set terminal pngcairo size 700,1040 font 'Helvetica,11' }
  set output out.'/omega_n_height.'.fmt
  set multiplot layout 3,1 margins 0.17,0.97,0.08,0.98 spacing 0,0.06
  set logscale x
  set xrange [1.8:110]
  set format x '%g'
  set xlabel 'drop height h [mm]'
  set key bottom right font ',8' maxrows 3 width -2
  set ylabel 'e_{eff}'
  set yrange [0.79:*]
  plot e_steel ls 2 lw 1 title 'input e', \
       for [i=1:words(variants)] data using (1e3*$4):(sel(word(variants,i), 5)) \
         with linespoints ls style(i) pt 7 ps 0.35 title word(variants,i)
  set key off
  set yrange [*:*]
  set ylabel 'P_{max} / P_{max}^{paper} - 1 [%]'
  plot for [i=1:words(variants)] data using (1e3*$4):(100*sel(word(variants,i), 6)) \
         with linespoints ls style(i) pt 7 ps 0.35 notitle
  set ylabel 't_c / t_c^{paper} - 1 [%]'
  plot for [i=1:words(variants)] data using (1e3*$4):(100*sel(word(variants,i), 7)) \
         with linespoints ls style(i) pt 7 ps 0.35 notitle
  unset multiplot
}

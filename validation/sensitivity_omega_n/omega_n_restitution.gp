# Does any omega_n assumption give back the restitution it was given?
# e_effective - e_input against e_input at h = 20 mm, zeta by eq. (6) (solid) and, for the
# paper's variant, by the exact relation (dashed). as-printed is left out: its deviation
# (-0.5 and below) would flatten the others; it is in sensitivity_omega_n_table.tex.
#   gnuplot -d -c omega_n_restitution.gp OUT   (reads OUT/omega_n_restitution.csv)
out = ARG1
here = system('dirname '.ARG0)
load here.'/../style.gnuplot'
data = out.'/omega_n_restitution.csv'
sel(v, z, r) = (strcol(1) eq v && strcol(2) eq z && strcol(3) eq r) ? $5 : NaN
variants = 'paper impact-energy rebound-energy self-consistent contact-time'
style(i) = i == 1 ? 1 : i + 2
rods = 'steel duralumin-c'
names = 'Steel Duralumin\ C'

do for [fmt in 'pdf png'] {
  if (fmt eq 'pdf') { set terminal pdfcairo size 3.5in,4.4in font 'Helvetica,9' } \
  else { set terminal pngcairo size 700,880 font 'Helvetica,11' }
  set output out.'/omega_n_restitution.'.fmt
  set multiplot layout 2,1 margins 0.16,0.97,0.09,0.97 spacing 0,0.08
  do for [k=1:2] {
    set xlabel 'input restitution e'
    set ylabel 'e_{eff} - e'
    set xrange [0.05:1.0]
    set key bottom right font ',8'
    set label 1 sprintf('%s rod, h = 20 mm', word('Steel Duralumin-C', k)) at graph 0.97,0.92 right
    plot 0 ls 2 lw 1 notitle, \
         for [i=1:words(variants)] data using 4:(sel(word(variants,i), 'paper', word(rods,k))) \
           with linespoints ls style(i) pt 7 ps 0.35 title word(variants,i), \
         data using 4:(sel('paper', 'exact', word(rods,k))) with lines ls 1 dt 2 title 'paper, exact {/Symbol z}'
  }
  unset multiplot
  unset label 1
}

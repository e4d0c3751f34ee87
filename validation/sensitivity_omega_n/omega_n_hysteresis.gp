# Force-deformation loops of the paper's law under each omega_n assumption, h = 20 mm,
# Table 2 e, zeta eq. (6): (a) steel rod, (b) duralumin rod C (cf. Figs. 5c and 6c of the paper).
#   gnuplot -d -c omega_n_hysteresis.gp OUT   (reads OUT/omega_n_hysteresis.csv)
out = ARG1
here = system('dirname '.ARG0)
load here.'/../style.gnuplot'
data = out.'/omega_n_hysteresis.csv'
sel(v, r, col) = (strcol(1) eq v && strcol(2) eq r) ? column(col) : NaN
variants = 'paper impact-energy rebound-energy self-consistent contact-time as-printed'
style(i) = i == 1 ? 1 : i + 2
rods = 'steel duralumin-c'

do for [fmt in 'pdf png'] {
  if (fmt eq 'pdf') { set terminal pdfcairo size 3.5in,4.4in font 'Helvetica,9' } \
  else { set terminal pngcairo size 700,880 font 'Helvetica,11' }
  set output out.'/omega_n_hysteresis.'.fmt
  set multiplot layout 2,1 margins 0.15,0.97,0.09,0.97 spacing 0,0.08
  do for [k=1:2] {
    set xlabel 'deformation x [{/Symbol m}m]'
    set ylabel 'contact force P [N]'
    set key top left font ',8'
    set xrange [-5:*]
    set label 1 sprintf('%s rod, h = 20 mm', word('Steel Duralumin-C', k)) at graph 0.97,0.08 right
    plot for [i=1:words(variants)] data using (1e6*$3):(sel(word(variants,i), word(rods,k), 4)) \
           with lines ls style(i) title word(variants,i)
  }
  unset multiplot
  unset label 1
}

# Soft against rigid near grazing: gnuplot -d -c orbit_soft_rigid.gp OUT -> OUT/orbit_soft_rigid.pdf, .png
# from OUT/orbit_soft_rigid_grazing.csv (validation/orbit_soft_rigid). The impact oscillator's
# period-1 orbit from its fold up to grazing: the largest Floquet multiplier's modulus against the
# orbit's impact speed, log-log; the instantaneous map (black) diverges like 1/(impact speed), the
# soft contacts (hunt-crossley on steel stiffened k-fold, one colour per k) turn over.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/orbit_soft_rigid_grazing.csv'
stiffenings = '1 10 100'
stiffening_colour(k) = k == 1 ? '#c0392b' : k == 10 ? '#e67e22' : '#27ae60'
pick(model, k, value) = (strcol('model') eq model && (model eq 'instantaneous' || column('stiffening') == k)) ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/orbit_soft_rigid' format full_width_in 2.8
  set logscale xy
  set xlabel 'Impact speed (m/s)'
  set ylabel 'Largest |multiplier|'
  set format x '10^{%T}'
  set format y '%g'
  set xrange [2e-4:0.1]
  set yrange [0.5:2000]
  set key outside right top font ',8'
  plot data using (pick('instantaneous', 0, column('impact_speed_mps'))):'max_multiplier_modulus' \
           with linespoints lc rgb '#000000' lw 1.2 pt 7 ps 0.3 title 'instantaneous, e*', \
       for [i=1:words(stiffenings)] data using (pick('soft', int(word(stiffenings, i)), column('impact_speed_mps'))):'max_multiplier_modulus' \
           with linespoints lc rgb stiffening_colour(int(word(stiffenings, i))) lw 1.2 pt 7 ps 0.3 \
           title sprintf('soft, k = %s', word(stiffenings, i))
}

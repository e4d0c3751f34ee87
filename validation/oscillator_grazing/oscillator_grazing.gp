# The impact oscillator's grazing and fold curves: gnuplot -d -c oscillator_grazing.gp OUT ->
# OUT/oscillator_grazing.pdf, .png from OUT/oscillator_grazing.csv (validation/oscillator_grazing).
# Force amplitude against drive frequency: the closed-form grazing force of the linear steady state
# (line), the grazing located by continuation of the non-impacting orbit (points on it), and the
# fold of the impacting orbit continued down in the force (points): between fold and grazing both
# orbits exist.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/oscillator_grazing.csv'
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/oscillator_grazing' format narrow_width_in 2.9
  set xlabel 'Drive frequency f (Hz)'
  set ylabel 'Force amplitude F (N)'
  set xrange [10:30]
  set yrange [0:60]
  set key top left Left reverse width -4 font ',8'
  m = real(csv_parameter(data, 'mass_kg')); k = real(csv_parameter(data, 'stiffness_N_per_m'))
  d = real(csv_parameter(data, 'stop_distance_m')); c = 2 * real(csv_parameter(data, 'damping_ratio')) * sqrt(k * m)
  grazing(f) = d * sqrt((k - m * (2 * pi * f)**2)**2 + (c * 2 * pi * f)**2)
  set samples 400
  plot grazing(x) with lines ls 2 title 'grazing, closed form', \
       data using 'frequency_Hz':'grazing_continued_N' with points pt 7 ps 0.5 lc rgb '#0b3c8c' title 'grazing, continuation', \
       data using 'frequency_Hz':'fold_N' with points pt 5 ps 0.5 lc rgb '#c0392b' title 'fold of the impacting orbit'
}

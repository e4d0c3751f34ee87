# The accelerometer's ringing: gnuplot -d -c elastic_rod_spectrum.gp OUT ->
# OUT/elastic_rod_spectrum.pdf, .png from OUT/elastic_rod_spectra.csv (validation/elastic_rod).
# Amplitude spectrum of the top-face acceleration minus the centre of mass's during contact,
# h = 20 mm, one colour per rod (virtual experiment). Each rod's peak sits at its first
# free-free longitudinal frequency c / (2L) (the article's Table of the elastic rod).
out = ARG1
here = system('dirname '.ARG0)
data = out.'/elastic_rod_spectra.csv'
rods = 'steel duralumin-a duralumin-b duralumin-c'
pick(r, value) = strcol('rod') eq r ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/elastic_rod_spectrum' format full_width_in 2.6
  set logscale y
  set xlabel 'Frequency (kHz)'
  set ylabel 'Amplitude (m/s)'
  set xrange [0:40]
  set format y '10^{%L}'
  set key outside right top vertical Left reverse noopaque nobox font ',8'
  set mxtics 5
  plot for [i=1:4] data using (pick(word(rods,i), 1e-3*column('frequency_hz'))):'amplitude_mps' \
         with lines lc rgb rod_colour(word(rods,i)) lw 1.2 title rod_label(word(rods,i))
}

# Does the contact stay elastic? gnuplot -d -c contact_pressure.gp OUT -> OUT/contact_pressure.pdf,
# .png from OUT/contact_pressure.csv (validation/velocity_dependence). The Hertz peak pressure
# p0 of each rod's drop (the paper's law, rigid model) against the drop height, and the onset
# of yield (yield_onset_factor Y, 1.74 Y at nu = 0.4) in the nylon: the band for the assumed range of Y, the line for the assumed Y.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/contact_pressure.csv'
rods = 'steel duralumin-a duralumin-b duralumin-c'
pick(r, value) = strcol('rod') eq r ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  factor = real(csv_parameter(data, 'yield_onset_factor'))
  onset = factor * real(csv_parameter(data, 'yield_stress_Pa')) / 1e6
  onset_lo = factor * real(csv_parameter(data, 'yield_stress_min_Pa')) / 1e6
  onset_hi = factor * real(csv_parameter(data, 'yield_stress_max_Pa')) / 1e6
  call here.'/../output.gnuplot' out.'/contact_pressure' format narrow_width_in 3.6
  set multiplot
  set origin 0, 0.27
  set size 1, 0.73
  set logscale x
  set xlabel 'Drop height h (mm)'
  set xtics (1, 3, 10, 30, 100)
  set xrange [1:200]
  set ylabel 'Peak pressure p_0 (MPa)'
  set yrange [0:*]
  set key off
  set arrow 1 from 20, graph 0 to 20, graph 1 nohead lc rgb '#555555' dt 3 lw 1.0
  plot '+' using 1:(onset_lo):(onset_hi) with filledcurves lc rgb '#bbbbbb', onset with lines ls 2, \
       for [i=1:4] data using (pick(word(rods,i), 1e3*column('height_m'))):(column('peak_contact_pressure_Pa')/1e6) \
         with lines lc rgb rod_colour(word(rods,i)) lw 1.6
  unset arrow 1
  set origin 0, 0.01
  set size 1, 0.22
  set margins 0, 0, 0, 0
  eval key_panel
  eval key_row
  set key maxrows 4
  plot NaN with filledcurves lc rgb '#bbbbbb' title sprintf('%.2f Y, Y = %.0f-%.0f MPa', factor, onset_lo/factor, onset_hi/factor), \
       NaN with lines ls 2 title sprintf('%.2f Y, Y = %.0f MPa', factor, onset/factor), \
       NaN with lines lc rgb '#555555' dt 3 lw 1.0 title 'h = 20 mm', \
       for [i=1:4] NaN with lines lc rgb rod_colour(word(rods,i)) lw 1.6 title rod_label(word(rods,i))
  unset multiplot
}

# A granular gas on LAMMPS against kinetic theory from hertzdash's e(g): gnuplot -d -c gas_cooling.gp OUT
# -> OUT/gas_cooling.pdf, .png from OUT/gas_cooling.csv and OUT/gas_cooling_dispersion.csv
# (validation/gas_cooling). (a) T/T1 compensated by Haff's law, (T/T1) s^2 with s = 1 + (t - t1)/tau1,
# against s: the engine's (points) and the prediction (line) for each law, in the law's colour; Haff's
# law is 1 and a late t^-5/3 rises as s^(1/3) (the guide). (b) The cells' index of dispersion over a
# homogeneous gas's: clustering where it passes 2.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/gas_cooling.csv'
cells = out.'/gas_cooling_dispersion.csv'
pick(law, value) = strcol('law') eq law ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  load here.'/../damping_laws/law_styles.gnuplot'
  call here.'/../output.gnuplot' out.'/gas_cooling' format full_width_in 3.0
  set multiplot
  set origin 0, 0.2; set size 0.5, 0.8
  set logscale x
  set xtics (1, 2, 5, 10, 20, 50)
  set xlabel 's = 1 + (t - t_1)/{/Symbol t}_1'
  set ylabel '(T / T_1) s^2'
  set key off
  set label 1 '(a)' at graph 0.03, 0.92 font ',10'
  plot for [law in 'tsuji-dem kuwabara-kono'] data using 'scaled_time':(pick(law, column('temperature_ratio') * column('scaled_time')**2)) \
         with points pt 7 ps 0.2 lc rgb law_lc(law) notitle, \
       for [law in 'tsuji-dem kuwabara-kono'] data using 'scaled_time':(pick(law, column('predicted_ratio') * column('scaled_time')**2)) \
         with lines lw 1.6 lc rgb law_lc(law) notitle, \
       1 with lines ls 2 notitle, \
       x**(1.0/3) with lines lc rgb '#555555' lw 1.2 dt 3 notitle
  set origin 0.5, 0.2; set size 0.5, 0.8
  set ylabel 'D / S(0)'
  set yrange [0:2.5]
  set label 1 '(b)' at graph 0.03, 0.92 font ',10'
  plot for [law in 'tsuji-dem kuwabara-kono'] cells using 'scaled_time':(pick(law, column('dispersion_ratio'))) \
         with linespoints pt 7 ps 0.25 lw 0.8 lc rgb law_lc(law) notitle, \
       2 with lines ls 2 notitle
  set origin 0, 0; set size 1, 0.2; set margins 0, 0, 0, 0
  eval key_panel
  set key at graph 0.08, 0.5 left center vertical maxrows 3 width -6
  unset label 1
  plot NaN with points pt 7 ps 0.6 lc rgb law_lc('tsuji-dem') title 'tsuji-dem, LAMMPS', \
       NaN with lines lw 1.6 lc rgb law_lc('tsuji-dem') title 'tsuji-dem, theory', \
       NaN with points pt 7 ps 0.6 lc rgb law_lc('kuwabara-kono') title 'kuwabara-kono, LAMMPS', \
       NaN with lines lw 1.6 lc rgb law_lc('kuwabara-kono') title 'kuwabara-kono, theory', \
       NaN with lines ls 2 title "Haff's law (a), clusters (b)", \
       NaN with lines lc rgb '#555555' lw 1.2 dt 3 title 'T as t^{-5/3} (a)'
  unset multiplot
}

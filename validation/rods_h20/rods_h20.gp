# All rods at h = 20 mm: gnuplot -d -c rods_h20.gp OUT -> OUT/rods_h20.pdf, OUT/rods_h20.png
# from OUT/rods_h20.csv (validation/rods_h20). Bars: the paper's model at the default
# nylon modulus; error bars: its range over the catalogue modulus; open circles: undamped Hertz.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/rods_h20.csv'
rods = 'steel duralumin-a duralumin-b duralumin-c'
# value on rod i's row only (NaN elsewhere): each rod is its own series, in its own colour,
# at x = i - 1.
at_rod(i, value) = strcol('rod') eq word(rods, i) ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/rods_h20' format full_width_in 6.0
  E = real(csv_parameter(data, 'ball_E_Pa'))/1e9
  E_min = real(csv_parameter(data, 'band_ball_E_min_Pa'))/1e9
  E_max = real(csv_parameter(data, 'band_ball_E_max_Pa'))/1e9
  set multiplot
  set style fill solid 0.45 border
  set boxwidth 0.55
  set xrange [-0.6:3.6]
  set yrange [0:*]
  set grid noxtics ytics
  set key off
  set label 1 at graph 0.96, 0.90 right front
  set xtics ('Steel' 0, 'A' 1, 'B' 2, 'C' 3)
  set xlabel 'Rod (A-C: duralumin)'

  eval quad_panel(1)
  set label 1 '(a)'
  set ylabel 'Peak force (N)'
  plot for [i=1:4] data using (at_rod(i, i - 1)):'peak_force_N':'peak_force_min_N':'peak_force_max_N':(0.55) \
         with boxerrorbars lc rgb rod_colour(word(rods, i)) lw 1.2, \
       for [i=1:4] data using (at_rod(i, i - 1)):'peak_force_hertz_N' with points ls 2 pt 6 ps 1.2
  eval quad_panel(2)
  set label 1 '(b)'
  set ylabel 'x_{max} ({/Symbol m}m)'
  plot for [i=1:4] data using (at_rod(i, i - 1)):(1e6*column('max_deformation_m')):(1e6*column('max_deformation_min_m')):(1e6*column('max_deformation_max_m')):(0.55) \
         with boxerrorbars lc rgb rod_colour(word(rods, i)) lw 1.2, \
       for [i=1:4] data using (at_rod(i, i - 1)):(1e6*column('max_deformation_hertz_m')) with points ls 2 pt 6 ps 1.2
  eval quad_panel(3)
  set label 1 '(c)'
  set ylabel 'Contact time (ms)'
  plot for [i=1:4] data using (at_rod(i, i - 1)):(1e3*column('contact_time_s')):(1e3*column('contact_time_min_s')):(1e3*column('contact_time_max_s')):(0.55) \
         with boxerrorbars lc rgb rod_colour(word(rods, i)) lw 1.2, \
       for [i=1:4] data using (at_rod(i, i - 1)):(1e3*column('contact_time_hertz_s')) with points ls 2 pt 6 ps 1.2
  eval quad_panel(4)
  set label 1 '(d)' at graph 0.04, 0.90 left
  set ylabel 'Restitution'
  set yrange [0.7:0.9]
  set boxwidth 0.3
  plot for [i=1:4] data using (at_rod(i, i - 1 - 0.16)):'e_input' with boxes lc rgb '#999999' fs solid 0.5 border lc rgb '#555555', \
       for [i=1:4] data using (at_rod(i, i - 1 + 0.16)):'e_effective':'e_effective_min':'e_effective_max':(0.3) \
         with boxerrorbars lc rgb rod_colour(word(rods, i)) lw 1.2
  eval quad_key_row
  eval key_panel
  eval key_row
  set key maxrows 4
  plot NaN with boxes lc rgb '#0b3c8c' fs solid 0.45 title sprintf("bars: paper’s model, E_{nylon} = %.1f GPa (one colour per rod)", E), \
       NaN with lines lc rgb '#555555' lw 1.2 title sprintf("error bars: E_{nylon} = %.1f-%.1f GPa", E_min, E_max), \
       NaN with points ls 2 pt 6 ps 1.2 title 'circles: undamped Hertz (e = 1, off scale in (d))', \
       NaN with boxes lc rgb '#999999' fs solid 0.5 title '(d) grey: input e, Table 2'
  unset multiplot
}

# All rods at h = 20 mm: gnuplot -d -c rods_h20.gp OUT -> OUT/rods_h20.pdf, OUT/rods_h20.png
# from OUT/rods_h20.csv (validation/rods_h20). Bars: the paper's model at the default
# nylon modulus; error bars: its range over the catalogue modulus; open circles: undamped Hertz.
out = ARG1
here = system('dirname '.ARG0)
data = out.'/rods_h20.csv'
label(r) = r eq 'steel' ? 'Steel' : r eq 'duralumin-a' ? 'Dural. A' : r eq 'duralumin-b' ? 'Dural. B' : \
           r eq 'duralumin-c' ? 'Dural. C' : r
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/rods_h20' format 7.0 5.2
  note = sprintf("{/=8 bars: paper's model, nylon E = %.1f GPa;  error bars: nylon E = %.1f-%.1f GPa;  circles: undamped Hertz}", \
                 real(csv_parameter(data, 'ball_E_Pa'))/1e9, real(csv_parameter(data, 'band_ball_E_min_Pa'))/1e9, \
                 real(csv_parameter(data, 'band_ball_E_max_Pa'))/1e9)
  set multiplot layout 2,2 title "All rods dropped from h = 20 mm onto the nylon hemisphere\n".note \
      margins 0.12,0.98,0.08,0.88 spacing 0.13,0.13
  set xtics font ',8.5'
  set style fill solid 0.35 border lc rgb '#0b3c8c'
  set boxwidth 0.55
  set xrange [-0.6:3.6]
  set yrange [0:*]
  set grid noxtics ytics
  set key off
  set label 1 at graph 0.96, 0.90 right front font ',10'

  set label 1 '(a)'
  set ylabel 'Peak force (N)'
  plot data using 0:'peak_force_N':'peak_force_min_N':'peak_force_max_N':(0.55):xtic(label(strcol('rod'))) \
         with boxerrorbars ls 1, \
       '' using 0:'peak_force_hertz_N' with points ls 2 pt 6 ps 1.2
  set label 1 '(b)'
  set ylabel 'Maximum deformation ({/Symbol m}m)'
  plot data using 0:(1e6*column('max_deformation_m')):(1e6*column('max_deformation_min_m')):(1e6*column('max_deformation_max_m')):(0.55):xtic(label(strcol('rod'))) \
         with boxerrorbars ls 1, \
       '' using 0:(1e6*column('max_deformation_hertz_m')) with points ls 2 pt 6 ps 1.2
  set label 1 '(c)'
  set ylabel 'Contact time (ms)'
  plot data using 0:(1e3*column('contact_time_s')):(1e3*column('contact_time_min_s')):(1e3*column('contact_time_max_s')):(0.55):xtic(label(strcol('rod'))) \
         with boxerrorbars ls 1, \
       '' using 0:(1e3*column('contact_time_hertz_s')) with points ls 2 pt 6 ps 1.2
  set label 1 '(d)' at graph 0.04, 0.90 left
  set ylabel 'Coefficient of restitution'
  set yrange [0.7:1.05]
  set boxwidth 0.3
  set key top right samplen 1.5 font ',8' opaque
  plot data using ($0-0.16):'e_input':xtic(label(strcol('rod'))) with boxes lc rgb '#999999' fs solid 0.5 border lc rgb '#555555' title 'input e (Table 2)', \
       '' using ($0+0.16):'e_effective':'e_effective_min':'e_effective_max':(0.3) with boxerrorbars ls 1 title 'effective e, model', \
       '' using 0:(NaN) with points ls 2 pt 6 ps 1.2 title 'undamped Hertz: e = 1'
  unset multiplot
}

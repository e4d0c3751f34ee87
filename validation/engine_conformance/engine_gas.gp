# A granular gas on LAMMPS cooling by Haff's law: gnuplot -d -c engine_gas.gp OUT -> OUT/engine_gas.pdf,
# .png from OUT/engine_gas.csv (validation/engine_conformance). The temperature over its value at t1
# against 1 + (t - t1)/tau on logarithmic axes, tau Haff's time predicted from hertzdash's e: each
# seed's run (points), Haff's law T/T1 = (1 + (t - t1)/tau)^-2 (line).
out = ARG1
here = system('dirname '.ARG0)
data = out.'/engine_gas.csv'
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/engine_gas' format narrow_width_in 2.7
  set logscale xy
  set xlabel '1 + (t - t_1)/{/Symbol t}'
  set ylabel 'T / T_1'
  set xrange [1:6]
  set xtics (1, 2, 3, 4, 5, 6)
  set yrange [0.01:1.2]
  set key bottom left Left reverse width -1 font ',8'
  set samples 200
  plot data using 'scaled_time':'temperature_ratio' with points pt 7 ps 0.25 lc rgb '#0b3c8c' title 'LAMMPS', \
       x**-2 with lines ls 2 title "Haff's law"
}

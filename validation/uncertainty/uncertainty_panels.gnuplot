# The five panels of Figs. 5 and 6 under the joint input uncertainty, from STEM.csv (written by
# validation/uncertainty):  call 'uncertainty_panels.gnuplot' STEM 'TITLE' ROD
# (a) force, (b) displacement, (d) acceleration, (e) velocity against time since contact onset:
# the pointwise 5-95 % band in the rod's tint, its median dashed and the paper's model at the
# assumed values solid, in the rod's colour. (c) the hysteresis loop: a loop has no pointwise
# band, so the loops of the runs at the 5th and 95th percentile of peak force are drawn thin,
# the 50th dashed. The sixth cell holds the legend.
data = ARG1.'.csv'
set style line 1 lc rgb rod_colour(ARG3) lw 2.0 dt 1
set style line 12 lc rgb rod_colour(ARG3) lw 1.4 dt 2
set style line 11 lc rgb rod_tint(ARG3) lw 1.2 dt 1
runs = int(csv_parameter(data, 'band_runs'))
t_ms = '(1e3*column("t_s"))'
in_contact(x) = x >= 0 ? 1e6*x : NaN

# Time tics: about four per panel whatever the contact time; value tics 1, 2 or 5 times a power of ten.
stats data using (1e3*column('t_s')) nooutput
t_step = STATS_max > 1.0 ? 0.5 : (STATS_max > 0.5 ? 0.25 : 0.1)
nice_step(span) = (r = span/5.0, m = 10**floor(log10(r)), r/m <= 1 ? m : r/m <= 2 ? 2*m : r/m <= 5 ? 5*m : 10*m)
stats data using 'force_q95_N' nooutput
f_step = nice_step(STATS_max)
stats data using (1e6*column('displacement_q95_m')) nooutput
d_span = STATS_max - STATS_min
x_step = STATS_max > 250 ? 100 : (STATS_max > 100 ? 50 : 20)
stats data using 'accel_q05_mps2' nooutput
a_step = nice_step(-STATS_min)

set multiplot layout 3,2 title ARG2
set key off
set autoscale xfix
set xtics t_step
set xlabel 'Time since contact onset (ms)'
set label 1 at graph 0.96, 0.90 right front
set rmargin 4

set label 1 '(a)'
set ytics f_step
set ylabel 'Contact force P (N)'
plot data using @t_ms:'force_q05_N':'force_q95_N' with filledcurves ls 11, \
     '' using @t_ms:'force_q50_N' with lines ls 12, \
     '' using @t_ms:'force_model_N' with lines ls 1

set label 1 '(b)'
set ytics nice_step(d_span)
set ylabel 'Displacement ({/Symbol m}m)'
plot data using @t_ms:(1e6*column('displacement_q05_m')):(1e6*column('displacement_q95_m')) with filledcurves ls 11, \
     '' using @t_ms:(1e6*column('displacement_q50_m')) with lines ls 12, \
     '' using @t_ms:(1e6*column('displacement_model_m')) with lines ls 1

set label 1 '(c)'
set ytics f_step
set xlabel 'Displacement x ({/Symbol m}m)'
set ylabel 'Contact force P (N)'
set autoscale x
set xrange [0:*]
set xtics x_step
plot data using (in_contact(column('loop_p05_displacement_m'))):'loop_p05_force_N' with lines ls 11, \
     '' using (in_contact(column('loop_p95_displacement_m'))):'loop_p95_force_N' with lines ls 11, \
     '' using (in_contact(column('loop_p50_displacement_m'))):'loop_p50_force_N' with lines ls 12, \
     '' using (in_contact(column('displacement_model_m'))):'force_model_N' with lines ls 1
set autoscale xfix
set xtics t_step
set xlabel 'Time since contact onset (ms)'

set label 1 '(d)' at graph 0.96, 0.10
set ytics a_step
set ylabel 'Rod acceleration (m/s^2)'
plot data using @t_ms:'accel_q05_mps2':'accel_q95_mps2' with filledcurves ls 11, \
     '' using @t_ms:'accel_q50_mps2' with lines ls 12, \
     '' using @t_ms:'accel_model_mps2' with lines ls 1

set label 1 '(e)' at graph 0.96, 0.90
set ytics 0.4
set ylabel 'Rod velocity (m/s)'
plot data using @t_ms:'velocity_q05_mps':'velocity_q95_mps' with filledcurves ls 11, \
     '' using @t_ms:'velocity_q50_mps' with lines ls 12, \
     '' using @t_ms:'velocity_model_mps' with lines ls 1

# Legend cell.
unset label 1
unset border
unset tics
unset grid
unset xlabel
unset ylabel
set key at graph 0.0, 0.5 left center Left reverse nobox samplen 2.5 spacing 1.4 font ',8'
set xrange [0:1]
set yrange [0:1]
plot 2 with lines ls 1 title 'Paper’s model, assumed inputs', \
     2 with filledcurves y1=3 ls 11 title sprintf('5-95 %% band, %d draws', runs), \
     2 with lines ls 12 title 'Median (in (c): 50th pct.)', \
     2 with lines ls 11 title '(c): 5th, 95th percentile', \
     NaN with lines lt -2 title '      of peak force'
unset multiplot

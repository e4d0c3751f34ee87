# The five panels of Figs. 5 and 6 from STEM.csv (written by validation/paper_figures):
#   call 'impact_panels.gnuplot' STEM 'TITLE' ROD
# The model is drawn in the rod's colour (style.gnuplot's rod_colour), its band in its tint.
# (a) force, (b) displacement, (c) hysteresis loop, (d) acceleration, (e) velocity vs time;
# the sixth cell holds the legend. Measured traces STEM_measured_*.csv are overlaid if present.
# (No straight apostrophe in the legend titles: it would hide the @legend_traces macro.)
data = ARG1.'.csv'
set style line 1 lc rgb rod_colour(ARG3) lw 2.0 dt 1
set style line 11 lc rgb rod_tint(ARG3) lw 0.8 dt 1
measured = system('ls '.ARG1.'_measured_*.csv 2>/dev/null')
n_measured = words(measured)
E_default = real(csv_parameter(data, 'ball_E_Pa'))/1e9
E_min = real(csv_parameter(data, 'band_ball_E_min_Pa'))/1e9
E_max = real(csv_parameter(data, 'band_ball_E_max_Pa'))/1e9
t_ms = '(1e3*column("t_s"))'
# The measured overlays as plot-command suffixes (empty without measured traces).
overlay(using) = n_measured == 0 ? '' : \
  sprintf(", for [i=1:%d] word(measured, i) using %s with lines ls 3", n_measured, using)
overlay_force = overlay(t_ms.":'force_N'")
overlay_accel = overlay(t_ms.":'accel_mps2'")
overlay_velocity = overlay(t_ms.":'velocity_mps'")
overlay_displacement = overlay(t_ms.":(1e6*column('displacement_m'))")
overlay_loop = overlay("(in_contact(column('displacement_m'))):'force_N'")
in_contact(x) = x >= 0 ? 1e6*x : NaN
# A trace marked synthetic (not a measurement) is never called measured.
n_synthetic = 0
do for [i=1:n_measured] { n_synthetic = n_synthetic + (csv_parameter(word(measured, i), 'synthetic') eq 'true') }
note = n_measured == 0 ? 'model only: the paper printed its measured traces only as plots' \
     : sprintf('%d trace(s) overlaid, of which %d SYNTHETIC, not measured', n_measured, n_synthetic)
trace_title = n_synthetic == n_measured ? 'SYNTHETIC trace (not a measurement)' \
            : n_synthetic > 0 ? 'Measured or SYNTHETIC (see header)' : 'Measured'
# The legend names the overlaid traces only if there are any.
legend_traces = n_measured == 0 ? '' : ", 2 with lines ls 3 title trace_title"

# Time tics: three to five labels per panel whatever the contact time (labels of 0.25 ms
# ran into each other at this panel width), a minor tic between labels.
stats data using (1e3*column('t_s')) nooutput
t_step = STATS_max > 1.0 ? 0.5 : (STATS_max > 0.4 ? 0.2 : 0.1)
stats data using (1e6*column('displacement_max_m')) nooutput
x_step = STATS_max > 250 ? 100 : (STATS_max > 100 ? 50 : 20)
# Value tics: at most about five per panel, 1, 2 or 5 times a power of ten.
nice_step(span) = (r = span/5.0, m = 10**floor(log10(r)), r/m <= 1 ? m : r/m <= 2 ? 2*m : r/m <= 5 ? 5*m : 10*m)
stats data using 'force_max_N' nooutput
f_step = nice_step(STATS_max)
stats data using (1e6*column('displacement_max_m')) nooutput
d_span = STATS_max - STATS_min
stats data using 'accel_min_mps2' nooutput
a_step = nice_step(-STATS_min)

set multiplot layout 3,2 title ARG2."\n{/=8 (".note.')}'
set key off
set autoscale xfix
set xtics t_step
set mxtics 2
set xlabel 'Time since contact onset (ms)'
set label 1 at graph 0.96, 0.90 right front
set rmargin 4

set label 1 '(a)'
set ytics f_step
set ylabel 'Contact force P (N)'
plot data using @t_ms:'force_min_N':'force_max_N' with filledcurves ls 11, \
     '' using @t_ms:'force_hertz_N' with lines ls 2, \
     '' using @t_ms:'force_N' with lines ls 1 @overlay_force

set label 1 '(b)'
set ytics nice_step(d_span)
set ylabel 'Displacement ({/Symbol m}m)'
plot data using @t_ms:(1e6*column('displacement_min_m')):(1e6*column('displacement_max_m')) with filledcurves ls 11, \
     '' using @t_ms:(1e6*column('displacement_hertz_m')) with lines ls 2, \
     '' using @t_ms:(1e6*column('displacement_m')) with lines ls 1 @overlay_displacement

set label 1 '(c)'
set ytics f_step
set xlabel 'Displacement x ({/Symbol m}m)'
set ylabel 'Contact force P (N)'
set autoscale x
set xrange [0:*]
set xtics x_step
plot data using (in_contact(column('displacement_Emin_m'))):'force_Emin_N' with lines ls 11, \
     '' using (in_contact(column('displacement_Emax_m'))):'force_Emax_N' with lines ls 11, \
     '' using (in_contact(column('displacement_hertz_m'))):'force_hertz_N' with lines ls 2, \
     '' using (in_contact(column('displacement_m'))):'force_N' with lines ls 1 @overlay_loop
set autoscale xfix
set xtics t_step
set mxtics 2
set xlabel 'Time since contact onset (ms)'

set label 1 '(d)' at graph 0.96, 0.10
set ytics a_step
set ylabel 'Rod acceleration (m/s^2)'
plot data using @t_ms:'accel_min_mps2':'accel_max_mps2' with filledcurves ls 11, \
     '' using @t_ms:'accel_hertz_mps2' with lines ls 2, \
     '' using @t_ms:'accel_mps2' with lines ls 1 @overlay_accel

set label 1 '(e)' at graph 0.96, 0.90
set ytics 0.4
set ylabel 'Rod velocity (m/s)'
plot data using @t_ms:'velocity_min_mps':'velocity_max_mps' with filledcurves ls 11, \
     '' using @t_ms:'velocity_hertz_mps' with lines ls 2, \
     '' using @t_ms:'velocity_mps' with lines ls 1 @overlay_velocity

# Legend cell (no left margin: the titles need the cell's width).
set lmargin 0
unset label 1
unset border
unset tics
unset grid
unset xlabel
unset ylabel
set key at graph 0.0, 0.5 left center Left reverse nobox samplen 2.5 spacing 1.4 font ',8'
set xrange [0:1]
set yrange [0:1]
plot 2 with lines ls 1 title sprintf("Paper’s model, E_{nylon} = %.1f GPa", E_default), \
     2 with filledcurves y1=3 ls 11 title sprintf("the same, E_{nylon} = %.1f-%.1f GPa", E_min, E_max), \
     2 with lines ls 2 title 'Undamped Hertz contact' @legend_traces
unset multiplot

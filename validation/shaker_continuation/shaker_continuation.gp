# The bouncing ball's orbits by continuation over its brute-force diagram: gnuplot -d -c
# shaker_continuation.gp OUT -> OUT/shaker_continuation.pdf, .png from
# OUT/shaker_continuation_branches.csv and _brute.csv (validation/shaker_continuation).
# Stacked: (a) the drive phase of each impact against Gamma: the brute-force diagram (grey dots), the
# continued orbits (stable: filled, unstable: open, one colour per period), the located period
# doublings and the fold (dashed). (b) The largest Floquet multiplier's modulus of each branch
# point; an orbit is stable below 1.
out = ARG1
here = system('dirname '.ARG0)
branches = out.'/shaker_continuation_branches.csv'
brute = out.'/shaker_continuation_brute.csv'
periods = '1 2 4 8 16'
period_colour(p) = p == 1 ? '#0b3c8c' : p == 2 ? '#c0392b' : p == 4 ? '#27ae60' : p == 8 ? '#8e44ad' : '#e67e22'
event(k) = real(system(sprintf("sed -n 's/^# event: [a-z-]* at gamma = \\([0-9.]*\\).*/\\1/p' '%s' | sed -n '%dp'", branches, k)))
events = int(system(sprintf("grep -c '^# event:' '%s'", branches)))
pick(p, s, value) = (column('period') == p && column('stable') == s) ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/shaker_continuation' format full_width_in 5.2
  set multiplot
  set xlabel '{/Symbol G} = A (2{/Symbol p} f)^2 / g'
  set xrange [1.0:1.75]
  set xtics 0.1
  set key off
  set tmargin 1.6
  set lmargin 10  # both panels' axes aligned
  set label 1 at graph 0, 1.08 left front font ',8'
  eval stack_panel(1, 2)
  set label 1 '(a) impact phases'
  set ylabel 'Phase (cycles)'
  set yrange [0:1]
  set ytics 0.25
  do for [k=1:events] { set arrow k from event(k), graph 0 to event(k), graph 1 nohead lc rgb '#555555' dt 2 lw 0.8 }
  plot brute using 'gamma':'impact_phase' with points pt 7 ps 0.4 lc rgb '#c8c8c8', \
       for [i=1:words(periods)] branches using (pick(int(word(periods, i)), 1, column('gamma'))):'impact_phase' \
           with points pt 7 ps 0.18 lc rgb period_colour(int(word(periods, i))), \
       for [i=1:words(periods)] branches using (pick(int(word(periods, i)), 0, column('gamma'))):'impact_phase' \
           with points pt 6 ps 0.22 lw 0.5 lc rgb period_colour(int(word(periods, i)))
  unset arrow
  eval stack_panel(2, 2)
  set label 1 '(b) stability'
  set ylabel 'Largest |multiplier|'
  set logscale y
  set yrange [0.1:10]
  set ytics auto
  set format y '%g'
  set arrow 1 from graph 0, first 1 to graph 1, first 1 nohead lc rgb '#555555' dt 2 lw 0.8
  plot for [i=1:words(periods)] branches using (pick(int(word(periods, i)), 1, column('gamma'))):'max_multiplier_modulus' \
           with points pt 7 ps 0.18 lc rgb period_colour(int(word(periods, i))), \
       for [i=1:words(periods)] branches using (pick(int(word(periods, i)), 0, column('gamma'))):'max_multiplier_modulus' \
           with points pt 6 ps 0.22 lw 0.5 lc rgb period_colour(int(word(periods, i)))
  unset arrow 1
  eval quad_key_row
  eval key_panel
  set lmargin 0
  eval key_row
  set key maxrows 3
  plot NaN with points pt 7 ps 0.8 lc rgb '#c8c8c8' title 'brute force', \
       for [i=1:words(periods)] NaN with points pt 7 ps 0.8 lc rgb period_colour(int(word(periods, i))) \
           title sprintf('period %s', word(periods, i)), \
       NaN with points pt 6 ps 0.8 lc rgb '#000000' title 'open: unstable', \
       NaN with lines lc rgb '#555555' dt 2 lw 0.8 title 'fold, doublings'
  unset multiplot
}

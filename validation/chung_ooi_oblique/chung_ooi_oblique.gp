# Chung and Ooi's tests 5 and 6 with each tangential model: gnuplot -d -c chung_ooi_oblique.gp OUT
# -> OUT/chung_ooi_oblique.pdf, .png from OUT/chung_ooi_oblique.csv and
# OUT/chung_ooi_oblique_reference.csv (validation/chung_ooi_oblique). (a) test 5's normalised
# recoil angle V_st'/(mu V_cn') and (b) normalised spin R omega'/(mu V_cn) against V_st/(mu V_cn);
# (c) test 6's beta = -V_st'/V_st against 3.5 mu (1 + e) V_cn / V_st and (d) its recoil tangent
# V_st'/V_cn' against V_st/V_cn. Lines: each model for the first material (steel, aluminium
# alloy), one colour and dash per model (style.gnuplot), gross sliding's closed form grey dotted (not in the key: the caption says it);
# points: the digitised curves, circles the first material, triangles the second (polyethylene, nylon).
out = ARG1
here = system('dirname '.ARG0)
data = out.'/chung_ooi_oblique.csv'
ref = out.'/chung_ooi_oblique_reference.csv'
pick(c, m, value) = strcol('curve') eq c && strcol('model') eq m ? value : NaN
curve(c, value) = strcol('curve') eq c ? value : NaN
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  models = csv_parameter(data, 'tangential_models')  # the registered models, in the registry's order
  call here.'/../output.gnuplot' out.'/chung_ooi_oblique' format full_width_in 4.8
  set multiplot
  set key off
  eval quad_panel(1)
  set xlabel 'V_{st} / ({/Symbol m} V_{cn})'
  set ylabel "V_{st}' / ({/Symbol m} V_{cn}')"
  set xrange [0:14]
  set yrange [-4:7]
  set xtics 2
  set ytics 2
  set label 1 '(a) test 5' at graph 0.05, 0.9 font ',9'
  plot (x >= 7 ? x - 7 : NaN) with lines lc rgb '#999999' lw 1 dt 3, \
       for [m in models] data using 'x':(pick('test5_steel_rebound_slip', m, column('y'))) with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m), \
       ref using 'x':(curve('test5_steel_rebound_slip', column('y'))) with points pt 6 ps 0.8 lc rgb 'black', \
       ref using 'x':(curve('test5_polyethylene_rebound_slip', column('y'))) with points pt 8 ps 0.8 lc rgb 'black'
  eval quad_panel(2)
  set ylabel "R {/Symbol w}' / ({/Symbol m} V_{cn})"
  set xrange [0:20]
  set yrange [-6:0.5]
  set xtics 5
  set ytics 1
  set label 1 '(b) test 5' at graph 0.6, 0.9
  plot (x >= 7 ? -5 : NaN) with lines lc rgb '#999999' lw 1 dt 3, \
       for [m in models] data using 'x':(pick('test5_steel_rebound_spin', m, column('y'))) with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m), \
       ref using 'x':(curve('test5_steel_rebound_spin', column('y'))) with points pt 6 ps 0.8 lc rgb 'black', \
       ref using 'x':(curve('test5_polyethylene_rebound_spin', column('y'))) with points pt 8 ps 0.8 lc rgb 'black'
  eval quad_panel(3)
  set logscale x
  set xlabel '3.5 {/Symbol m} (1 + e) V_{cn} / V_{st}'
  set ylabel "{/Symbol b} = -V_{st}' / V_{st}"
  set xrange [0.15:30]
  set yrange [-1:0.8]
  set xtics (0.2, 0.5, 1, 2, 5, 10, 20)
  set ytics 0.5
  set label 1 '(c) test 6' at graph 0.05, 0.9
  plot (x < 1 ? x - 1 : NaN) with lines lc rgb '#999999' lw 1 dt 3, \
       for [m in models] data using 'x':(pick('test6_aluminium_slip_ratio', m, column('y'))) with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m), \
       ref using 'x':(curve('test6_aluminium_slip_ratio', column('y'))) with points pt 6 ps 0.8 lc rgb 'black', \
       ref using 'x':(curve('test6_nylon_slip_ratio', column('y'))) with points pt 8 ps 0.8 lc rgb 'black'
  eval quad_panel(4)
  unset logscale x
  set xlabel 'V_{st} / V_{cn}'
  set ylabel "V_{st}' / V_{cn}'"
  set xrange [0:7]
  set yrange [-2:8.5]
  set xtics 1
  set ytics 2
  set label 1 '(d) test 6' at graph 0.05, 0.9
  plot (x > 2.1 ? (x - 2.1) / 0.5 : NaN) with lines lc rgb '#999999' lw 1 dt 3, \
       for [m in models] data using 'x':(pick('test6_aluminium_recoil_tangent', m, column('y'))) with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m), \
       ref using 'x':(curve('test6_aluminium_recoil_tangent', column('y'))) with points pt 6 ps 0.8 lc rgb 'black', \
       ref using 'x':(curve('test6_nylon_recoil_tangent', column('y'))) with points pt 8 ps 0.8 lc rgb 'black'
  eval quad_key_row
  eval key_panel
  eval key_row
  plot for [m in models] NaN with lines lw 1.5 lc rgb tangential_lc(m) dt tangential_dt(m) title m, \
       NaN with points pt 6 ps 0.8 lc rgb 'black' title 'steel, alloy', \
       NaN with points pt 8 ps 0.8 lc rgb 'black' title 'PE, nylon'
  unset multiplot
}

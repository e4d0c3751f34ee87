# Fig. 5 of Hongo et al. reproduced: gnuplot -d -c fig5.gp OUT  ->  OUT/fig5.pdf, OUT/fig5.png
# from OUT/fig5.csv (and OUT/fig5_measured_*.csv if any), written by validation/paper_figures.
out = ARG1
here = system('dirname '.ARG0)
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/fig5' format full_width_in 7.4
  call here.'/impact_panels.gnuplot' out.'/fig5' 'Fig. 5 reproduced: steel rod, h = 20 mm' 'steel'
}

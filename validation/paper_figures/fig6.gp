# Fig. 6 of Hongo et al. reproduced: gnuplot -d -c fig6.gp OUT  ->  OUT/fig6.pdf, OUT/fig6.png
# from OUT/fig6.csv (and OUT/fig6_measured_*.csv if any), written by validation/paper_figures.
out = ARG1
here = system('dirname '.ARG0)
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/fig6' format full_width_in 7.4
  call here.'/impact_panels.gnuplot' out.'/fig6' 'Fig. 6 reproduced: duralumin rod C, h = 20 mm' 'duralumin-c'
}

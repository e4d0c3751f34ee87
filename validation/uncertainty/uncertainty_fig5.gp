# Fig. 5 of Hongo et al. under the joint input uncertainty: gnuplot -d -c uncertainty_fig5.gp OUT
#   ->  OUT/uncertainty_fig5.pdf, OUT/uncertainty_fig5.png from OUT/uncertainty_fig5.csv (validation/uncertainty).
out = ARG1
here = system('dirname '.ARG0)
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/uncertainty_fig5' format full_width_in 7.4
  call here.'/uncertainty_panels.gnuplot' out.'/uncertainty_fig5' 'Fig. 5 under joint input uncertainty: steel rod, h = 20 mm' 'steel'
}

# Fig. 6 of Hongo et al. under the joint input uncertainty: gnuplot -d -c uncertainty_fig6.gp OUT
#   ->  OUT/uncertainty_fig6.pdf, OUT/uncertainty_fig6.png from OUT/uncertainty_fig6.csv (validation/uncertainty).
out = ARG1
here = system('dirname '.ARG0)
do for [format in 'pdf png'] {
  reset
  load here.'/../style.gnuplot'
  call here.'/../output.gnuplot' out.'/uncertainty_fig6' format full_width_in 7.4
  call here.'/uncertainty_panels.gnuplot' out.'/uncertainty_fig6' 'Fig. 6 under joint input uncertainty: duralumin rod C, h = 20 mm' 'duralumin-c'
}

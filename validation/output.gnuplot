# Sets the terminal and output file for one figure format. Usage, after loading style.gnuplot:
#   call VALIDATION.'/output.gnuplot' 'OUTDIR/name' 'pdf'|'png'|'svg' WIDTH_IN HEIGHT_IN
# pdf: pdfcairo at WIDTH_IN x HEIGHT_IN inches (for the paper); svg: 96 pixels per inch (`fit --figure`);
# png: pngcairo at 150 pixels per inch, fonts and lines scaled to match (for the README).
# figure_suffix, when defined (validation/draw_figure.sh sets it to .tmp.PID), is appended to
# the file name: the figure is drawn under a temporary name and renamed once complete.
if (!exists('figure_suffix')) { figure_suffix = '' }
fig_width_in = real(ARG3)
fig_height_in = real(ARG4)
if (ARG2 eq 'pdf') {
  set terminal pdfcairo enhanced color font 'Helvetica,9' size fig_width_in, fig_height_in fontscale 1.0 linewidth 1.0
  set output ARG1.'.pdf'.figure_suffix
} else { if (ARG2 eq 'svg') {
  set terminal svg enhanced font 'Helvetica,9' size int(fig_width_in*96), int(fig_height_in*96) linewidth 1.0
  set output ARG1.'.svg'.figure_suffix
} else {
  fig_dpi = 150.0
  set terminal pngcairo enhanced color font 'Helvetica,9' size int(fig_width_in*fig_dpi), int(fig_height_in*fig_dpi) \
      fontscale fig_dpi/72.0 linewidth fig_dpi/72.0
  set output ARG1.'.png'.figure_suffix
} }

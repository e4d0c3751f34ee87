# Line style per damping law for the damping_laws figures, on top of style.gnuplot:
# the paper's law ls 1 (navy, solid), undamped Hertz ls 2 (grey, dashed), and the
# literature laws cycle through eleven colours with solid, dashed and dotted lines.
law_colours = '#e67e22 #27ae60 #8e44ad #c0392b #16a085 #d35400 #2c3e50 #7f8c8d #f1c40f #1abc9c #e84393'
law_colour(i) = word(law_colours, (i - 1) % words(law_colours) + 1)
law_dash(i) = (i - 1) % 3 + 1
# Model names in order of appearance in column 1 of a CSV (after its '#' header and column names).
law_names(file) = system("grep -v '^#' '".file."' | tail -n +2 | cut -d, -f1 | uniq | tr '\\n' ' '")
# Terminal for one format: pdfcairo (paper) or pngcairo at 150 px per inch (README).
set_terminal(format, name, w, h) = (format eq 'pdf') ? \
  sprintf("set terminal pdfcairo enhanced color font 'Helvetica,9' size %g,%g; set output '%s.pdf'", w, h, name) : \
  sprintf("set terminal pngcairo enhanced color font 'Helvetica,9' size %d,%d fontscale %g linewidth %g; set output '%s.png'", \
          int(w*150), int(h*150), 150.0/72, 150.0/72, name)
law_dt(name, i) = name eq 'hongo' || name eq 'kelvin-voigt' ? 1 : name eq 'none' ? 2 : law_dash(i)
# Width: the paper's law bold; Kelvin-Voigt wide, so the x^{1/4} DEM dashpot, which
# coincides with it in the restitution map, stays visible on top of it.
law_lw(name) = name eq 'hongo' ? 2.4 : name eq 'kelvin-voigt' ? 4.5 : 1.4
law_lc(name, i) = name eq 'hongo' ? '#0b3c8c' : name eq 'none' ? '#555555' : name eq 'kelvin-voigt' ? '#c39bd3' : law_colour(i)
# Two square-ish panels side by side and the key to their right, in screen coordinates.
panel_a = 'set lmargin at screen 0.11; set rmargin at screen 0.39; set bmargin at screen 0.19; set tmargin at screen 0.96'
panel_b = 'set lmargin at screen 0.45; set rmargin at screen 0.74; set bmargin at screen 0.19; set tmargin at screen 0.96; unset ylabel'
side_key = "set key at screen 0.995, 0.95 right top box opaque font ',8' samplen 2.5 spacing 1.0 width -1"

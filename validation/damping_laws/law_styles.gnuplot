# Line style per damping law for the damping_laws figures, on top of style.gnuplot:
# the paper's law ls 1 (navy, solid), undamped Hertz ls 2 (grey, dashed), and the
# literature laws cycle through eleven colours with solid, dashed and dotted lines.
law_colours = '#e67e22 #27ae60 #8e44ad #c0392b #16a085 #d35400 #2c3e50 #7f8c8d #f1c40f #1abc9c #e84393'
law_colour(i) = word(law_colours, (i - 1) % words(law_colours) + 1)
law_dash(i) = (i - 1) % 3 + 1
# Model names in order of appearance in column 1 of a CSV (after its '#' header and column names).
law_names(file) = system("grep -v '^#' '".file."' | tail -n +2 | cut -d, -f1 | uniq | tr '\\n' ' '")
law_dt(name, i) = name eq 'hongo' || name eq 'kelvin-voigt' || name eq 'kuwabara-kono' ? 1 : name eq 'none' ? 2 : law_dash(i)
# Width: the paper's law bold; Kelvin-Voigt wide, so the x^{1/4} DEM dashpot, which
# coincides with it in the restitution map, stays visible on top of it; the viscoelastic law
# (the paper's force with a fixed time constant, so equal to it wherever both are calibrated
# at the same speed) solid and narrower, drawn over the paper's law without hiding it.
law_lw(name) = name eq 'hongo' ? 2.4 : name eq 'kelvin-voigt' ? 4.5 : name eq 'kuwabara-kono' ? 1.2 : 1.4
law_lc(name, i) = name eq 'hongo' ? '#0b3c8c' : name eq 'kuwabara-kono' ? '#8e44ad' : name eq 'none' ? '#555555' : name eq 'kelvin-voigt' ? '#c39bd3' : law_colour(i)
# The legend of every law, for a key panel (style.gnuplot's key_panel).
law_key = 'plot for [i=1:words(laws)] NaN with lines lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i), i) ' . \
          'dt law_dt(word(laws, i), i) title word(laws, i)'

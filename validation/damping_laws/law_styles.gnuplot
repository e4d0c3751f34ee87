# Line style per damping law, on top of style.gnuplot, keyed by the law's name so that a law
# has the same colour, dash and width in every figure whatever other laws are drawn with it
# (tests/law_styles_test.sh requires every registered law's style to differ from every other's).
# The paper's law is bold navy, undamped Hertz grey dashed; Kelvin-Voigt is wide and pale, so
# the x^{1/4} DEM dashpot, which coincides with it in the restitution map, stays visible on top
# of it; the viscoelastic law (the paper's force with a fixed time constant, equal to it wherever
# both are calibrated at the same speed) is solid and narrower, drawn over the paper's law
# without hiding it. A law of yours that is not in the table is drawn black, dash-dot and bold
# until you give it a line here: never in another law's colour.
#                  name                colour     dash  width
law_table = 'none                #555555  2  1.4 ' . \
            'hongo               #0b3c8c  1  2.4 ' . \
            'kelvin-voigt        #c39bd3  1  4.5 ' . \
            'hunt-crossley       #c0392b  1  1.4 ' . \
            'herbert-mcwhannell  #16a085  2  1.4 ' . \
            'lee-wang            #d35400  3  1.4 ' . \
            'lankarani-nikravesh #2c3e50  1  1.4 ' . \
            'gonthier            #7f8c8d  2  1.4 ' . \
            'zhiying-qishao      #f1c40f  3  1.4 ' . \
            'flores              #1abc9c  1  1.4 ' . \
            'hu-guo              #e84393  2  1.4 ' . \
            'gharib-hurmuzlu     #e67e22  3  1.4 ' . \
            'tsuji-dem           #27ae60  1  1.4 ' . \
            'kuwabara-kono       #8e44ad  1  1.2 ' . \
            'lee-herrmann        #6d4c41  2  1.6 '
# The position of `name` in the table's first column, 0 if it has none.
law_row(name) = sum [k = 1:words(law_table) / 4] (word(law_table, 4 * k - 3) eq name ? k : 0)
law_field(name, j, fallback) = law_row(name) > 0 ? word(law_table, 4 * law_row(name) - 4 + j) : fallback
law_lc(name) = law_field(name, 2, '#000000')
law_dt(name) = int(law_field(name, 3, '4'))
law_lw(name) = real(law_field(name, 4, '2.0'))
# Model names in order of appearance in column 1 of a CSV (after its '#' header and column names).
law_names(file) = system("grep -v '^#' '".file."' | tail -n +2 | cut -d, -f1 | uniq | tr '\\n' ' '")
# The legend of every law in `laws`, for a key panel (style.gnuplot's key_panel).
law_key = 'plot for [i=1:words(laws)] NaN with lines lw law_lw(word(laws, i)) lc rgb law_lc(word(laws, i)) ' . \
          'dt law_dt(word(laws, i)) title word(laws, i)'

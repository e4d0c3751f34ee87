# House style for every figure: load it first in each .gp script, then call
#   call VALIDATION.'/output.gnuplot' 'OUTDIR/name' 'pdf'|'png' WIDTH_IN HEIGHT_IN
# with WIDTH_IN one of the two canvas widths below. The article includes every figure at
# its natural size, so its fonts are the sizes set here: 9 pt, keys and notes 8 pt, never less.
full_width_in = 6.3    # the article's \textwidth (A4, 25 mm margins)
narrow_width_in = 3.9  # a figure beside the text's flow, 0.62 \textwidth
# Line styles: 1 paper model, 2 undamped Hertz reference, 3 measured data,
# 4.. other models/variants. Band fill for parameter ranges.
set encoding utf8
set style line 1 lc rgb '#0b3c8c' lw 2.0 dt 1
set style line 2 lc rgb '#555555' lw 1.4 dt 2
set style line 3 lc rgb '#c0392b' lw 1.4 dt 1 pt 7 ps 0.4
set style line 4 lc rgb '#e67e22' lw 1.6 dt 1
set style line 5 lc rgb '#27ae60' lw 1.6 dt 1
set style line 6 lc rgb '#8e44ad' lw 1.6 dt 1
set style line 7 lc rgb '#16a085' lw 1.6 dt 4
set style line 8 lc rgb '#7f8c8d' lw 1.6 dt 5
set style fill transparent solid 0.25 noborder
set border lw 1.0
set grid lc rgb '#dddddd' lw 0.6
set key top right samplen 2.5 spacing 1.1 box opaque
set tics nomirror out scale 0.6
set datafile separator ','
set datafile commentschars '#'
# 11: the fill of a parameter band around line style 1 (draw with filledcurves ls 11).
set style line 11 lc rgb '#7f9fd8' lw 0.8 dt 1
# One colour per rod of Tables 1-3, in every figure that tells rods apart.
rod_colour(rod) = rod eq 'steel' ? '#0b3c8c' : rod eq 'duralumin-a' ? '#27ae60' : rod eq 'duralumin-b' ? '#8e44ad' : \
                  rod eq 'duralumin-c' ? '#d35400' : '#000000'
rod_tint(rod) = rod eq 'steel' ? '#7f9fd8' : rod eq 'duralumin-a' ? '#93d6ae' : rod eq 'duralumin-b' ? '#c6a1d6' : \
                rod eq 'duralumin-c' ? '#f0b27f' : '#bbbbbb'
rod_label(rod) = rod eq 'steel' ? 'Steel' : rod eq 'duralumin-a' ? 'Duralumin A' : rod eq 'duralumin-b' ? 'Duralumin B' : \
                 rod eq 'duralumin-c' ? 'Duralumin C' : rod
# Two panels and a legend side by side on a full-width canvas: the panels' margins are
# gnuplot's automatic ones, so tick labels and axis labels always fit inside the canvas.
two_panels_a = 'set origin 0, 0; set size 0.345, 1'
two_panels_b = 'set origin 0.335, 0; set size 0.345, 1'
two_panels_key = 'set origin 0.68, 0; set size 0.32, 1; set margins 0, 0, 0, 0'
# Four panels in a 2 x 2 grid, (1) top left to (4) bottom right, automatic margins, above
# a row for their legend (quad_key_row, then eval key_panel and plot the entries).
quad_panel(k) = sprintf('set origin %g, %g; set size 0.5, 0.43', ((k - 1) % 2) * 0.5, k <= 2 ? 0.57 : 0.14)
quad_key_row = 'set origin 0, 0.01; set size 1, 0.12; set margins 0, 0, 0, 0'
# Panel k of n stacked full-width panels above a legend row (quad_key_row), automatic margins.
stack_panel(k, n) = sprintf('set origin 0, %g; set size 1, %g', 0.13 + (n - k) * 0.87 / n, 0.87 / n)
# In a key row: the entries side by side, centred.
key_row = "set key at graph 0.03, 0.5 left center vertical maxrows 3 width -2" 
# A legend in a panel of its own (a multiplot cell): no axes, the key centred, 8 pt.
# Plot its entries as NaN series after `eval key_panel`.
key_panel = "unset logscale; unset border; unset tics; unset grid; unset xlabel; unset ylabel; unset title; unset label; " . \
            "set xrange [0:1]; set yrange [0:1]; set key at graph 0, 0.5 left center Left reverse noopaque nobox font ',8' " . \
            "samplen 2 spacing 1.0 width 0"
# Read a "# name: value" provenance line from a CSV written by CsvWriter.
csv_parameter(file, name) = system(sprintf("sed -n 's/^# %s: //p' '%s' | head -n 1", name, file))
# A tick step for at most four ticks over a range r: the least of 1, 2, 5 or 10 times a power of
# ten at or above r / 3 (panels too short for gnuplot's own choice: `fit --figure`, `sweep --figure`).
nice_mantissa(m) = m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10
nice_step(r) = r <= 0 ? 1 : nice_mantissa(r / 3 / 10**floor(log10(r / 3))) * 10**floor(log10(r / 3))
# One colour and dash per tangential model (validation/oblique_impacts), used identically everywhere.
tangential_lc(m) = m eq 'mindlin-no-slip' ? '#1f5fbf' : m eq 'mindlin-rescale' ? '#e69f00' : m eq 'mindlin-deresiewicz' ? '#c0392b' : m eq 'linear-spring' ? '#2e8b57' : m eq 'cattaneo-mindlin-mdr' ? '#7b3294' : '#555555'
tangential_dt(m) = m eq 'mindlin-no-slip' ? 1 : m eq 'mindlin-rescale' ? 3 : m eq 'mindlin-deresiewicz' ? 2 : m eq 'cattaneo-mindlin-mdr' ? 5 : 4

# House style for every figure: load it first in each .gp script, then call
#   call VALIDATION.'/output.gnuplot' 'OUTDIR/name' 'pdf'|'png' WIDTH_IN HEIGHT_IN
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
# Read a "# name = value" provenance line from a CSV written by CsvWriter.
csv_parameter(file, name) = system(sprintf("sed -n 's/^# %s = //p' '%s' | head -n 1", name, file))

# Chapter 09's trade, from the table --sweep writes: the dense and the hashed grid on one scene at
# densities lambda from 4 to 4096 cells per object, render time (left) and memory (right). Rows are
# found by their structure column and columns by name, never by position.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/09_hashed_voxels/trade_plot.gnuplot
set terminal pngcairo size 1280,720 enhanced font ',18' linewidth 2
set output png
# The header as one string (tab is not in the CSV), to ask which columns this run wrote.
set datafile separator "\t"
stats csv every ::0::0 using (header = ','.strcol(1).',', 0) nooutput
set datafile separator ','
set datafile columnheaders
has(name) = strstrt(header, ','.name.',') > 0
# A filter returns NaN for the rows it skips: as missing data, they do not break a line.
set datafile missing NaN
# gnuplot's strcol stops at a comma even inside quotes: "teapot in a stadium, depth 5" reads as
# its first part, the scene's name.
stats csv using (scene = strcol('scene'), 0) nooutput
on(s, name) = strcol('structure') eq s ? column(name) : NaN
structures = 'grid hashed'
name(s) = s eq 'grid' ? 'dense grid' : s eq 'hashed' ? 'hashed grid' : s
set style line 1 lc rgb '#0060ad' lw 2 pt 7 ps 2
set style line 2 lc rgb '#d95f02' lw 3 pt 5 ps 1.8 dt 2
heading = "Chapter 09, hashed voxels: the dense grid against the hashed grid\n" \
    .'{/*0.75 on the '.scene.'}'
set multiplot title heading font ',22'
set tmargin at screen 0.8
set bmargin at screen 0.15
set logscale xy
set format x '%g'
set format y '%g'
do for [e = -9:9] { set ytics add (2 * 10.0**e, 5 * 10.0**e) }
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
set autoscale fix
set offsets graph 0.05, graph 0.05, graph 0.08, graph 0.08
set xlabel 'density λ, cells per object'
set lmargin at screen 0.11
set rmargin at screen 0.48
set title 'render time' font ',18'
set ylabel 'render time, ms (median of the runs)'
set key top right spacing 1.2
bars = has('render_ms_min') && has('render_ms_max')
# Without min/max columns (older runs) the bars' loop is empty; lo and hi just keep it valid.
lo = bars ? 'render_ms_min' : 'render_ms'
hi = bars ? 'render_ms_max' : 'render_ms'
plot for [i = 1:words(structures)] csv using 'lambda':(on(word(structures, i), 'render_ms')) \
         with linespoints ls i title name(word(structures, i)), \
     for [i = 1:words(structures) * bars] csv \
         using 'lambda':(on(word(structures, i), 'render_ms')):(column(lo)):(column(hi)) \
         with yerrorbars ls i lw 1 ps 0 notitle
set lmargin at screen 0.61
set rmargin at screen 0.98
set title 'memory' font ',18'
set ylabel 'size of the structure, MB'
set key top left spacing 1.2
plot for [i = 1:words(structures)] csv using 'lambda':(on(word(structures, i), 'bytes') / 1e6) \
         with linespoints ls i title name(word(structures, i))
unset multiplot

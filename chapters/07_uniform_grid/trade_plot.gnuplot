# Chapter 07's trade, from two of the tables --sweep writes: render time against the number of
# objects for brute force and the grid, log-log (left; brute force's line has slope 1, O(N)), and
# the density lambda against render time and the grid's size (right, X.csv). Rows are found by
# their structure column and columns by name, never by position; X_scenes.csv stays in its CSV.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/07_uniform_grid/trade_plot.gnuplot
set terminal pngcairo size 1280,720 enhanced font ',18' linewidth 2
set output png
grows = csv[1:strlen(csv) - 4].'_n.csv'
# The headers as strings (tab is not in the CSVs), to ask which columns this run wrote.
set datafile separator "\t"
stats grows every ::0::0 using (grows_header = ','.strcol(1).',', 0) nooutput
stats csv every ::0::0 using (header = ','.strcol(1).',', 0) nooutput
set datafile separator ','
set datafile columnheaders
has(h, name) = strstrt(h, ','.name.',') > 0
# A filter returns NaN for the rows it skips: as missing data, they do not break a line.
set datafile missing NaN
# gnuplot's strcol stops at a comma even inside quotes: "mountain, depth 7" reads as mountain.
stats csv using (scene = strcol('scene'), objects = column('objects'), column('bytes') / 1e6) \
    nooutput
# The right axis does not take offsets: a margin of its own around the grid's sizes.
set y2range [STATS_min / 1.3:STATS_max * 1.3]
ms(s) = strcol('structure') eq s ? column('render_ms') : NaN
times(x) = sprintf(x < 10 ? '%.1fx' : '%.0fx', x)
set style line 1 lc rgb '#d95f02' lw 2 pt 7 ps 2
set style line 2 lc rgb '#0060ad' lw 3 pt 5 ps 1.8
set style line 3 lc rgb '#1b9e77' lw 2 pt 9 ps 2.2 dt 2
heading = 'Chapter 07, the uniform grid: against brute force, and against its own density'
set multiplot title heading font ',22'
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
set tmargin at screen 0.83
set bmargin at screen 0.15
set lmargin at screen 0.09
set rmargin at screen 0.49
set logscale xy
set format x '10^{%T}'
set format y '10^{%T}'
set xlabel 'objects (fractal mountains)'
set ylabel 'render time, ms (median of the runs)'
set title 'as the scene grows' font ',18'
set key top left reverse Left spacing 1.2
set autoscale fix
set offsets graph 0.08, graph 0.1, graph 0.1, graph 0.2
bars = has(grows_header, 'render_ms_min') && has(grows_header, 'render_ms_max')
# Without min/max columns (older runs) the bars' loop is empty; lo and hi just keep it valid.
lo = bars ? 'render_ms_min' : 'render_ms'
hi = bars ? 'render_ms_max' : 'render_ms'
plot grows using 'objects':(ms('brute')) with linespoints ls 1 title 'brute force', \
     '' using 'objects':(ms('grid')) with linespoints ls 2 title 'grid (labels: speed-up)', \
     '' using 'objects':(ms('grid')):(times(column('speedup'))) \
         with labels offset 0, -1.1 font ',15' notitle, \
     for [i = 1:bars] '' using 'objects':(ms('brute')):(column(lo)):(column(hi)) \
         with yerrorbars ls 1 lw 1 ps 0 notitle, \
     for [i = 1:bars] '' using 'objects':(ms('grid')):(column(lo)):(column(hi)) \
         with yerrorbars ls 2 lw 1 ps 0 notitle
set lmargin at screen 0.6
set rmargin at screen 0.89
set xlabel 'density λ, cells per object'
set format x '%g'
# Linear time: it varies by a factor of three, and the minimum is the point.
unset logscale y
set ytics autofreq
set format y '%g'
set ylabel 'render time, ms' textcolor rgb '#0060ad'
set y2label 'grid size, MB' textcolor rgb '#1b9e77'
set logscale y2
set format y2 '%g'
set ytics nomirror textcolor rgb '#0060ad'
set y2tics textcolor rgb '#1b9e77'
do for [e = -9:9] { set y2tics add (2 * 10.0**e, 5 * 10.0**e) }
set title sprintf('the %s, %d objects', scene, objects) font ',18'
set key top center spacing 1.2
set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1
bars = has(header, 'render_ms_min') && has(header, 'render_ms_max')
lo = bars ? 'render_ms_min' : 'render_ms'
hi = bars ? 'render_ms_max' : 'render_ms'
plot csv using 'lambda':'render_ms' with linespoints ls 2 title 'render time', \
     '' using 'lambda':(column('bytes') / 1e6) axes x1y2 with linespoints ls 3 title 'grid size', \
     for [i = 1:bars] '' using 'lambda':'render_ms':(column(lo)):(column(hi)) \
         with yerrorbars ls 2 lw 1 ps 0 notitle
unset multiplot

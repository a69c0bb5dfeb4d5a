# Chapter 10's trade, from the table --sweep writes: the BVH (SAH splits, full depth) by its leaf
# size, render time (left) against the nodes visited and the objects tested per ray (right). Rows
# are found by structure and setting (sah:leafN:depthD; the leaf sweep is at the depth of the
# first such row) and columns by name, never by position; the other rows stay in the CSV.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/10_hierarchies/trade_plot.gnuplot
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
field(s, n) = n <= 1 ? (strstrt(s, ':') ? s[1:strstrt(s, ':') - 1] : s) \
    : field(s[strstrt(s, ':') + 1:], n - 1)
sah(s) = strcol('structure') eq 'bvh' && field(s, 1) eq 'sah' && field(s, 2)[1:4] eq 'leaf'
depth = ''
# gnuplot's strcol stops at a comma even inside quotes: "teapot in a stadium, depth 5" reads as
# its first part, the scene's name.
stats csv using (s = strcol('setting'), depth eq '' && sah(s) \
    ? (depth = field(s, 3), scene = strcol('scene'), objects = column('objects')) : 0, 0) nooutput
leaf(s) = field(s, 2)[5:] + 0
swept(s) = sah(s) && field(s, 3) eq depth
size(name) = (s = strcol(name), swept(s) ? leaf(s) : NaN)
on(name) = swept(strcol('setting')) ? column(name) : NaN
set style line 1 lc rgb '#0060ad' lw 3 pt 7 ps 2
set style line 2 lc rgb '#d95f02' lw 2 pt 5 ps 1.8
set style line 3 lc rgb '#1b9e77' lw 2 pt 9 ps 2.2 dt 2
heading = sprintf("Chapter 10, hierarchies: the BVH's leaf size\n{/*0.75 on the %s, %d objects}", \
    scene, objects)
set multiplot title heading font ',22'
set tmargin at screen 0.8
set bmargin at screen 0.15
set logscale x 2
set xtics 2
set format x '%g'
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
set autoscale xfix
set offsets graph 0.05, graph 0.05, graph 0.08, graph 0.08
set xlabel 'most objects in a leaf'
set lmargin at screen 0.1
set rmargin at screen 0.48
set title 'render time' font ',18'
set ylabel 'render time, ms (median of the runs)'
set key off
bars = has('render_ms_min') && has('render_ms_max')
# Without min/max columns (older runs) the bars' loop is empty; lo and hi just keep it valid.
lo = bars ? 'render_ms_min' : 'render_ms'
hi = bars ? 'render_ms_max' : 'render_ms'
plot csv using (size('setting')):(on('render_ms')) with linespoints ls 1 notitle, \
     for [i = 1:bars] '' using (size('setting')):(on('render_ms')):(on(lo)):(on(hi)) \
         with yerrorbars ls 1 lw 1 ps 0 notitle
set lmargin at screen 0.6
set rmargin at screen 0.98
set title 'work per ray' font ',18'
set ylabel 'count per ray'
set yrange [0:*]
set offsets graph 0.05, graph 0.05, graph 0.08, 0
set key at graph 0.04, graph 0.62 left top reverse Left spacing 1.2
plot csv using (size('setting')):(on('nodes_per_ray')) \
         with linespoints ls 2 title 'nodes visited', \
     '' using (size('setting')):(on('tests_per_ray')) with linespoints ls 3 title 'objects tested'
unset multiplot

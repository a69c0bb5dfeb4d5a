# The benchmark's plots (gnuplot -e "dir='build/bench'" bench_plot.gnuplot): rays per second against
# the scene's size for every structure (incoherent closest-hit rays, one thread; points, as the
# scenes are six different ones, not one curve), and the BVH's time and nodes per ray against N.
# Rows are found by their rays, structure and threads columns and columns by name, never by
# position: new ones may be appended.
set terminal pngcairo size 1280,720 enhanced font ',18' linewidth 2
set datafile separator ','
set datafile columnheaders
set datafile missing NaN
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
set logscale x
set format x '10^{%T}'
set xlabel 'objects in the scene'

add(list, w) = strstrt(' '.list.' ', ' '.w.' ') ? list : list.' '.w
structures = ''
stats dir.'/results.csv' using (structures = add(structures, strcol('structure')), 0) nooutput
# Each structure under its one name, the registry's (chapters/programs/structures.hpp; --help says
# what each is), and Embree's two.
# Twelve colours and markers: room for every structure of the registry and Embree's two, and a few
# more, before two share a look.
colour(i) = word('#666666 #1f78b4 #a6cee3 #33a02c #b2df8a #e31a1c #ff7f00 #6a3d9a #b15928 #fb9a99 #cab2d6 #999933', \
    (i - 1) % 12 + 1)
marker(i) = word('1 5 4 9 8 7 13 11 6 3 2 10', (i - 1) % 12 + 1) + 0
pick(s) = strcol('rays') eq 'incoherent' && strcol('structure') eq s && column('threads') == 1 \
    ? column('mrays_per_s') : NaN
set output dir.'/results.png'
set title 'The benchmark: incoherent closest-hit rays, one thread' font ',22'
set ylabel 'million rays per second'
set logscale y
set format y '10^{%T}'
set autoscale fix
set key outside right center spacing 1.3 reverse Left
set offsets graph 0.06, graph 0.06, graph 0.08, graph 0.08
plot for [i = 1:words(structures)] dir.'/results.csv' using 'objects':(pick(word(structures, i))) \
    with points pt marker(i) ps 2.2 lw 2 lc rgb colour(i) title word(structures, i)

set output dir.'/scaling.png'
set title "The BVH as the scene grows\n" \
    .'{/*0.75 fractal mountains of 2 x 4^{d} triangles; primary rays, one thread}' font ',22'
set ylabel 'time per ray, ns' textcolor rgb '#0060ad'
set y2label 'nodes visited per ray' textcolor rgb '#d95f02'
unset logscale y
set format y '%g'
# The right axis does not take offsets: room of its own above the highest point.
stats dir.'/scaling.csv' using 'nodes_per_ray' nooutput
set yrange [0:*]
set y2range [0:STATS_max * 1.1]
set ytics nomirror textcolor rgb '#0060ad'
set y2tics textcolor rgb '#d95f02'
set key inside top left spacing 1.3 reverse Left
set offsets graph 0.05, graph 0.05, graph 0.1, 0
plot dir.'/scaling.csv' using 'objects':'ns_per_ray' \
         with linespoints lc rgb '#0060ad' lw 3 pt 7 ps 2 title 'time per ray', \
     '' using 'objects':'nodes_per_ray' axes x1y2 \
         with linespoints lc rgb '#d95f02' lw 2 pt 5 ps 1.8 dt 2 \
         title 'nodes visited per ray'

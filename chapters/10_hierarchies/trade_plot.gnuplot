# Chapter 10's trade, from the table --sweep writes: its first six rows are the BVH on the teapot in
# a stadium at leaf sizes 1 to 32; the render time and the nodes and tests per ray of each.
# Columns: scene, objects, structure, setting, build_ms, bytes, tests_per_ray, nodes_per_ray,
# cells_per_ray, render_ms.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" -e "title='10_hierarchies'" trade_plot.gnuplot
set datafile separator ','
set terminal pngcairo size 900,600 noenhanced font ',10'
set output png
set title title.': the BVH on the teapot in a stadium, by leaf size'
set xlabel 'leaf size (objects)'
set logscale xy
set grid
set key top left
leaf(k) = 2 ** k
plot csv every ::1::6 using (leaf($0)):10 with linespoints pt 7 lw 2 title 'render ms', \
     csv every ::1::6 using (leaf($0)):8 with linespoints pt 5 title 'nodes per ray', \
     csv every ::1::6 using (leaf($0)):7 with linespoints pt 9 title 'tests per ray'

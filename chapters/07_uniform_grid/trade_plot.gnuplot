# Chapter 07's trade, from the two tables --sweep writes: render time against the number of
# objects for brute force and the grid, log-log (left; brute force's line has slope 1, O(N)), and
# the density lambda against render time and the grid's size (right).
# Rows as main.cpp writes them: in *_n.csv, brute and grid alternate per scene (columns: scene,
# objects, structure, tests_per_ray, cells_per_ray, render_ms, ...); in the main CSV, one row per
# lambda (columns: scene, objects, lambda, resolution, cells, empty %, refs/object, bytes, build ms,
# tests/ray, cells/ray, render ms).
# gnuplot -e "csv='in.csv'" -e "png='out.png'" -e "title='07_uniform_grid'" trade_plot.gnuplot
set datafile separator ','
set terminal pngcairo size 1200,500 noenhanced font ',10'
set output png
grows = csv[1:strlen(csv) - 4].'_n.csv'
set multiplot layout 1,2 title title.': brute force against the grid, and the grid against its density'
set grid
set logscale xy
set format x '1e%T'
set xlabel 'objects (the fractal mountain, depth 1 to 8)'
set ylabel 'render ms (median)'
set key top left
set title 'render time as the scene grows'
plot grows every 2::1 using 2:6 with linespoints pt 7 title 'brute force', \
     grows every 2::2 using 2:6 with linespoints pt 5 lw 2 title 'uniform grid'
set xlabel 'lambda (cells per object)'
set format x '%g'
set ylabel 'render ms (median)'
set y2label 'grid MB'
set y2tics
set logscale y2
set title 'the density lambda on the mountain, depth 7'
plot csv every ::1 using 3:12 with linespoints pt 7 title 'render ms', \
     csv every ::1 using 3:($8 / 1e6) axes x1y2 with linespoints pt 5 title 'grid MB'
unset multiplot

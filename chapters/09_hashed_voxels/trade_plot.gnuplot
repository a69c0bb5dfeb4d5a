# Chapter 09's trade, from the table --sweep writes: the dense and the hashed grid on the teapot in
# a stadium at densities from 4 to 4096 cells per object (their rows alternate: grid, hashed),
# render time (left) and memory (right).
# Columns: scene, structure, lambda, resolution, occupied_cells, references, table_size,
# collisions, bytes, build_ms, tests_per_ray, cells_per_ray, lookups_per_ray, skipped_per_ray,
# render_ms.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" -e "title='09_hashed_voxels'" trade_plot.gnuplot
set datafile separator ','
set terminal pngcairo size 1200,500 noenhanced font ',10'
set output png
set multiplot layout 1,2 title title.': the dense grid and the hashed grid on the teapot in a stadium'
set logscale xy
set grid
set key top right
set xlabel 'lambda (cells per object)'
set ylabel 'render ms (median)'
plot csv every 2::1 using 3:15 with linespoints pt 7 title 'dense grid', \
     csv every 2::2 using 3:15 with linespoints pt 5 lw 2 title 'hashed grid'
set ylabel 'MB'
set key top left
plot csv every 2::1 using 3:($9 / 1e6) with linespoints pt 7 title 'dense grid', \
     csv every 2::2 using 3:($9 / 1e6) with linespoints pt 5 lw 2 title 'hashed grid'
unset multiplot

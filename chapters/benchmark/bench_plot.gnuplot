# The benchmark's plots (gnuplot -e "dir='build/bench'" bench_plot.gnuplot): rays per second against
# the scene's size for every structure (incoherent closest-hit rays, one thread; points, as the
# scenes are six different ones, not one curve), and the BVH's time
# per ray against N.
set datafile separator ','
set terminal pngcairo size 900,560 noenhanced
set key outside right top
set grid
set logscale xy
set format y '%g'
set format x '%g'
set xlabel 'objects in the scene'

set output dir.'/results.png'
set title 'incoherent closest-hit rays, 1 thread'
set ylabel 'million rays per second'
pick(s) = (strcol(3) eq 'incoherent' && strcol(4) eq s && column(5) == 1) ? column(6) : 1/0
plot for [s in 'brute grid grid-mailbox hashed hgrid bvh embree-medium embree-high'] \
    dir.'/results.csv' skip 1 using 2:(pick(s)) with points pointsize 1.5 title s

set output dir.'/scaling.png'
set title 'the BVH on mountains of 2 x 4^d triangles, primary rays, 1 thread'
set ylabel 'nanoseconds per ray'
set logscale x
unset logscale y
set yrange [0:*]
plot dir.'/scaling.csv' skip 1 using 1:3 with linespoints pointsize 1.2 title 'ns per ray', \
     '' skip 1 using 1:($4 * 10) with linespoints pointsize 1.2 title 'nodes per ray x 10'

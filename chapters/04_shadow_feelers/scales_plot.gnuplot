# Chapter 04's scale families: wrong pixels by scale, before the bounds (the rows the sweep gave at
# the kit's state before them, scales_before.csv) and after (the sweep's own _scales.csv), with the
# pixels of the scenes the kit warns about.
#   gnuplot -e "after='build/trade/04_shadow_feelers_scales.csv'" -e "png='scales.png'" scales_plot.gnuplot
if (!exists("before")) before = 'scales_before.csv'
set datafile separator ','
set terminal pngcairo size 800,480 font ',11'
set output png
set logscale x
set logscale y
set format x '10^{%L}'
set xlabel 'scale s of the scene'
set ylabel 'wrong pixels, of about 50,000 a scale (none: drawn at 0.5)'
set key top left
set yrange [0.5:*]
set title "990 scenes a machine made: six families, 0 to 1e6 from the origin, eyes near and far"
# Sums by scale (column 2) of the wrong pixels (8) in scenes warned (9 = 1) or not.
sum_by(file, warned) = sprintf("< awk -F, 'NR>1 && $9==%d {w[$2]+=$8} END {for (s in w) print s\",\"(w[s]>0?w[s]:0.5)}' %s | sort -g", warned, file)
plot sum_by(before, 0) using 1:2 with linespoints lw 2 pt 7 title 'before: wrong, no warning', \
     sum_by(after, 0) using 1:2 with linespoints lw 2 pt 5 title 'after: wrong, no warning', \
     sum_by(after, 1) using 1:2 with linespoints lw 1 pt 9 dt 2 title 'after: wrong, the kit warns'

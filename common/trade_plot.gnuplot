# Draws a chapter's trade table (common/trade.hpp's CSV) as cost against error, one labelled point
# per row, both axes logarithmic: the further down and left, the better the trade.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" -e "title='01_ray_casting'" common/trade_plot.gnuplot
set datafile separator ','
set terminal pngcairo size 900,600 noenhanced font ',10'
set output png
set title title
set xlabel 'seconds (median of the repeats)'
stats csv using 7 nooutput
set ylabel 'error (see the CSV: error_metric)'
set logscale x
if (STATS_min > 0) set logscale y
set grid
set key off
plot csv using 4:7 every ::1 with linespoints pt 7 ps 1.2, \
     csv using 4:7:3 every ::1 with labels offset char 1,0.6 left

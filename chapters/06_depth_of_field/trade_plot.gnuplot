# Chapter 06's trade: error against time as the lens samples per pixel grow, one labelled point per
# row, log-log (down and left is better). Columns are read by name: new ones may be appended.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/06_depth_of_field/trade_plot.gnuplot
set terminal pngcairo size 1280,720 enhanced font ',18' linewidth 2
set output png
# The header as one string (tab is not in the CSV), to ask which columns this run wrote.
set datafile separator "\t"
stats csv every ::0::0 using (header = ','.strcol(1).',', 0) nooutput
set datafile separator ','
set datafile columnheaders
has(name) = strstrt(header, ','.name.',') > 0
bars = has('seconds_min') && has('seconds_max')
stats csv using (metric = strcol('error_metric'), 0) nooutput
# rmse_linear_rgb_vs_1024spp: the reference's spp is in the name.
pre = 'rmse_linear_rgb_vs_'
spp = strstrt(metric, pre) == 1 ? metric[strlen(pre) + 1:strstrt(metric, 'spp') - 1] : ''
set title 'Chapter 06, depth of field: lens samples per pixel, cost against error' \
    font ',22' noenhanced
set xlabel 'render time, seconds (median of the runs'.(bars ? '; bars: fastest to slowest)' : ')')
set ylabel (spp ne '' ? "RMSE over linear RGB\nagainst a ".spp.'-spp reference' : metric) noenhanced
set logscale xy
set format x '%g'
set format y '%g'
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
# Tics at 1, 2 and 5 of each decade: the data spans too few decades for powers of ten alone.
do for [e = -9:9] {
  set xtics add (2 * 10.0**e, 5 * 10.0**e)
  set ytics add (2 * 10.0**e, 5 * 10.0**e)
}
set key off
samples(n) = n.(n eq '1' ? ' sample' : ' samples')
set autoscale fix
set offsets graph 0.06, graph 0.28, graph 0.12, graph 0.12
set style line 1 lc rgb '#0060ad' lw 2 pt 7 ps 2.2
# Without min/max columns (older runs) the bars' loop is empty; lo and hi just keep it valid.
lo = bars ? 'seconds_min' : 'seconds'
hi = bars ? 'seconds_max' : 'seconds'
plot csv using 'seconds':'error' with linespoints ls 1, \
     '' using 'seconds':'error':(samples(strcol('value'))) \
         with labels offset char 1.2, 0.9 left noenhanced, \
     for [i = 1:bars] '' using 'seconds':'error':(column(lo)):(column(hi)) \
         with xerrorbars ls 1 lw 1 ps 0

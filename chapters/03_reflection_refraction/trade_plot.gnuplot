# Chapter 03's trade, from the tables --sweep writes beside each other: error against time for the
# depth limit (X.csv) and the weight cut-off (X_weight.csv), each against the same deep reference,
# and the kit's default settings with either Fresnel reflectance (X_settings.csv) as two marked
# points; log-log (down and left is better). The reference's own row has no error, so no point.
# The Schlick table (X_schlick.csv) has another metric and stays in its CSV.
# Columns are read by name: new ones may be appended.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/03_reflection_refraction/trade_plot.gnuplot
set terminal pngcairo size 1280,720 enhanced font ',18' linewidth 2
set output png
base = csv[1:strlen(csv) - 4]
weight = base.'_weight.csv'
settings = base.'_settings.csv'
# The header as one string (tab is not in the CSV), to ask which columns this run wrote.
set datafile separator "\t"
stats csv every ::0::0 using (header = ','.strcol(1).',', 0) nooutput
set datafile separator ','
set datafile columnheaders
has(name) = strstrt(header, ','.name.',') > 0
# A filter returns NaN for the rows it skips: as missing data, they do not break a line.
set datafile missing NaN
stats csv using (metric = strcol('error_metric'), 0) nooutput
# rmse_linear_rgb_vs_depth_32_no_cutoff: the reference is in the name.
pre = 'rmse_linear_rgb_vs_depth_'
depth = strstrt(metric, pre) == 1 ? metric[strlen(pre) + 1:strstrt(metric, '_no_cutoff') - 1] : ''
bars = has('seconds_min') && has('seconds_max')
set title 'Chapter 03, reflection and refraction: when to stop the recursion' \
    font ',22' noenhanced
set xlabel 'render time, seconds (median of the runs'.(bars ? '; bars: fastest to slowest)' : ')')
set ylabel noenhanced (depth ne '' \
    ? "RMSE over linear RGB against depth ".depth."\nand no weight cut-off" : metric)
set logscale xy
set format x '%g'
set format y '10^{%T}'
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
# More tics on x than powers of ten: the times span less than a decade.
do for [e = -9:9] {
  set xtics add (1.5 * 10.0**e, 2 * 10.0**e, 3 * 10.0**e, 4 * 10.0**e, 5 * 10.0**e)
}
set key top right spacing 1.3
set autoscale fix
set offsets graph 0.04, graph 0.07, graph 0.08, graph 0.08
set style line 1 lc rgb '#0060ad' lw 2 pt 7 ps 1.8
set style line 2 lc rgb '#d95f02' lw 2 pt 5 ps 1.8
set style line 3 lc rgb '#1b9e77' lw 2 pt 13 ps 3
set style line 4 lc rgb '#7570b3' lw 2 pt 11 ps 3
# Zero error (the reference's own row) has no place on a log axis.
positive(name) = column(name) > 0 ? column(name) : NaN
is(s) = strcol('value') eq s ? positive('error') : NaN
# Without min/max columns (older runs) the bars' loop is empty; lo and hi just keep it valid.
lo = bars ? 'seconds_min' : 'seconds'
hi = bars ? 'seconds_max' : 'seconds'
plot csv using 'seconds':(positive('error')) with linespoints ls 1 \
         title 'depth limit, no weight cut-off (label: depth)', \
     '' using 'seconds':(positive('error')):'value' \
         with labels offset char 0.9, 0.8 left notitle noenhanced, \
     weight using 'seconds':(positive('error')) with linespoints ls 2 \
         title 'weight cut-off at depth '.depth.' (label: least weight)', \
     '' using 'seconds':(positive('error')):'value' \
         with labels offset char -0.9, -0.8 right notitle noenhanced, \
     settings using 'seconds':(is('default_exact')) with points ls 3 \
         title 'kit defaults, exact Fresnel', \
     '' using 'seconds':(is('default_schlick')) with points ls 4 title 'kit defaults, Schlick', \
     for [i = 1:bars] csv using 'seconds':(positive('error')):(column(lo)):(column(hi)) \
         with xerrorbars ls 1 lw 1 ps 0 notitle, \
     for [i = 1:bars] weight using 'seconds':(positive('error')):(column(lo)):(column(hi)) \
         with xerrorbars ls 2 lw 1 ps 0 notitle, \
     for [i = 1:bars] settings using 'seconds':(positive('error')):(column(lo)):(column(hi)) \
         with xerrorbars lc 'black' lw 1 ps 0 notitle

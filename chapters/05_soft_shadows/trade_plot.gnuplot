# Chapter 05's trade: error against time as the shadow samples per light grow, one line per sampling
# scheme (the value column is scheme:samples), log-log (down and left is better). Columns are read
# by name: new ones may be appended.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/05_soft_shadows/trade_plot.gnuplot
set terminal pngcairo size 1280,720 enhanced font ',18' linewidth 2
set output png
# The header as one string (tab is not in the CSV), to ask which columns this run wrote.
set datafile separator "\t"
stats csv every ::0::0 using (header = ','.strcol(1).',', 0) nooutput
set datafile separator ','
set datafile columnheaders
has(name) = strstrt(header, ','.name.',') > 0
bars = has('seconds_min') && has('seconds_max')
# A series' filter returns NaN for other rows: as missing data, they do not break its line.
set datafile missing NaN
scheme(v) = v[1:strstrt(v, ':') - 1]
samples(v) = v[strstrt(v, ':') + 1:]
add(list, w) = strstrt(' '.list.' ', ' '.w.' ') ? list : list.' '.w
schemes = ''
stats csv using (schemes = add(schemes, scheme(strcol('value'))), \
    metric = strcol('error_metric'), 0) nooutput
# rmse_linear_rgb_vs_4096_stratified_samples_per_light: the reference is in the name.
pre = 'rmse_linear_rgb_vs_'
spaced(s) = strstrt(s, '_') ? s[1:strstrt(s, '_') - 1].' '.spaced(s[strstrt(s, '_') + 1:]) : s
set title 'Chapter 05, soft shadows: samples per light, cost against error' font ',22' noenhanced
set xlabel 'render time, seconds (median of the runs'.(bars ? '; bars: fastest to slowest)' : ')')
set ylabel noenhanced (strstrt(metric, pre) == 1 \
    ? "RMSE over linear RGB against\n".spaced(metric[strlen(pre) + 1:]) : metric)
set logscale xy
set format x '%g'
set format y '%g'
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
# Tics at 1, 2 and 5 of each decade: the data spans too few decades for powers of ten alone.
do for [e = -9:9] {
  set xtics add (2 * 10.0**e, 5 * 10.0**e)
  set ytics add (2 * 10.0**e, 5 * 10.0**e)
}
set key top right spacing 1.3 title 'point labels: samples per light'
set autoscale fix
set offsets graph 0.06, graph 0.06, graph 0.12, graph 0.12
set style line 1 lc rgb '#d95f02' lw 2 pt 5 ps 2
set style line 2 lc rgb '#0060ad' lw 2 pt 7 ps 2.2
set style line 3 lc rgb '#1b9e77' lw 2 pt 9 ps 2.2
# Without min/max columns (older runs) the bars' loop is empty; lo and hi just keep it valid.
lo = bars ? 'seconds_min' : 'seconds'
hi = bars ? 'seconds_max' : 'seconds'
pick(i, name) = scheme(strcol('value')) eq word(schemes, i) ? column(name) : NaN
n = words(schemes)
# The first scheme's labels go above its points, the next's below: at 1 sample they coincide.
plot for [i = 1:n] csv using 'seconds':(pick(i, 'error')) \
         with linespoints ls i title word(schemes, i), \
     for [i = 1:n] csv using 'seconds':(pick(i, 'error')):(samples(strcol('value'))) \
         with labels offset char (i == 1 ? -0.8 : 0.8), (i == 1 ? 1.0 : -1.0) notitle noenhanced, \
     for [i = 1:n * bars] csv using 'seconds':(pick(i, 'error')):(column(lo)):(column(hi)) \
         with xerrorbars ls i lw 1 ps 0 notitle

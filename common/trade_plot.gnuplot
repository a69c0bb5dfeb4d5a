# Draws a chapter's trade table (common/trade.hpp's CSV) as cost against error, one labelled point
# per row, log-log: the further down and left, the better the trade. The default for a chapter
# without its own chapters/NN_name/trade_plot.gnuplot, so its words come from the table (knob,
# error_metric) and from the title, a folder name such as 01_ray_casting. A knob such as
# scheme:samples draws one line per scheme, labelled by samples. Columns are read by name: new
# ones may be appended.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" -e "title='01_ray_casting'" common/trade_plot.gnuplot
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
spaced(s) = strstrt(s, '_') ? s[1:strstrt(s, '_') - 1].' '.spaced(s[strstrt(s, '_') + 1:]) : s
head(v) = strstrt(v, ':') ? v[1:strstrt(v, ':') - 1] : ''
tail(v) = v[strstrt(v, ':') + 1:]
add(list, w) = strstrt(' '.list.' ', ' '.w.' ') ? list : list.' '.w
series = ''
stats csv using (series = add(series, head(strcol('value'))), knob = strcol('knob'), \
    metric = strcol('error_metric'), 0) nooutput
n = words(series)
pre = 'rmse_linear_rgb_vs_'
words_of(m) = strstrt(m, pre) == 1 \
    ? "RMSE over linear RGB against\n".spaced(m[strlen(pre) + 1:]) : spaced(m)
# 01_ray_casting: Chapter 01, ray casting.
named = strstrt(title, '_') == 3 ? 'Chapter '.title[1:2].', '.spaced(title[4:]) : title
set title named.': '.spaced(tail(knob)).', cost against error' font ',22' noenhanced
set xlabel 'render time, seconds (median of the runs'.(bars ? '; bars: fastest to slowest)' : ')')
set ylabel words_of(metric) noenhanced
set logscale xy
set format x '%g'
set format y '%g'
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
# Tics at 1, 2 and 5 of each decade: a sweep often spans too few decades for powers of ten alone.
do for [e = -9:9] {
  set xtics add (2 * 10.0**e, 5 * 10.0**e)
  set ytics add (2 * 10.0**e, 5 * 10.0**e)
}
set key top right spacing 1.3 noenhanced
set autoscale fix
set offsets graph 0.06, graph 0.2, graph 0.12, graph 0.12
set style line 1 lc rgb '#0060ad' lw 2 pt 7 ps 2.2
set style line 2 lc rgb '#d95f02' lw 2 pt 5 ps 2
set style line 3 lc rgb '#1b9e77' lw 2 pt 9 ps 2.2
set style line 4 lc rgb '#7570b3' lw 2 pt 13 ps 2.2
# Values without a scheme: prefix make one series of every row.
pick(i, name) = n == 0 || head(strcol('value')) eq word(series, i) ? column(name) : NaN
label(v) = strstrt(v, ':') ? tail(v) : v
# Without min/max columns (older runs) the bars' loop is empty; lo and hi just keep it valid.
lo = bars ? 'seconds_min' : 'seconds'
hi = bars ? 'seconds_max' : 'seconds'
lines = n > 0 ? n : 1
plot for [i = 1:lines] csv using 'seconds':(pick(i, 'error')) with linespoints ls i \
         title (n > 1 ? word(series, i) : ''), \
     for [i = 1:lines] csv using 'seconds':(pick(i, 'error')):(label(strcol('value'))) \
         with labels offset char 1.2, (i % 2 ? 0.9 : -0.9) left notitle noenhanced, \
     for [i = 1:lines * bars] csv using 'seconds':(pick(i, 'error')):(column(lo)):(column(hi)) \
         with xerrorbars ls i lw 1 ps 0 notitle

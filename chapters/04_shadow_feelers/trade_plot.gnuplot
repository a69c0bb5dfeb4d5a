# Chapter 04's trade is by scene scale: the feelers that re-hit their own surface (left) and the
# real occluders 0.25 S above it that they miss (right, X_missed.csv), per offset method, for the
# sweep's first configuration (triangles, front side, hit point on the surface, eye 3 S away); the
# other configurations and the cost table (X_cost.csv) stay in the CSVs. Rows are found by their
# value (surface:side:point:eye:offset:scale) and columns by name, never by position.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/04_shadow_feelers/trade_plot.gnuplot
set terminal pngcairo size 1280,720 enhanced font ',18' linewidth 2
set output png
missed = csv[1:strlen(csv) - 4].'_missed.csv'
set datafile separator ','
set datafile columnheaders
# A filter returns NaN for the rows it skips: as missing data, they do not break a line.
set datafile missing NaN
last(s) = strstrt(s, ':') ? last(s[strstrt(s, ':') + 1:]) : s
configuration = 'triangles:front:surface:3S'
# Wachter-Binder first, under the others: it stays at 0%, where they often are too.
methods = 'robust none t-min normal'
name(m) = m eq 'none' ? 'no offset' : m eq 't-min' ? 't_{min} = 10^{-4}' \
    : m eq 'normal' ? 'p + 10^{-4} n' : m eq 'robust' ? 'Wachter-Binder' : m
# gnuplot reads '1e-4' as a number in data but not from a string: mantissa and exponent apart.
number(s) = strstrt(s, 'e') \
    ? (s[1:strstrt(s, 'e') - 1] + 0.0) * 10.0**(s[strstrt(s, 'e') + 1:] + 0) : s + 0.0
is(m) = (v = strcol('value'), v eq configuration.':'.m.':'.last(v))
scale(m) = is(m) ? number(last(strcol('value'))) : NaN
set style line 1 lc rgb '#1b9e77' lw 5 pt 13 ps 2.2 dt 1
set style line 2 lc rgb '#d95f02' lw 2 pt 7 ps 2 dt 1
set style line 3 lc rgb '#7570b3' lw 2 pt 5 ps 1.8 dt 2
set style line 4 lc rgb '#e7298a' lw 2 pt 9 ps 2.2 dt 4
heading = "Chapter 04, shadow feelers: offsets against the scene's scale S\n" \
    .'{/*0.8 (triangles of a sphere, eye 3 S away)}'
set multiplot title heading font ',22'
set logscale x
set format x '10^{%T}'
set xrange [3e-5:3e6]
set yrange [-3:105]
set ytics 0, 25, 100
set format y '%g%%'
set xlabel 'scene scale S'
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
set tmargin at screen 0.8
set bmargin at screen 0.14
set lmargin at screen 0.09
set rmargin at screen 0.49
set title 'feelers that re-hit their own surface'
set key top left reverse Left samplen 3 spacing 1.1 opaque
plot for [i = 1:words(methods)] csv using (scale(word(methods, i))):(100 * column('error')) \
    with linespoints ls i title name(word(methods, i))
set lmargin at screen 0.58
set rmargin at screen 0.98
set title 'occluders 0.25 S above the surface missed'
set key off
plot for [i = 1:words(methods)] missed using (scale(word(methods, i))):(100 * column('error')) \
    with linespoints ls i notitle
unset multiplot

# Chapter 02's trade is a table of cases, not a curve: the wrong hit/miss answers of each test in
# float (solid bars) and double (pale bars) on each extreme case, spheres left, triangles right, on
# a log axis (no bar: no wrong answer); each test's legend entry gives its cost, the median time
# per test over the cases. Rows are found by their value (group:case:test:precision) and columns
# by name, never by position. The t-error table (X_t_error.csv) stays in its CSV.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/02_spheres_triangles/trade_plot.gnuplot
set terminal pngcairo size 1280,720 enhanced font ',16' linewidth 2
set output png
set datafile separator ','
set datafile columnheaders
# A filter returns NaN for the rows it skips: as missing data, they are dropped.
set datafile missing NaN
field(s, n) = n <= 1 ? (strstrt(s, ':') ? s[1:strstrt(s, ':') - 1] : s) \
    : field(s[strstrt(s, ':') + 1:], n - 1)
add(list, w) = strstrt(' '.list.' ', ' '.w.' ') ? list : list.' '.w
position(list, w) = sum [k = 1:words(list)] (word(list, k) eq w ? k : 0)
# Tick labels: D=1e3 as D=10^3; vertex-aimed on two lines, inside-far-mesh as inside / far mesh.
power(c) = c[1:strstrt(c, '=1e')].'10^{'.c[strstrt(c, '=1e') + 3:].'}'
spaces(c) = strstrt(c, '-') ? c[1:strstrt(c, '-') - 1].' '.spaces(c[strstrt(c, '-') + 1:]) : c
lines(c) = strstrt(c, '-') ? c[1:strstrt(c, '-') - 1]."\n".spaces(c[strstrt(c, '-') + 1:]) : c
tick(c) = strstrt(c, '=1e') ? power(c) : lines(c)
name(t) = t eq 'moller-trumbore' ? 'Moller-Trumbore' : t eq 'slide' ? "slide's" : t
colour(t) = t eq 'slide' ? 0xd95f02 : t eq 'precise' ? 0x0060ad \
    : t eq 'moller-trumbore' ? 0x7570b3 : 0x1b9e77
is(g, t, p) = (v = strcol('value'), field(v, 1) eq g && field(v, 3) eq t && field(v, 4) eq p)
stats csv using (metric = strcol('error_metric'), 0) nooutput
known = 'fraction of wrong hit/miss answers against long double'
heading = 'Chapter 02, spheres and triangles: which tests go wrong where, and at what cost'
set multiplot title heading font ',20'
set grid ytics lc rgb '#b8b8b8' lw 0.75 dt 2
set xtics scale 0 nomirror font ',14'
set key vertical maxrows 3 samplen 1.5 spacing 1.1 left top Left reverse
set style fill solid 1.0 border -1
set tmargin at screen 0.83
set bmargin at screen 0.31
do for [g in 'sphere triangle'] {
  set autoscale
  unset logscale
  cases = ''
  tests = ''
  precisions = ''
  stats csv using (v = strcol('value'), field(v, 1) eq g ? (cases = add(cases, field(v, 2)), \
      tests = add(tests, field(v, 3)), precisions = add(precisions, field(v, 4)), 0) : 0) nooutput
  n = words(tests) * words(precisions)
  slot(i, j) = (i - 1) * words(precisions) + j
  array ns[n]
  do for [i = 1:words(tests)] {
    do for [j = 1:words(precisions)] {
      stats csv using (is(g, word(tests, i), word(precisions, j)) \
          ? 1e9 * column('seconds') / column('rays') : NaN) nooutput
      ns[slot(i, j)] = STATS_median
    }
  }
  set logscale y
  set yrange [5e-4:100]
  set format y '%g%%'
  set xtics ()
  do for [k = 1:words(cases)] { set xtics add (tick(word(cases, k)) k) }
  set xrange [0.5:words(cases) + 0.5]
  width = 0.85 / n
  set boxwidth width * 0.9
  if (g eq 'sphere') {
    set title 'spheres' font ',18'
    set xlabel "D: a unit sphere's distance; r: the radius of one at distance 1" font ',14'
    set ylabel noenhanced (metric eq known \
        ? "wrong hit/miss answers against\nlong double, percent of the rays" : metric.', percent')
    set lmargin at screen 0.12
    set rmargin at screen 0.635
    set key at screen 0.12, screen 0.185
  } else {
    set title 'triangles' font ',18'
    unset xlabel
    # The same axis as the spheres': its labels once are enough, leaving room for the cases.
    unset ylabel
    set format y ''
    set lmargin at screen 0.65
    set rmargin at screen 0.985
    set key at screen 0.65, screen 0.185
    set label 1 'solid bars: float, pale bars: double; no bar: no wrong answer; ' \
        .'time: median per test, float / double' at screen 0.5, screen 0.04 center
  }
  x(i, j) = position(cases, field(strcol('value'), 2)) + (slot(i, j) - (n + 1) / 2.0) * width
  # Zero goes far below the axis rather than missing, so that a test never wrong keeps its key.
  y(i, j) = is(g, word(tests, i), word(precisions, j)) \
      ? (column('error') > 0 ? 100 * column('error') : 1e-9) : NaN
  title(i) = name(word(tests, i)).': '.sprintf('%.1f', ns[slot(i, 1)]) \
      .(words(precisions) > 1 ? sprintf(' / %.1f', ns[slot(i, 2)]) : '').' ns'
  plot for [i = 1:words(tests)] for [j = 1:words(precisions)] csv using (x(i, j)):(y(i, j)) \
      with boxes lc rgb colour(word(tests, i)) fs solid (j == 1 ? 1.0 : 0.3) \
      title (j == 1 ? title(i) : '')
}
unset multiplot

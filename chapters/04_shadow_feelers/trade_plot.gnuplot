# Chapter 04's trade is by scene scale: the fraction of shadow feelers that re-hit their own
# surface (left) and of real occluders 0.25 S above it that they miss (right), per offset method,
# for the first configuration the sweep measures (triangles, front side, hit point on the surface,
# eye 3 S away). Rows as main.cpp writes them: data rows 1-44, the offset method varying fastest
# (none, t-min, normal, robust), the scale from 1e-4 to 1e6 slowest; other configurations stay in
# the CSVs.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" -e "title='04_shadow_feelers'" trade_plot.gnuplot
set datafile separator ','
set terminal pngcairo size 1200,500 noenhanced font ',10'
set output png
missed = csv[1:strlen(csv) - 4].'_missed.csv'
set multiplot layout 1,2 title title.': offsets against scale (triangles, eye 3 S away)'
set logscale x
set xrange [5e-5:2e6]
set yrange [-0.02:1.02]
set format x '1e%T'
set xlabel 'scene scale S'
set grid
set key top left
scale(k) = 10.0 ** (k - 4)
set title 'feelers re-hitting their own surface'
plot csv every 4::1::44 using (scale($0)):7 with linespoints pt 7 title 'no offset', \
     csv every 4::2::44 using (scale($0)):7 with linespoints pt 5 title 't_min = 1e-4', \
     csv every 4::3::44 using (scale($0)):7 with linespoints pt 9 title 'p + 1e-4 n', \
     csv every 4::4::44 using (scale($0)):7 with linespoints pt 11 lw 2 title 'Wachter-Binder'
set title 'occluders 0.25 S above the surface missed'
plot missed every 4::1::44 using (scale($0)):7 with linespoints pt 7 title 'no offset', \
     missed every 4::2::44 using (scale($0)):7 with linespoints pt 5 title 't_min = 1e-4', \
     missed every 4::3::44 using (scale($0)):7 with linespoints pt 9 title 'p + 1e-4 n', \
     missed every 4::4::44 using (scale($0)):7 with linespoints pt 11 lw 2 title 'Wachter-Binder'
unset multiplot

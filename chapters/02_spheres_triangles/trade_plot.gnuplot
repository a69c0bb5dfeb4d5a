# Chapter 02's trade is a table of cases, not a curve: wrong hit/miss answers (in percent, on a log
# axis where 0.0001 stands for none) of each float test on each extreme case, spheres left,
# triangles right. Rows as main.cpp's sweep writes them: spheres in float are data rows 1-18,
# triangles in float 37-51. The double rows stay in the CSV.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" -e "title='02_spheres_triangles'" trade_plot.gnuplot
set datafile separator ','
set terminal pngcairo size 1200,560 noenhanced font ',9'
set output png
set multiplot layout 1,2 title title.": wrong hit/miss answers in float (0.0001% means none)"
set logscale y
set yrange [5e-5:100]
set ylabel 'wrong answers, percent'
set grid ytics
set key off
set xtics rotate by -60 scale 0
set bmargin 12
set style fill solid 0.8
set boxwidth 0.7
set title 'spheres: slide and precise forms'
plot csv every ::1::18 using 0:($7 * 100 + 1e-4):xticlabels(3) with boxes
set title 'triangles: slide, Moller-Trumbore, watertight'
plot csv every ::37::51 using 0:($7 * 100 + 1e-4):xticlabels(3) with boxes
unset multiplot

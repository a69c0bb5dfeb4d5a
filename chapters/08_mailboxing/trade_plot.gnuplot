# Chapter 08's trade, from the table --sweep writes (one row per scene, density and ray kind):
# the tests and the time the mailboxes save against the cells an object is listed in.
# Columns: scene, objects, lambda, references_per_object, kind, count, tests_per_ray_grid,
# tests_per_ray_mailboxes, tests_saved_percent, ms_grid, ms_mailboxes, time_saved_percent.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" -e "title='08_mailboxing'" trade_plot.gnuplot
set datafile separator ','
set terminal pngcairo size 900,600 noenhanced font ',10'
set output png
set title title.': what the mailboxes save, every scene, density and kind of ray'
set xlabel 'references per object (cells an object is listed in)'
set ylabel 'saved (percent)'
set logscale x
set grid
set key top left
plot csv every ::1 using 4:9 with points pt 7 title 'tests saved', \
     csv every ::1 using 4:12 with points pt 5 title 'time saved'

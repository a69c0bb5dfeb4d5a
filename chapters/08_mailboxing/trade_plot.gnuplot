# Chapter 08's trade, from the table --sweep writes (one row per scene, density and kind of ray):
# the tests and the time the mailboxes save against the cells an object is listed in, one colour
# per scene. Columns are read by name, never by position.
# gnuplot -e "csv='in.csv'" -e "png='out.png'" chapters/08_mailboxing/trade_plot.gnuplot
set terminal pngcairo size 1280,720 enhanced font ',18' linewidth 2
set output png
set datafile separator ','
set datafile columnheaders
set datafile missing NaN
# gnuplot's strcol stops at a comma even inside quotes: "sticks, depth 5" reads as sticks, enough
# to tell the scenes apart.
add(list, w) = strstrt(' '.list.' ', ' '.w.' ') ? list : list.' '.w
scenes = ''
stats csv using (scenes = add(scenes, strcol('scene')), 0) nooutput
on(s, name) = strcol('scene') eq s ? column(name) : NaN
array objects[words(scenes)]
do for [i = 1:words(scenes)] {
  stats csv using (on(word(scenes, i), 'objects')) nooutput
  objects[i] = STATS_max
}
colour(i) = word('#d95f02 #0060ad #1b9e77 #7570b3 #e7298a #666666', (i - 1) % 6 + 1)
set title "Chapter 08, mailboxing: what the mailboxes save\n{/*0.75 each scene at several grid " \
    .'densities; at each, primary, shadow and secondary rays}' font ',22'
set xlabel 'references per object (cells an object is listed in)'
set ylabel 'saved against the grid alone, percent'
set logscale x
set format x '%g'
do for [e = -9:9] { set xtics add (2 * 10.0**e, 5 * 10.0**e) }
set format y '%g%%'
set grid lc rgb '#b8b8b8' lw 0.75 dt 2
set autoscale xfix
set offsets graph 0.05, graph 0.05, 0, 0
set key top left reverse Left spacing 1.2 samplen 1
set xzeroaxis lt -1 lw 1
n = words(scenes)
plot for [i = 1:n] csv using 'references_per_object':(on(word(scenes, i), 'tests_saved_percent')) \
         with points pt 7 ps 2.2 lc rgb colour(i) \
         title sprintf('%s, %d objects', word(scenes, i), objects[i]), \
     for [i = 1:n] csv using 'references_per_object':(on(word(scenes, i), 'time_saved_percent')) \
         with points pt 6 ps 2.2 lw 2 lc rgb colour(i) notitle, \
     NaN with points pt 7 ps 2.2 lc 'black' title 'tests saved', \
     NaN with points pt 6 ps 2.2 lw 2 lc 'black' title 'time saved'

# gnuplot script written by efbench report: gnuplot bench/results/fig6_640x480.gp
set terminal pngcairo size 1500,640 font 'DejaVu Sans,10' noenhanced
set output 'bench/results/fig6_640x480.png'
set title 'Time relative to edgeflag 8x at 640x480 (log scale; below 100%: faster than edgeflag 8x)'
set datafile missing 'NaN'
set logscale y 2
set ylabel 'time relative to edgeflag 8x (%)'
set format y '%g%%'
set grid ytics
set key outside right top
set xtics rotate by -60 left font ',8' nomirror
set xrange [-1:38]
set bmargin 9
set arrow from graph 0, first 100 to graph 1, first 100 nohead lw 2 lc rgb 'black'
set arrow from 17.5, graph 0 to 17.5, graph 1 nohead dt 2 lc rgb 'gray40'
set label 'real-life (illustrations, text)' at 8.5, graph 0.97 center
set label "the paper's synthetic tests" at 27.5, graph 0.97 center
plot 'bench/results/fig6_640x480.dat' using 1:3:xtic(2) with points pt 4 ps 1.4 title 'agg', \
     'bench/results/fig6_640x480.dat' using 1:4:xtic(2) with points pt 5 ps 1.4 title 'cairo', \
     'bench/results/fig6_640x480.dat' using 1:5:xtic(2) with points pt 6 ps 1.4 title 'cairo-noaa', \
     'bench/results/fig6_640x480.dat' using 1:6:xtic(2) with points pt 7 ps 1.4 title 'freetype', \
     'bench/results/fig6_640x480.dat' using 1:7:xtic(2) with points pt 8 ps 1.4 title 'stb', \
     'bench/results/fig6_640x480.dat' using 1:9:xtic(2) with points pt 9 ps 1.4 title 'ef16', \
     'bench/results/fig6_640x480.dat' using 1:10:xtic(2) with points pt 10 ps 1.4 title 'ef32', \
     'bench/results/fig6_640x480.dat' using 1:11:xtic(2) with points pt 11 ps 1.4 title 'ef8t', \
     'bench/results/fig6_640x480.dat' using 1:12:xtic(2) with points pt 12 ps 1.4 title 'ef16t', \
     'bench/results/fig6_640x480.dat' using 1:13:xtic(2) with points pt 13 ps 1.4 title 'ef32t', \
     'bench/results/fig6_640x480.dat' using 1:14:xtic(2) with points pt 14 ps 1.4 title 'ef16rgb', \
     'bench/results/fig6_640x480.dat' using 1:15:xtic(2) with points pt 15 ps 1.4 title 'ef16trgb'

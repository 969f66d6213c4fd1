set terminal pngcairo size 900,600 enhanced font 'sans,11'
set output 'fig52.png'
set title 'ms against N, averaged over r (thesis figure 5.2), 800x600'
set xlabel 'N'
set ylabel 'ms'
set grid
set key outside right top noenhanced
set logscale y
plot 'fig52.dat' index 0 using 1:2 with linespoints lw 2 dt 1 lc 1 title columnheader(1), 'fig52.dat' index 1 using 1:2 with linespoints lw 2 dt 1 lc 2 title columnheader(1), 'fig52.dat' index 2 using 1:2 with linespoints lw 2 dt 1 lc 3 title columnheader(1), 'fig52.dat' index 3 using 1:2 with linespoints lw 2 dt 1 lc 4 title columnheader(1), 'fig52.dat' index 4 using 1:2 with linespoints lw 2 dt 2 lc 1 title columnheader(1), 'fig52.dat' index 5 using 1:2 with linespoints lw 2 dt 2 lc 2 title columnheader(1), 'fig52.dat' index 6 using 1:2 with linespoints lw 2 dt 2 lc 3 title columnheader(1), 'fig52.dat' index 7 using 1:2 with linespoints lw 2 dt 2 lc 4 title columnheader(1)

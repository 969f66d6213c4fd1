set terminal pngcairo size 900,600 enhanced font 'sans,11'
set output 'bench_ms.png.tmp'
set title "graphs/ssao.graph: ms against k.count" noenhanced
set grid
set key outside right top noenhanced
set xlabel "k.count" noenhanced
set ylabel "ms (ao)" noenhanced
plot for [i=0:2] 'bench_ms.dat' index i using 1:2 with linespoints lw 2 pt 7 title columnheader(1)

# phong-plots.gp - the lecture's "Phong model - plots": (cos alpha)^p for exponents 1 to 1000.
# Run by `make figures` as: gnuplot -e "output='FILE.png'; build='BUILD'" phong-plots.gp
set terminal pngcairo size 1100,520 font "sans,12"
set output output
set title "Blinn-Phong: increasing p narrows the peak of (n . h)^p = (cos alpha)^p"
set xlabel "alpha, the angle between n and h (degrees)"
set ylabel "(cos alpha)^p (fraction of the peak, no unit)"
set xrange [-90:90]
set yrange [0:1.05]
set xtics 15
set samples 2001
set key top right box opaque
set grid
c(a) = cos(a * pi / 180)
plot c(x)**1 title "p = 1" lw 2, \
     c(x)**5 title "p = 5" lw 2, \
     c(x)**10 title "p = 10" lw 2, \
     c(x)**50 title "p = 50" lw 2, \
     c(x)**100 title "p = 100" lw 2, \
     c(x)**1000 title "p = 1000" lw 2

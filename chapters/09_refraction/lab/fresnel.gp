# fresnel.gp - chapter 09's Fresnel plot: R against the angle of incidence, into and out of glass.
# Run by `make figures` as: gnuplot -e "output='FILE.png'; build='BUILD'" fresnel.gp
# Its data: `lab --fresnel-table` of the double build of chapter 09's lab (fresnel_table.h), columns
# angle in_exact in_schlick out_exact out_schlick out_schlick_cos_i.
set terminal pngcairo size 1100,500 font "sans,10"
set output output
data = sprintf("< %s/09_refraction/lab --fresnel-table", build)
theta_c = asin(1 / 1.5) * 180 / pi
set grid lc rgb "#dddddd"
set ylabel "reflectance R (fraction of the power reflected)"
set xlabel "angle of incidence {/Symbol q}_i (degrees from the normal, incoming side)"
set arrow 1 from theta_c, 0 to theta_c, 1.02 nohead dt 3 lc rgb "#888888"
set multiplot layout 1, 2 title "Glass of index 1.5: Fresnel's equations (exact) and Schlick's approximation"
set xrange [0:90]
set yrange [0:1.02]
set xtics 10
set ytics 0.1
# the keys go where no curve is: right of the critical angle and above the curve into glass here, top
# left in the close-up, so that the steep rise near the critical angle stays in view
set key at 44, 0.95 left top box opaque samplen 2
set label 1 sprintf("critical angle %.1f°", theta_c) at theta_c + 1, 0.55 tc rgb "#555555"
set title "0° to 90° (in: into glass; out: out of glass)"
plot data using 1:2 with lines lw 2 lc rgb "#1f5fa8" title "in (1 → 1.5), exact", \
     data using 1:3 with lines lw 2 dt 2 lc rgb "#1f5fa8" title "in, Schlick", \
     data using 1:4 with lines lw 2 lc rgb "#c0392b" title "out (1.5 → 1), exact", \
     data using 1:5 with lines lw 2 dt 2 lc rgb "#c0392b" title "out, Schlick in cos {/Symbol q}_t", \
     data using 1:6 with lines lw 2 dt 4 lc rgb "#27ae60" title "out, Schlick in cos {/Symbol q}_i"
set title "out of glass, near the critical angle"
set xrange [30:45]
set xtics 2
unset label 1
set key at 30.3, 0.97 left top box opaque
plot data using 1:4 with lines lw 2 lc rgb "#c0392b" title "exact", \
     data using 1:5 with lines lw 2 dt 2 lc rgb "#c0392b" title "Schlick in cos {/Symbol q}_t", \
     data using 1:6 with lines lw 2 dt 4 lc rgb "#27ae60" title "Schlick in cos {/Symbol q}_i (jumps)"
unset multiplot

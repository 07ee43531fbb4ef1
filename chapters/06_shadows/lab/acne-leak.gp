# acne-leak.gp - the acne and leak table of chapter 06's lab as a plot.
# Run by `make figures` as: gnuplot -e "output='FILE.png'; build='BUILD'" acne-leak.gp
# Its data: `lab --acne-table` of the double and the float build of chapter 06,
# lines "build policy shape scale acne% leak%".
set terminal pngcairo size 1100,800 font "sans,10"
set output output
data = sprintf("< %s/06_shadows/lab --acne-table; %s-float/06_shadows/lab --acne-table", build, build)

# one row per (policy, build): none, fixed, bound from the top, double above float
row(p, b) = (p eq "none" ? 2 : p eq "fixed" ? 1 : 0) * 2 + (b eq "double" ? 1 : 0)
col(s) = log10(s) / 2 + 2   # 1e-4 .. 1e4 -> 0 .. 4
# the cell's column on the lines of shape sh, NaN (not drawn) elsewhere
x(sh) = strcol(3) eq sh ? col($4) : NaN

set multiplot layout 2, 2
set xrange [-0.5:4.5]
set yrange [-0.5:5.5]
set xtics ("1e-4" 0, "1e-2" 1, "1" 2, "1e2" 3, "1e4" 4)
set ytics ("bound, float" 0, "bound, double" 1, "fixed, float" 2, "fixed, double" 3, "none, float" 4, "none, double" 5)
set xlabel "scene scale s (world units: the square's side, the sphere's diameter)"
set cbrange [0:100]
set palette defined (0 "#f4f4f4", 0.5 "#f6c9a8", 50 "#e07040", 100 "#b03018")
unset key
set tics nomirror
do for [shape in "square sphere"] {
    set title sprintf("%s, acne: %% of points in shadow with nothing between them and the light", shape)
    set cblabel "acne: % of the shape's points in shadow"
    plot data using (x(shape)):(row(strcol(2), strcol(1))):(0.5):(0.5):5 \
             with boxxyerror fc palette fs solid noborder, \
         data using (x(shape)):(row(strcol(2), strcol(1))):(sprintf("%.1f", $5)) with labels
    set title sprintf("%s, leaks: %% of points lit through an occluder 1e-4 s away", shape)
    set cblabel "leaks: % of the shape's points lit"
    plot data using (x(shape)):(row(strcol(2), strcol(1))):(0.5):(0.5):6 \
             with boxxyerror fc palette fs solid noborder, \
         data using (x(shape)):(row(strcol(2), strcol(1))):(sprintf("%.1f", $6)) with labels
}
unset multiplot

# plots.sh - the figures of bench/bench.sh (sourced): gnuplot, PNG, into docs/figures/bench_*.png.
#
#   bench_knobs_NN.png   chapter NN's knobs: time against error, one point per setting
#   bench_knobs_all.png  samples per pixel and precision, in the latest chapter (threads: bench_scaling)
#   bench_growth.png     time per ray against triangles, log-log, with the fitted slopes
#   bench_scaling.png    time against image size and samples per pixel; thread speed-up
#   bench_stages.png     the scene of all stages, rendered by every chapter (tools/panels), in one row;
#   bench_stages_2rows.png  the same in two rows, for a slide

rm -f "$figures"/bench_*.png
plot_term='set terminal pngcairo size 900,600 font "sans,12" noenhanced'

# knob_plot OUT TITLE DATA: DATA lines are "X Y LABEL DEFAULT SCENE KNOB" (X the time relative to the
# default, Y the RMSE against the reference setting; SCENE 0: built-in, 1: scene of all stages; KNOB the
# panel), in the order of the knob's values.  One panel per knob, side by side, each point labelled with
# its value and the points of a scene joined in that order; the default settings get an open square.
# The error axis is logarithmic: a setting that gives the reference image exactly (RMSE 0) sits on the
# bottom line, "0 (exact)".  Settings that failed ("-") are left out.  bench/labels.awk places the
# labels so that none covers another or a point; a label it moves away from its point is tied to it by a
# thin grey line.
knob_plot() {
    local out=$1 title=$2 data=$3 knobs n ymax floor ylo yhi k=0 width panel plots
    awk '$1 != "-" && $2 != "-" && $1 > 0' "$data" >"$data.ok" && mv "$data.ok" "$data"
    ymax=$(awk '$2 + 0 > m { m = $2 + 0 } END { print m + 0 }' "$data")
    if [ "$ymax" = 0 ]; then
        speed_plot "$out" "$title" "$data"
        return
    fi
    knobs=$(awk '!seen[$6]++ { print $6 }' "$data")
    n=$(echo "$knobs" | wc -l)
    # The floor: a decade below the smallest error that is not 0; the top: room for labels above.
    read -r floor ylo yhi < <(awk -v m="$ymax" '$2 + 0 > 0 && (lo == "" || $2 + 0 < lo) { lo = $2 + 0 }
        END { f = 10 ^ (int(log(lo) / log(10) + 100) - 100) / 3; print f, f / 2.5, m * 4 }' "$data")
    # Panels 430 pixels wide, 100 apart (the next panel's tick labels), 150 on the left for the axis label.
    width=$((n == 1 ? 900 : 90 + 530 * n))
    {
        echo "set terminal pngcairo size $width,640 font \"sans,12\" noenhanced"
        echo "set output \"$out\""
        echo "set multiplot title \"$title\" font \"sans,14\""
        echo "set grid"
        echo "set logscale y"
        echo "set format y \"%g\""
        echo "set yrange [$ylo:$yhi]"
        echo "set ytics add (\"0 (exact)\" $floor)"
        echo "set ylabel \"RMSE against the reference setting (levels of 0-255)\""
        echo "set xlabel \"render time / default's (1 thread)\""
        echo "set bmargin at screen 0.2"
        echo "set tmargin at screen 0.88"
        echo "unset key"
        for knob in $knobs; do
            panel=$data.$k
            awk -v knob="$knob" -v floor="$floor" '$6 == knob { y = ($2 + 0 == 0 ? floor : $2); print $1, y, $3, $4, $5 }' \
                "$data" >"$panel"
            awk '$5 == 0' "$panel" >"$panel.s0"
            awk '$5 == 1' "$panel" >"$panel.s1"
            # The x axis, set here (not by gnuplot) so that bench/labels.awk can place the labels: log when
            # the times span more than a factor 4; room on the right for labels.
            read -r xmin xmax logx < <(awk '{ if (min == "" || $1 < min) min = $1; if ($1 > max) max = $1 }
                END { if (max / min > 4) print min / 1.5, max * 2.5, 1
                      else { span = max - min; if (span < 0.1 * max) span = 0.1 * max; print min - 0.2 * span, max + 0.6 * span, 0 } }' "$panel")
            awk -v xmin="$xmin" -v xmax="$xmax" -v logx="$logx" -v ymin="$ylo" -v ymax="$yhi" -v logy=1 -v key=0 \
                -v char_w="$(awk -v n="$n" 'BEGIN { print (n == 1 ? 0.0095 * 760 / 710 : 0.0095 * 760 / 430) }')" \
                -f "$here/labels.awk" "$panel" >"$panel.labels"
            local l=$((150 + 530 * k)) r=$((150 + 530 * k + 430))
            [ "$n" = 1 ] && l=150 r=860
            echo "set lmargin at screen $(awk -v a=$l -v w=$width 'BEGIN { print a / w }')"
            echo "set rmargin at screen $(awk -v a=$r -v w=$width 'BEGIN { print a / w }')"
            echo "set xrange [$xmin:$xmax]"
            [ "$logx" = 1 ] && echo "set logscale x" || echo "unset logscale x"
            echo "set title \"${knob//_/ }\""
            [ $k -gt 0 ] && echo "unset ylabel"
            echo "plot \"$panel.labels\" using (\$7 == 1 ? \$4 : 1/0):5:(\$1 - \$4):(\$2 - \$5) with vectors nohead lw 0.5 lc rgb \"#aaaaaa\", \\"
            echo "     \"$panel.s0\" using 1:2 with linespoints pt 7 ps 1.5 lw 1 lc rgb \"#1f77b4\", \\"
            echo "     \"$panel.s1\" using 1:2 with linespoints pt 9 ps 1.7 lw 1 dt 2 lc rgb \"#d62728\", \\"
            echo "     \"$panel\" using (\$4 == 1 ? \$1 : 1/0):2 with points pt 4 ps 3.2 lw 2 lc rgb \"black\", \\"
            echo "     \"$panel.labels\" using (\$6 == 0 ? \$1 : 1/0):2:3 with labels left font \"sans,10\" tc rgb \"#1f77b4\", \\"
            echo "     \"$panel.labels\" using (\$6 == 1 ? \$1 : 1/0):2:3 with labels left font \"sans,10\" tc rgb \"#d62728\""
            k=$((k + 1))
        done
        # The key, once, under the panels.
        echo "set key at screen 0.5, screen 0.06 center vertical maxrows 3 box"
        echo "unset title; unset xlabel; unset ylabel; unset grid; unset tics; unset border"
        echo "set lmargin at screen 0.05; set rmargin at screen 0.95; set tmargin at screen 0.2; set bmargin at screen 0.01"
        echo "unset logscale; set xrange [0:1]; set yrange [0:1]"
        echo "plot 2 with linespoints pt 7 ps 1.5 lc rgb \"#1f77b4\" title \"built-in scene of the chapter\", \\"
        echo "     2 with linespoints pt 9 ps 1.7 dt 2 lc rgb \"#d62728\" title \"scene of all stages (latest chapter with the knob)\", \\"
        echo "     2 with points pt 4 ps 3.2 lw 2 lc rgb \"black\" title \"default setting\""
        echo "unset multiplot"
    } >"$data.gp"
    gnuplot "$data.gp"
}

# speed_plot OUT TITLE DATA: when no setting changes a pixel (the knobs are
# about speed alone, as the grid's), the time of each setting as bars, one
# pair per setting (built-in scene, scene of all stages), on a log scale.
speed_plot() {
    local out=$1 title=$2 data=$3 n
    awk '{ key = $3; if (!(key in seen)) { seen[key] = 1; order[++n] = key }; v[key, $5] = $1; d[key] = $4 }
         END { for (k = 1; k <= n; k++) { key = order[k]
                   printf "\"%s%s\" %s %s\n", key, (d[key] == 1 ? " (default)" : ""),
                       ((key, 0) in v ? v[key, 0] : "-"), ((key, 1) in v ? v[key, 1] : "-") } }' "$data" >"$data.bars"
    n=$(wc -l <"$data.bars")
    gnuplot <<EOF
set terminal pngcairo size $((n > 10 ? 300 + 60 * n : 900)),600 font "sans,12" noenhanced
set output "$out"
set title "$title\nevery setting gives the same image: the cost alone"
set ylabel "time relative to the default (1 thread)"
set logscale y
set yrange [$(awk '{ for (k = 2; k <= 3; k++) if ($k != "-") { if (lo == "" || $k < lo) lo = $k; if ($k > hi) hi = $k } }
                END { printf "%g:%g", (lo < 1 ? lo : 1) / 2, (hi > 1 ? hi : 1) * 3 }' "$data.bars")]
set grid ytics
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set xtics rotate by -30 left font "sans,10" offset -1, 0
set key below
set datafile missing "-"
plot "$data.bars" using 2:xtic(1) lc rgb "#1f77b4" title "built-in scene of the chapter", \
     "" using 3 lc rgb "#d62728" title "scene of all stages (latest chapter with the knob)", \
     1 with lines dt 2 lc rgb "black" notitle
EOF
}

awk -F'\t' '{ print $2 }' "$knob_rows" | sort -u | while read -r c; do
    [ -n "$c" ] || continue
    data=$work/plot_knobs_$c.dat
    # One panel per knob (named in its title), each point labelled with its value.
    knob_names=$(awk -F'\t' -v c="$c" '$2 == c && !seen[$3]++ { print $3 }' "$knob_rows")
    awk -F'\t' -v c="$c" '$2 == c {
        if ($10 != "-") print $10, $11, $4, $5, 0, "--" $3
        if ($19 != "-") print $19, $20, $4, $5, 1, "--" $3
    }' "$knob_rows" >"$data"
    knob_plot "$figures/bench_knobs_$(num "$c").png" "Chapter $(title "$c"): $(echo $knob_names | awk '{ for (k = 1; k <= NF; k++) printf "%s--%s", (k == 1 ? "" : k == NF ? " and " : ", "), $k }'), cost against error" "$data"
done

data=$work/plot_knobs_all.dat
{
    awk -F'\t' '$3 == "samples" {
        if ($10 != "-") print $10, $11, $4, $5, 0, "samples_per_pixel_(-n)"
        if ($19 != "-") print $19, $20, $4, $5, 1, "samples_per_pixel_(-n)" }' "$common_rows"
    # precision: double (the reference and the default, at time 1 and error 0) and float
    awk -F'\t' -v latest="$(num "$latest")" '$1 == latest || $1 == "stages" { s = ($1 == "stages")
        print 1, 0, "double", 1, s, "precision_(REAL)"
        if ($8 != "-") print $8, $9, "float", 0, s, "precision_(REAL)" }' "$precision_rows"
} >"$data"
knob_plot "$figures/bench_knobs_all.png" "Samples per pixel and precision, in chapter $(num "$latest") ($(title "$latest" | cut -d' ' -f2-)): cost against error" "$data"

# Growth: time per ray against triangles, with a least-squares line through
# the points from about 1000 triangles up (fewer, and the eye ray's own cost shows).
growth_fits=$work/growth_fits.tsv
: >"$growth_fits"
if [ -s "$growth_rows" ]; then
    plots=""
    colours=("#1f77b4" "#d62728" "#2ca02c" "#9467bd")
    k=0
    for c in "${growth_chapters[@]}"; do
        awk -F'\t' -v c="$c" '$1 == c { print $2, $5, $8, $9, $6, $7 }' "$growth_rows" >"$work/growth_$c.dat"
        [ -s "$work/growth_$c.dat" ] || continue
        read -r a b < <(awk '$1 >= 500 { x = log($1) / log(10); y = log($2) / log(10); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
            END { if (n >= 2) { b = (n * sxy - sx * sy) / (n * sxx - sx * sx); a = (sy - b * sx) / n; printf "%.6g %.6g\n", a, b } else print "- -" }' \
            "$work/growth_$c.dat")
        printf '%s\t%s\t%s\n' "$c" "$a" "$b" >>"$growth_fits"
        kind=$(case "$c" in *grid*) echo "grid" ;; *) echo "linear scan" ;; esac)
        col=${colours[k % 4]}
        plots="$plots${plots:+, }\"$work/growth_$c.dat\" using 1:2:3:4 with yerrorbars pt 7 ps 1.4 lw 1.5 lc rgb \"$col\" title \"$(title "$c") ($kind): median, quartiles\""
        plots="$plots, \"$work/growth_$c.dat\" using 1:5 with points pt 1 ps 1 lc rgb \"$col\" notitle, \"\" using 1:6 with points pt 1 ps 1 lc rgb \"$col\" notitle"
        if [ "$a" != "-" ]; then
            plots="$plots, 10**($a) * x**($b) with lines lw 2 dt 2 lc rgb \"$col\" title sprintf(\"fit from about 1000 triangles up: slope %.2f\", $b)"
        fi
        k=$((k + 1))
    done
    gnuplot <<EOF
$plot_term
set output "$figures/bench_growth.png"
set title "Time per eye ray against the number of triangles (tessellated sphere, 1 thread)\nmedian of the runs, bars from the first to the third quartile, crosses the fastest and slowest run"
set xlabel "triangles in the scene"
set ylabel "render time per eye ray (microseconds)"
set logscale xy
set format x "%.0f"
set format y "%g"
set grid
set key top left box opaque
set xrange [50:2*$max_triangles]
plot $plots
EOF
fi

# Scaling: time against eye rays (image size; samples per pixel), and threads.
awk -F'\t' '$2 != "-" { print $5, $2, $3, $4 }' "$work/sizes.tsv" >"$work/scale_sizes.dat"
awk -F'\t' '$2 != "-" { print $5, $2, $3, $4 }' "$work/spp_stage.tsv" >"$work/scale_spp.dat"
awk -F'\t' '$2 != "-" { split($1, w, " "); print w[2], $2, $3, $4 }' "$work/threads_stage.tsv" >"$work/scale_threads.dat"
awk -F'\t' '$2 != "-" { split($1, w, " "); print w[2], $2, $3, $4 }' "$work/threads_builtin.tsv" >"$work/scale_threads_b.dat"
t1_stage=$(awk 'NR == 1 { print $2 }' "$work/scale_threads.dat")
t1_builtin=$(awk 'NR == 1 { print $2 }' "$work/scale_threads_b.dat")
gnuplot <<EOF
set terminal pngcairo size 1200,520 font "sans,12" noenhanced
set output "$figures/bench_scaling.png"
set multiplot layout 1,2 title "$(title "$latest"), scene of all stages"
set key below
set title "Time against the work (1 thread)"
set xlabel "rays cast (all kinds)"
set ylabel "render time (s)"
set logscale xy
set grid
set key below
plot "$work/scale_sizes.dat" using 1:2:3:4 with yerrorlines pt 7 lc rgb "#1f77b4" title "image size x1/4 to x2 per side, 1 spp", \
     "$work/scale_spp.dat" using 1:2:3:4 with yerrorlines pt 9 lc rgb "#d62728" title "1, 4, 16 samples per pixel, half size"
unset logscale
set title "Threads on this machine ($cores cores)"
set xlabel "threads (-j)"
set ylabel "speed-up over 1 thread (median time ratio)"
set xrange [0.5:$cores + 0.5]
set xtics 1
set yrange [0:$cores + 0.5]
plot x with lines dt 2 lc rgb "gray" title "ideal", \
     "$work/scale_threads.dat" using 1:($t1_stage / \$2) with linespoints pt 7 lw 2 lc rgb "#d62728" title "scene of all stages", \
     "$work/scale_threads_b.dat" using 1:($t1_builtin / \$2) with linespoints pt 9 lw 2 lc rgb "#1f77b4" title "built-in scene"
unset multiplot
EOF

# The strip: every chapter's image of the scene of all stages, side by side,
# each under its chapter's name (tools/panels.c, as the chapters' figures).
if [ -s "$strip_list" ]; then
    set --
    while IFS=$'\t' read -r c img ignores; do
        set -- "$@" "$img" "$(title "$c")"
    done <"$strip_list"
    "$build/tools/panels" "$figures/bench_stages.png" "$@" || note "the strip failed"
    # The same in two rows, for a slide (a strip of eleven is 3680 x 285).
    "$build/tools/panels" --rows 2 "$figures/bench_stages_2rows.png" "$@" || note "the two-row strip failed"
fi

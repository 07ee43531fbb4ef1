# povray.sh - section 5 of bench/bench.sh (sourced): the course's scenes in POV-Ray 3.7.
#
# bench/scene2pov translates wire-box, two-boxes and bunny (scene2pov.c says
# how); POV-Ray renders them without antialiasing on 1 and 2 threads, and its
# image is compared with the course's reference image.  The project's side is
# the latest chapter that models every feature of the scene (its renderer
# prints no "ignores:" line for it), with the course's Phong form where the
# renderer offers a choice named "course".  Writes $work/pov_rows.tsv:
#   scene size pov_vs_ref(share max) pov_j1 pov_j2 chapter chapter_vs_ref ch_j1 ch_j2 note

pov_rows=$work/pov_rows.tsv
pov_reps=${BENCH_POV_REPS:-9} # rounds of this section, which the ten minutes' cut leaves whole (lib.sh)
[[ $pov_reps =~ ^[1-9][0-9]*$ ]] || pov_reps=9
: >"$pov_rows"
pov_scenes="wire-box two-boxes bunny"
pov_version=""
pov_note=""
slow="" # the scenes the project's renderer took too long on for rounds

# pov_summary LOG: "SECONDS RAYS": POV-Ray's own trace time (without its
# parse time and start-up), and the pixel count of the image as its rays;
# for the project's renderer's log, its summary (summary_of).  POV-Ray's
# log is kept as $work/pov/last_pov.log, for its parse time.
pov_summary() {
    if ! grep -q 'Trace Time:' "$1"; then
        summary_of "$1"
        return
    fi
    cp -- "$1" "$work/pov/last_pov.log"
    awk '/^ *Trace Time:/ && match($0, /\([0-9.]+ seconds\)/) { s = substr($0, RSTART + 1, RLENGTH - 10) }
         END { if (s != "") print s, (pixels + 0) }' pixels="$pov_pixels" "$1"
}

if ! command -v povray >/dev/null 2>&1; then
    pov_note="POV-Ray is not installed (tools/deps.sh installs it for make bench)."
elif [ ! -d "$cornell/scenes/ray1" ]; then
    pov_note="The course's scenes ($cornell) are absent: the comparison needs them."
else
    pov_version=$(povray -version 2>&1 | grep -m1 -i 'POV-Ray' | sed 's/^ *//')
    mkdir -p "$work/pov"
    for s in $pov_scenes; do
        xml=$cornell/scenes/ray1/$s.xml
        ref=$cornell/scenes/ray1/reference/$s.xml.png
        [ -f "$xml" ] && [ -f "$ref" ] || continue
        read -r W H < <("$tools/imgcmp" size "$ref")
        pov_pixels=$((W * H))
        kind=$("$tools/scene2pov" "$xml" "$work/pov/$s.pov") || { note "pov $s: cannot translate"; continue; }
        echo "$tools/scene2pov $xml $work/pov/$s.pov" >>"$work/commands.txt"
        povopts="+W$W +H$H -D +FN -A File_Gamma=2.2"
        timed=$work/pov/$s.pov
        if [ "$kind" = colour ]; then
            # One render per channel; each traces the whole scene, so one of them is timed.
            for ch in r g b; do
                "$tools/scene2pov" "$xml" "$work/pov/${s}_$ch.pov" $ch >/dev/null
                echo "$tools/scene2pov $xml $work/pov/${s}_$ch.pov $ch" >>"$work/commands.txt"
                povray "+I$work/pov/${s}_$ch.pov" "+O$work/pov/${s}_$ch.png" $povopts +WT2 >"$work/pov/${s}_$ch.log" 2>&1
            done
            "$tools/imgcmp" merge "$work/pov/${s}_r.png" "$work/pov/${s}_g.png" "$work/pov/${s}_b.png" \
                "$work/pov/${s}_pov.png"
            timed=$work/pov/${s}_r.pov
        fi
        # The project's renderer: the latest chapter that ignores nothing in the scene.
        chapter="" knob="" why=""
        for c in "${chapters[@]}"; do
            probe=$("$build/$c/render" -j 1 -s 8x8 -o "$work/pov/probe.png" "$xml" 2>&1 | sed -n 's/.*: ignores: //p')
            if [ -z "$probe" ]; then
                chapter=$c
            else
                why="$c ignores: $probe"
            fi
        done
        if [ -n "$chapter" ]; then
            knob=$(knobs_of "$build/$chapter/render" | awk -F'\t' '$2 == "choice" && (" " $4 " ") ~ / course / { printf "--%s=course", $1; exit }')
        fi
        # Chapter 11 runs as its lab's renderer, build/11_grid/lab --accel=fast: the fast grid, the same
        # image byte for byte; the lesson's renderer marches the lecture's simple grid, which the lab
        # measures apart (chapters/11_grid/lab/README.md).
        ours=("$build/$chapter/render") chapter_label=$chapter
        if [ "$chapter" = 11_grid ] && [ -x "$build/11_grid/lab" ]; then
            ours=("$build/11_grid/lab" --accel=fast) chapter_label=11_grid/lab
        fi
        # A probe at an eighth of the side (1/64 of the pixels, 2 threads) predicts the project's time
        # at the reference size.  Past 3 s (chapter 04's linear scan over a mesh) both renderers
        # render and are timed at the side that takes about 1 s, 3 rounds, and are compared there.
        ch_share="-" ch_max="-" c1="-" c2="-" c1r="" c2r="" tsize=${W}x$H pov_rounds=$pov_reps
        if [ -n "$chapter" ]; then
            "${ours[@]}" -j 2 -s "$(scaled_size "${W}x$H" 0.125)" $knob -o "$work/pov/probe.png" "$xml" \
                >"$work/pov/${s}_probe.log" 2>&1
            t_est=$(summary_of "$work/pov/${s}_probe.log" | awk '{ print 64 * $1 }')
            if awk -v t="${t_est:-99}" 'BEGIN { exit !(t > 3) }'; then
                tsize=$(scaled_size "${W}x$H" "$(awk -v t="${t_est:-99}" 'BEGIN { printf "%.3f", sqrt(1 / t) }')")
                slow="$slow $s" pov_rounds=3
                note "ours $s: $chapter would take about $t_est s on 2 threads: rendered and timed at $tsize"
            else
                "${ours[@]}" -j 2 $knob -o "$work/pov/${s}_ours.png" "$xml" >"$work/pov/${s}_ours.log" 2>&1
                echo "${ours[*]} -j 2 $knob $xml -o OUT.png" >>"$work/commands.txt"
                read -r ch_share ch_max < <(diff_of "$work/pov/${s}_ours.png" "$ref")
            fi
        fi
        pov_pixels=$((${tsize%x*} * ${tsize#*x}))
        tpovopts="+W${tsize%x*} +H${tsize#*x} -D +FN -A File_Gamma=2.2"
        MEASURE_PARSE=pov_summary
        # The project's renderer and POV-Ray in one group, so that each round runs the four in turn
        # and both see the same load.
        settings_clear
        if [ -n "$chapter" ]; then
            setting "ours -j1" "$work/pov/${s}_o1.png" "${ours[@]}" -j 1 -s "$tsize" $knob "$xml"
            setting "ours -j2" "$work/pov/${s}_o2.png" "${ours[@]}" -j 2 -s "$tsize" $knob "$xml"
        fi
        setting "pov -j1" "$work/pov/${s}_t1.png" povray "+I$timed" "+O@OUT@" $tpovopts +WT1
        setting "pov -j2" "$work/pov/${s}_t2.png" povray "+I$timed" "+O@OUT@" $tpovopts +WT2
        MEASURE_ALL_ROUNDS=1 measure "pov_$s" "$pov_rounds"
        MEASURE_PARSE=summary_of
        pov_parse=$(awk '/^ *Parse Time:/ && match($0, /\([0-9.]+ seconds\)/) { p = substr($0, RSTART + 1, RLENGTH - 10) }
            END { print p }' "$work/pov/last_pov.log" 2>/dev/null)
        if [ "$kind" != colour ]; then
            if [ "$tsize" = "${W}x$H" ]; then
                cp "$work/pov/${s}_t2.png" "$work/pov/${s}_pov.png"
            else
                povray "+I$timed" "+O$work/pov/${s}_pov.png" $povopts +WT2 >"$work/pov/${s}_pov.log" 2>&1
            fi
        fi
        read -r pshare pmax < <(diff_of "$work/pov/${s}_pov.png" "$ref")
        if [ -n "$chapter" ]; then
            c1=$(field "pov_$s" "ours -j1" 2) c2=$(field "pov_$s" "ours -j2" 2)
            c1r="$(field "pov_$s" "ours -j1" 3)-$(field "pov_$s" "ours -j1" 4)"
            c2r="$(field "pov_$s" "ours -j2" 3)-$(field "pov_$s" "ours -j2" 4)"
        fi
        # The project's image against POV-Ray's at the timed size (for a colour scene POV-Ray's timed
        # image is one channel: compared only for grey ones).
        op_share="-" op_max="-"
        if [ -n "$chapter" ] && [ "$kind" != colour ]; then
            read -r op_share op_max < <(diff_of "$work/pov/${s}_o2.png" "$work/pov/${s}_t2.png")
        fi
        p1=$(field "pov_$s" "pov -j1" 2) p2=$(field "pov_$s" "pov -j2" 2)
        # Empty fields would merge when read back with IFS=tab: "-" stands for none.
        printf '%s\t%s\t%s %s\t%s\t%s\t%s\t%s\t%s %s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$s" "${W}x$H" "$pshare" "$pmax" \
            "$p1" "$(field "pov_$s" "pov -j1" 3)-$(field "pov_$s" "pov -j1" 4)" \
            "$p2" "$(field "pov_$s" "pov -j2" 3)-$(field "pov_$s" "pov -j2" 4)" \
            "$ch_share" "$ch_max" "${chapter_label:--}" "${knob:--}" "$c1" "${c1r:--}" "$c2" "${c2r:--}" "$kind" "${why:--}" "${pov_parse:--}" "$tsize" "$op_share $op_max" \
            >>"$pov_rows"
    done
fi

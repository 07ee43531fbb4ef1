#!/bin/bash
# bench.sh BUILD FLOAT_BUILD TOOLS - the measurements of docs/measurements.md.
#
# Run by `make bench`, which builds the renderers of the double build BUILD and
# the float build FLOAT_BUILD and the bench's tools into TOOLS first.  Writes
# docs/measurements.md and docs/figures/bench_*.png; its scratch files go into
# BUILD/bench/.  Nothing is listed by hand: the chapters are the folders
# chapters/NN_name/, each renderer's knobs the --NAME=V lines of its --help,
# and a chapter's sweep of extremes is its optional hook (bench/hooks/README.md).
#
# Environment: BENCH_REPS (rounds per timing, default 5), BENCH_TARGET (the
# seconds one timed render is sized to take on one thread, default 0.2),
# BENCH_MAX_TRIANGLES (largest tessellated sphere, default 1000000),
# BENCH_LINEAR_MAX_TRIANGLES (largest for the linear scan, default 100000),
# BENCH_CUT (seconds after which timings take 3 rounds at most, default 150),
# RT_CORNELL (the course's data folder, default ../shared/cornell/sp17-ray1/data).
# BENCH_REPLOT=1 draws the plots and writes the page again from the last run's measurements (seconds).
set -u
if [ $# -ne 3 ]; then
    echo "usage: $0 BUILD FLOAT_BUILD TOOLS" >&2
    exit 2
fi
build=$1 fbuild=$2 tools=$3
reps=${BENCH_REPS:-5}
target=${BENCH_TARGET:-0.2}
max_triangles=${BENCH_MAX_TRIANGLES:-1000000}
linear_max=${BENCH_LINEAR_MAX_TRIANGLES:-100000}
budget_cut=${BENCH_CUT:-150}
cornell=${RT_CORNELL:-../shared/cornell/sp17-ray1/data}
figures=docs/figures
page=docs/measurements.md
work=$build/bench
stage_scene=bench/scenes/stages.xml
here=$(dirname "$0")
# shellcheck source=bench/lib.sh
. "$here/lib.sh"

mapfile -t chapters < <(for d in chapters/[0-9][0-9]_*/; do basename "$d"; done | sort)
if [ ${#chapters[@]} -eq 0 ]; then
    echo "bench: no chapters/NN_name/ folders" >&2
    exit 1
fi
latest=${chapters[${#chapters[@]} - 1]}
num() { echo "${1%%_*}"; }
title() { echo "$1" | sed 's/^\([0-9]*\)_/\1 /; s/_/ /g'; }
for c in "${chapters[@]}"; do
    for b in "$build" "$fbuild"; do
        [ -x "$b/$c/render" ] || { echo "bench: $b/$c/render is missing (run make bench)" >&2; exit 1; }
    done
done

# The calibrated sizes, one per chapter and scene, found once (in this shell,
# not in a $(...) subshell, so that they are kept): calibrate CHAPTER, then
# builtin_size CHAPTER and stage_size CHAPTER print them.
declare -A size_builtin size_stage
calibrate() {
    [ -n "${size_builtin[$1]:-}" ] || size_builtin[$1]=$(calibrated_size "$build/$1/render")
    [ -n "${size_stage[$1]:-}" ] || size_stage[$1]=$(calibrated_size "$build/$1/render" "$stage_scene")
}
builtin_size() { echo "${size_builtin[$1]}"; }
stage_size() { echo "${size_stage[$1]}"; }

# BENCH_REPLOT=1: no measuring; the plots and the page are made again from the measurements the last run
# kept in $work (its state.sh), so that a change to plots.sh or page.sh is seen in seconds.
if [ "${BENCH_REPLOT:-}" = 1 ]; then
    [ -f "$work/state.sh" ] || { echo "bench: BENCH_REPLOT=1, but $work/state.sh is missing: run make bench first" >&2; exit 1; }
    # shellcheck disable=SC1091
    . "$work/state.sh"
    note "plots (again, from the measurements of $started)"
    . "$here/plots.sh"
    note "page"
    . "$here/page.sh"
    note "bench: wrote $page and $(ls "$figures"/bench_*.png 2>/dev/null | wc -l) figures in ${SECONDS} s"
    exit 0
fi

rm -rf "$work"
mkdir -p "$work/img" "$work/page" "$figures" || exit 1
: >"$work/commands.txt"

started=$(date -u '+%Y-%m-%d %H:%M UTC')
cpu=$(awk -F': ' '/^model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null)
cores=$(nproc 2>/dev/null || echo 1)
compiler=$(${CC:-cc} --version 2>/dev/null | head -n 1)
load_before=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)
note "bench: ${#chapters[@]} chapters (${chapters[*]}), $reps rounds per timing, $cores cores ($cpu)"

# ---- 1. the knob table --------------------------------------------------------------
#
# Each knob is measured where it first appears, on that chapter's built-in
# scene, and in the latest chapter that still has it, on the scene of all
# stages (bench/scenes/stages.xml), where every later stage runs too.  Each
# setting is timed on one thread at a size calibrated for the default
# setting; its image is compared with the image of the reference setting.

for c in "${chapters[@]}"; do
    calibrate "$c"
    note "calibrated $c: built-in scene ${size_builtin[$c]}, scene of all stages ${size_stage[$c]} (about $target s on 1 thread)"
done

# id chapter knob value default? ref?, then for each scene (built-in, all stages) time min max ratio rmse psnr
# mae share largest, then the stage chapter and the help: 26 columns
knob_rows=$work/knob_rows.tsv
: >"$knob_rows"
skipped_knobs=""
prev_knobs=""
for c in "${chapters[@]}"; do
    knobs_of "$build/$c/render" >"$work/knobs_$c.tsv"
    while IFS=$'\t' read -r name kind default choices help; do
        case " $prev_knobs " in *" $name "*) continue ;; esac
        plan=$(knob_plan "$name" "$kind" "$default" "$choices")
        if [ "$plan" = skip ]; then
            skipped_knobs="$skipped_knobs $(num "$c"):--$name"
            continue
        fi
        ref=${plan##*ref=}
        values=${plan% ref=*}
        # The latest chapter that still has the knob renders the scene of all stages.
        last=$c
        for d in "${chapters[@]}"; do
            [[ "$d" > "$c" ]] && "$build/$d/render" --help 2>/dev/null | grep -q -- "^      --$name=V " && last=$d
        done
        for where in builtin stage; do
            settings_clear
            if [ $where = builtin ]; then
                size=$(builtin_size "$c")
                for v in $values; do
                    setting "--$name=$v" "$work/img/k_${c}_${name}_$v.png" "$build/$c/render" -j 1 -s "$size" "--$name=$v"
                done
            else
                size=$(stage_size "$last")
                for v in $values; do
                    setting "--$name=$v" "$work/img/ks_${c}_${name}_$v.png" "$build/$last/render" -j 1 -s "$size" \
                        "--$name=$v" "$stage_scene"
                done
            fi
            measure "knob_${where}_${c}_$name" "$reps"
        done
        for v in $values; do
            row="$(num "$c").$name=$v	$c	$name	$v	$([ "$v" = "$default" ] && echo 1 || echo 0)	$([ "$v" = "$ref" ] && echo 1 || echo 0)"
            for where in builtin stage; do
                g=knob_${where}_${c}_$name
                t=$(field "$g" "--$name=$v" 2) t_min=$(field "$g" "--$name=$v" 3) t_max=$(field "$g" "--$name=$v" 4)
                t_def=$(field "$g" "--$name=$default" 2)
                prefix=$([ $where = builtin ] && echo k || echo ks)
                err=$(error_of "$work/img/${prefix}_${c}_${name}_$v.png" "$work/img/${prefix}_${c}_${name}_$ref.png")
                row="$row	$t	$t_min	$t_max	$(ratio "$t" "$t_def")	${err// /	}"
            done
            printf '%s\t%s\t%s\n' "$row" "$last" "$help" >>"$knob_rows"
        done
    done <"$work/knobs_$c.tsv"
    prev_knobs=$(cut -f1 "$work/knobs_$c.tsv" | tr '\n' ' ')
done

# The sweeps of extremes: each chapter's hook (bench/hooks/README.md).
for c in "${chapters[@]}"; do
    hook=""
    for h in "chapters/$c/bench.sh" "bench/hooks/$c.sh"; do
        [ -f "$h" ] && { hook=$h; break; }
    done
    [ -n "$hook" ] || continue
    note "extremes $c: $hook"
    if ! sh "$hook" "$build" "$fbuild" >"$work/page/extremes_$c.md" 2>"$work/extremes_$c.log"; then
        { echo; echo "(\`$hook\` failed: $(tail -n 1 "$work/extremes_$c.log"))"; } >>"$work/page/extremes_$c.md"
    fi
    echo "sh $hook $build $fbuild" >>"$work/commands.txt"
done

# The options every renderer shares: samples per pixel and threads, in the
# latest chapter (precision is section 4).
common_rows=$work/common_rows.tsv
: >"$common_rows"
for where in builtin stage; do
    scene_arg=""
    [ $where = stage ] && scene_arg=$stage_scene
    size=$([ $where = builtin ] && builtin_size "$latest" || stage_size "$latest")
    half=$(scaled_size "$size" 0.5)
    settings_clear
    for n in 1 4 16; do
        setting "-n $n" "$work/img/spp_${where}_$n.png" "$build/$latest/render" -j 1 -s "$half" -n $n $scene_arg
    done
    measure "spp_$where" "$reps"
    settings_clear
    for ((j = 1; j <= cores; j++)); do
        setting "-j $j" "$work/img/thr_${where}_$j.png" "$build/$latest/render" -j $j -s "$size" $scene_arg
    done
    measure "threads_$where" "$reps"
done
# common_row NAME VALUE OPTION DEFAULT BEST MEASURE IMG REF BASE HELP: the row
# of `-OPTION VALUE` on both scenes: its time (and spread) in MEASURE_where,
# its speed against `-OPTION BASE`, its image against IMG_where_REF's.
common_row() {
    local name=$1 value=$2 option=$3 default=$4 best=$5 measure=$6 img=$7 ref=$8 base=$9 help=${10}
    local row="all.$name=$value	$latest	$name	$value	$default	$best" where t err
    for where in builtin stage; do
        t=$(field "${measure}_$where" "-$option $value" 2)
        err=$(error_of "$work/img/${img}_${where}_$value.png" "$work/img/${img}_${where}_$ref.png")
        row="$row	$t	$(field "${measure}_$where" "-$option $value" 3)	$(field "${measure}_$where" "-$option $value" 4)	$(ratio "$t" "$(field "${measure}_$where" "-$option $base" 2)")	${err// /	}"
    done
    printf '%s\t%s\t%s\n' "$row" "$latest" "$help" >>"$common_rows"
}
for n in 1 4 16; do
    common_row samples $n n "$([ $n = 1 ] && echo 1 || echo 0)" "$([ $n = 16 ] && echo 1 || echo 0)" spp spp 16 1 \
        "samples per pixel (-n), at half the side"
done
for ((j = 1; j <= cores; j++)); do
    common_row threads $j j "$([ $j = "$cores" ] && echo 1 || echo 0)" "$([ $j = 1 ] && echo 1 || echo 0)" threads thr 1 \
        "$cores" "threads (-j)"
done

# ---- 4. float against double (measured here: the knob table shows it too) -------------

precision_rows=$work/precision_rows.tsv
: >"$precision_rows"
precision() { # id label chapter scene-or-empty size
    local id=$1 label=$2 c=$3 scene=$4 size=$5
    settings_clear
    setting double "$work/img/p_${id}_double.png" "$build/$c/render" -j 1 -s "$size" $scene
    setting float "$work/img/p_${id}_float.png" "$fbuild/$c/render" -j 1 -s "$size" $scene
    measure "precision_$id" "$reps"
    local td tf
    td=$(field "precision_$id" double 2) tf=$(field "precision_$id" float 2)
    local err
    err=$(error_of "$work/img/p_${id}_double.png" "$work/img/p_${id}_float.png")
    # id label size double range float range ratio rmse psnr mae share largest
    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$id" "$label" "$size" "$td" \
        "$(field "precision_$id" double 3)-$(field "precision_$id" double 4)" "$tf" \
        "$(field "precision_$id" float 3)-$(field "precision_$id" float 4)" "$(ratio "$tf" "$td")" "${err// /	}" \
        >>"$precision_rows"
}
for c in "${chapters[@]}"; do
    precision "$(num "$c")" "$c, built-in scene" "$c" "" "$(builtin_size "$c")"
done
precision stages "$latest, scene of all stages" "$latest" "$stage_scene" "$(stage_size "$latest")"

# ---- 3. growth with the work ----------------------------------------------------------

mkdir -p "$work/growth"
growth_rows=$work/growth_rows.tsv
: >"$growth_rows"
# The linear scan: the first chapter that renders meshes; the grid: chapters named *grid*.
growth_chapters=()
"$tools/tessellate" 100 "$work/growth/probe.obj" >/dev/null
printf '<scene><image>8 8</image><surface type="Mesh"><data>probe.obj</data></surface></scene>\n' \
    >"$work/growth/probe.xml"
for c in "${chapters[@]}"; do
    if "$build/$c/render" -j 1 -o "$work/growth/probe.png" "$work/growth/probe.xml" 2>&1 | grep -q 'ignores:.*meshes'; then
        continue
    fi
    growth_chapters+=("$c")
    break
done
for c in "${chapters[@]}"; do
    case "$c" in *grid*) [ "$c" != "${growth_chapters[0]:-}" ] && growth_chapters+=("$c") ;; esac
done
triangle_counts=""
for n in 100 1000 10000 100000 1000000 10000000; do
    [ "$n" -le "$max_triangles" ] && triangle_counts="$triangle_counts $n"
done
if [ ${#growth_chapters[@]} -gt 0 ]; then
    for n in $triangle_counts; do
        t=$("$tools/tessellate" "$n" "$work/growth/sphere_$n.obj") || continue
        side=$(awk -v n="$n" 'BEGIN { s = int(sqrt(2e7 / n)); if (s < 8) s = 8; if (s > 512) s = 512; print s }')
        cat >"$work/growth/sphere_$n.xml" <<EOF
<scene>
  <image>$side $side</image>
  <camera type="PerspectiveCamera"><viewPoint>0 0 4</viewPoint><viewDir>0 0 -1</viewDir>
    <projDistance>2</projDistance><viewWidth>1.2</viewWidth><viewHeight>1.2</viewHeight></camera>
  <surface type="Mesh"><data>sphere_$n.obj</data></surface>
</scene>
EOF
        settings_clear
        for c in "${growth_chapters[@]}"; do
            # The linear scan stops at $linear_max triangles: at 10^6 one 8 x 8 image took a minute of the
            # budget on the shared machine; its slope is fitted well below that.
            case "$c" in *grid*) ;; *) [ "$n" -gt "$linear_max" ] && continue ;; esac
            size=$(min_side=8 calibrated_size "$build/$c/render" "$work/growth/sphere_$n.xml")
            setting "$c" "$work/growth/img_${c}_$n.png" "$build/$c/render" -j 1 -s "$size" "$work/growth/sphere_$n.xml"
        done
        # Repeated until each point's quartiles are within 10 % of its median (at most 15 runs): one
        # noisy point sets a fitted slope.
        measure_steady "growth_$n" "$([ "$n" -ge 1000000 ] && echo 3 || echo "$reps")" 15 0.1
        for c in "${growth_chapters[@]}"; do
            tm=$(field "growth_$n" "$c" 2) rays=$(field "growth_$n" "$c" 5)
            # not run (the linear scan above $linear_max triangles) or failed: no row
            if [ -z "$tm" ] || [ "$tm" = "-" ] || [ -z "$rays" ] || [ "$rays" = "-" ] || [ "$rays" = 0 ]; then continue; fi
            # Microseconds per ray: three significant digits, no exponent.
            us() { awk -v t="$1" -v r="$rays" 'BEGIN { x = 1e6 * t / r; d = x >= 100 ? 0 : x >= 10 ? 1 : 2; printf "%.*f", d, x }'; }
            # chapter triangles median rays us us_min us_max us_q1 us_q3 runs
            printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$c" "$t" "$tm" "$rays" "$(us "$tm")" \
                "$(us "$(field "growth_$n" "$c" 3)")" "$(us "$(field "growth_$n" "$c" 4)")" \
                "$(us "$(field "growth_$n" "$c" 8)")" "$(us "$(field "growth_$n" "$c" 9)")" \
                "$(field "growth_$n" "$c" 10)" >>"$growth_rows"
        done
        rm -f "$work/growth/sphere_$n.obj"
    done
fi
# Image size and samples per pixel against time, in the latest chapter on the scene of all stages.
size=$(stage_size "$latest")
settings_clear
for f in 0.25 0.5 1 2; do
    s=$(scaled_size "$size" $f)
    setting "-s $s" "$work/img/size_$f.png" "$build/$latest/render" -j 1 -s "$s" "$stage_scene"
done
measure sizes "$reps"

# Each chapter's built-in scene at one size, side by side, on 1 and 2 threads: what each stage costs
# (the chapters' READMEs quote these lines).  At most 3 rounds: eleven renderers in turn.
chapter_side=${BENCH_CHAPTER_SIZE:-256x256}
settings_clear
for c in "${chapters[@]}"; do
    setting "$c -j1" "$work/img/chap_${c}_1.png" "$build/$c/render" -j 1 -s "$chapter_side"
    setting "$c -j2" "$work/img/chap_${c}_2.png" "$build/$c/render" -j 2 -s "$chapter_side"
done
measure chapters "$([ "$reps" -gt 3 ] && echo 3 || echo "$reps")"

# ---- 5. POV-Ray -------------------------------------------------------------------------

. "$here/povray.sh"

# ---- 6. one scene through all stages ---------------------------------------------------

strip_list=$work/strip.txt
: >"$strip_list"
for c in "${chapters[@]}"; do
    log=$work/strip_$c.log
    echo "$build/$c/render $stage_scene -o OUT.png" >>"$work/commands.txt"
    if "$build/$c/render" -o "$work/img/stage_$c.png" "$stage_scene" >"$log" 2>&1; then
        ignores=$(sed -n 's/.*: ignores: //p' "$log" | head -n 1)
        printf '%s\t%s\t%s\n' "$c" "$work/img/stage_$c.png" "$ignores" >>"$strip_list"
        note "stages $c: $(summary_of "$log" | awk '{ printf "%.3f s", $1 }')"
    else
        note "stages $c: failed: $(head -n 1 "$log")"
    fi
done

# ---- 7. the grid against Embree (bench/grid/, when present) -----------------------------

grid_log=""
# The target is the Makefile's or that of a file it includes from bench/grid/.
if grep -qs '^bench-grid:' Makefile bench/grid/*.mk; then
    note "make bench-grid"
    grid_log=$work/grid.log
    # The bunny only, one run per timing (bench/grid/run.sh): the whole of make bench-grid (the
    # sphere's 20 grids of the knob rows among it) takes longer.
    if BENCH_GRID_QUICK=1 make --no-print-directory bench-grid >"$grid_log" 2>&1; then
        note "bench-grid: done"
    else
        note "bench-grid: failed (see $grid_log)"
    fi
fi

load_after=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)

# What the plots and the page need, kept for BENCH_REPLOT=1.
declare -p chapters latest reps target started cpu cores compiler load_before load_after reduced_at skipped_knobs \
    growth_chapters max_triangles linear_max size_builtin size_stage chapter_side knob_rows common_rows \
    precision_rows growth_rows strip_list grid_log pov_rows pov_reps pov_version pov_note slow >"$work/state.sh" 2>/dev/null

# ---- plots and the page -----------------------------------------------------------------

note "plots"
. "$here/plots.sh"
note "page"
. "$here/page.sh"
note "bench: wrote $page and $(ls "$figures"/bench_*.png 2>/dev/null | wc -l) figures in ${SECONDS} s"

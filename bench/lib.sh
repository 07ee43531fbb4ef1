# lib.sh - the measuring helpers of bench/bench.sh (sourced, bash).
#
# A measurement is a group of settings timed side by side: every round runs
# each setting once, in order, and there are $reps rounds, so that a burst of
# other work on the shared machine falls on all settings alike.  The time of a
# setting is the median of its rounds, with the fastest and slowest shown.
# A renderer's time is the one its summary line prints (the render loop only:
# not the start-up, the scene parsing or the PNG encoding).

# A progress line: seconds since the bench started, then the text.
note() { printf '[%4ds] %s\n' "$SECONDS" "$*"; }

# summary_of LOG: "SECONDS RAYS" from a renderer's summary line,
#   "NAME: WxH, N spp, 262144 rays, 0.050 s, 2 threads -> out.png", or
#   "NAME: WxH, N spp, 262144 eye + 101003 shadow rays, 0.050 s, ..."
# (all kinds of rays summed), with "0 non-finite samples, " before the time
# since common/render_loop.c counts them.  Prints nothing when there is no summary.
summary_of() {
    awk '/ spp, .* rays, ([0-9]+ non-finite samples?, )?[0-9.]+ s, / {
        s = $0; sub(/^.* spp, /, "", s)
        r = s; sub(/ rays, .*$/, "", r)
        n = split(r, parts, / [+] /); rays = 0
        for (k = 1; k <= n; k++) { split(parts[k], w, " "); rays += w[1] }
        t = s; sub(/^.* rays, /, "", t); sub(/^[0-9]+ non-finite samples?, /, "", t); sub(/ s, .*$/, "", t)
        line = t " " rays
    } END { if (line != "") print line }' "$1"
}

# The settings of the next measurement: labels, command lines (words split
# on blanks; "-o IMAGE" is added, or replaces @OUT@ where the command has it)
# and image paths.  MEASURE_PARSE names the function that reads "SECONDS RAYS"
# from a run's output (summary_of unless set).
S_LABEL=() S_CMD=() S_IMG=()
settings_clear() { S_LABEL=() S_CMD=() S_IMG=(); }
# setting LABEL IMAGE COMMAND...
setting() {
    S_LABEL+=("$1")
    S_IMG+=("$2")
    shift 2
    S_CMD+=("$*")
}

# measure GROUP ROUNDS: times the settings; writes $work/GROUP.tsv with one
# line per setting:
#   LABEL  MEDIAN_S  MIN_S  MAX_S  RAYS  IMAGE  STATUS  Q1_S  Q3_S  RUNS
# (STATUS ok, or the first line the renderer printed when it failed; Q1 and Q3
# the quartiles of the runs' times), and adds every command line to
# $work/commands.txt.  One progress line per setting.  With MEASURE_MORE=1 the
# rounds add to the group's earlier ones (measure_steady).
# A setting that takes more than ten times $target in the first round runs
# only once (its min and max are then its one time).
# Past $budget_cut seconds (default 150) every measurement takes at most 3
# rounds, so that the bench keeps within its ten minutes as chapters add
# knobs; $reduced_at records when that began.  MEASURE_ALL_ROUNDS=1 keeps
# them all, the slow settings' too (the POV-Ray section's few short runs,
# which decide a goal).
reduced_at=""
measure() {
    local group=$1 rounds=$2 n=${#S_LABEL[@]} k r log status parse=${MEASURE_PARSE:-summary_of}
    if [ -z "${MEASURE_ALL_ROUNDS:-}" ] && [ "$SECONDS" -gt "${budget_cut:-300}" ] && [ "$rounds" -gt 3 ]; then
        rounds=3
        if [ -z "$reduced_at" ]; then
            reduced_at=$SECONDS
            note "more than ${budget_cut:-300} s: 3 rounds per timing from here on"
        fi
    fi
    local times=$work/$group.times more=${MEASURE_MORE:-}
    [ -n "$more" ] || : >"$times"
    local failed=()
    for ((k = 0; k < n; k++)); do
        failed[k]=""
        [ -n "$more" ] && continue
        case "${S_CMD[k]}" in
            *@OUT@*) printf '%s\n' "${S_CMD[k]//@OUT@/OUT.png}" >>"$work/commands.txt" ;;
            *) printf '%s -o OUT.png\n' "${S_CMD[k]}" >>"$work/commands.txt" ;;
        esac
    done
    local once=()
    for ((r = 0; r < rounds; r++)); do
        for ((k = 0; k < n; k++)); do
            [ -n "${failed[k]}" ] && continue
            [ -n "${once[k]:-}" ] && continue
            log=$work/run.log
            local cmd=${S_CMD[k]}
            case "$cmd" in *@OUT@*) cmd=${cmd//@OUT@/${S_IMG[k]}} ;; *) cmd="$cmd -o ${S_IMG[k]}" ;; esac
            # shellcheck disable=SC2086
            if $cmd </dev/null >"$log" 2>&1; then
                status=$($parse "$log")
                if [ -n "$status" ]; then
                    printf '%d\t%s\n' "$k" "$status" >>"$times"
                    # A setting ten times slower than the bench's target runs once.
                    if [ -z "${MEASURE_ALL_ROUNDS:-}" ] && [ "$r" = 0 ] &&
                        awk -v t="${status%% *}" -v g="$target" 'BEGIN { exit !(t > 10 * g) }'; then
                        once[k]=1
                    fi
                    continue
                fi
            fi
            failed[k]=$(grep -v '^$' "$log" | head -n 1 | tr '\t' ' ')
            failed[k]=${failed[k]:-no summary line}
        done
    done
    : >"$work/$group.tsv"
    for ((k = 0; k < n; k++)); do
        local line
        if [ -n "${failed[k]}" ]; then
            line=$(printf '%s\t-\t-\t-\t-\t%s\t%s' "${S_LABEL[k]}" "${S_IMG[k]}" "${failed[k]}")
            note "$group ${S_LABEL[k]}: failed: ${failed[k]}"
        else
            line=$(awk -F'\t' -v k="$k" -v label="${S_LABEL[k]}" -v img="${S_IMG[k]}" '
                $1 == k { split($2, f, " "); t[++n] = f[1]; rays = f[2] }
                END {
                    for (i = 2; i <= n; i++) { x = t[i]; for (j = i - 1; j >= 1 && t[j] > x; j--) t[j + 1] = t[j]; t[j + 1] = x }
                    printf "%s\t%.4f\t%.4f\t%.4f\t%d\t%s\tok\t%.4f\t%.4f\t%d", label, q(0.5), t[1], t[n], rays, img, q(0.25), q(0.75), n
                }
                function q(p,    x, i) { x = 1 + p * (n - 1); i = int(x); return i >= n ? t[n] : t[i] + (x - i) * (t[i + 1] - t[i]) }' "$times")
            note "$group ${S_LABEL[k]}: $(printf '%s' "$line" | awk -F'\t' '{ printf "%.3f s (%.3f-%.3f, quartiles %.3f-%.3f), %d runs, %d rays", $2, $3, $4, $8, $9, $10, $5 }')"
        fi
        printf '%s\n' "$line" >>"$work/$group.tsv"
    done
}

# measure_steady GROUP ROUNDS MAX_ROUNDS SPREAD: measure GROUP, then two more
# rounds at a time while a setting has run fewer than 5 times, or its quartiles
# lie further apart than SPREAD times its median (a burst of other work on the
# shared machine), and fewer than MAX_ROUNDS times.  Its median then rests on
# the quiet runs.
measure_steady() {
    local group=$1 rounds=$2 max=$3 spread=$4
    measure "$group" "$rounds"
    while awk -F'\t' -v s="$spread" -v m="$max" '$7 == "ok" && $10 < m && $2 > 0 && ($10 < 5 || ($9 - $8) > s * $2) { f = 1 }
                                            END { exit !f }' "$work/$group.tsv"; do
        MEASURE_MORE=1 measure "$group" 2
    done
}

# field GROUP LABEL COLUMN: one column (2 median, 3 min, 4 max, 5 rays,
# 6 image, 7 status, 8 and 9 the quartiles, 10 the runs) of a measured setting.
field() { awk -F'\t' -v l="$2" -v c="$3" '$1 == l { print $c; exit }' "$work/$1.tsv"; }

# diff_of A.png B.png: "SHARE_% MAXDIFF" (imgcmp), or "- -" when either is missing.
diff_of() {
    if [ -f "$1" ] && [ -f "$2" ]; then
        "$tools/imgcmp" "$1" "$2" | awk '{ print $1, $2 }'
    else
        echo "- -"
    fi
}

# error_of A.png B.png: "RMSE PSNR MAE SHARE_% MAXDIFF" (imgcmp: the error in levels of 0-255, the
# PSNR in dB, then the share of differing pixels and the largest difference), or "- - - - -" when
# either is missing.
error_of() {
    if [ -f "$1" ] && [ -f "$2" ]; then
        "$tools/imgcmp" "$1" "$2" | awk '{ print $6, $7, $5, $1, $2 }'
    else
        echo "- - - - -"
    fi
}

# ratio A B: A / B to two decimals, or "-".
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "-" || b == "-" || b + 0 == 0) print "-"; else printf "%.2f\n", a / b }'; }

# calibrated_size COMMAND...: a size "WxH" with the aspect of the command's
# own image at which it renders in about $target seconds on one thread
# (clamped to sides of $min_side, default 16, to 2048 pixels).  Runs the
# command once at its own size on one thread.
calibrated_size() {
    local img=$work/calibrate.png log=$work/calibrate.log
    # shellcheck disable=SC2048,SC2086
    if ! $* -j 1 -o "$img" </dev/null >"$log" 2>&1; then
        echo "256x256"
        return
    fi
    local t
    t=$(summary_of "$log" | awk '{ print $1 }')
    read -r w h < <("$tools/imgcmp" size "$img")
    awk -v t="${t:-0}" -v w="$w" -v h="$h" -v target="$target" -v m="${min_side:-16}" 'BEGIN {
        if (t < 0.001) t = 0.001
        f = sqrt(target / t)
        W = int(w * f + 0.5); H = int(h * f + 0.5)
        if (W > 2048) { H = int(H * 2048 / W); W = 2048 } if (H > 2048) { W = int(W * 2048 / H); H = 2048 }
        if (W < m) W = m; if (H < m) H = m
        printf "%dx%d\n", W, H
    }'
}

# scaled_size WxH F: the size with both sides multiplied by F.
scaled_size() { echo "$1" | awk -F'x' -v f="$2" '{ W = int($1 * f + 0.5); H = int($2 * f + 0.5); if (W < 8) W = 8; if (H < 8) H = 8; printf "%dx%d\n", W, H }'; }

# knobs_of RENDERER: the knobs of a renderer's --help (common/options.c
# prints each as "      --NAME=V   HELP (a|b|c; default a)" or "(default N)"),
# one a line: NAME <tab> choice|number <tab> DEFAULT <tab> CHOICES (- for a
# number) <tab> HELP.
knobs_of() {
    "$1" --help 2>/dev/null | awk '/^      --[A-Za-z0-9_-]+=V / {
        name = $1; sub(/^--/, "", name); sub(/=V$/, "", name)
        rest = $0; sub(/^ *--[^ ]+ +/, "", rest)
        if (match(rest, /\([^()]*; default [^()]*\)$/)) {
            inner = substr(rest, RSTART + 1, RLENGTH - 2); help = substr(rest, 1, RSTART - 2)
            split(inner, p, /; default /); choices = p[1]; gsub(/[|]/, " ", choices)
            printf "%s\tchoice\t%s\t%s\t%s\n", name, p[2], choices, help
        } else if (match(rest, /\(default [^()]*\)$/)) {
            d = substr(rest, RSTART + 9, RLENGTH - 10); help = substr(rest, 1, RSTART - 2)
            printf "%s\tnumber\t%s\t-\t%s\n", name, d, help
        }
    }'
}

# knob_plan NAME KIND DEFAULT CHOICES: the settings of a knob and its
# reference, from bench/knobs.conf or guessed (see there): prints
# "skip" or "VALUE... ref=VALUE".
knob_plan() {
    local name=$1 kind=$2 default=$3 choices=$4 conf
    conf=$(awk -v n="$name" '$1 == n { $1 = ""; print; exit }' bench/knobs.conf 2>/dev/null)
    case " $conf " in *" skip "*) echo skip; return ;; esac
    awk -v conf="$conf" -v kind="$kind" -v d="$default" -v choices="$choices" 'BEGIN {
        n = split(conf, w, " "); nv = 0; ref = ""
        for (k = 1; k <= n; k++) if (w[k] ~ /^ref=/) ref = substr(w[k], 5); else v[++nv] = w[k]
        if (nv == 0 && kind == "choice") { nv = split(choices, v, " "); if (ref == "") ref = d }
        if (nv == 0 && kind == "number") {
            if (d ~ /^-?[0-9]+$/) {
                if (d + 0 <= 0) { print "skip"; exit }
                v[++nv] = 1; h = int(d / 2); if (h > 1 && h != d) v[++nv] = h
                if (d != 1) v[++nv] = d; v[++nv] = 2 * d; if (ref == "") ref = "max"
            } else {
                v[++nv] = sprintf("%g", d / 10); v[++nv] = d; v[++nv] = sprintf("%g", d * 10)
            }
        }
        # The default under the name --help gives it (1e-3 in the list is 0.001 there).
        found_d = 0
        for (k = 1; k <= nv; k++) if (v[k] == d || (kind == "number" && v[k] + 0 == d + 0)) { found_d = 1; v[k] = d }
        if (!found_d) v[++nv] = d
        if (kind == "number" && ref != "max" && ref != "min" && ref != "" && ref + 0 == d + 0) ref = d
        if (kind == "number")
            for (i = 2; i <= nv; i++) { x = v[i]; for (j = i - 1; j >= 1 && v[j] + 0 > x + 0; j--) v[j + 1] = v[j]; v[j + 1] = x }
        if (ref == "max" || ref == "min") {
            best = v[1]; for (k = 2; k <= nv; k++) if ((ref == "max" && v[k] + 0 > best + 0) || (ref == "min" && v[k] + 0 < best + 0)) best = v[k]
            ref = best
        }
        ok = 0; for (k = 1; k <= nv; k++) if (v[k] == ref) ok = 1
        if (!ok) ref = d
        line = ""; for (k = 1; k <= nv; k++) line = line v[k] " "
        print line "ref=" ref
    }'
}

# labels.awk - where the labels of a knob plot go, so that none covers another
# (bench/plots.sh, knob_plot).
#
# Input: the plot's data, "X Y LABEL DEFAULT SCENE" (X > 0; LABEL "" for none), and
# the axes as variables: xmin, xmax, logx (1: log scale), ymin, ymax, logy; key=0 when the key is not
# in the plot's top right corner; char_w, a character's width as a share of the plot's (0.0095).
# Output, one line per label: "LX LY \"TEXT\" X Y SCENE MOVED": the label's
# left end at (LX, LY) for the point (X, Y); MOVED 1 when it had to go further
# from its point than its usual place (the plot then draws a leader line).
#
# Points of one scene at the same place share one label ("depth=4, depth=8").
# Each label then takes the first free place, in the plot's own units (0 to 1
# across and up), of: beside its point (above for the built-in scene, below
# for the scene of all stages), then one line further away, one line the
# other way, two lines, and so on, then the same a fifth of the width further
# right, and so on; a place is free when its box meets no point, no label
# placed before it and not the key (top right).
function u_of(x) { return logx ? (log(x) - log(xmin)) / (log(xmax) - log(xmin)) : (x - xmin) / (xmax - xmin) }
function v_of(y) { return logy ? (log(y) - log(ymin)) / (log(ymax) - log(ymin)) : (y - ymin) / (ymax - ymin) }
function x_of(u) { return logx ? exp(log(xmin) + u * (log(xmax) - log(xmin))) : xmin + u * (xmax - xmin) }
function y_of(v) { return logy ? exp(log(ymin) + v * (log(ymax) - log(ymin))) : ymin + v * (ymax - ymin) }
function free(l, r, b, t,    k) {
    if (l < 0 || r > 1 || b < 0 || t > 1)
        return 0
    for (k = 1; k <= n_box; k++)
        if (l < box_r[k] && box_l[k] < r && b < box_t[k] && box_b[k] < t)
            return 0
    return 1
}
BEGIN {
    if (char_w == "") char_w = 0.0095
    line_h = 0.045; gap = 0.012
    # the key, top right, unless key=0 (the plot has it elsewhere)
    n_box = 0
    if (key != "0") { n_box = 1; box_l[1] = 0.26; box_r[1] = 1; box_b[1] = 0.77; box_t[1] = 1 }
}
{ # every point, labelled or not, keeps labels off it
    n_box++; box_l[n_box] = u_of($1) - 0.015; box_r[n_box] = u_of($1) + 0.01
    box_b[n_box] = v_of($2) - 0.03; box_t[n_box] = v_of($2) + 0.03
}
$3 != "\"\"" {
    key = $5 SUBSEP int(u_of($1) * 150 + 0.5) SUBSEP int(v_of($2) * 150 + 0.5)
    if (!(key in text)) {
        order[++n] = key; px[key] = $1; py[key] = $2; scene[key] = $5; text[key] = $3
    } else {
        text[key] = text[key] ", " $3
    }
}
END {
    for (i = 1; i <= n; i++) {
        key = order[i]
        u = u_of(px[key]) + gap; v0 = v_of(py[key]) + (scene[key] == 0 ? 0.6 : -0.6) * line_h
        away = scene[key] == 0 ? 1 : -1
        w = length(text[key]) * char_w
        placed = 0
        for (col = 0; col <= 4 && !placed; col++)
            for (step = 0; step <= 40 && !placed; step++) {
                k = int((step + 1) / 2) * (step % 2 ? 1 : -1) * away
                v = v0 + k * line_h; l = u + 0.2 * col
                if (free(l, l + w, v - line_h / 2, v + line_h / 2)) {
                    placed = 1
                    n_box++; box_l[n_box] = l; box_r[n_box] = l + w; box_b[n_box] = v - line_h / 2; box_t[n_box] = v + line_h / 2
                    printf "%.6g %.6g \"%s\" %s %s %s %d\n", x_of(l), y_of(v), text[key], px[key], py[key], scene[key],
                        k != 0 || col != 0
                }
            }
        if (!placed) # no free place: beside the point, as gnuplot would put it
            printf "%.6g %.6g \"%s\" %s %s %s 0\n", x_of(u), y_of(v0), text[key], px[key], py[key], scene[key]
    }
}

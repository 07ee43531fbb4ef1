#!/bin/bash
# hints.sh DIR - the suites' hints name the mistakes a student makes.
#
# Copies the project into DIR, plants one mistake at a time into a copy of a
# solution (a sed script on its code lines, never on its comments), builds
# the chapter's suite, runs the test that must catch it, and checks that the
# output names the mistake (grep -E patterns, all must be found) and nothing
# it must not (one pattern).  Run by tests/make.sh; needs solutions/.
set -u
dir=${1:?usage: hints.sh DIR}
cc=${CC:-cc}
mkdir -p "$dir" || exit 1
cp -R Makefile common chapters solutions tests tools fuzz "$dir/" || exit 1
mkdir -p "$dir/bench" && cp -R bench/grid "$dir/bench/" || exit 1
failed=0

# plant NAME CHAPTER FILE SED TEST MUST_NOT PATTERN...: STUDENT=1 with the
# other chapters from the reference when FILE is "skeleton" (the untouched
# exercise), else FILE of solutions/CHAPTER edited by SED; a FILE with a
# slash is that path, a file the chapter hands out complete (chapters/...).
plant() {
    local name=$1 chapter=$2 file=$3 script=$4 test=$5 must_not=$6
    shift 6
    local build=build-planted make_args=() out src
    case $file in
    */*) src=$file ;;
    *) src=solutions/$chapter/$file ;;
    esac
    if [ "$file" = skeleton ]; then
        local others
        others=$(cd "$dir/chapters" && ls -d [0-9][0-9]_* | grep -v "^$chapter" | cut -c1-2 | tr '\n' ' ')
        make_args=(STUDENT=1 "REFERENCE=$others" BUILD=$build-skeleton)
        build=$build-skeleton
    else
        cp "$src" "$dir/$src"
        sed -i "$script" "$dir/$src"
        if cmp -s "$src" "$dir/$src"; then
            echo "  FAIL    $name: the sed script changed nothing in $src"
            failed=$((failed + 1))
            return
        fi
        make_args=(BUILD=$build)
    fi
    if ! make -s --no-print-directory -C "$dir" CC="$cc" "${make_args[@]}" "$build/tests/test_$chapter" \
            >"$dir/build.log" 2>&1; then
        echo "  FAIL    $name: the planted mistake does not compile:"
        sed 's/^/          /' "$dir/build.log" | head -20
        failed=$((failed + 1))
    else
        out=$("$dir/$build/tests/test_$chapter" --only "$test" 2>&1)
        local pattern missing=""
        for pattern in "$@"; do
            printf '%s\n' "$out" | grep -qE -- "$pattern" || missing="$missing '$pattern'"
        done
        if printf '%s\n' "$out" | grep -q '^\[       OK \]'; then
            missing="$missing (the test passed)"
        fi
        if [ -n "$missing" ] || { [ -n "$must_not" ] && printf '%s\n' "$out" | grep -qE -- "$must_not"; }; then
            echo "  FAIL    $name: $test does not say$missing${must_not:+ or says '$must_not'}:"
            printf '%s\n' "$out" | sed 's/^/          /' | head -30
            failed=$((failed + 1))
        else
            echo "  ok      $name"
        fi
    fi
    [ "$file" = skeleton ] || cp "$src" "$dir/$src"
}

# Chapter 01: the image's width and height, each in its place.
plant "hint: viewWidth and viewHeight swapped" 01_camera_rays camera.c \
    's|real us = (u - (real)0.5) \* cam->width;|real us = (u - (real)0.5) * cam->height;|; s|real vs = (v - (real)0.5) \* cam->height;|real vs = (v - (real)0.5) * cam->width;|' \
    test_perspective_rays "" "viewWidth and viewHeight swapped"
plant "hint: v divided by n_x" 01_camera_rays pixel.c \
    's|\*v = ((real)j + dv) / (real)ny;|*v = ((real)j + dv) / (real)nx; (void)ny;|' \
    test_pixel_centres "" "v divided by n_x"
# The basis's signs, orders and lengths; the rays of both projections; the pixel's mapping.
plant "hint: w along viewDir" 01_camera_rays camera.c \
    's|\*w = vec3_neg(unit(view_dir));|*w = unit(view_dir);|' \
    test_basis_orthonormal_right_handed "" "wrong sign of w: w = -viewDir / \|viewDir\|"
plant "hint: u = viewUp x viewDir" 01_camera_rays camera.c \
    's|vec3_cross(unit(view_dir), unit(view_up))|vec3_cross(unit(view_up), unit(view_dir))|' \
    test_basis_lecture_camera "" "u points left: u = viewDir x viewUp"
plant "hint: v = u x w" 01_camera_rays camera.c \
    's|\*v = vec3_cross(\*w, \*u);|*v = vec3_cross(*u, *w);|' \
    test_basis_lecture_camera "" "v points down: v = w x u"
plant "hint: u not normalized" 01_camera_rays camera.c \
    's|\*u = unit(vec3_cross(unit(view_dir), unit(view_up)));|*u = vec3_cross(unit(view_dir), unit(view_up));|' \
    test_basis_lecture_camera "" "u not normalized"
plant "hint: v taken as viewUp" 01_camera_rays camera.c \
    's|\*v = vec3_cross(\*w, \*u);|*v = unit(view_up);|' \
    test_basis_lecture_camera "" "v taken as viewUp"
plant "hint: w not normalized" 01_camera_rays camera.c \
    's|\*w = vec3_neg(unit(view_dir));|*w = vec3_neg(view_dir);|' \
    test_basis_lecture_camera "" "w not normalized"
plant "hint: the perspective ray along +d w" 01_camera_rays camera.c \
    's|vec3_scale(cam->w, -cam->d)|vec3_scale(cam->w, cam->d)|' \
    test_four_corner_rays_exactly "" "wrong sign of w: -d w"
plant "hint: the perspective d normalized" 01_camera_rays camera.c \
    's|r.d = vec3_add(vec3_scale(cam->w, -cam->d), offset);|r.d = vec3_normalize(vec3_add(vec3_scale(cam->w, -cam->d), offset));|' \
    test_perspective_rays "" "d normalized: keep d = -d w"
plant "hint: the image rectangle not centred" 01_camera_rays camera.c \
    's|real us = (u - (real)0.5) \* cam->width;|real us = u * cam->width;|; s|real vs = (v - (real)0.5) \* cam->height;|real vs = v * cam->height;|' \
    test_perspective_rays "" "the rectangle not centred on the view direction"
plant "hint: v_s flipped in the camera" 01_camera_rays camera.c \
    's|real vs = (v - (real)0.5) \* cam->height;|real vs = ((real)0.5 - v) * cam->height;|' \
    test_perspective_rays "" "v flipped: \+ v_s v"
plant "hint: the orthographic ray along +w" 01_camera_rays camera.c \
    's|r.d = vec3_neg(cam->w);|r.d = cam->w;|' \
    test_orthographic_rays "" "wrong sign of w: the camera looks along -w, d = -w"
plant "hint: the orthographic rays from the eye" 01_camera_rays camera.c \
    's|r.p = vec3_add(cam->e, offset);|r.p = cam->e; (void)offset;|' \
    test_orthographic_rays "" "every ray starts at the eye"
plant "hint: the orthographic d scaled by projDistance" 01_camera_rays camera.c \
    's|r.d = vec3_neg(cam->w);|r.d = vec3_scale(cam->w, -cam->d);|' \
    test_orthographic_rays "" "d scaled by projDistance"
plant "hint: du ignored" 01_camera_rays pixel.c \
    's|(real)i + du)|(real)i + (real)0.5 + 0 * du)|; s|(real)j + dv)|(real)j + (real)0.5 + 0 * dv)|' \
    test_pixel_sample_offsets "" "du ignored"
plant "hint: divided by n_x - 1" 01_camera_rays pixel.c \
    's|(real)nx;|(real)(nx - 1);|; s|(real)ny;|(real)(ny - 1);|' \
    test_pixel_centres "" "divided by n_x - 1"
plant "hint: v flipped in the mapping" 01_camera_rays pixel.c \
    's|\*v = ((real)j + dv) / (real)ny;|*v = 1 - ((real)j + dv) / (real)ny;|' \
    test_pixel_centres "" "v flipped: j = 0 is the bottom row"
plant "hint: integer division" 01_camera_rays pixel.c \
    's|((real)i + du) / (real)nx|(real)(i / nx) + du / (real)nx|; s|((real)j + dv) / (real)ny|(real)(j / ny) + dv / (real)ny|' \
    test_pixel_centres "" "integer division"
plant "hint: u and v swapped" 01_camera_rays pixel.c \
    's|u = ((real)i + du) / (real)nx|u = ((real)j + dv) / (real)ny|; s|v = ((real)j + dv) / (real)ny|v = ((real)i + du) / (real)nx|' \
    test_pixel_centres "" "u and v swapped: u goes with the column i"
plant "hint: du and dv swapped" 01_camera_rays pixel.c \
    's|(real)i + du)|(real)i + dv)|; s|(real)j + dv)|(real)j + du)|' \
    test_pixel_sample_offsets "" "du and dv swapped"
plant "hint: u_s = u viewWidth - 1/2" 01_camera_rays camera.c \
    's|real us = (u - (real)0.5) \* cam->width;|real us = u * cam->width - (real)0.5;|; s|real vs = (v - (real)0.5) \* cam->height;|real vs = v * cam->height - (real)0.5;|' \
    test_perspective_rays "" "u_s = u viewWidth - 1/2"
# Chapter 02: a tangent ray is a hit; the robust discriminant's foot of the perpendicular.
plant "hint: a tangent ray refused by disc > 0" 02_sphere sphere.c \
    's|if (!(disc >= 0))$|if (!(disc > 0))|' \
    test_textbook "" "tangent ray is a hit" "not disc > 0"
plant "hint: C with + R^2" 02_sphere sphere.c \
    '0,/real C = vec3_dot(f, f) - s->radius \* s->radius;/s//real C = vec3_dot(f, f) + s->radius * s->radius;/' \
    test_roots_textbook "" "R\^2 is subtracted, not added"
plant "hint: a factor 4 in disc = B^2 - A C" 02_sphere sphere.c \
    's|B \* B - A \* C|B * B - 4 * A * C|' \
    test_roots_textbook "" "no factor 4"
plant "hint: l with t_m of the wrong sign" 02_sphere sphere.c \
    's|vec3_scale(r.d, -B / A)|vec3_scale(r.d, B / A)|' \
    test_roots_robust "" "the sign of t_m is wrong"
plant "hint: l with t_m not divided by A" 02_sphere sphere.c \
    's|vec3_scale(r.d, -B / A)|vec3_scale(r.d, -B)|' \
    test_roots_robust "" "divided by A = d\.d"
# The textbook roots and the stable pair: A in its places, R squared, t0 and t1 of the pair.
plant "hint: the textbook roots not divided by A" 02_sphere sphere.c \
    's|\*t0 = (-B - root) / A;|*t0 = (-B - root);|; s|\*t1 = (-B + root) / A;|*t1 = (-B + root);|' \
    test_roots_textbook "" "the roots not divided by A = d\.d"
plant "hint: the textbook discriminant without A" 02_sphere sphere.c \
    's|real disc = B \* B - A \* C;|real disc = B * B - C;|' \
    test_roots_textbook "" "disc = B\^2 - A C: the factor A is missing"
plant "hint: the robust discriminant with R, not R^2" 02_sphere sphere.c \
    's|real disc = A \* (s->radius \* s->radius - vec3_dot(l, l));|real disc = A * (s->radius - vec3_dot(l, l));|' \
    test_roots_robust "" "R squared, not R"
plant "hint: the stable pair's t1 = C / A" 02_sphere sphere.c \
    's|\*t1 = q != 0 ? C / q : \*t0;|*t1 = C / A;|' \
    test_roots_robust "" "t1 = C / q, not C / A"
plant "hint: the stable pair's t0 = -q / A" 02_sphere sphere.c \
    's|\*t0 = q / A;|*t0 = -q / A;|' \
    test_roots_robust "" "the minus sign is inside q"
# f's sign, the robust discriminant and pair, the normal, the window and the choice of root.
plant "hint: f = c - p" 02_sphere sphere.c \
    '0,/vec3 f = vec3_sub(r.p, s->center);/s//vec3 f = vec3_sub(s->center, r.p);/' \
    test_roots_textbook "" "the roots are negated: f = p - c"
plant "hint: the robust discriminant without A" 02_sphere sphere.c \
    's|real disc = A \* (s->radius \* s->radius - vec3_dot(l, l));|real disc = s->radius * s->radius - vec3_dot(l, l); (void)A;|' \
    test_roots_robust "" "disc = A \(R\^2 - l\.l\): the factor A is missing"
plant "hint: the small root by the textbook formula" 02_sphere sphere.c \
    's|real q = -(B + (B < 0 ? -root : root));|real q = -(B + (B < 0 ? root : -root));|' \
    test_small_root_near_surface "" "the small root computed as \(-B -\+ sqrt\(disc\)\) / A cancels"
plant "hint: t1 = q / C" 02_sphere sphere.c \
    's|\*t1 = q != 0 ? C / q : \*t0;|*t1 = q / C;|' \
    test_roots_robust "" "t1 = C / q \(the product of the roots is C / A\), not q / C"
plant "hint: t1 = C / q with q = 0" 02_sphere sphere.c \
    's|\*t1 = q != 0 ? C / q : \*t0;|*t1 = C / q;|' \
    test_b_zero_sign "" "t1 = C / q with q = 0 is 0 / 0 = NaN"
plant "hint: no bound (6) on t1" 02_sphere sphere.c \
    's|if (\*t1 \* \*t1 \* A > real_abs(C))|if (0)|' \
    test_tangent_rays_from_the_surface "" "t1 = C / q without the bound \(6\)"
plant "hint: the normal divided by R" 02_sphere sphere.c \
    's|return length > 0 ? vec3_scale(m, 1 / length) : m;|return vec3_scale(m, 1 / s->radius); (void)length;|' \
    test_normal_unit_far_from_origin "" "divided by R: x is on the sphere only up to rounding"
plant "hint: the normal inwards" 02_sphere sphere.c \
    's|vec3 m = vec3_sub(x, s->center);|vec3 m = vec3_sub(s->center, x);|' \
    test_normal_unit_far_from_origin "" "the normal points inwards"
plant "hint: the normal not normalized" 02_sphere sphere.c \
    's|return length > 0 ? vec3_scale(m, 1 / length) : m;|return m; (void)length;|' \
    test_normal_unit_far_from_origin "" "not normalized: n = \(x - c\) / \|x - c\|"
plant "hint: the normal NaN at the centre" 02_sphere sphere.c \
    's|return length > 0 ? vec3_scale(m, 1 / length) : m;|return vec3_scale(m, 1 / length);|' \
    test_normal_unit_far_from_origin "" "divided by \|x - c\| = 0"
plant "hint: the normal's guard a fixed epsilon" 02_sphere sphere.c \
    's|return length > 0 ? vec3_scale(m, 1 / length) : m;|return length > REAL_EPSILON ? vec3_scale(m, 1 / length) : m;|' \
    test_normal_unit_far_from_origin "" "a fixed epsilon takes every point of a small"
# |x - c| by its squares: zero or not unit for a sphere at either end of the range.
plant "hint: |x - c| as sqrt((x - c).(x - c))" 02_sphere sphere.c \
    's|length = vec3_length(m)|length = real_sqrt(vec3_dot(m, m))|' \
    test_normal_unit_far_from_origin "" "the squares underflowed to 0"
plant "hint: the sphere's t == t_min accepted" 02_sphere sphere.c \
    's|if (near > t_min \&\& near < t_max)|if (near >= t_min \&\& near < t_max)|; s|if (far > t_min \&\& far < t_max)|if (far >= t_min \&\& far < t_max)|' \
    test_nearest_root "" "accepted t == t_min: the window \(t_min, t_max\) is open"
plant "hint: the sphere's t == t_max accepted" 02_sphere sphere.c \
    's|if (near > t_min \&\& near < t_max)|if (near > t_min \&\& near <= t_max)|; s|if (far > t_min \&\& far < t_max)|if (far > t_min \&\& far <= t_max)|' \
    test_nearest_root "" "accepted t == t_max \(or t_max ignored\)"
plant "hint: no far root from inside" 02_sphere sphere.c \
    's|if (far > t_min \&\& far < t_max)|if (0 \&\& far > t_min)|' \
    test_nearest_root "" "no hit when the near root is before t_min"
plant "hint: t0 taken as the nearer root" 02_sphere sphere.c \
    's|real near = real_fmin(t0, t1), far = real_fmax(t0, t1);|real near = t0, far = t1;|' \
    test_nearest_root "" "assumed t0 is the nearer root"
plant "hint: the far root first" 02_sphere sphere.c \
    's|real near = real_fmin(t0, t1), far = real_fmax(t0, t1);|real near = real_fmax(t0, t1), far = real_fmin(t0, t1);|' \
    test_nearest_root "" "took the far root"
plant "hint: the robust discriminant's sign reversed" 02_sphere sphere.c \
    's|real disc = A \* (s->radius \* s->radius - vec3_dot(l, l));|real disc = A * (vec3_dot(l, l) - s->radius * s->radius);|' \
    test_roots_robust "" "the discriminant's sign reversed"
plant "hint: the textbook discriminant's sign reversed" 02_sphere sphere.c \
    's|real disc = B \* B - A \* C;|real disc = A * C - B * B;|' \
    test_roots_textbook "" "the discriminant's sign reversed"
plant "hint: the textbook A = |d|" 02_sphere sphere.c \
    '0,/real A = vec3_dot(r.d, r.d);/s//real A = vec3_length(r.d);/' \
    test_roots_textbook "" "A = d\.d, the squared length of d, not \|d\|"
plant "hint: the textbook B = 2 d.f" 02_sphere sphere.c \
    '0,/real B = vec3_dot(r.d, f);/s//real B = 2 * vec3_dot(r.d, f);/' \
    test_roots_textbook "" "B = d\.f, not 2 d\.f"
# Chapter 03: which comparison let a false hit in, or kept a hit out.
plant "hint: the triangle's edges open" 03_triangle triangle.c \
    's|gamma >= 0 \&\& gamma <= 1|gamma > 0 \&\& gamma < 1|; s|beta >= 0 \&\& beta + gamma <= 1|beta > 0 \&\& beta + gamma < 1|' \
    test_vertices_and_edge_midpoints "" "the edges are open"
plant "hint: beta + gamma <= 1 left out" 03_triangle triangle.c \
    's|beta + gamma <= 1|beta <= 1|' \
    test_just_outside "" "beta \+ gamma > 1 accepted"
plant "hint: beta >= 0 left out" 03_triangle triangle.c \
    's|beta >= 0 \&\& beta + gamma|1 \&\& beta + gamma|' \
    test_hit_point_is_consistent "" "a negative beta or gamma accepted"
plant "hint: the triangle's t == t_min accepted" 03_triangle triangle.c \
    's|!(t > t_min \&\&|!(t >= t_min \&\&|' \
    test_t_window "" "accepted t == t_min"
plant "hint: the triangle's t == t_max accepted" 03_triangle triangle.c \
    's|t < t_max))|t <= t_max))|' \
    test_t_window "" "accepted t == t_max"
plant "hint: beta and gamma swapped" 03_triangle triangle.c \
    's|.beta = beta, .gamma = gamma|.beta = gamma, .gamma = beta|' \
    test_vertices_and_edge_midpoints "" "beta and gamma swapped"
# A column of Cramer's rule with the wrong sign: a point inside missed, a point outside hit.
plant "hint: a - p taken as p - a" 03_triangle triangle.c \
    's|vec3 a_p = vec3_sub(tri->a, r.p);|vec3 a_p = vec3_sub(r.p, tri->a);|' \
    test_centroid "" "a point inside missed: .*column of the wrong sign"
plant "hint: gamma's columns swapped" 03_triangle triangle.c \
    's|det3(a_b, a_p, r.d) / M|det3(a_b, r.d, a_p) / M|' \
    test_just_outside "" "a point outside reported with t, beta and gamma in range: a column"
# Chapter 04: the loop over the list stops early, or lets a farther hit replace a closer one.
plant "hint: the closest-hit loop stops at the first hit" 04_many_shapes closest_hit.c \
    's|found = true;|found = true; break;|' \
    test_closest_hit_in_any_order "" "stopped at the first surface it hit"
plant "hint: t_best not shrunk" 04_many_shapes closest_hit.c \
    's|t_best = candidate.t;||' \
    test_closest_hit_in_any_order "" "later in the list replaced the closer"
# The loop's index, window, found flag and bounds; the first of two at the same t.
plant "hint: the surface's index not set" 04_many_shapes closest_hit.c \
    's|candidate.surface = k;||' \
    test_empty_and_single "" "hit->surface is no index of the list"
plant "hint: t_best started at infinity" 04_many_shapes closest_hit.c \
    's|real t_best = t_max;|real t_best = REAL_INFINITY; (void)t_max;|' \
    test_t_window "" "a hit at or outside the window"
plant "hint: every surface asked from t = 0" 04_many_shapes closest_hit.c \
    's|r, t_min, t_best, \&candidate|r, 0 * t_min, t_best, \&candidate|' \
    test_t_window "" "pass t_min on unchanged"
plant "hint: the loop from k = 1" 04_many_shapes closest_hit.c \
    's|int k = 0;|int k = 1;|' \
    test_closest_hit_in_any_order "" "a surface of the list never asked"
plant "hint: the loop to k < n - 1" 04_many_shapes closest_hit.c \
    's|k < list->n;|k < list->n - 1;|' \
    test_empty_and_single "" "a surface of the list never asked"
plant "hint: found set back to false by a miss" 04_many_shapes closest_hit.c \
    's|if (surface_intersect(\&list->items\[k\], list, r, t_min, t_best, \&candidate)) {|found = false; &|' \
    test_t_window "" "never back to false"
plant "hint: the later of two surfaces at the same t" 04_many_shapes closest_hit.c \
    's|r, t_min, t_best, \&candidate|r, t_min, nextafter(t_best, REAL_INFINITY), \&candidate|' \
    test_coincident_surfaces_first_wins "" "the first in the list keeps it"
plant "hint: an epsilon of the loop's own on t_best" 04_many_shapes closest_hit.c \
    's|r, t_min, t_best, \&candidate|r, t_min, t_best - REAL_EPSILON, \&candidate|' \
    test_closest_at_any_scale "" "a length of the loop's own"
plant "hint: t_best rounded through a float" 04_many_shapes closest_hit.c \
    's|t_best = candidate.t;|t_best = (float)candidate.t;|' \
    test_coincident_surfaces_first_wins "" "not rounded through a float"
# l = light.pos - point, not divided by r, with the right 1/r^2: the numbers
# of dividing by r instead of r^2.  Both must be named.
plant "hint: l not normalized (the numbers of 1/r)" 05_lambert lambert.c \
    's|vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));|vec3 l = to_light;|' \
    test_irradiance_facing "" "divided by r, not r\^2" "l not normalized"
# The light's intensity left out; r^2 taken as the length r.
plant "hint: L_d without the light's intensity" 05_lambert lambert.c \
    's|color_mul(k_d, light->intensity)|k_d|' \
    test_irradiance_facing "" "intensity I missing"
plant "hint: r^2 taken as the length" 05_lambert lambert.c \
    's|vec3_length_squared(to_light)|vec3_length(to_light)|' \
    test_irradiance_facing "" "r\^2 taken as the length"
# A threshold of its own on n . l (against acne, say): a band of black along every terminator.
plant "hint: n . l cut off below 1e-3" 05_lambert lambert.c \
    's|real cos_theta = real_fmax(0, vec3_dot(n, l));|real cos_theta = vec3_dot(n, l) < 1e-3 ? 0 : vec3_dot(n, l);|' \
    test_cosine_law "" "none at a small n \. l"
# l from the light to the point, and the cosine not clamped: each test that reads them names them.
plant "hint: l points away from the light (the light behind)" 05_lambert lambert.c \
    's|vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));|vec3 l = vec3_scale(to_light, -1 / real_sqrt(r2));|' \
    test_light_behind "" "l points away from the light"
plant "hint: the cosine not clamped (the built-in scene)" 05_lambert lambert.c \
    's|real cos_theta = real_fmax(0, vec3_dot(n, l));|real cos_theta = vec3_dot(n, l);|' \
    test_builtin_scene_rays "" "the cosine not clamped"
plant "hint: L_d clamped to 1" 05_lambert lambert.c \
    's|return color_scale(color_mul(k_d, light->intensity), cos_theta / r2);|color c = color_scale(color_mul(k_d, light->intensity), cos_theta / r2); return color_make(real_fmin(c.r, 1), real_fmin(c.g, 1), real_fmin(c.b, 1));|' \
    test_inverse_square "" "clamped to 1: a radiance may exceed 1"
# The falloff, k_d, a factor pi, |n . l|.
plant "hint: no 1/r^2" 05_lambert lambert.c \
    's|cos_theta / r2)|cos_theta)|' \
    test_irradiance_facing "" "no falloff: divide by r\^2"
plant "hint: k_d left out" 05_lambert lambert.c \
    's|return color_scale(color_mul(k_d, light->intensity), cos_theta / r2);|(void)k_d; return color_scale(light->intensity, cos_theta / r2);|' \
    test_irradiance_facing "" "k_d missing"
plant "hint: divided by pi" 05_lambert lambert.c \
    's|cos_theta / r2)|cos_theta / r2 / (real)3.14159265358979)|' \
    test_irradiance_facing "" "divided by pi"
plant "hint: |n . l|" 05_lambert lambert.c \
    's|real_fmax(0, vec3_dot(n, l))|real_abs(vec3_dot(n, l))|' \
    test_cosine_law "" "\|n \. l\|: a light behind the surface gives nothing"
# The shadow ray built by hand from the hit point: acne, and spawn_ray_to named.
plant "hint: a shadow ray from the hit point itself" 06_shadows shadow.c \
    's|ray shadow = spawn_ray_to(sp, light_pos, policy, &t_max);|(void)policy; t_max = 1; ray shadow = {sp->hit.point, vec3_sub(light_pos, sp->hit.point)};|' \
    test_no_acne_no_leak "" "% acne" "likely mistake: .*spawn_ray_to"
# A light in the surface's plane taken as in front; a ray counted for a light behind.
plant "hint: a light in the surface's plane in front" 06_shadows shadow.c \
    's|vec3_sub(light_pos, sp->hit.point)) > 0))|vec3_sub(light_pos, sp->hit.point)) >= 0))|' \
    test_light_behind_the_surface "" "> 0, not >= 0"
plant "hint: a shadow ray counted for a light behind" 06_shadows shadow.c \
    's|^    ++rays\[RAY_SHADOW\];$||; s|if (!(vec3_dot(sp->n|++rays[RAY_SHADOW]; &|' \
    test_light_behind_the_surface "" "no shadow ray towards a light behind the surface"
# The light behind, the shadow segment's ends, the count, the policy.
plant "hint: no test of a light behind" 06_shadows shadow.c \
    's|if (!(vec3_dot(sp->n, vec3_sub(light_pos, sp->hit.point)) > 0))|if (0)|' \
    test_light_behind_the_surface "" "a light behind the surface is blocked by the surface itself"
plant "hint: behind by the geometric normal" 06_shadows shadow.c \
    's|vec3_dot(sp->n, vec3_sub|vec3_dot(sp->hit.normal, vec3_sub|' \
    test_light_behind_the_surface "" "the side was judged by the geometric normal"
plant "hint: the shadow segment to infinity" 06_shadows shadow.c \
    's|shadow, 0, t_max, \&blocker|shadow, 0, REAL_INFINITY + 0 * t_max, \&blocker|' \
    test_occluder_between_beyond_behind "" "not beyond the light \(t_max, not infinity\)"
plant "hint: the shadow segment to t = 1" 06_shadows shadow.c \
    's|shadow, 0, t_max, \&blocker|shadow, 0, 1, \&blocker|' \
    test_shadow_ray_is_the_segment "" "the segment reaches the light"
plant "hint: the shadow ray not counted" 06_shadows shadow.c \
    's|++rays\[RAY_SHADOW\];|(void)rays;|' \
    test_occluder_between_beyond_behind "" "count the shadow ray"
plant "hint: the shadow window from an epsilon" 06_shadows shadow.c \
    's|shadow, 0, t_max, \&blocker|shadow, (real)1e-4, t_max, \&blocker|' \
    test_no_acne_no_leak "" "the window must be \(0, t_max\)"
plant "hint: a policy of its own" 06_shadows shadow.c \
    's|spawn_ray_to(sp, light_pos, policy, \&t_max)|spawn_ray_to(sp, light_pos, (eps_policy){0}, \&t_max); (void)policy|' \
    test_shadow_ray_is_the_segment "" "leave the surface by the policy given"
# x^p by a loop of products: right for whole p only.
plant "hint: x^p by an integer loop" 07_blinn_phong phong.c \
    's|real highlight = real_pow(real_fmax(0, vec3_dot(n, h)), p);|real highlight = 1; for (int i = 0; i < p; i++) highlight *= real_fmax(0, vec3_dot(n, h));|' \
    test_exponent_behaviour "" "p = 2\.5" "fractional p"
plant "hint: the specular term without the light's intensity" 07_blinn_phong phong.c \
    's|color_mul(k_s, light->intensity)|k_s|' \
    test_specular_per_channel "" "intensity I missing"
# The lights' loop: ambient once, and a blocked light skipped, not the end.
plant "hint: ambient added with each light" 07_blinn_phong shade_phong.c \
    's|result = color_add(result, light_contribution(tr, sp, shader, light));|result = color_add(result, color_add(tr->desc->ambient, light_contribution(tr, sp, shader, light)));|' \
    test_two_lights_add "" "ambient added again with each light"
plant "hint: the lights' loop stops at a blocked light" 07_blinn_phong shade_phong.c \
    's|result = color_add(result, light_contribution(tr, sp, shader, light));|& else break;|' \
    test_two_lights_add "" "loop stopped at the blocked first light"
# Phong's r . v for Blinn-Phong's n . h; p as a factor; the lights' loop from k = 1.
plant "hint: Phong's (r . v)^p" 07_blinn_phong phong.c \
    's|vec3 h = vec3_normalize(vec3_add(v, l));|vec3 h = vec3_sub(vec3_scale(n, 2 * vec3_dot(n, l)), l);|; s|real_fmax(0, vec3_dot(n, h))|real_fmax(0, vec3_dot(v, h))|' \
    test_half_vector "" "Phong's \(r \. v\)\^p"
plant "hint: p as a factor" 07_blinn_phong phong.c \
    's|real_pow(real_fmax(0, vec3_dot(n, h)), p)|p * real_fmax(0, vec3_dot(n, h))|' \
    test_half_vector "" "p as a factor"
plant "hint: the lights' loop from k = 1" 07_blinn_phong shade_phong.c \
    's|for (int k = 0; k < tr->desc->n_lights; k++)|for (int k = 1; k < tr->desc->n_lights; k++)|' \
    test_two_lights_add "" "only the last light: the loop starts at k = 0"
# The half vector, the clamps, the forms, the falloff; the ambient term and the lights' loop.
plant "hint: h = v - l" 07_blinn_phong phong.c \
    's|vec3_normalize(vec3_add(v, l))|vec3_normalize(vec3_sub(v, l))|' \
    test_half_vector "" "h is the sum v \+ l, not the difference"
plant "hint: h not normalized" 07_blinn_phong phong.c \
    's|vec3_normalize(vec3_add(v, l))|vec3_add(v, l)|' \
    test_half_vector "" "h not normalized"
plant "hint: h halved" 07_blinn_phong phong.c \
    's|vec3_normalize(vec3_add(v, l))|vec3_scale(vec3_add(v, l), (real)0.5)|' \
    test_half_vector "" "h halved"
plant "hint: n . h not clamped" 07_blinn_phong phong.c \
    's|real_pow(real_fmax(0, vec3_dot(n, h)), p)|real_pow(vec3_dot(n, h), p)|' \
    test_exponent_behaviour "" "clamp n \. h before the power"
plant "hint: the lecture's cosine not clamped" 07_blinn_phong phong.c \
    's|highlight \*= real_fmax(0, vec3_dot(n, l));|highlight *= vec3_dot(n, l);|' \
    test_course_and_lecture_forms "" "the lecture's cosine is max\(0, n \. l\)"
plant "hint: the forms swapped" 07_blinn_phong phong.c \
    's|if (form == PHONG_LECTURE)|if (form != PHONG_LECTURE)|' \
    test_exponent_behaviour "" "times n \. l: that is the lecture's form"
plant "hint: the specular term without 1/r^2" 07_blinn_phong phong.c \
    's|highlight / r2)|highlight)|' \
    test_exponent_behaviour "" "no falloff: divide by r\^2"
plant "hint: l not normalized before h" 07_blinn_phong phong.c \
    's|vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));|vec3 l = to_light;|' \
    test_half_vector "" "l not normalized before the bisector"
plant "hint: no ambient" 07_blinn_phong shade_phong.c \
    's|color result = tr->desc->ambient;|color result = color_make(0, 0, 0);|' \
    test_two_lights_add "" "ambient missing"
plant "hint: ambient times k_d" 07_blinn_phong shade_phong.c \
    's|color result = tr->desc->ambient;|color result = color_mul(tr->desc->ambient, shader->diffuse_color);|' \
    test_ambient_and_lights_behind "" "ambient times k_d"
plant "hint: only the first light" 07_blinn_phong shade_phong.c \
    's|for (int k = 0; k < tr->desc->n_lights; k++)|for (int k = 0; k < 1 \&\& k < tr->desc->n_lights; k++)|' \
    test_two_lights_add "" "only the first light: loop over all n_lights"
plant "hint: a policy of its own for the lights" 07_blinn_phong shade_phong.c \
    's|tracer_eps(tr), rays)|(eps_policy){0}, rays)|' \
    test_shadow_policy_from_knobs "" "the policy was not the tracer's"
plant "hint: no shadows" 07_blinn_phong shade_phong.c \
    's|if (!light_blocked(tr, sp, light->position, tracer_eps(tr), rays))|(void)rays; if (1)|' \
    test_two_lights_add "" "the blocked light was added: ask light_blocked first"
plant "hint: the result replaced by each light" 07_blinn_phong shade_phong.c \
    's|result = color_add(result, light_contribution(tr, sp, shader, light));|result = color_add(tr->desc->ambient, light_contribution(tr, sp, shader, light));|' \
    test_two_lights_add "" "only the last light"
# Chapter 08: reflect keeps |d| and the sign; the mirror ray turns about sp->n,
# starts from t = 0 and carries k_m.
plant "hint: reflect of a normalized d" 08_mirrors mirror.c \
    's|return vec3_sub(d, vec3_scale(n, 2 \* vec3_dot(d, n)));|vec3 u = vec3_normalize(d); return vec3_sub(u, vec3_scale(n, 2 * vec3_dot(u, n)));|' \
    test_reflect_known "" "d normalized"
plant "hint: reflect gives -r" 08_mirrors mirror.c \
    's|return vec3_sub(d, vec3_scale(n, 2 \* vec3_dot(d, n)));|return vec3_sub(vec3_scale(n, 2 * vec3_dot(d, n)), d);|' \
    test_reflect_known "" "-r: r = d - 2"
plant "hint: the mirror ray about the geometric normal" 08_mirrors mirror.c \
    's|reflect(sp->r.d, sp->n)|reflect(sp->r.d, sp->hit.normal)|' \
    test_mirror_ray_reaches_probe "" "about hit\.normal"
plant "hint: the mirror ray traced from t_min > 0" 08_mirrors mirror.c \
    's|mirror, 0, REAL_INFINITY|mirror, (real)1e-4, REAL_INFINITY|' \
    test_mirror_ray_policy_from_knobs "" "t_min above 0"
plant "hint: path_next asked with 1 instead of k_m" 08_mirrors mirror.c \
    's|path_next(tr, depth, k_m, \&next)|path_next(tr, depth, color_make(k_m.r * 0 + 1, 1, 1), \&next)|' \
    test_mirror_ray_reaches_probe "" "path_next asked with 1 instead of k_m"
# The mirror ray counted before path_next decides; path_next asked one level deeper.
plant "hint: the mirror ray counted before path_next" 08_mirrors mirror.c \
    's|^    ++rays\[RAY_REFLECTED\];$||; s|^    tracer next;$|    tracer next; ++rays[RAY_REFLECTED];|' \
    test_furnace_mirror_sphere "" "counted though path_next did not cast it"
plant "hint: path_next asked with depth + 1" 08_mirrors mirror.c \
    's|path_next(tr, depth, k_m, \&next)|path_next(tr, depth + 1, k_m, \&next)|' \
    test_facing_mirrors_depth_and_weight "" "one level short"
# reflect's sign and factor 2; the mirror ray's count, depth, tracer and start.
plant "hint: reflect d + 2 (d . n) n" 08_mirrors mirror.c \
    's|return vec3_sub(d, vec3_scale(n, 2 \* vec3_dot(d, n)));|return vec3_add(d, vec3_scale(n, 2 * vec3_dot(d, n)));|' \
    test_reflect_known "" "d \+ 2 \(d \. n\) n: the correction is subtracted"
plant "hint: reflect without the 2" 08_mirrors mirror.c \
    's|return vec3_sub(d, vec3_scale(n, 2 \* vec3_dot(d, n)));|return vec3_sub(d, vec3_scale(n, vec3_dot(d, n)));|' \
    test_reflect_known "" "the factor 2 is missing"
plant "hint: the mirror ray not counted" 08_mirrors mirror.c \
    's|++rays\[RAY_REFLECTED\];|(void)rays;|' \
    test_mirror_ray_reaches_probe "" "count each mirror ray once"
plant "hint: the mirror ray one level too shallow" 08_mirrors mirror.c \
    's|REAL_INFINITY, depth + 1, rays)|REAL_INFINITY, depth, rays)|' \
    test_mirror_ray_reaches_probe "" "one level deeper"
plant "hint: the mirror ray traced with tr" 08_mirrors mirror.c \
    's|return trace(\&next, mirror|return trace(tr, mirror|' \
    test_mirror_ray_reaches_probe "" "trace with next, not tr"
plant "hint: the mirror ray from the point itself" 08_mirrors mirror.c \
    's|ray mirror = spawn_ray(sp, reflect(sp->r.d, sp->n), tracer_eps(tr));|ray mirror = {sp->hit.point, reflect(sp->r.d, sp->n)};|' \
    test_mirror_ray_policy_from_knobs "" "started at the point itself"
plant "hint: L_m clamped to 1" 08_mirrors mirror.c \
    's|return trace(\&next, mirror, 0, REAL_INFINITY, depth + 1, rays);|color c = trace(\&next, mirror, 0, REAL_INFINITY, depth + 1, rays); return color_make(real_fmin(c.r, 1), real_fmin(c.g, 1), real_fmin(c.b, 1));|' \
    test_mirror_ray_reaches_probe "" "L_m clamped to 1 before k_m"
# Chapter 09: refract's rounding and r; Fresnel's squares; Schlick's terms; the glass rays.
plant "hint: cos^2(theta_t) not grouped for r = 1" 09_refraction refract.c \
    's|(1 - r \* r) + r \* r \* (cos_i \* cos_i)|1 - r * r * (1 - cos_i * cos_i)|' \
    test_refract_equal_indices "" "not 1 - r\^2 \(1 - cos\^2\(theta_i\)\), which rounds"
plant "hint: d not scaled by r in T" 09_refraction refract.c \
    's|vec3_scale(d, r)|d|' \
    test_snell_law "" "d not scaled by r"
plant "hint: Fresnel's amplitudes averaged, then squared" 09_refraction fresnel.c \
    's|(r_s \* r_s + r_p \* r_p) / 2|((r_s + r_p) / 2) * ((r_s + r_p) / 2)|' \
    test_fresnel_exact_values "" "amplitudes averaged, then squared"
plant "hint: Fresnel's amplitudes not squared" 09_refraction fresnel.c \
    's|(r_s \* r_s + r_p \* r_p) / 2|(r_s + r_p) / 2|' \
    test_fresnel_exact_values "" "not squared: they are amplitudes"
plant "hint: Schlick's R_0 not squared" 09_refraction fresnel.c \
    's|real R_0 = r \* r;|real R_0 = r;|' \
    test_schlick_cosines "" "R_0 not squared"
plant "hint: Schlick's power 4" 09_refraction fresnel.c \
    's|m \* m \* m \* m \* m|m * m * m * m|' \
    test_schlick_cosines "" "power is 5"
plant "hint: Schlick without 1 - R_0" 09_refraction fresnel.c \
    's|R_0 + (1 - R_0) \* m|R_0 + m|' \
    test_schlick_cosines "" "\(1 - R_0\) missing"
plant "hint: Schlick's power of cos, not 1 - cos" 09_refraction fresnel.c \
    's|real m = 1 - (eta_i <= eta_t ? cos_i : cos_t);|real m = (eta_i <= eta_t ? cos_i : cos_t);|' \
    test_schlick_cosines "" "cos\^5: the power is of 1 - cos"
plant "hint: Schlick's r over eta_t alone" 09_refraction fresnel.c \
    's|real r = (eta_i - eta_t) / (eta_i + eta_t);|real r = (eta_i - eta_t) / eta_t;|' \
    test_fresnel_normal_incidence "" "the sum eta_i \+ eta_t goes below"
plant "hint: depth + 1 given to the glass rays" 09_refraction shade_glass.c \
    's|R, depth, rays|R, depth + 1, rays|; s|T, depth, rays|T, depth + 1, rays|' \
    test_glass_weights "" "depth \+ 1 given"
plant "hint: the transmitted ray along d" 09_refraction shade_glass.c \
    's|e.T, T, depth|sp->r.d, T, depth|' \
    test_slab_returns_entry_direction "" "cast along d, not bent"
plant "hint: the reflected glass ray with weight 1 - R" 09_refraction shade_glass.c \
    's|mirror_radiance(tr, sp, R, depth|mirror_radiance(tr, sp, T, depth|' \
    test_glass_weights "" "not 1 - R, which is 0 here"
# refract: the signs and squares of the cosines, and r in n's coefficient.
plant "hint: cos(theta_i) = d . n" 09_refraction refract.c \
    's|real cos_i = -vec3_dot(d, n);|real cos_i = vec3_dot(d, n);|' \
    test_snell_law "" "cos\(theta_i\) = d \. n has the wrong sign"
plant "hint: cos(theta_t) without the square root" 09_refraction refract.c \
    's|\*cos_t = real_sqrt(cos2_t);|*cos_t = cos2_t;|' \
    test_snell_law "" "the square root left out"
plant "hint: cos^2(theta_t) with r for r^2" 09_refraction refract.c \
    's|real cos2_t = (1 - r \* r) + r \* r \* (cos_i \* cos_i);|real cos2_t = (1 - r) + r * (cos_i * cos_i);|' \
    test_snell_law "" "r\^2, not r"
plant "hint: n's coefficient without r" 09_refraction refract.c \
    's|vec3_scale(n, r \* cos_i - \*cos_t)|vec3_scale(n, cos_i - *cos_t)|' \
    test_snell_law "" "n's coefficient without r"
plant "hint: cos(theta_t) taken as cos(theta_i)" 09_refraction refract.c \
    's|\*cos_t = real_sqrt(cos2_t);|*cos_t = cos_i + 0 * cos2_t;|' \
    test_snell_law "" "cos\(theta_t\) taken as cos\(theta_i\)"
# Glass: R and 1 - R swapped; each ray's path coefficient 1 instead of its weight.
plant "hint: the glass weights swapped" 09_refraction shade_glass.c \
    's|L = color_mul(R, mirror_radiance|L = color_mul(T, mirror_radiance|; s|color_mul(T, transmitted_radiance|color_mul(R, transmitted_radiance|' \
    test_glass_weights "" "R and 1 - R swapped"
plant "hint: the glass rays traced with coefficient 1" 09_refraction shade_glass.c \
    's|mirror_radiance(tr, sp, R, depth|mirror_radiance(tr, sp, color_make(1, 1, 1), depth|; s|transmitted_radiance(tr, sp, e.T, T, depth|transmitted_radiance(tr, sp, e.T, color_make(1, 1, 1), depth|' \
    test_glass_weights "" "min-weight 0\\.97" "coefficient other than its weight"
# The ratio, C_t's sign, Fresnel's r_p and / 2, Schlick's side, the glass weights and rays.
plant "hint: r = eta_t / eta_i" 09_refraction refract.c \
    's|real r = eta_i / eta_t;|real r = eta_t / eta_i;|' \
    test_snell_law "" "the ratio is upside down"
plant "hint: C_t = +cos(theta_t) n" 09_refraction refract.c \
    's|r \* cos_i - \*cos_t|r * cos_i + *cos_t|' \
    test_snell_law "" "C_t = \+cos\(theta_t\) n"
plant "hint: Fresnel's r_p with the cosines swapped" 09_refraction fresnel.c \
    's|real r_p = (eta_t \* cos_i - eta_i \* cos_t) / (eta_t \* cos_i + eta_i \* cos_t);|real r_p = (eta_t * cos_t - eta_i * cos_i) / (eta_t * cos_t + eta_i * cos_i);|' \
    test_fresnel_exact_values "" "r_p with the cosines swapped"
plant "hint: Fresnel without the / 2" 09_refraction fresnel.c \
    's|(r_s \* r_s + r_p \* r_p) / 2|(r_s * r_s + r_p * r_p)|' \
    test_fresnel_exact_values "" "r_s\^2 \+ r_p\^2 without the / 2"
plant "hint: Schlick always with cos_i" 09_refraction fresnel.c \
    's|real m = 1 - (eta_i <= eta_t ? cos_i : cos_t);|real m = 1 - cos_i + 0 * cos_t;|' \
    test_schlick_cosines "" "out of glass the cosine is cos_t"
plant "hint: Schlick's sides swapped" 09_refraction fresnel.c \
    's|real m = 1 - (eta_i <= eta_t ? cos_i : cos_t);|real m = 1 - (eta_i <= eta_t ? cos_t : cos_i);|' \
    test_schlick_cosines "" "into glass the cosine is cos_i"
plant "hint: the glass radiances not weighted" 09_refraction shade_glass.c \
    's|L = color_mul(R, mirror_radiance(tr, sp, R, depth, rays));|L = mirror_radiance(tr, sp, R, depth, rays);|; s|L = color_add(L, color_mul(T, transmitted_radiance(tr, sp, e.T, T, depth, rays)));|L = color_add(L, transmitted_radiance(tr, sp, e.T, T, depth, rays));|' \
    test_glass_weights "" "L_reflected not multiplied by R"
plant "hint: L_transmitted weighted 1" 09_refraction shade_glass.c \
    's|color_mul(T, transmitted_radiance|color_mul(color_make(1, 1, 1), transmitted_radiance|' \
    test_glass_weights "" "L_transmitted not multiplied by 1 - R"
plant "hint: the reflected glass ray only past the critical angle" 09_refraction shade_glass.c \
    's|if (e.R > 0) /\* R L_reflected \*/|if (!e.transmits)|' \
    test_glass_weights "" "no reflected ray traced, or its L not added"
plant "hint: one glass ray only" 09_refraction shade_glass.c \
    's|if (e.transmits \&\& e.R < 1) /\* + (1 - R) L_transmitted \*/|else if (e.transmits \&\& e.R < 1)|' \
    test_glass_weights "" "a ray not traced though its weight"
plant "hint: the glass radiance clamped to 1" 09_refraction shade_glass.c \
    's|^    return L;|    return color_make(real_fmin(L.r, 1), real_fmin(L.g, 1), real_fmin(L.b, 1));|' \
    test_glass_weights "" "L clamped to 1: a radiance is not clamped"
# Chapter 10: a wrap that leaves C's negative remainder is named as the wrap in
# the lookups, not as their rounding; the lookups' own mistakes are named.
plant "hint: a repeat wrap without the fix for a negative %, in nearest" 10_interpolation texture.c \
    's|return (int)(m < 0 ? m + n : m);|return (int)m;|' \
    test_nearest_quirk "dropped the fraction" "the wrap, not the lookup" "texel_index\(RepeatTexture, -1, 5\) gives -1"
plant "hint: a repeat wrap without the fix for a negative %, in bilinear" 10_interpolation texture.c \
    's|return (int)(m < 0 ? m + n : m);|return (int)m;|' \
    test_bilinear_random "" "the wrap, not the lookup" "test_texel_index_repeat"
plant "hint: nearest without + 1/2" 10_interpolation texture.c \
    's|(long long)(x + (real)0.5)|(long long)x|; s|(long long)(y + (real)0.5)|(long long)y|' \
    test_nearest "the wrap" "dropped the fraction without adding 1/2 first"
plant "hint: bilinear's weights along x swapped" 10_interpolation texture.c \
    's|texture_image_texel(img, x0, y0), 1 - s)|texture_image_texel(img, x0, y0), s)|; s|texture_image_texel(img, x1, y0), s)|texture_image_texel(img, x1, y0), 1 - s)|; s|texture_image_texel(img, x0, y1), 1 - s)|texture_image_texel(img, x0, y1), s)|; s|texture_image_texel(img, x1, y1), s)|texture_image_texel(img, x1, y1), 1 - s)|' \
    test_bilinear "" "likely mistake: the weights along x swapped"
# interpolate_vec3 with beta and gamma swapped: named by the tests of the given code that calls it.
for t in test_interpolate_uv test_vertex_normal test_smooth_shading; do
    plant "hint: beta and gamma swapped, in $t" 10_interpolation interpolate.c \
        's|vec3_scale(A_b, beta)), vec3_scale(A_c, gamma)|vec3_scale(A_b, gamma)), vec3_scale(A_c, beta)|' \
        "$t" "" "likely mistake: beta and gamma swapped"
done
# interpolate_vec3's weights and a normalization that belongs to vertex_normal.
plant "hint: alpha = 1 - beta" 10_interpolation interpolate.c \
    's|real alpha = 1 - beta - gamma;|real alpha = 1 - beta;|' \
    test_interpolate_vertices_edges "" "alpha = 1 - beta: the weight of vertex a is 1 - beta - gamma"
plant "hint: alpha on vertex b" 10_interpolation interpolate.c \
    's|vec3_scale(A_a, alpha), vec3_scale(A_b, beta)|vec3_scale(A_a, beta), vec3_scale(A_b, alpha)|' \
    test_interpolate_vertices_edges "" "alpha and beta swapped"
plant "hint: the blend divided by 3" 10_interpolation interpolate.c \
    's|return vec3_add(\(.*\));$|return vec3_scale(vec3_add(\1), (real)1 / 3);|' \
    test_interpolate_random "" "divided by 3"
plant "hint: the blend normalized" 10_interpolation interpolate.c \
    's|return vec3_add(\(.*\));$|return vec3_normalize(vec3_add(\1));|' \
    test_interpolate_uv "" "the blend normalized: interpolate_vec3 blends any attribute"
plant "hint: each vertex's value normalized before the blend" 10_interpolation interpolate.c \
    's|vec3_scale(A_\([abc]\), |vec3_scale(vec3_normalize(A_\1), |g' \
    test_interpolate_random "" "each vertex's value normalized before the blend"
# The wrap: the remainder's sign, clamping to n, the kinds swapped.
plant "hint: the remainder's absolute value" 10_interpolation texture.c \
    's|return (int)(m < 0 ? m + n : m);|return (int)(m < 0 ? -m : m);|' \
    test_texel_index_repeat "" "absolute value mirrors the texture"
plant "hint: n added to every remainder" 10_interpolation texture.c \
    's|return (int)(m < 0 ? m + n : m);|return (int)(m + n);|' \
    test_texel_index_repeat "" "i % n \+ n is n too many"
plant "hint: a negative remainder plus n - 1" 10_interpolation texture.c \
    's|return (int)(m < 0 ? m + n : m);|return (int)(m < 0 ? m + n - 1 : m);|' \
    test_texel_index_repeat "" "negative remainder plus n - 1"
plant "hint: i converted to int before the %" 10_interpolation texture.c \
    's|m = i % n;|m = (int)i % n;|' \
    test_texel_index_repeat "" "converted to int before the %"
plant "hint: clamped to n" 10_interpolation texture.c \
    's|i >= n ? n - 1 : (int)i;|i >= n ? n : (int)i;|' \
    test_texel_index_clamp "" "clamped to n \(or only i > n clamped\)"
plant "hint: only i > n clamped" 10_interpolation texture.c \
    's|i >= n ? n - 1 : (int)i;|i > n ? n - 1 : (int)i;|' \
    test_texel_index_clamp "" "clamped to n \(or only i > n clamped\)"
plant "hint: a negative i not clamped" 10_interpolation texture.c \
    's|return i < 0 ? 0 : i >= n|return i >= n|' \
    test_texel_index_clamp "" "a negative i is not clamped"
plant "hint: Repeat and Clamp swapped" 10_interpolation texture.c \
    's|(kind == TEXTURE_REPEAT)|(kind == TEXTURE_CLAMP)|' \
    test_texel_index_repeat "" "clamped: a RepeatTexture wraps"
# Nearest: the rounding, v's flip, the sides.
plant "hint: nearest by floor(x + 1/2)" 10_interpolation texture.c \
    's|(long long)(\([xy]\) + (real)0.5)|(long long)real_floor(\1 + (real)0.5)|g' \
    test_nearest_quirk "" "floor\(x \+ 1/2\) or round\(x\)"
plant "hint: nearest by ceil(x)" 10_interpolation texture.c \
    's|(long long)(\([xy]\) + (real)0.5)|(long long)real_ceil(\1)|g' \
    test_nearest "" "ceil\(x\) rounds every fraction up"
plant "hint: nearest by x - 1/2" 10_interpolation texture.c \
    's|(long long)(\([xy]\) + (real)0.5)|(long long)(\1 - (real)0.5)|g' \
    test_nearest "" "x - 1/2: the nearest texel"
plant "hint: v flipped again" 10_interpolation texture.c \
    's|(long long)(y + (real)0.5), img->height|(long long)((real)img->height - y + (real)0.5), img->height|' \
    test_nearest "" "v not flipped: rows count down from the top"
plant "hint: nearest with u and v swapped" 10_interpolation texture.c \
    's|return texture_image_texel(img, column, row);|return texture_image_texel(img, row, column);|' \
    test_nearest "" "u and v swapped"
plant "hint: nearest's row wrapped by the width" 10_interpolation texture.c \
    's|(long long)(y + (real)0.5), img->height|(long long)(y + (real)0.5), img->width|' \
    test_nearest "" "the row wrapped by the width"
# Bilinear: the corner, the half-texel shift, the fractions, the second column and row.
plant "hint: bilinear's weights along y swapped" 10_interpolation texture.c \
    's|color_add(color_scale(top, 1 - t), color_scale(bottom, t))|color_add(color_scale(top, t), color_scale(bottom, 1 - t))|' \
    test_bilinear "" "the weights along y swapped"
plant "hint: bilinear's weights from the opposite corner" 10_interpolation texture.c \
    's|real s = x - fx, t = y - fy;|real s = 1 - (x - fx), t = 1 - (y - fy);|' \
    test_bilinear "" "the weights from the opposite corner"
plant "hint: bilinear's t from x" 10_interpolation texture.c \
    's|real s = x - fx, t = y - fy;|real s = x - fx, t = x - fx;|' \
    test_bilinear "" "t = x - x0"
plant "hint: bilinear's x0 truncated" 10_interpolation texture.c \
    's|real fx = real_floor(x), fy = real_floor(y);|real fx = (real)(long long)x, fy = (real)(long long)y;|' \
    test_bilinear_random "" "rounds towards zero: x0 = floor\(x\)"
plant "hint: bilinear's centres at x + 1/2" 10_interpolation texture.c \
    's|real fx = real_floor(x), fy = real_floor(y);|x -= (real)0.5, y -= (real)0.5; &|' \
    test_bilinear "" "x - 1/2 \(texel centres at x \+ 1/2\)"
plant "hint: bilinear's index shifted, not its fraction" 10_interpolation texture.c \
    's|real fx = real_floor(x), fy = real_floor(y);|real fx = real_floor(x - (real)0.5), fy = real_floor(y - (real)0.5);|' \
    test_bilinear "" "the fraction not taken after it"
plant "hint: bilinear's index from x + 1/2" 10_interpolation texture.c \
    's|real fx = real_floor(x), fy = real_floor(y);|real fx = real_floor(x + (real)0.5), fy = real_floor(y + (real)0.5);|' \
    test_bilinear "" "nearest's \+ 1/2 in the index alone"
plant "hint: bilinear's x1 from the wrapped x0" 10_interpolation texture.c \
    's|int x1 = texel_index(tex->kind, (long long)fx + 1, img->width);|int x1 = x0 + 1;|' \
    test_bilinear "" "from the wrapped x0: past the last"
plant "hint: bilinear's rows wrapped by the width" 10_interpolation texture.c \
    's|\(int y[01] = texel_index(tex->kind, (long long)fy[ +1]*, img->\)height|\1width|' \
    test_bilinear_random "" "the rows wrapped by the width"
plant "hint: bilinear's fractions from the wrapped indices" 10_interpolation texture.c \
    's|real s = x - fx, t = y - fy;|real s = x - (real)texel_index(tex->kind, (long long)fx, img->width), t = y - (real)texel_index(tex->kind, (long long)fy, img->height);|' \
    test_bilinear_random "" "the fractions from the wrapped indices"
# interpolate_vec3: each weight on its own vertex, alpha in full and real.
plant "hint: alpha and gamma swapped" 10_interpolation interpolate.c \
    's|vec3_scale(A_a, alpha), vec3_scale(A_b, beta)), vec3_scale(A_c, gamma)|vec3_scale(A_a, gamma), vec3_scale(A_b, beta)), vec3_scale(A_c, alpha)|' \
    test_interpolate_vertices_edges "" "alpha and gamma swapped"
plant "hint: the weights rotated" 10_interpolation interpolate.c \
    's|vec3_scale(A_a, alpha), vec3_scale(A_b, beta)), vec3_scale(A_c, gamma)|vec3_scale(A_a, gamma), vec3_scale(A_b, alpha)), vec3_scale(A_c, beta)|' \
    test_interpolate_random "" "the weights belong to the wrong vertices"
plant "hint: vertex a left out" 10_interpolation interpolate.c \
    's|vec3_scale(A_a, alpha)|vec3_scale(A_a, 0 * alpha)|' \
    test_interpolate_random "" "vertex a left out"
plant "hint: A_a not scaled by alpha" 10_interpolation interpolate.c \
    's|vec3_scale(A_a, alpha)|A_a|; s|real alpha = 1 - beta - gamma;||' \
    test_interpolate_vertices_edges "" "vertex a's weight left out"
plant "hint: alpha = 1 - gamma" 10_interpolation interpolate.c \
    's|real alpha = 1 - beta - gamma;|real alpha = 1 - gamma;|' \
    test_interpolate_random "" "alpha = 1 - gamma"
plant "hint: alpha = beta + gamma" 10_interpolation interpolate.c \
    's|real alpha = 1 - beta - gamma;|real alpha = beta + gamma;|' \
    test_interpolate_vertices_edges "" "alpha = beta \+ gamma"
plant "hint: alpha converted to an int" 10_interpolation interpolate.c \
    's|real alpha = 1 - beta - gamma;|int alpha = (int)(1 - beta - gamma);|' \
    test_interpolate_random "" "alpha converted to an int"
# The wrap: n added to a remainder of 0, negative i, a mask, the last texel.
plant "hint: a remainder of 0 plus n" 10_interpolation texture.c \
    's|return (int)(m < 0 ? m + n : m);|return (int)(m <= 0 ? m + n : m);|' \
    test_texel_index_repeat "" "a remainder of 0 plus n"
plant "hint: a negative i read as texel 0 in a repeat" 10_interpolation texture.c \
    's|long long m = i % n;|long long m = i < 0 ? 0 : i % n;|' \
    test_texel_index_repeat "" "a negative i read as texel 0"
plant "hint: the wrap by i & (n - 1)" 10_interpolation texture.c \
    's|long long m = i % n;|long long m = i \& (n - 1);|' \
    test_texel_index_repeat "" "i & \(n - 1\) is i mod n only when n is a power of two"
plant "hint: clamped to n - 2" 10_interpolation texture.c \
    's|i >= n ? n - 1 : (int)i;|i >= n - 1 ? n - 2 : (int)i;|' \
    test_texel_index_clamp "" "clamped to n - 2"
# Nearest: 1 / 2 in integers, an int index, lround, the wrap's side, no wrap, one kind only.
plant "hint: nearest's 1 / 2 in integers" 10_interpolation texture.c \
    's|(long long)(\([xy]\) + (real)0.5)|(long long)(\1 + 1 / 2)|g' \
    test_nearest "" "1 / 2 in integers is 0"
plant "hint: nearest's index converted to int" 10_interpolation texture.c \
    's|(long long)(\([xy]\) + (real)0.5)|(int)(\1 + (real)0.5)|g' \
    test_nearest_quirk "" "the index converted to int overflowed"
plant "hint: nearest by lround" 10_interpolation texture.c \
    's|(long long)(\([xy]\) + (real)0.5)|lround(\1)|g; s|#include "texture_space.h"|#include "texture_space.h"\n#include <math.h>|' \
    test_nearest_quirk "" "floor\(x \+ 1/2\) or round\(x\)"
plant "hint: nearest's column wrapped by the height" 10_interpolation texture.c \
    's|(long long)(x + (real)0.5), img->width|(long long)(x + (real)0.5), img->height|' \
    test_nearest "" "the column wrapped by the height"
plant "hint: nearest not wrapped" 10_interpolation texture.c \
    's|texel_index(tex->kind, (long long)(\([xy]\) + (real)0.5), img->[a-z]*)|(int)(long long)(\1 + (real)0.5)|g' \
    test_nearest "" "not wrapped: each index goes through texel_index"
plant "hint: nearest always repeats" 10_interpolation texture.c \
    's|texel_index(tex->kind, (long long)(\([xy]\) + |texel_index(TEXTURE_REPEAT, (long long)(\1 + |g' \
    test_nearest "" "wrapped the other way"
# Bilinear: the fractions' axes and source, the rows, the wrap of the second column and row, the weights.
plant "hint: bilinear's s and t swapped" 10_interpolation texture.c \
    's|real s = x - fx, t = y - fy;|real s = y - fy, t = x - fx;|' \
    test_bilinear "" "s and t swapped"
plant "hint: bilinear's fraction of (long long)x" 10_interpolation texture.c \
    's|real s = x - fx, t = y - fy;|real s = x - (real)(long long)x, t = y - (real)(long long)y;|' \
    test_bilinear_random "" "the fraction of \(long long\)x"
plant "hint: bilinear's bottom row blended with t" 10_interpolation texture.c \
    's|texture_image_texel(img, x0, y1), 1 - s)|texture_image_texel(img, x0, y1), 1 - t)|; s|texture_image_texel(img, x1, y1), s)|texture_image_texel(img, x1, y1), t)|' \
    test_bilinear "" "the bottom row blended with t"
plant "hint: bilinear's rows both weighed 1 - t" 10_interpolation texture.c \
    's|return color_add(color_scale(top, 1 - t), color_scale(bottom, t));|return color_add(color_scale(top, 1 - t), color_scale(bottom, 1 - t));|' \
    test_bilinear "" "both rows weighed 1 - t"
plant "hint: bilinear's weights along x swapped in the top row" 10_interpolation texture.c \
    's|texture_image_texel(img, x0, y0), 1 - s)|texture_image_texel(img, x0, y0), s)|; s|texture_image_texel(img, x1, y0), s)|texture_image_texel(img, x1, y0), 1 - s)|' \
    test_bilinear "" "the weights along x swapped in the top row"
plant "hint: bilinear's second row above" 10_interpolation texture.c \
    's|(long long)fy + 1, img->height|(long long)fy - 1, img->height|' \
    test_bilinear "" "the second row is y0 - 1"
plant "hint: bilinear's x0 + 1 and y0 + 1 not wrapped" 10_interpolation texture.c \
    's|texel_index(tex->kind, (long long)f\([xy]\) + 1, img->[a-z]*)|(int)f\1 + 1|' \
    test_bilinear "" "x0 \+ 1 or y0 \+ 1 not wrapped"
plant "hint: bilinear's y1 from the wrapped y0" 10_interpolation texture.c \
    's|int y1 = texel_index(tex->kind, (long long)fy + 1, img->height);|int y1 = y0 + 1;|' \
    test_bilinear_random "" "y1 = y0 \+ 1 from the wrapped y0"
plant "hint: bilinear with u and v swapped" 10_interpolation texture.c \
    's|texture_image_texel(img, x\([01]\), y\([01]\))|texture_image_texel(img, y\2, x\1)|g' \
    test_bilinear "" "u and v swapped"
plant "hint: bilinear reads the nearest texel" 10_interpolation texture.c \
    's|return color_add(color_scale(top, 1 - t), color_scale(bottom, t));|(void)top, (void)bottom, (void)t; return texture_nearest(tex, uv);|' \
    test_bilinear "" "the nearest texel: blend the four texels"
plant "hint: bilinear always repeats" 10_interpolation texture.c \
    's|texel_index(tex->kind, (long long)f|texel_index(TEXTURE_REPEAT, (long long)f|g' \
    test_bilinear "" "wrapped the other way"
# Chapter 11: the resolution without the cap, with a shrink of a half a try,
# with the cube root for a flat scene; the entry with no case for inv_d = 0
# (a ray along an axis then visits no cell: the entry named, not dda_step).
plant "hint: the resolution over the cap" 11_grid grid_build.c \
    's|if (cells <= (double)max_cells)|if (cells > 0)|' \
    test_resolution "" "cap 990" "likely mistake: the cap"
plant "hint: the resolution shrinks too far" 11_grid grid_build.c \
    's|s \*= fmax(0.9, 0.99 \* pow((double)max_cells / cells, 1.0 / (spanned ? spanned : 1)));|s *= 0.5;|' \
    test_resolution "" "got      10 x 2 x 5" "by a tenth at most a try"
plant "hint: the cube root for a flat scene" 11_grid grid_build.c \
    's|pow(fmax(wanted, 1) / volume, 1.0 / spanned)|pow(fmax(wanted, 1) / volume, 1.0 / 3)|' \
    test_resolution "" "flat scene" "not the cube root"
plant "hint: the entry with no case for inv_d = 0" 11_grid grid_march.c \
    's|if (inv_d\[a\] == 0) {|if (inv_d[a] == 0 \&\& t0 == NULL) {|' \
    test_dda_axis_steps "dda_step along" "0 cells" "likely mistake: enter: a component d_a = \+0 or -0"
# The resolution's formula: lambda N, round, at least one cell, the root of the cells over the volume.
plant "hint: the resolution without the density" 11_grid grid_build.c \
    's|fmin(density \* (double)surfaces,|fmin((double)surfaces + 0 * density,|' \
    test_resolution "" "the density left out"
plant "hint: the resolution without the number of surfaces" 11_grid grid_build.c \
    's|fmin(density \* (double)surfaces,|fmin(density + 0 * (double)surfaces,|' \
    test_resolution "" "the number of surfaces left out"
plant "hint: the density cut to an integer" 11_grid grid_build.c \
    's|fmin(density \* (double)surfaces,|fmin((double)(long)density * (double)surfaces,|' \
    test_resolution "" "the density cut to an integer"
plant "hint: the resolution by floor" 11_grid grid_build.c \
    's|fmax(round(e\[a\] \* s), 1)|fmax(floor(e[a] * s), 1)|' \
    test_resolution "" "n_a = floor\(e_a s\)"
plant "hint: the resolution by ceil" 11_grid grid_build.c \
    's|fmax(round(e\[a\] \* s), 1)|fmax(ceil(e[a] * s), 1)|' \
    test_resolution "" "n_a = ceil\(e_a s\)"
plant "hint: a spanned axis rounded to 0 cells" 11_grid grid_build.c \
    's|fmin(fmax(round(e\[a\] \* s), 1), 1 << 20)|fmin(round(e[a] * s), 1 << 20)|' \
    test_resolution "" "rounds to 0 still gets one cell"
plant "hint: a flat axis's zero extent in the volume" 11_grid grid_build.c \
    's|if (extent\[a\] > 0) {|if (extent[a] >= 0) {|' \
    test_resolution "" "zero extent makes s infinite"
plant "hint: s upside down" 11_grid grid_build.c \
    's|pow(fmax(wanted, 1) / volume, 1.0 / spanned)|pow(volume / fmax(wanted, 1), 1.0 / spanned)|' \
    test_resolution "" "s upside down"
plant "hint: the root of the cells alone" 11_grid grid_build.c \
    's|pow(fmax(wanted, 1) / volume, 1.0 / spanned)|pow(fmax(wanted, 1), 1.0 / spanned) / volume|' \
    test_resolution "" "the root is of the cells over the volume"
plant "hint: a product equal to the cap shrunk" 11_grid grid_build.c \
    's|if (cells <= (double)max_cells)|if (cells < (double)max_cells)|' \
    test_resolution "" "a product equal to the cap shrunk"
# The cell range: floor and ceil at a boundary, the clamps, the axis and the corner.
plant "hint: the first cell by floor(f_lo)" 11_grid grid_build.c \
    's|real_ceil(f_lo) - 1, 0|real_floor(f_lo), 0|' \
    test_cell_range "" "first = floor\(f_lo\): a box whose low side"
plant "hint: the last cell by ceil(f_hi) - 1" 11_grid grid_build.c \
    's|real_to_index(real_floor(f_hi), -1|real_to_index(real_ceil(f_hi) - 1, -1|' \
    test_cell_range "" "last = ceil\(f_hi\) - 1"
plant "hint: the last cell by ceil(f_hi)" 11_grid grid_build.c \
    's|real_to_index(real_floor(f_hi), -1|real_to_index(real_ceil(f_hi), -1|' \
    test_cell_range "" "last = ceil\(f_hi\): that is the cell after the box"
plant "hint: the cell range by floor and ceil" 11_grid grid_build.c \
    's|real_to_index(real_ceil(f_lo) - 1, 0|real_to_index(real_floor(f_lo), 0|; s|real_to_index(real_floor(f_hi), -1|real_to_index(real_ceil(f_hi), -1|' \
    test_cell_range "" "last = ceil\(f_hi\): that is the cell after the box"
plant "hint: the last cell clamped to n" 11_grid grid_build.c \
    's|-1, g->n\[a\] - 1);|-1, g->n[a]);|' \
    test_cell_range "" "last clamped to n"
plant "hint: x's cell size for every axis" 11_grid grid_build.c \
    's|/ vec3_axis(g->cell, a);|/ vec3_axis(g->cell, 0);|g' \
    test_cell_range "" "the x axis's cell size used for another axis"
plant "hint: f_hi from box_lo" 11_grid grid_build.c \
    's|real f_hi = (vec3_axis(box_hi, a)|real f_hi = (vec3_axis(box_lo, a) + 0 * vec3_axis(box_hi, a)|' \
    test_cell_range "" "f_hi computed from box_lo"
# The entry: the slabs' crossings swapped for d_a < 0, the window narrowed by every axis.
plant "hint: the entry without min and max" 11_grid grid_march.c \
    's|real near = real_fmin(t_lo, t_hi) - slack\[a\], far = real_fmax(t_lo, t_hi) + slack\[a\];|real near = t_lo - slack[a], far = t_hi + slack[a];|' \
    test_dda_cells "" "enter: for d_a < 0 the ray enters the slab at hi_a"
plant "hint: the entry's t0 not narrowed" 11_grid grid_march.c \
    's|\*t0 = real_fmax(\*t0, near);|*t0 = real_fmin(*t0, near);|' \
    test_dda_cells "" "enter: the ray is inside the box only where it is inside all three slabs"
plant "hint: the entry's window overwritten by each axis" 11_grid grid_march.c \
    's|\*t0 = real_fmax(\*t0, near);|*t0 = near;|; s|\*t1 = real_fmin(\*t1, far);|*t1 = far;|' \
    test_dda_cells "" "enter: the ray is inside the box only where it is inside all three slabs"
plant "hint: the entry without the slack" 11_grid grid_march.c \
    's|real near = real_fmin(t_lo, t_hi) - slack\[a\], far = real_fmax(t_lo, t_hi) + slack\[a\];|real near = real_fmin(t_lo, t_hi), far = real_fmax(t_lo, t_hi); (void)slack;|' \
    test_dda_cells "" "enter without the slack"
plant "hint: the entry's slack taken inwards" 11_grid grid_march.c \
    's|real near = real_fmin(t_lo, t_hi) - slack\[a\], far = real_fmax(t_lo, t_hi) + slack\[a\];|real near = real_fmin(t_lo, t_hi) + slack[a], far = real_fmax(t_lo, t_hi) - slack[a];|' \
    test_dda_cells "" "enter without the slack \(or with it taken inwards\)"
plant "hint: the entry's slabs open for d_a = 0" 11_grid grid_march.c \
    's|if (!(p >= lo \&\& p <= hi))|if (!(p > lo \&\& p < hi))|' \
    test_dda_cells "" "on a face of axis a is inside that slab"
# dda_step: the t added up, the plane, the sign, the grid's ends.
plant "hint: dda_step adds a t step" 11_grid grid_march.c \
    's|m->next\[a\] = crossing(g, a, m->i\[a\] + (m->step\[a\] > 0), r, inv_d);|(void)r; m->next[a] += vec3_axis(g->cell, a) * real_abs(inv_d[a]);|' \
    test_dda_no_accumulation "" "next_x gathered rounding"
plant "hint: dda_step's plane for the wrong direction" 11_grid grid_march.c \
    's|m->i\[a\] + (m->step\[a\] > 0), r, inv_d);|m->i[a] + (m->step[a] < 0), r, inv_d);|' \
    test_dda_cells "" "next_a comes from the wrong plane"
plant "hint: dda_step's next from the old cell" 11_grid grid_march.c \
    's|m->i\[a\] += m->step\[a\];|real t_old = crossing(g, a, m->i[a] + (m->step[a] > 0), r, inv_d); m->i[a] += m->step[a];|; s|^    m->next\[a\] = crossing(g, a, m->i\[a\] + (m->step\[a\] > 0), r, inv_d);|    m->next[a] = t_old;|' \
    test_dda_cells "" "next_a comes from the wrong plane"
plant "hint: dda_step always steps up" 11_grid grid_march.c \
    's|m->i\[a\] += m->step\[a\];|m->i[a] += 1;|' \
    test_dda_axis_steps "" "dda_step along x with step -1"
plant "hint: dda_step stops at the last cell" 11_grid grid_march.c \
    's|m->i\[a\] >= g->n\[a\]|m->i[a] >= g->n[a] - 1|' \
    test_dda_cells "" "dda_step stops too early"
plant "hint: dda_step goes past the grid" 11_grid grid_march.c \
    's|m->i\[a\] >= g->n\[a\]|m->i[a] > g->n[a]|' \
    test_dda_cells "" "dda_step goes on past the grid"
# The stop rule: this cell's boundary minus the slack, not the next one's, and not the first hit.
plant "hint: the stop rule without the slack" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best_t <= m.next[a] + 0 * slack[a])|' \
    test_stop_rule "" "the stop rule without the slack"
plant "hint: the stop rule with the slack added" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best_t <= m.next[a] + slack[a])|' \
    test_stop_rule "" "the stop rule without the slack \(or with it added\)"
plant "hint: the stop rule at the next cell's boundary" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best_t <= m.next[a] + vec3_axis(g->cell, a) * real_abs(inv_d[a]) - slack[a])|' \
    test_stop_rule "" "tested the next cell's far boundary"
plant "hint: the march stops at the first hit" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best >= 0)|' \
    test_stop_rule "" "stopped at the first cell holding a hit"
plant "hint: the march waits for a hit before it stops" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best >= 0 \&\& s.best_t <= m.next[a] - slack[a])|' \
    test_stop_rule "" "the stop rule waits for a hit"
plant "hint: the march never stops at a hit" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (0)|' \
    test_stop_rule "" "the march goes on after the best hit"
plant "hint: the stop rule at the farthest boundary" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best_t <= real_fmax(m.next[0], real_fmax(m.next[1], m.next[2])) - slack[a])|' \
    test_stop_rule "" "the march ended before the sphere's cell"
# The resolution: the first try within the cap, the cap on rounded counts, a flat axis, 2^20 an axis.
plant "hint: the first try from lambda N above the cap" 11_grid grid_build.c \
    's|double wanted = fmin(density \* (double)surfaces, (double)max_cells);|double wanted = density * (double)surfaces + 0 * (double)max_cells;|' \
    test_resolution "" "s for min\(lambda N, C\) cells"
plant "hint: the cap checked before rounding" 11_grid grid_build.c \
    's|cells \*= na;|cells *= extent[a] > 0 ? e[a] * s : 1;|' \
    test_resolution "" "shrink s and round again"
plant "hint: a flat axis with 0 cells" 11_grid grid_build.c \
    's|fmin(fmax(round(e\[a\] \* s), 1), 1 << 20) : 1;|fmin(fmax(round(e[a] * s), 1), 1 << 20) : 0;|' \
    test_resolution "" "a flat axis without cells"
plant "hint: an axis over 2^20 cells" 11_grid grid_build.c \
    's|fmin(fmax(round(e\[a\] \* s), 1), 1 << 20)|fmax(round(e[a] * s), 1)|' \
    test_resolution "" "an axis over 2\^20 cells"
# The cell range: the clamps' bounds, the box's sides, where f counts from and in what unit.
plant "hint: the first cell clamped to n - 1" 11_grid grid_build.c \
    's|real_ceil(f_lo) - 1, 0, g->n\[a\]);|real_ceil(f_lo) - 1, 0, g->n[a] - 1);|' \
    test_cell_range "" "first clamped to n - 1"
plant "hint: the last cell clamped at 0" 11_grid grid_build.c \
    's|real_floor(f_hi), -1, g->n\[a\] - 1);|real_floor(f_hi), 0, g->n[a] - 1);|' \
    test_cell_range "" "last clamped at 0 from below"
plant "hint: the cell range not clamped" 11_grid grid_build.c \
    's|real_to_index(real_ceil(f_lo) - 1, 0, g->n\[a\])|(int)(real_ceil(f_lo) - 1)|; s|real_to_index(real_floor(f_hi), -1, g->n\[a\] - 1)|(int)real_floor(f_hi)|' \
    test_cell_range "" "not clamped to the grid"
plant "hint: box_lo and box_hi swapped" 11_grid grid_build.c \
    's|real f_lo = (vec3_axis(box_lo, a)|real f_lo = (vec3_axis(box_hi, a)|; s|real f_hi = (vec3_axis(box_hi, a)|real f_hi = (vec3_axis(box_lo, a)|' \
    test_cell_range "" "box_lo and box_hi swapped"
plant "hint: the first cell truncated" 11_grid grid_build.c \
    's|real_to_index(real_ceil(f_lo) - 1, 0|real_to_index((real)(long long)f_lo, 0|' \
    test_cell_range "" "so does a truncated f_lo"
plant "hint: the first cell floor(f_lo) - 1" 11_grid grid_build.c \
    's|real_to_index(real_ceil(f_lo) - 1, 0|real_to_index(real_floor(f_lo) - 1, 0|' \
    test_cell_range "" "floor\(f_lo\) - 1 is one cell too many"
plant "hint: the cell range counted from the origin" 11_grid grid_build.c \
    's|(vec3_axis(box_lo, a) - vec3_axis(g->lo, a))|(vec3_axis(box_lo, a) - 0 * vec3_axis(g->lo, a))|; s|(vec3_axis(box_hi, a) - vec3_axis(g->lo, a))|(vec3_axis(box_hi, a) - 0 * vec3_axis(g->lo, a))|' \
    test_cell_range "" "f counted from the origin"
plant "hint: the cell range times the cell size" 11_grid grid_build.c \
    's|/ vec3_axis(g->cell, a);|* vec3_axis(g->cell, a);|g' \
    test_cell_range "" "divide by the cell's size"
plant "hint: f_hi from the grid's high corner" 11_grid grid_build.c \
    's|real f_hi = (vec3_axis(box_hi, a) - vec3_axis(g->lo, a))|real f_hi = (vec3_axis(box_hi, a) - vec3_axis(g->hi, a))|' \
    test_cell_range "" "f_hi counted from the grid's high corner"
plant "hint: the last cell truncated" 11_grid grid_build.c \
    's|real_to_index(real_floor(f_hi), -1|real_to_index(f_hi < 0 ? real_ceil(f_hi) : real_floor(f_hi), -1|' \
    test_cell_range "" "last truncated towards zero"
# The entry: a parallel axis, the crossings' sign, the miss, the slack on one side, the window's start.
plant "hint: the entry's parallel axis never misses" 11_grid grid_march.c \
    's|if (!(p >= lo \&\& p <= hi))|if (0 \&\& !(p >= lo \&\& p <= hi))|' \
    test_stop_rule "" "misses the box unless lo_a <= p_a <= hi_a"
plant "hint: the entry's crossings' sign flipped" 11_grid grid_march.c \
    's|real t_lo = (lo - p) \* inv_d\[a\], t_hi = (hi - p) \* inv_d\[a\];|real t_lo = (p - lo) * inv_d[a], t_hi = (p - hi) * inv_d[a];|' \
    test_dda_cells "" "the crossings' sign flipped"
plant "hint: the entry never misses" 11_grid grid_march.c \
    's|return \*t0 <= \*t1;|return true;|' \
    test_dda_cells "" "misses the box when \*t0 > \*t1"
plant "hint: the entry's slack on the entering side only" 11_grid grid_march.c \
    's|far = real_fmax(t_lo, t_hi) + slack\[a\];|far = real_fmax(t_lo, t_hi);|' \
    test_dda_cells "" "enter with the slack on one side only"
plant "hint: the entry's slack on the leaving side only" 11_grid grid_march.c \
    's|real near = real_fmin(t_lo, t_hi) - slack\[a\],|real near = real_fmin(t_lo, t_hi),|' \
    test_dda_cells "" "enter with the slack on one side only"
plant "hint: the entry's window from 0, not t0" 11_grid grid_march.c \
    's|\*t0 = real_fmax(\*t0, near);|*t0 = real_fmax(0, near);|' \
    test_dda_cells "" "\*t0 = max\(\*t0, entering t of each axis\)"
# dda_step: the grid's first cell, the plane for each direction, next kept up to date, the check after the step.
plant "hint: dda_step stops at cell 0" 11_grid grid_march.c \
    's|if (m->i\[a\] < 0 \|\| m->i\[a\] >= g->n\[a\])|if (m->i[a] <= 0 \|\| m->i[a] >= g->n[a])|' \
    test_dda_cells "" "dda_step stops too early"
plant "hint: dda_step's plane i + step" 11_grid grid_march.c \
    's|m->next\[a\] = crossing(g, a, m->i\[a\] + (m->step\[a\] > 0), r, inv_d);|m->next[a] = crossing(g, a, m->i[a] + m->step[a], r, inv_d);|' \
    test_dda_cells "" "next_a comes from the wrong plane"
plant "hint: dda_step's plane i" 11_grid grid_march.c \
    's|m->next\[a\] = crossing(g, a, m->i\[a\] + (m->step\[a\] > 0), r, inv_d);|m->next[a] = crossing(g, a, m->i[a], r, inv_d);|' \
    test_dda_cells "" "next_a comes from the plane the ray just crossed"
plant "hint: dda_step's plane i + 1 both ways" 11_grid grid_march.c \
    's|m->next\[a\] = crossing(g, a, m->i\[a\] + (m->step\[a\] > 0), r, inv_d);|m->next[a] = crossing(g, a, m->i[a] + 1, r, inv_d);|' \
    test_dda_cells "" "next_a comes from the wrong plane"
plant "hint: dda_step's next not updated" 11_grid grid_march.c \
    's|m->next\[a\] = crossing(g, a, m->i\[a\] + (m->step\[a\] > 0), r, inv_d);|(void)r, (void)inv_d;|' \
    test_dda_cells "" "or is not updated"
plant "hint: dda_step checks the grid before the step" 11_grid grid_march.c \
    's|^    m->i\[a\] += m->step\[a\];|    if (m->i[a] < 0 \|\| m->i[a] >= g->n[a]) return false;|; s|^    if (m->i\[a\] < 0 \|\| m->i\[a\] >= g->n\[a\])$|    m->i[a] += m->step[a]; if (0)|' \
    test_dda_cells "" "dda_step goes on past the grid"
# The stop rule: this cell's boundary on the axis it ends by.
plant "hint: the stop rule against t0" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best_t <= t0 - slack[a])|' \
    test_stop_rule "" "the march goes on after the best hit"
plant "hint: the stop rule at x's boundary" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best_t <= m.next[0] - slack[0])|' \
    test_dda_axis_steps "" "the stop rule tests next_a - slack_a of the axis a the cell ends by"
plant "hint: the stop rule with x's slack" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best_t <= m.next[a] - slack[0])|' \
    test_stop_rule "" "the stop rule with another axis's slack"
# Survivors of a mutation campaign, each now caught: an empty shadow segment taken for blocked; no ambient
# without lights; r^2 expanded (cancels far away); an epsilon on Cramer's M; a glass ray skipped for a small
# weight; bilinear's floor through an int; the entry's t0 from one axis; inv_d = 0 tested as d = 0; a fixed
# epsilon for the entry's and the stop rule's slack; a mirror ray's window that ends at 1e30.
plant "hint: an empty shadow segment blocks" 06_shadows shadow.c \
    's|return t_max > 0 \&\& tr->closest_hit|return !(t_max > 0) \|\| tr->closest_hit|' \
    test_light_on_a_surface "" "holds no surface"
plant "hint: no ambient without lights" 07_blinn_phong shade_phong.c \
    's|^    color result = tr->desc->ambient;|    color result = tr->desc->n_lights == 0 ? color_make(0, 0, 0) : tr->desc->ambient;|' \
    test_ambient_and_lights_behind "" "an early return for no lights"
plant "hint: the specular r^2 expanded" 07_blinn_phong phong.c \
    's|real r2 = vec3_length_squared(to_light);|real r2 = vec3_dot(light->position, light->position) - 2 * vec3_dot(light->position, point) + vec3_dot(point, point);|' \
    test_half_vector "" "which cancels far from"
plant "hint: an epsilon on M relative to the data" 03_triangle triangle.c \
    's|if (M == 0 \|\| !isfinite(M))|if (real_abs(M) <= (real)1e-12 * vec3_length(a_b) * vec3_length(a_c) * vec3_length(r.d) \|\| !isfinite(M))|' \
    test_grazing_rays "" "an epsilon on M"
plant "hint: a glass ray skipped for a small weight" 09_refraction shade_glass.c \
    's|if (e.R > 0) /\* R L_reflected \*/|if (e.R > (real)1e-3 \|\| !e.transmits)|' \
    test_glass_weights "" "a threshold of shade_glass's own"
plant "hint: bilinear's floor through an int" 10_interpolation texture.c \
    's|(long long)fx, img->width);|(int)fx, img->width);|; s|(long long)fx + 1, img->width);|(int)fx + 1, img->width);|' \
    test_bilinear "" "an int conversion of floor\(x\) is undefined"
plant "hint: the entry's t0 from x's crossing alone" 11_grid grid_march.c \
    's|\*t0 = real_fmax(\*t0, near);|*t0 = a == 0 ? near : real_fmax(*t0, near);|' \
    test_march_counts "" "behind the origin or before t_min"
plant "hint: the entry tests d_a = 0 for inv_d_a = 0" 11_grid grid_march.c \
    's|if (inv_d\[a\] == 0) {|if (vec3_axis(r.d, a) == 0) {|' \
    test_dda_cells "" "not d_a == 0"
plant "hint: the entry with a fixed epsilon for the slack" 11_grid grid_march.c \
    's|real near = real_fmin(t_lo, t_hi) - slack\[a\], far = real_fmax(t_lo, t_hi) + slack\[a\];|real near = real_fmin(t_lo, t_hi) - (real)1e-9, far = real_fmax(t_lo, t_hi) + (real)1e-9; (void)slack;|' \
    test_dda_cells "" "enter with a slack of its own"
plant "hint: the stop rule with a fixed epsilon for the slack" 11_grid grid_march.c \
    's|if (s.best_t <= m.next\[a\] - slack\[a\])|if (s.best_t <= m.next[a] - (real)1e-9)|' \
    test_stop_rule "" "the stop rule with a slack of its own"
plant "hint: the mirror ray's window ends at 1e30" 08_mirrors mirror.c \
    's|return trace(\&next, mirror, 0, REAL_INFINITY, depth + 1, rays);|return trace(\&next, mirror, 0, (real)1e30, depth + 1, rays);|' \
    test_mirror_ray_reaches_probe "" "not up to a large number of one's own"
plant "hint: the resolution from the extents' own product" 11_grid grid_build.c \
    's|e\[a\] = extent\[a\] > 0 ? extent\[a\] / largest : 0;|e[a] = extent[a]; (void)largest;|' \
    test_resolution "" "relative to the largest, e_a / e_max"
# Scale, dimensions and the right one of two vectors; the handed-out code paths a student edits anyway.
plant "hint: sphere_roots' scale without the radius" 02_sphere sphere.c \
    's|vec3_make(vec3_max_abs(r.p), vec3_max_abs(s->center), s->radius)|vec3_make(vec3_max_abs(r.p), vec3_max_abs(s->center), 0)|' \
    test_roots_at_any_scale "" "the scale of the lengths is that of p, c and R together"
plant "hint: triangle_normal by 1 / sqrt(n . n)" 03_triangle triangle.c \
    's|return vec3_normalize(vec3_scale(n, 1 / largest));|return vec3_scale(n, 1 / real_sqrt(vec3_dot(n, n)));|' \
    test_normal "" "neither overflows nor underflows"
plant "hint: t_best a distance, not t" 04_many_shapes closest_hit.c \
    's|t_best = candidate.t;|t_best = vec3_length(vec3_sub(candidate.point, r.p));|' \
    test_closest_hit_in_any_order "" "not its distance from p"
plant "hint: the sphere's normal at the ray's start" 04_many_shapes chapters/04_many_shapes/surface.c \
    's|\*hit = surface_hit_record(s, r, t, n, 0, 0);|*hit = surface_hit_record(s, r, t, vec3_normalize(vec3_sub(r.p, s->sphere.center)), 0, 0);|' \
    test_hit_record_fields "" "pointing out of the sphere"
plant "hint: the sphere's normal turned towards the ray" 04_many_shapes chapters/04_many_shapes/surface.c \
    's|\*hit = surface_hit_record(s, r, t, n, 0, 0);|*hit = surface_hit_record(s, r, t, vec3_dot(n, r.d) > 0 ? vec3_neg(n) : n, 0, 0);|' \
    test_hit_record_fields "" "normal turned towards the ray"
plant "hint: the shape's face not recorded" 04_many_shapes chapters/04_many_shapes/surface.c \
    's|((surface_list \*)list)->items\[i\].face = s->face;|(void)0;|' \
    test_box_in_scene "" "a Box's triangle"
plant "hint: v = -d, not normalized" 05_lambert chapters/05_lambert/tracer.c \
    's|sp.v = vec3_neg(vec3_normalize(r.d));|sp.v = vec3_neg(r.d);|' \
    test_back_of_triangle_lit "" "whatever the length of d"
plant "hint: chapter 05's stage by the last light" 05_lambert chapters/05_lambert/shade_lambert.c \
    's|sp->n, &tr->desc->lights\[0\]);|sp->n, \&tr->desc->lights[tr->desc->n_lights - 1]);|' \
    test_trace_uses_the_query "" "the scene's first light as the lecture's one light"
plant "hint: the bound's back-off without the target" 06_shadows chapters/06_shadows/spawn.c \
    's|real_fmax(vec3_max_abs(target), vec3_max_abs(r.p));|vec3_max_abs(r.p);|' \
    test_spawn_ray_to_far_end "" "the target's or the ray's start"
plant "hint: chapter 06's Lambert with the geometric normal" 06_shadows chapters/06_shadows/shade_shadows.c \
    's|sp->hit.point, sp->n, light);|sp->hit.point, sp->hit.normal, light);|' \
    test_shadow_rays_only_when_needed "" "the shading normal sp->n"
plant "hint: chapter 06's stage by the last light" 06_shadows chapters/06_shadows/shade_shadows.c \
    's|const scene_light \*light = &tr->desc->lights\[0\];|const scene_light *light = \&tr->desc->lights[tr->desc->n_lights - 1];|' \
    test_shadow_rays_only_when_needed "" "the scene's first light"
plant "hint: the path's largest weight without blue" 08_mirrors chapters/08_mirrors/path.c \
    's|real_fmax(w.g, w.b)|real_fmax(w.g, w.g)|' \
    test_mirror_ray_reaches_probe "" "the largest channel of its weight"
plant "hint: a mirror only when k_m's red is" 08_mirrors chapters/08_mirrors/shade_glazed.c \
    's|(k_m.r == 0 \&\& k_m.g == 0 \&\& k_m.b == 0)|(k_m.r == 0)|' \
    test_mirror_ray_reaches_probe "" "any channel of k_m"
plant "hint: the path's weight by its channels' mean" 08_mirrors chapters/08_mirrors/path.c \
    's|real largest = real_fmax(w.r, real_fmax(w.g, w.b));|real largest = (w.r + w.g + w.b) / 3;|' \
    test_mirror_ray_reaches_probe "" "not the channels' mean"
plant "hint: no light gives the background" 05_lambert chapters/05_lambert/shade_lambert.c \
    's|return color_make(0, 0, 0);|return tr->desc->back_color;|' \
    test_back_of_triangle_lit "" "not the background colour"
plant "hint: the first cell moved forwards" 11_grid grid_march.c \
    's|x -= (real)m.step\[a\] \* back;|x += (real)m.step[a] * back;|' \
    test_dda_cells "" "moved forwards"
plant "hint: the shading normal turned by the geometric normal" 10_interpolation chapters/10_interpolation/shade_interp.c \
    's|ip.sp.n = shading_normal(ip.n_raw, sp->n);|ip.sp.n = shading_normal(ip.n_raw, sp->hit.normal);|' \
    test_smooth_shading "" "faces the viewer, sp->n"
plant "hint: the mesh's (u, v) with gamma and beta swapped" 10_interpolation chapters/10_interpolation/shade_interp.c \
    's|m->uvs\[f->vt\[2\]\], hit->beta, hit->gamma)|m->uvs[f->vt[2]], hit->gamma, hit->beta)|' \
    test_textured_sphere "" "in the order of the face's corners"
plant "hint: a matte point's normal flipped for a mirror ray" 10_interpolation chapters/10_interpolation/shade_interp.c \
    's|if (ip.smooth \&\& mirrors \&\& knobs->below == BELOW_FLIP)|if (ip.smooth \&\& (mirrors \|\| 1) \&\& knobs->below == BELOW_FLIP)|' \
    test_smooth_shading "" "a matte point keeps n_s"
plant "hint: first clamped to n_x on every axis" 11_grid grid_build.c \
    's|first\[a\] = real_to_index(real_ceil(f_lo) - 1, 0, g->n\[a\]);|first[a] = real_to_index(real_ceil(f_lo) - 1, 0, g->n[0]);|' \
    test_cell_range "" "the x axis's count of cells"
plant "hint: the shade function given depth + 1" 05_lambert chapters/05_lambert/tracer.c \
    's|color L = tr->shade(tr, &sp, depth, rays);|color L = tr->shade(tr, \&sp, depth + 1, rays);|' \
    test_trace_uses_the_query "" "the depth it was given"
plant "hint: a face's (u, v) from its first corner's vt alone" 10_interpolation chapters/10_interpolation/shade_interp.c \
    's|ip.has_uv = f->vt\[0\] >= 0 \&\& f->vt\[1\] >= 0 \&\& f->vt\[2\] >= 0;|ip.has_uv = f->vt[0] >= 0;|' \
    test_textured_sphere "" "every one of its corners has texture coordinates"
plant "hint: the surfaces without finite bounds never tested" 11_grid grid_march.c \
    's|e < g->start\[g->n_cells + 1\]; e++) /\* the surfaces without bounds \*/|e < g->start[g->n_cells]; e++)|' \
    test_empty_and_single "" "every ray tests it"
plant "hint: a scene's sphere with its shader and source swapped" 04_many_shapes chapters/04_many_shapes/surface.c \
    's|(sphere){s->center, s->radius}, s->shader, s->source)|(sphere){s->center, s->radius}, s->source, s->shader)|' \
    test_box_in_scene "" "each in its own place"
# A light just above the surface's plane is in front: no tolerance of one's own on n . (light_pos - point) > 0.
plant "hint: a tolerance on the light behind" 06_shadows shadow.c \
    's|vec3_dot(sp->n, vec3_sub(light_pos, sp->hit.point)) > 0|vec3_dot(sp->n, vec3_normalize(vec3_sub(light_pos, sp->hit.point))) > (real)1e-6|' \
    test_light_behind_the_surface "" "a tolerance of one's own in the test of a light behind"
# The resolution: e_max is the largest of all three extents.
plant "hint: e_max over x and y only" 11_grid grid_build.c \
    's|const double largest = fmax(fmax(extent\[0\], extent\[1\]), extent\[2\]);|const double largest = fmax(extent[0], extent[1]);|' \
    test_resolution "" "e_max, the largest extent, taken over two axes only"
# The resolution: lambda N is any real, not cut to an integer.
plant "hint: lambda N cut to an integer" 11_grid grid_build.c \
    's|double wanted = fmin(density \* (double)surfaces, (double)max_cells);|double wanted = fmin((double)(long)(density * (double)surfaces), (double)max_cells);|' \
    test_resolution "" "lambda N cut to an integer"
# The resolution's shrink: by a tenth at most a try, and again until the cap holds.
plant "hint: the shrink without its floor of 0.9" 11_grid grid_build.c \
    's|s \*= fmax(0.9, 0.99 \* pow((double)max_cells / cells, 1.0 / (spanned ? spanned : 1)));|s *= 0.99 * pow((double)max_cells / cells, 1.0 / (spanned ? spanned : 1));|' \
    test_resolution "" "s shrinks by a tenth at most a try"
plant "hint: the cap given up after three tries" 11_grid grid_build.c \
    's|^    for (;;) {|    for (int tries = 0; tries < 3; tries++) {|' \
    test_resolution "" "shrink s and round again, as many times as it takes"
# The untouched skeleton: no guessed mistake, the placeholder named.
plant "hint: an untouched exercise is named, not guessed at" 07_blinn_phong skeleton "" \
    test_exponent_behaviour "likely mistake: [^n]" "is still an exercise" "likely mistake: none yet"
plant "hint: an untouched exercise, in a test's own message" 06_shadows skeleton "" \
    test_occluder_between_beyond_behind "likely mistake: [^n]" "is still an exercise" "likely mistake: none yet"

[ "$failed" -eq 0 ]

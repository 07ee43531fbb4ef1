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
# exercise), else FILE of solutions/CHAPTER edited by SED.
plant() {
    local name=$1 chapter=$2 file=$3 script=$4 test=$5 must_not=$6
    shift 6
    local build=build-planted make_args=() out
    if [ "$file" = skeleton ]; then
        local others
        others=$(cd "$dir/chapters" && ls -d [0-9][0-9]_* | grep -v "^$chapter" | cut -c1-2 | tr '\n' ' ')
        make_args=(STUDENT=1 "REFERENCE=$others" BUILD=$build-skeleton)
        build=$build-skeleton
    else
        cp "solutions/$chapter/$file" "$dir/solutions/$chapter/$file"
        sed -i "$script" "$dir/solutions/$chapter/$file"
        if cmp -s "solutions/$chapter/$file" "$dir/solutions/$chapter/$file"; then
            echo "  FAIL    $name: the sed script changed nothing in solutions/$chapter/$file"
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
    [ "$file" = skeleton ] || cp "solutions/$chapter/$file" "$dir/solutions/$chapter/$file"
}

# l = light.pos - point, not divided by r, with the right 1/r^2: the numbers
# of dividing by r instead of r^2.  Both must be named.
plant "hint: l not normalized (the numbers of 1/r)" 05_lambert lambert.c \
    's|vec3 l = vec3_scale(to_light, 1 / real_sqrt(r2));|vec3 l = to_light;|' \
    test_irradiance_facing "" "divided by r, not r\^2" "l not normalized"
# The shadow ray built by hand from the hit point: acne, and spawn_ray_to named.
plant "hint: a shadow ray from the hit point itself" 06_shadows shadow.c \
    's|ray shadow = spawn_ray_to(sp, light_pos, policy, &t_max);|(void)policy; t_max = 1; ray shadow = {sp->hit.point, vec3_sub(light_pos, sp->hit.point)};|' \
    test_no_acne_no_leak "" "% acne" "likely mistake: .*spawn_ray_to"
# x^p by a loop of products: right for whole p only.
plant "hint: x^p by an integer loop" 07_blinn_phong phong.c \
    's|real highlight = real_pow(real_fmax(0, vec3_dot(n, h)), p);|real highlight = 1; for (int i = 0; i < p; i++) highlight *= real_fmax(0, vec3_dot(n, h));|' \
    test_exponent_behaviour "" "p = 2\.5" "fractional p"
# Glass: R and 1 - R swapped; each ray's path coefficient 1 instead of its weight.
plant "hint: the glass weights swapped" 09_refraction shade_glass.c \
    's|L = color_mul(R, mirror_radiance|L = color_mul(T, mirror_radiance|; s|color_mul(T, transmitted_radiance|color_mul(R, transmitted_radiance|' \
    test_glass_weights "" "R and 1 - R swapped"
plant "hint: the glass rays traced with coefficient 1" 09_refraction shade_glass.c \
    's|mirror_radiance(tr, sp, R, depth|mirror_radiance(tr, sp, color_make(1, 1, 1), depth|; s|transmitted_radiance(tr, sp, e.T, T, depth|transmitted_radiance(tr, sp, e.T, color_make(1, 1, 1), depth|' \
    test_glass_weights "" "min-weight 0\\.97" "coefficient other than its weight"
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
# The untouched skeleton: no guessed mistake, the placeholder named.
plant "hint: an untouched exercise is named, not guessed at" 07_blinn_phong skeleton "" \
    test_exponent_behaviour "likely mistake: [^n]" "is still an exercise" "likely mistake: none yet"
plant "hint: an untouched exercise, in a test's own message" 06_shadows skeleton "" \
    test_occluder_between_beyond_behind "likely mistake: [^n]" "is still an exercise" "likely mistake: none yet"

[ "$failed" -eq 0 ]

/* interp_stage.c - chapter 10: the stage, as the renderer describes it. */
#include "10_interpolation/interp_stage.h"

#include "10_interpolation/scenes/interp_scene.h"

interp_knobs interp_settings = INTERP_KNOBS_DEFAULT;

static const knob interp_knob_list[] = {
    {"shadow-eps", KNOB_CHOICE, &interp_settings.earlier.path.phong.spawn.eps, eps_policy_names,
     "where secondary rays start: none (the blunder), fixed 1e-3, bound (error bound)"},
    {"phong", KNOB_CHOICE, &interp_settings.earlier.path.phong.form, phong_form_names,
     "specular term: course k_s (n.h)^p I/r^2, lecture also times max(0, n.l)"},
    {"depth", KNOB_INT, &interp_settings.earlier.path.depth, NULL,
     "deepest bounce traced (0: eye rays only; at most 256)"},
    {"min-weight", KNOB_REAL, &interp_settings.earlier.path.min_weight, NULL,
     "no ray whose path weight (product of k_m, R, 1 - R along it) is below this (0: off)"},
    {"fresnel", KNOB_CHOICE, &interp_settings.earlier.fresnel, fresnel_mode_names,
     "glass reflectance: exact (Fresnel's equations) or schlick (Schlick's approximation)"},
    {"normals", KNOB_CHOICE, &interp_settings.normals, normal_source_names,
     "shading normal of a mesh with vn: interpolated, or geometric (the flat faces)"},
    {"texture-filter", KNOB_CHOICE, &interp_settings.filter, texture_filter_names,
     "texture lookup: nearest texel (the course's images) or bilinear blend of four"},
    {"below-surface", KNOB_CHOICE, &interp_settings.below, below_policy_names,
     "a mirror direction below the geometric surface: flip it above, or keep it (speckles)"},
};

/* snippet: interp_stage */
shading_stage interp_stage(build_query_fn build)
{
    return (shading_stage){
        .name = "10_interpolation",
        .summary = "10_interpolation: interpolated vertex normals and texture coordinates, textures, over the "
                   "shading of chapters 05-09",
        .knobs = interp_knob_list,
        .n_knobs = sizeof interp_knob_list / sizeof interp_knob_list[0],
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS | FEATURE_MANY_LIGHTS | FEATURE_PHONG |
                    FEATURE_AMBIENT | FEATURE_MIRRORS | FEATURE_GLASS | FEATURE_TEXTURES | FEATURE_VERTEX_NORMALS,
        .shade = shade_interp,
        .shade_knobs = &interp_settings,
        .build_query = build, /* NULL: chapter 04's linear scan */
        .builtin = interp_scene,
    };
}
/* end snippet */

/* interp_stage.c - chapter 10: the stage, as the renderer describes it. */
#include "10_interpolation/interp_stage.h"

#include "10_interpolation/scenes/interp_scene.h"

/* snippet: interp_stage */
shading_stage interp_stage(interp_knobs *k, knob *rows, build_query_fn build)
{
    stage_knobs aimed = {.interp = k}; /* the rows of chapters 06-09's knobs, then this chapter's */
    int n = glass_knob_rows(&k->earlier, rows, &aimed);
    rows[n++] = (knob){"normals", KNOB_CHOICE, &k->normals, normal_source_names,
                       "shading normal of a mesh with vn: interpolated, or geometric (the flat faces)"};
    rows[n++] = (knob){"texture-filter", KNOB_CHOICE, &k->filter, texture_filter_names,
                       "texture lookup: nearest texel (the course's images) or bilinear blend of four"};
    rows[n++] = (knob){"below-surface", KNOB_CHOICE, &k->below, below_policy_names,
                       "a mirror direction below the geometric surface: flip it above, or keep it (speckles)"};
    return (shading_stage){
        .name = "10_interpolation",
        .summary = "10_interpolation: interpolated vertex normals and texture coordinates, textures, over the "
                   "shading of chapters 05-09",
        .knobs = rows,
        .n_knobs = n,
        .modelled = FEATURE_SPHERES | FEATURE_TRIANGLES | FEATURE_BOXES | FEATURE_MESHES | FEATURE_SHADERS |
                    FEATURE_RGB_NORMALS | FEATURE_LIGHTS | FEATURE_SHADOWS | FEATURE_MANY_LIGHTS | FEATURE_PHONG |
                    FEATURE_AMBIENT | FEATURE_MIRRORS | FEATURE_GLASS | FEATURE_TEXTURES | FEATURE_VERTEX_NORMALS,
        .shade = shade_interp,
        .shade_knobs = aimed,
        .build_query = build, /* NULL: chapter 04's linear scan */
        .builtin = interp_scene,
    };
}
/* end snippet */

/* SPDX-License-Identifier: MIT */
/* Stage 1, base: render state defaults and validation, pixel format sizes, and
 * the argument checks of meshes and line lists that every later stage shares. */
#include "zl_internal.h"

void zl_state_default(zl_state *s)
{
    s->depth_test = 1;
    s->depth_write = 1;
    s->depth_func = ZL_LESS;
    s->color_mask = ZL_MASK_RGB;
    s->cull = ZL_CULL_NONE;
    s->front_face = ZL_FRONT_CCW;
    s->shading = ZL_SHADE_FLAT;
    s->light_on = 0;
    s->ambient = 0;
    s->color.r = 255;
    s->color.g = 255;
    s->color.b = 255;
    s->light_dir.x = 0;
    s->light_dir.y = 0;
    s->light_dir.z = ZL_FX_ONE;
    s->near_z = 0;
    s->far_z = 0;
}

zl_status zl_state_check(const zl_state *s)
{
    if (s == NULL)
        return ZL_ERR_ARG;
    if (s->depth_func > ZL_ALWAYS || s->cull > ZL_CULL_FRONT || s->front_face > ZL_FRONT_CW ||
        s->shading > ZL_SHADE_GOURAUD || s->color_mask > ZL_MASK_RGB || s->depth_test > 1 ||
        s->depth_write > 1 || s->light_on > 1)
        return ZL_ERR_ARG;
    if ((!ZL_FEATURE_LIGHTING && s->light_on) || (!ZL_FEATURE_DEPTH_MAP && (s->near_z != 0 || s->far_z != 0)) ||
        (!ZL_FEATURE_DEPTH_FUNCS && s->depth_test && s->depth_func != ZL_LESS && s->depth_func != ZL_LEQUAL &&
         s->depth_func != ZL_ALWAYS))
        return ZL_ERR_UNSUPPORTED; /* compiled out (zl_config.h) */
    /* A unit vector: components within +-1.0 keep the lighting dot product
     * (normal below 2^31 times light) far inside 64 bits. */
    if (s->light_on && (s->light_dir.x < -ZL_FX_ONE || s->light_dir.x > ZL_FX_ONE ||
                        s->light_dir.y < -ZL_FX_ONE || s->light_dir.y > ZL_FX_ONE ||
                        s->light_dir.z < -ZL_FX_ONE || s->light_dir.z > ZL_FX_ONE))
        return ZL_ERR_RANGE;
    if ((s->near_z != 0 || s->far_z != 0) && !(s->near_z > 0 && s->far_z > s->near_z))
        return ZL_ERR_RANGE;
    return ZL_OK;
}

unsigned zl_format_bytes(zl_format f)
{
    switch (f) {
    case ZL_FORMAT_RGB565:
    case ZL_FORMAT_RGB565_BE:
        return 2;
    case ZL_FORMAT_RGB888:
        return 3;
    }
    return 0;
}

zl_status zl_check_mesh(const zl_mesh *m, int pixel_space)
{
    uint32_t i, n;
    int32_t bad = 0;
    (void)pixel_space;
    if (m == NULL)
        return ZL_ERR_ARG;
    if ((m->vertex_count > 0 && m->positions == NULL) || (m->triangle_count > 0 && m->indices == NULL))
        return ZL_ERR_ARG;
    /* vertex_count - 1 - index is negative exactly for an index out of
     * range: OR-ing them tests a whole mesh with one branch at the end. */
    n = (uint32_t)m->triangle_count * 3u;
    for (i = 0; i < n; i += 3) {
        const int32_t top = (int32_t)m->vertex_count - 1;
        bad |= (top - ZL_MESH_IDX(m->indices, i)) | (top - ZL_MESH_IDX(m->indices, i + 1)) |
               (top - ZL_MESH_IDX(m->indices, i + 2));
    }
    return bad < 0 ? ZL_ERR_RANGE : ZL_OK;
}

zl_status zl_check_lines(const zl_lines *l)
{
    if (!ZL_FEATURE_LINES) /* compiled out (zl_config.h) */
        return ZL_ERR_UNSUPPORTED;
    uint32_t i;
    if (l == NULL)
        return ZL_ERR_ARG;
    if (l->prim > ZL_PRIM_POINTS)
        return ZL_ERR_ARG;
    if (l->count > 0 && l->positions == NULL)
        return ZL_ERR_ARG;
    for (i = 0; i < l->count; i++)
        if ((l->indices != NULL ? l->indices[i] : i) >= l->vertex_count)
            return ZL_ERR_RANGE;
    return ZL_OK;
}

/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: the entry point that runs the chosen row method
 * (active edge table or ray caster) over a planned scene. It sits above the
 * methods, which sit above the scene (zl_vis_scene.c), so calls run one way.
 */
#include "zl_vis_internal.h"

int zl_vis_render_rows(zl_vis *v, zl_rgb clear, zl_vis_row_fn fn, void *user)
{
    if (v == NULL || fn == NULL)
        return ZL_ERR_ARG;
    if (v->cfg.algorithm == ZL_VIS_AET)
        return zl_aet_render_rows(v, clear, fn, user);
    if (v->cfg.algorithm == ZL_VIS_RAYCAST)
        return zl_raycast_render_rows(v, clear, fn, user);
    return ZL_ERR_ARG;
}

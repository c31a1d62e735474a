/* SPDX-License-Identifier: MIT */
/* The benchmark scene (see bench_scene.h). */
#include "bench_scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int bench_scene_load(const char *path, zl_obj *obj, zl_mesh *mesh, zl_mat4 *mvp, zl_state *state)
{
    zl_obj_options opt;
    char msg[512];
    zl_mat4 proj, view;
    zl_vec3 eye = {0, 0, ZL_FX_ONE * 7 / 2}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_obj_options_default(&opt);
    opt.normalize = 1;
    if (zl_obj_load_file(obj, path, &opt, msg, sizeof msg) != ZL_OBJ_OK) {
        fprintf(stderr, "%s\n", msg);
        return 1;
    }
    *mesh = zl_obj_mesh(obj);
    if (zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(BENCH_W) / BENCH_H,
                            ZL_FX_ONE / 10, ZL_FX_INT(100)) != ZL_OK ||
        zl_mat4_look_at(&view, eye, target, up) != ZL_OK) {
        fprintf(stderr, "bench: cannot build the camera\n");
        return 1;
    }
    zl_mat4_mul(mvp, &proj, &view);
    zl_state_default(state);
    state->cull = ZL_CULL_BACK;
    state->light_on = 1;
    state->ambient = 40;
    state->color.r = 230;
    state->color.g = 200;
    state->color.b = 160;
    /* towards the light: up, right and towards the viewer, unit length */
    state->light_dir.x = 24576;
    state->light_dir.y = 32768;
    state->light_dir.z = 49152;
    return 0;
}

/* zl_draw_mesh's draw cache (zl_context.draw_cache) at the library's size:
 * the default call's cached path, as zl_context held it before issue 23. */
static uint64_t draw_cache_buf[ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) / 8 + 1];

void bench_scene_context(zl_context *ctx, uint16_t *color, uint16_t *depth, const zl_state *state)
{
    zl_target t;
    zl_rgb background = {20, 24, 32};
    memset(&t, 0, sizeof t);
    t.color = color;
    t.color_stride = BENCH_W * 2;
    t.depth = depth;
    t.depth_stride = BENCH_W * 2;
    t.width = BENCH_W;
    t.height = BENCH_H;
    t.format = ZL_FORMAT_RGB565;
    if (zl_init(ctx, &t) != ZL_OK)
        exit(2);
    ctx->draw_cache = draw_cache_buf;
    ctx->draw_cache_bytes = sizeof draw_cache_buf;
    zl_clear(ctx, background, 65535);
    ctx->state = *state;
}

/* SPDX-License-Identifier: MIT */
/* The ATmega2560 demo's scene: see model_scene.h. */
#include "model_scene.h"

#include "torus_mesh.h"

void model_scene_config(zl_frame_config *cfg)
{
    zl_frame_config c = {0};
    c.width = MODEL_SCENE_W;
    c.height = MODEL_SCENE_H;
    c.band_rows = 1; /* scanline mode: one row of colour and one of depth */
    c.format = ZL_FORMAT_RGB565_BE;
    c.color_buffers = 1;
    c.max_meshes = 1;
    c.max_vertices = TORUS_VERTEX_COUNT;
    c.max_triangles = MODEL_SCENE_MAX_TRIANGLES;
    c.max_active = MODEL_SCENE_MAX_ACTIVE;
    *cfg = c;
}

void model_scene_roomy_config(zl_frame_config *cfg)
{
    model_scene_config(cfg);
    cfg->max_triangles = TORUS_TRIANGLE_COUNT;
    cfg->max_active = TORUS_TRIANGLE_COUNT;
}

/* The torus turns 7.5 degrees a frame about y and half that about x; the
 * camera stands at (0, 0, 3.4) looking at the origin. This and scene_setup
 * are out of line so that their temporaries (six matrices) are off the
 * stack before the frame renders: on an 8 KB AVR the stack is what is left. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static zl_status scene_matrices(zl_mat4 *mvp, zl_mat4 *model, uint16_t step)
{
    zl_mat4 proj, view, pv, turn_y, turn_x;
    zl_vec3 eye = {0, 0, ZL_FX_INT(3) + ZL_FX_ONE * 2 / 5}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_fixed deg = (ZL_FX_INT(15) / 2) * (int32_t)step;
    zl_status s = zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(45)), ZL_FX_INT(5) / 4, ZL_FX_ONE / 2,
                                      ZL_FX_INT(10));
    if (s == ZL_OK)
        s = zl_mat4_look_at(&view, eye, target, up);
    if (s != ZL_OK)
        return s;
    zl_mat4_rotate_y(&turn_y, zl_angle_from_deg(deg));
    zl_mat4_rotate_x(&turn_x, zl_angle_from_deg(deg / 2 + ZL_FX_INT(30)));
    zl_mat4_mul(model, &turn_x, &turn_y);
    zl_mat4_mul(&pv, &proj, &view);
    zl_mat4_mul(mvp, &pv, model);
    return ZL_OK;
}

/* The matrix of frame `step`, and the state: flat shading lights in model
 * space, so the fixed world light (upper left, towards the viewer) is
 * turned back by the model's rotation (its transpose). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static zl_status scene_setup(zl_mat4 *mvp, zl_state *st, uint16_t step)
{
    static const zl_fixed world_light[3] = {-26214, 39321, 45875}; /* (-0.4, 0.6, 0.7) */
    zl_fixed l[3];
    zl_mat4 model;
    unsigned i, k;
    zl_status s = scene_matrices(mvp, &model, step);
    if (s != ZL_OK)
        return s;
    for (i = 0; i < 3u; i++) {
        int64_t sum = 0;
        for (k = 0; k < 3u; k++)
            sum += (int64_t)model.m[k * 4u + i] * world_light[k];
        l[i] = (zl_fixed)(sum / 65536);
    }
    zl_state_default(st);
    st->cull = ZL_CULL_BACK;
    st->light_on = 1;
    st->ambient = 60;
    st->color.r = 250;
    st->color.g = 170;
    st->color.b = 60;
    st->light_dir.x = l[0];
    st->light_dir.y = l[1];
    st->light_dir.z = l[2];
    return ZL_OK;
}

/* Begin frame `index` in work and submit the torus. Out of line: its
 * matrix, state and configuration (about 150 bytes on the AVR) are copied
 * into the work buffer by zl_frame_add_mesh, so they leave the stack before
 * the rows render. */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static zl_status scene_begin(zl_frame *frame, uint16_t index, const zl_frame_config *cfg, uint64_t *work,
                             size_t work_bytes)
{
    static const zl_rgb background = {10, 20, 40};
    zl_frame_config c;
    zl_mat4 mvp;
    zl_state st;
    zl_status s;
    if (cfg != NULL)
        c = *cfg;
    else
        model_scene_config(&c);
    if (zl_frame_bytes(&c) > work_bytes)
        return ZL_ERR_ARG;
    s = scene_setup(&mvp, &st, (uint16_t)(index % MODEL_SCENE_FRAMES));
    if (s == ZL_OK)
        s = zl_frame_begin(frame, &c, work, work_bytes, background, 65535);
    if (s == ZL_OK)
        s = zl_frame_add_mesh(frame, &torus_mesh, &mvp, &st);
    return s;
}

int model_scene_render(uint16_t index, const zl_frame_config *cfg, uint64_t *work, size_t work_bytes,
                       zl_band_fn row_fn, void *user, zl_frame_needs_t *needs)
{
    zl_frame frame;
    int r;
    zl_status s = scene_begin(&frame, index, cfg, work, work_bytes);
    if (s != ZL_OK)
        return s;
    r = zl_frame_render(&frame, row_fn, user);
    if (needs != NULL)
        *needs = zl_frame_needs(&frame);
    return r;
}

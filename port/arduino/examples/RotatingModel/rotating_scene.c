/* SPDX-License-Identifier: MIT */
/* The RotatingModel example's scene: see rotating_scene.h. */
#include "rotating_scene.h"

/* A cube of side 2 about the origin; const, so it stays in flash where the
 * compiler can put it there (on AVR, const data is copied to RAM: 96 + 72 +
 * 36 bytes here). */
static const zl_fixed cube_positions[8 * 3] = {
    ZL_FX_INT(-1), ZL_FX_INT(-1), ZL_FX_INT(-1), ZL_FX_INT(1), ZL_FX_INT(-1), ZL_FX_INT(-1),
    ZL_FX_INT(1),  ZL_FX_INT(1),  ZL_FX_INT(-1), ZL_FX_INT(-1), ZL_FX_INT(1), ZL_FX_INT(-1),
    ZL_FX_INT(-1), ZL_FX_INT(-1), ZL_FX_INT(1),  ZL_FX_INT(1),  ZL_FX_INT(-1), ZL_FX_INT(1),
    ZL_FX_INT(1),  ZL_FX_INT(1),  ZL_FX_INT(1),  ZL_FX_INT(-1), ZL_FX_INT(1),  ZL_FX_INT(1),
};
/* Two counter-clockwise triangles per face, seen from outside. */
static const uint16_t cube_indices[12 * 3] = {
    4, 5, 6, 4, 6, 7, /* +z */
    1, 0, 3, 1, 3, 2, /* -z */
    5, 1, 2, 5, 2, 6, /* +x */
    0, 4, 7, 0, 7, 3, /* -x */
    7, 6, 2, 7, 2, 3, /* +y */
    0, 1, 5, 0, 5, 4, /* -y */
};
static const uint8_t cube_face_colors[12 * 3] = {
    230, 60,  50,  230, 60,  50,  /* red */
    60,  200, 80,  60,  200, 80,  /* green */
    60,  110, 230, 60,  110, 230, /* blue */
    240, 200, 60,  240, 200, 60,  /* yellow */
    220, 220, 220, 220, 220, 220, /* white */
    200, 80,  220, 200, 80,  220, /* magenta */
};

void rotating_scene_config(zl_frame_config *cfg)
{
    zl_frame_config c = {0};
    c.width = ROTATING_SCENE_W;
    c.height = ROTATING_SCENE_H;
    c.band_rows = 1; /* scanline mode: one row of colour and depth */
    c.format = ZL_FORMAT_RGB565_BE;
    c.color_buffers = 1; /* the sketch's SPI writes block */
    c.max_meshes = 1;
    c.max_vertices = 8;
    c.max_triangles = 12;
    /* A triangle clipped by the near plane counts once per piece (up to 8);
     * the cube never reaches it, so 12 suffices: a changed scene that
     * needs more stops with ZL_ERR_CAPACITY before drawing. */
    c.max_active = 12;
    *cfg = c;
}

/* The model turns 3 degrees a frame about y and 1.5 about x; the camera
 * stands at (0, 0, 5) looking at the origin. */
static zl_status scene_mvp(zl_mat4 *mvp, zl_mat4 *model, uint16_t step)
{
    zl_mat4 proj, view, pv, turn_y, turn_x;
    zl_vec3 eye = {0, 0, ZL_FX_INT(5)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_fixed deg_y = ZL_FX_INT(3) * (int32_t)step;
    zl_status s = zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(40)), ZL_FX_ONE, ZL_FX_ONE / 2,
                                      ZL_FX_INT(20));
    if (s == ZL_OK)
        s = zl_mat4_look_at(&view, eye, target, up);
    if (s != ZL_OK)
        return s;
    zl_mat4_rotate_y(&turn_y, zl_angle_from_deg(deg_y));
    zl_mat4_rotate_x(&turn_x, zl_angle_from_deg(deg_y / 2));
    zl_mat4_mul(model, &turn_x, &turn_y);
    zl_mat4_mul(&pv, &proj, &view);
    zl_mat4_mul(mvp, &pv, model);
    return ZL_OK;
}

/* Lighting is in model space: the light direction is turned back by the
 * inverse (transpose) of the model's rotation, so the light stays fixed in
 * the world (above, left, in front of the viewer) while the cube turns. */
static void scene_state(zl_state *st, const zl_mat4 *model)
{
    static const zl_fixed world_light[3] = {-24576, 32768, 49152}; /* about unit length */
    zl_fixed model_light[3];
    int i;
    for (i = 0; i < 3; i++) {
        int64_t sum = 0;
        int k;
        for (k = 0; k < 3; k++)
            sum += (int64_t)model->m[k * 4 + i] * world_light[k];
        model_light[i] = (zl_fixed)(sum / 65536);
    }
    zl_state_default(st);
    st->cull = ZL_CULL_BACK;
    st->light_on = 1;
    st->ambient = 70;
    st->light_dir.x = model_light[0];
    st->light_dir.y = model_light[1];
    st->light_dir.z = model_light[2];
}

/* The 2D overlay drawn into every row before it goes to the panel
 * (zl_overlay.h): the frame number top left, a gauge of the turn along the
 * bottom. The same calls on every row give the image they give on a whole
 * frame. */
typedef struct {
    zl_band_fn row_fn;
    void *user;
    uint16_t step;
} overlay_pass;

/* "frame NNN" without stdio: step is 0 .. 999. */
static void frame_label(char out[10], uint16_t step)
{
    static const char prefix[] = "frame ";
    uint8_t i;
    for (i = 0; i < 6; i++)
        out[i] = prefix[i];
    out[6] = (char)('0' + step / 100u % 10u);
    out[7] = (char)('0' + step / 10u % 10u);
    out[8] = (char)('0' + step % 10u);
    out[9] = '\0';
}

static int draw_overlay(void *user, const zl_band *band)
{
    static const zl_rgb text = {255, 255, 255}, gauge = {255, 200, 40}, border = {200, 200, 200};
    const overlay_pass *o = (const overlay_pass *)user;
    uint16_t filled = (uint16_t)((uint32_t)(ROTATING_SCENE_W - 12u) * o->step / ROTATING_SCENE_FRAMES);
    char label[10];
    zl_canvas c;
    if (zl_canvas_of_band(&c, band) != ZL_OK)
        return ZL_ERR_ARG;
    frame_label(label, o->step);
    (void)zl_canvas_text(&c, 6, 6, label, 2, text);
    (void)zl_canvas_rect(&c, 4, (int16_t)(ROTATING_SCENE_H - 14u), (uint16_t)(ROTATING_SCENE_W - 8u), 10, border);
    (void)zl_canvas_fill_rect(&c, 6, (int16_t)(ROTATING_SCENE_H - 12u), filled, 6, gauge);
    return o->row_fn(o->user, band);
}

int rotating_scene_render(uint16_t index, uint64_t *work, size_t work_bytes, zl_band_fn row_fn,
                          void *user)
{
    overlay_pass pass;
    static const zl_rgb background = {16, 24, 40};
    static const zl_mesh cube = {cube_positions, cube_indices, NULL, cube_face_colors, 8, 12};
    zl_frame_config cfg;
    zl_frame frame;
    zl_mat4 mvp, model;
    zl_state st;
    zl_status s;
    rotating_scene_config(&cfg);
    if (zl_frame_bytes(&cfg) > work_bytes)
        return ZL_ERR_ARG;
    pass.row_fn = row_fn;
    pass.user = user;
    pass.step = (uint16_t)(index % ROTATING_SCENE_FRAMES);
    s = scene_mvp(&mvp, &model, pass.step);
    if (s != ZL_OK)
        return s;
    scene_state(&st, &model);
    s = zl_frame_begin(&frame, &cfg, work, work_bytes, background, 65535);
    if (s == ZL_OK)
        s = zl_frame_add_mesh(&frame, &cube, &mvp, &st);
    if (s != ZL_OK)
        return s;
    return zl_frame_render(&frame, draw_overlay, &pass);
}

/* SPDX-License-Identifier: MIT */
/* The OLED demo's animation: see oled_scene.h. */
#include "oled_scene.h"

#include "bunny_mesh.h"

/* The animation needs at most 1473 kept triangles and 78 active ones on a
 * row (zl_frame_needs() over all frames, printed by host/oled_reference.c);
 * these leave a margin. If a changed scene needs more, the firmware and the
 * reference stop with ZL_ERR_CAPACITY before drawing, never draw wrongly. */
#define OLED_SCENE_MAX_ACTIVE 128
#define OLED_SCENE_MAX_TRIANGLES 2048

void oled_scene_config(zl_frame_config *cfg)
{
    zl_frame_config c = {0};
    c.width = OLED_SCENE_W;
    c.height = OLED_SCENE_H;
    c.band_rows = 1; /* scanline mode */
    c.format = ZL_FORMAT_RGB565;
    c.color_buffers = 1;
    c.max_meshes = 1;
    c.max_vertices = bunny_mesh.vertex_count;
    c.max_triangles = OLED_SCENE_MAX_TRIANGLES;
    c.max_active = OLED_SCENE_MAX_ACTIVE;
    *cfg = c;
}

/* Model turned by `index` steps about y, seen from (0, 0.3, 3.2) looking at
 * the origin: the bunny fills most of the panel's height. */
static int scene_mvp(zl_mat4 *mvp, int index)
{
    zl_mat4 proj, view, model, pv;
    zl_vec3 eye = {0, ZL_FX_ONE * 3 / 10, ZL_FX_ONE * 32 / 10};
    zl_vec3 target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    int degrees = (index % OLED_SCENE_FRAMES) * OLED_SCENE_DEGREES_PER_FRAME;
    if (zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(45)), ZL_FX_INT(OLED_SCENE_W) / OLED_SCENE_H,
                            ZL_FX_ONE / 10, ZL_FX_INT(100)) != ZL_OK ||
        zl_mat4_look_at(&view, eye, target, up) != ZL_OK)
        return -1;
    zl_mat4_rotate_y(&model, zl_angle_from_deg(ZL_FX_INT(degrees)));
    zl_mat4_mul(&pv, &proj, &view);
    zl_mat4_mul(mvp, &pv, &model);
    return 0;
}

/* Lighting is in model space: turn the light against the model so that it
 * stays fixed in the world, above and in front, left of the viewer. */
static int scene_state(zl_state *st, int index)
{
    zl_vec3 towards_light = {24576, 32768, 49152}; /* (0.375, 0.5, 0.75): about unit length */
    zl_mat4 unturn;
    zl_vec4 l;
    int degrees = (index % OLED_SCENE_FRAMES) * OLED_SCENE_DEGREES_PER_FRAME;
    zl_mat4_rotate_y(&unturn, zl_angle_from_deg(ZL_FX_INT(-degrees)));
    if (zl_transform_point(&unturn, towards_light, &l) != ZL_OK)
        return -1;
    zl_state_default(st);
    st->cull = ZL_CULL_BACK;
    st->light_on = 1;
    st->ambient = 60;
    st->color.r = 230;
    st->color.g = 200;
    st->color.b = 160;
    st->light_dir.x = l.x;
    st->light_dir.y = l.y;
    st->light_dir.z = l.z;
    return 0;
}

/* The overlay drawn into every row before it goes to the panel: the frame
 * number top left and a gauge of the turn along the bottom. */
typedef struct {
    zl_band_fn row_fn;
    void *user;
    int index;
} overlay_pass;

/* "frame NN" without stdio: index is 0 .. 99. */
static void frame_label(char out[9], int index)
{
    static const char prefix[] = "frame ";
    int i;
    for (i = 0; i < 6; i++)
        out[i] = prefix[i];
    out[6] = (char)('0' + index / 10 % 10);
    out[7] = (char)('0' + index % 10);
    out[8] = '\0';
}

static int draw_overlay(void *user, const zl_band *band)
{
    static const zl_rgb text = {255, 255, 255}, gauge = {255, 220, 120}, frame = {160, 160, 160};
    const overlay_pass *o = (const overlay_pass *)user;
    int degrees = (o->index % OLED_SCENE_FRAMES) * OLED_SCENE_DEGREES_PER_FRAME;
    char label[9];
    zl_canvas c;
    if (zl_canvas_of_band(&c, band) != ZL_OK)
        return ZL_ERR_ARG;
    frame_label(label, o->index % 100);
    (void)zl_canvas_text(&c, 2, 2, label, 1, text);
    (void)zl_canvas_rect(&c, 2, OLED_SCENE_H - 6, 62, 4, frame);
    (void)zl_canvas_fill_rect(&c, 3, OLED_SCENE_H - 5, (uint16_t)(60 * degrees / 360), 2, gauge);
    return o->row_fn(o->user, band);
}

int oled_scene_render(int index, void *work, size_t work_bytes, zl_band_fn row_fn, void *user,
                      zl_frame_needs_t *needs)
{
    overlay_pass pass;
    /* A dark blue-grey background (grey level 2, not 0): a row or window
     * written in the wrong place shows against it. */
    static const zl_rgb background = {30, 40, 60};
    zl_frame_config cfg;
    zl_frame frame;
    zl_mat4 mvp;
    zl_state st;
    zl_status s;
    int r;
    oled_scene_config(&cfg);
    if (scene_mvp(&mvp, index) != 0 || scene_state(&st, index) != 0)
        return ZL_ERR_ARG;
    s = zl_frame_begin(&frame, &cfg, work, work_bytes, background, 65535);
    if (s == ZL_OK)
        s = zl_frame_add_mesh(&frame, &bunny_mesh, &mvp, &st);
    if (s != ZL_OK)
        return s;
    pass.row_fn = row_fn;
    pass.user = user;
    pass.index = index;
    r = zl_frame_render(&frame, draw_overlay, &pass);
    if (needs != NULL)
        *needs = zl_frame_needs(&frame);
    return r;
}

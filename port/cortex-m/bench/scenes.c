/* The benchmark and golden scenes: see scenes.h. */
#include "scenes.h"

#include <string.h>

#include "bunny_mesh.h"
#include "grid_mesh.h"
#include "tetra_mesh.h"

/* Fill rate: four triangles, each containing the clip-space square
 * [-1,1] x [-1,1] (so the whole viewport), alternately wound, at depths 0.8,
 * 0.6, 0.4, 0.2: drawn in that order every fragment passes LESS. */
#define F(v) ((zl_fixed)((v) * 65536))
static const zl_fixed fill_positions[] = {
    F(-1), F(-1), F(0.8),  F(3), F(-1), F(0.8),  F(-1), F(3), F(0.8),
    F(1),  F(1),  F(0.6),  F(1), F(-3), F(0.6),  F(-3), F(1), F(0.6),
    F(-1), F(1),  F(0.4),  F(-1), F(-3), F(0.4), F(3), F(1), F(0.4),
    F(1),  F(-1), F(0.2),  F(1), F(3), F(0.2),   F(-3), F(-1), F(0.2),
};
#undef F
static const uint16_t fill_indices[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
static const uint8_t fill_face_colors[] = {200, 40, 40, 40, 200, 40, 40, 40, 200, 220, 220, 60};
static const uint8_t fill_vertex_colors[] = {
    255, 0, 0,    0, 255, 0,    0, 0, 255,
    255, 255, 0,  0, 255, 255,  255, 0, 255,
    250, 250, 250, 10, 10, 10,  128, 64, 32,
    30, 160, 90,  200, 30, 120, 90, 90, 220,
};

static void identity_like(zl_mat4 *m, zl_fixed sx, zl_fixed tx, zl_fixed tz)
{
    /* clip = (sx * x + tx, sx * y + tx, z + tz, 1) */
    zl_mat4_identity(m);
    m->m[0] = sx;
    m->m[3] = tx;
    m->m[5] = sx;
    m->m[7] = tx;
    m->m[11] = tz;
}

/* The perspective camera; with exact != 0 the state gets its near and far
 * for the exact depth mapping (zl_state near_z, far_z). */
static int camera(zl_mat4 *mvp, zl_state *state, zl_vec3 eye, int exact)
{
    zl_mat4 proj, view;
    zl_vec3 target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    if (zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(SCENE_W) / SCENE_H,
                            ZL_FX_ONE / 10, ZL_FX_INT(100)) != ZL_OK ||
        zl_mat4_look_at(&view, eye, target, up) != ZL_OK)
        return -1;
    zl_mat4_mul(mvp, &proj, &view);
    if (exact) {
        state->near_z = ZL_FX_ONE / 10;
        state->far_z = ZL_FX_INT(100);
    }
    return 0;
}

int scene_make(scene *s, int which)
{
    memset(s, 0, sizeof *s);
    zl_state_default(&s->state);
    switch (which) {
    case SCENE_BUNNY:
    case SCENE_BUNNY_EXACT: {
        /* exactly tools/bench/bench_scene.c (bunny_exact: and the exact depth mapping) */
        zl_vec3 eye = {0, 0, ZL_FX_ONE * 7 / 2};
        s->name = which == SCENE_BUNNY ? "bunny" : "bunny_exact";
        s->mesh = bunny_mesh;
        s->state.cull = ZL_CULL_BACK;
        s->state.light_on = 1;
        s->state.ambient = 40;
        s->state.color.r = 230;
        s->state.color.g = 200;
        s->state.color.b = 160;
        s->state.light_dir.x = 24576;
        s->state.light_dir.y = 32768;
        s->state.light_dir.z = 49152;
        return camera(&s->mvp, &s->state, eye, which == SCENE_BUNNY_EXACT);
    }
    case SCENE_FILL:
    case SCENE_FILL_GOURAUD:
        s->name = which == SCENE_FILL ? "fill" : "fill_gouraud";
        s->mesh.positions = fill_positions;
        s->mesh.indices = fill_indices;
        s->mesh.vertex_count = 12;
        s->mesh.triangle_count = 4;
        if (which == SCENE_FILL) {
            s->mesh.face_colors = fill_face_colors;
        } else {
            s->mesh.vertex_colors = fill_vertex_colors;
            s->state.shading = ZL_SHADE_GOURAUD;
            s->gouraud = 1;
        }
        identity_like(&s->mvp, ZL_FX_ONE, 0, 0);
        return 0;
    case SCENE_TRIS:
        /* grid x, y in 0..64 -> clip x / 32 - 1, depth 0.5 */
        s->name = "tris";
        s->mesh = grid_mesh;
        s->state.color.r = 90;
        s->state.color.g = 180;
        s->state.color.b = 250;
        identity_like(&s->mvp, ZL_FX_ONE / 32, -ZL_FX_ONE, ZL_FX_ONE / 2);
        return 0;
    case SCENE_TETRA: {
        zl_vec3 eye = {ZL_FX_ONE / 5, ZL_FX_ONE / 10, ZL_FX_ONE * 2 / 5}; /* inside the model's hull: near clipping */
        s->name = "tetra";
        s->mesh = tetra_mesh;
        s->state.shading = ZL_SHADE_GOURAUD;
        s->gouraud = 1;
        return camera(&s->mvp, &s->state, eye, 1); /* clipped: the exact mapping's clip path */
    }
    default:
        return -1;
    }
}

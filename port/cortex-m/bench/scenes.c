/* SPDX-License-Identifier: MIT */
/* The benchmark and golden scenes: see scenes.h. */
#include "scenes.h"

#include <string.h>

#include "bunny_mesh.h"
#include "checker_texture.h"
#include "floor_mesh.h"
#include "glass_texture.h"
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

/* The benchmark camera, with the near plane at near_z (0.1 but in bunny_clip). */
static int camera_view_near(zl_mat4 *mvp, zl_mat4 *view, zl_vec3 eye, zl_fixed near_z)
{
    zl_mat4 proj;
    zl_vec3 target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    if (zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(SCENE_W) / SCENE_H, near_z,
                            ZL_FX_INT(100)) != ZL_OK ||
        zl_mat4_look_at(view, eye, target, up) != ZL_OK)
        return -1;
    zl_mat4_mul(mvp, &proj, view);
    return 0;
}

static int camera_view(zl_mat4 *mvp, zl_mat4 *view, zl_vec3 eye)
{
    return camera_view_near(mvp, view, eye, ZL_FX_ONE / 10);
}

/* The perspective camera; with exact != 0 the state gets its near and far
 * for the exact depth mapping (zl_state near_z, far_z). */
static int camera(zl_mat4 *mvp, zl_state *state, zl_vec3 eye, int exact)
{
    zl_mat4 view;
    if (camera_view(mvp, &view, eye) != 0)
        return -1;
    if (exact) {
        state->near_z = ZL_FX_ONE / 10;
        state->far_z = ZL_FX_INT(100);
    }
    return 0;
}

static uint8_t bunny_lit[3 * BUNNY_VERTEX_COUNT];

/* SCENE_BUNNY_SMOOTH (see scenes.h). */
static int bunny_smooth(scene *s)
{
    zl_vec3 eye = {0, 0, ZL_FX_ONE * 7 / 2};
    zl_lighting *lt = &s->lighting;
    s->name = "bunny_specular";
    s->mesh = bunny_mesh;
    s->mesh.vertex_colors = NULL; /* the material is one colour */
    s->state.cull = ZL_CULL_BACK;
    s->state.shading = ZL_SHADE_GOURAUD;
    s->gouraud = 1;
    if (camera_view(&s->mvp, &s->modelview, eye) != 0)
        return -1;
    zl_lighting_default(lt);
    lt->ambient.r = lt->ambient.g = lt->ambient.b = 40;
    lt->material.r = 230;
    lt->material.g = 200;
    lt->material.b = 160;
    lt->light_count = 2;
    lt->shininess = 24;
    lt->lights[0].dir.x = -ZL_FX_ONE; /* key light: eye space, up left, towards the viewer */
    lt->lights[0].dir.y = ZL_FX_INT(2);
    lt->lights[0].dir.z = ZL_FX_INT(2);
    lt->lights[0].diffuse.r = lt->lights[0].diffuse.g = lt->lights[0].diffuse.b = 215;
    lt->lights[0].specular.r = lt->lights[0].specular.g = lt->lights[0].specular.b = 255;
    lt->lights[1].dir.x = ZL_FX_ONE; /* fill light from the right and behind */
    lt->lights[1].dir.y = ZL_FX_ONE / 4;
    lt->lights[1].dir.z = -ZL_FX_ONE;
    lt->lights[1].diffuse.r = 40;
    lt->lights[1].diffuse.g = 60;
    lt->lights[1].diffuse.b = 110;
    s->normals = bunny_normals;
    s->lit = bunny_lit;
    if (zl_light_vertices(lt, &s->modelview, &s->mesh, s->normals, s->lit) != ZL_OK)
        return -1;
    s->mesh.vertex_colors = s->lit;
    return 0;
}

static uint8_t bunny_lit_one[3 * BUNNY_VERTEX_COUNT];
static uint8_t bunny_vertex_colors[3 * BUNNY_VERTEX_COUNT];

/* A colour channel from a model coordinate (the bunny is normalised to
 * about [-1, 1]): 40 + (p + 1) * 100, clamped to 0..255. */
static uint8_t channel_of(zl_fixed p)
{
    int32_t c = 40 + (int32_t)(((int32_t)p + ZL_FX_ONE) / 655);
    return (uint8_t)(c < 0 ? 0 : c > 255 ? 255 : c);
}

/* SCENE_BUNNY_GOURAUD: the benchmark scene with a colour per vertex. */
static int bunny_gouraud(scene *s)
{
    uint32_t i;
    if (scene_make(s, SCENE_BUNNY) != 0)
        return -1;
    s->name = "bunny_gouraud";
    s->state.light_on = 0;
    s->state.shading = ZL_SHADE_GOURAUD;
    s->gouraud = 1;
    for (i = 0; i < 3u * BUNNY_VERTEX_COUNT; i++)
        bunny_vertex_colors[i] = channel_of(bunny_positions[i]);
    s->mesh.vertex_colors = bunny_vertex_colors;
    return 0;
}

/* SCENE_BUNNY_LIT ("bunny_smooth"): the benchmark scene lit per vertex by
 * zl_light_vertices with the flat bunny's light (ambient 40, material
 * 230 200 160, one directional light, no specular), in eye space. */
static int bunny_lit_scene(scene *s)
{
    zl_vec3 eye = {0, 0, ZL_FX_ONE * 7 / 2};
    zl_lighting *lt = &s->lighting;
    zl_mat4 mvp;
    if (scene_make(s, SCENE_BUNNY) != 0 || camera_view(&mvp, &s->modelview, eye) != 0)
        return -1;
    s->name = "bunny_smooth";
    s->mesh.vertex_colors = NULL;
    s->state.light_on = 0;
    s->state.shading = ZL_SHADE_GOURAUD;
    s->gouraud = 1;
    zl_lighting_default(lt);
    lt->ambient.r = lt->ambient.g = lt->ambient.b = 40;
    lt->material.r = 230;
    lt->material.g = 200;
    lt->material.b = 160;
    lt->light_count = 1;
    lt->lights[0].dir.x = ZL_FX_ONE * 3 / 8;
    lt->lights[0].dir.y = ZL_FX_HALF;
    lt->lights[0].dir.z = ZL_FX_ONE * 3 / 4;
    lt->lights[0].diffuse.r = lt->lights[0].diffuse.g = lt->lights[0].diffuse.b = 215;
    s->normals = bunny_normals;
    s->lit = bunny_lit_one;
    if (zl_light_vertices(lt, &s->modelview, &s->mesh, s->normals, s->lit) != ZL_OK)
        return -1;
    s->mesh.vertex_colors = s->lit;
    return 0;
}

/* The textured scene's camera: from (0, 1.2, 1.5) towards (0, 0, -6). */
static int floor_camera(zl_mat4 *vp)
{
    zl_mat4 proj, view;
    zl_vec3 eye = {0, ZL_FX_ONE * 6 / 5, ZL_FX_ONE * 3 / 2}, target = {0, 0, -ZL_FX_INT(6)}, up = {0, ZL_FX_ONE, 0};
    if (zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(SCENE_W) / SCENE_H,
                            ZL_FX_ONE / 10, ZL_FX_INT(100)) != ZL_OK ||
        zl_mat4_look_at(&view, eye, target, up) != ZL_OK)
        return -1;
    zl_mat4_mul(vp, &proj, &view);
    return 0;
}

/* vp times a translation by (0, y, 0) and a scale of x by sx. */
static void lifted(zl_mat4 *out, const zl_mat4 *vp, zl_fixed y, zl_fixed sx)
{
    zl_mat4 t, sc, m;
    zl_vec3 ty = {0, y, 0}, s3 = {sx, ZL_FX_ONE, ZL_FX_ONE};
    zl_mat4_translate(&t, ty);
    zl_mat4_scale(&sc, s3);
    zl_mat4_mul(&m, &t, &sc);
    zl_mat4_mul(out, vp, &m);
}

static int textured_scene(scene *s)
{
    zl_mat4 vp;
    if (floor_camera(&vp) != 0)
        return -1;
    s->name = "textured";
    s->mesh = floor_mesh;
    s->mvp = vp;
    s->styled = 1;
    zl_style_default(&s->style);
    s->style.texture = &checker_texture;
    s->style.texcoords = floor_texcoords;
    s->style.tex_mapping = ZL_TEX_PERSPECTIVE;
    s->extra_count = 2;
    /* glass: RGBA4444 texels, alpha blended, no depth writes */
    s->extra_mesh[0] = floor_mesh;
    lifted(&s->extra_mvp[0], &vp, ZL_FX_HALF, ZL_FX_ONE);
    zl_state_default(&s->extra_state[0]);
    s->extra_state[0].depth_write = 0;
    zl_style_default(&s->extra_style[0]);
    s->extra_style[0].texture = &glass_texture;
    s->extra_style[0].texcoords = floor_texcoords;
    s->extra_style[0].tex_mapping = ZL_TEX_PERSPECTIVE;
    s->extra_style[0].blend = ZL_BLEND_ALPHA;
    s->extra_style[0].alpha = 200;
    /* an additive band between the two */
    s->extra_mesh[1] = floor_mesh;
    lifted(&s->extra_mvp[1], &vp, ZL_FX_ONE / 4, ZL_FX_ONE / 4);
    zl_state_default(&s->extra_state[1]);
    s->extra_state[1].depth_write = 0;
    s->extra_state[1].color.r = 40;
    s->extra_state[1].color.g = 90;
    s->extra_state[1].color.b = 200;
    zl_style_default(&s->extra_style[1]);
    s->extra_style[1].blend = ZL_BLEND_ADD;
    s->extra_style[1].alpha = 120;
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
    case SCENE_BUNNY_SMOOTH:
        return bunny_smooth(s);
    case SCENE_TETRA: {
        zl_vec3 eye = {ZL_FX_ONE / 5, ZL_FX_ONE / 10, ZL_FX_ONE * 2 / 5}; /* inside the model's hull: near clipping */
        s->name = "tetra";
        s->mesh = tetra_mesh;
        s->state.shading = ZL_SHADE_GOURAUD;
        s->gouraud = 1;
        return camera(&s->mvp, &s->state, eye, 1); /* clipped: the exact mapping's clip path */
    }
    case SCENE_TEXTURED:
        return textured_scene(s);
    case SCENE_BUNNY_CLIP: {
        zl_mat4 view;
        zl_vec3 eye = {0, 0, ZL_FX_ONE * 7 / 2};
        if (scene_make(s, SCENE_BUNNY) != 0)
            return -1;
        s->name = "bunny_clip";
        s->state.cull = ZL_CULL_NONE; /* the cut-open model's inside shows */
        return camera_view_near(&s->mvp, &view, eye, ZL_FX_ONE * 345 / 100);
    }
    case SCENE_BUNNY_GOURAUD:
        return bunny_gouraud(s);
    case SCENE_BUNNY_LIT:
        return bunny_lit_scene(s);
    default:
        return -1;
    }
}

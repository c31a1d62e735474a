/* SPDX-License-Identifier: MIT */
/*
 * zl_config.h's mesh read hook (ZL_MESH_READ_*, issue 23) covers what it
 * says it covers: zl_draw_mesh (general path, vertex cache, draw cache) and
 * scanline and band mode, within and over capacity, flat lit with face
 * colours and Gouraud with vertex colours, triangles clipped by the near and
 * side planes. The core is built with mesh_key_config.h, whose hook decodes
 * scrambled meshes: each scene is drawn once from the plain arrays with the
 * key 0 and once from scrambled ones with a key, and the pixels must be the
 * same. A read that bypassed the hook would see another position, vertex or
 * colour. The scrambled arrays read with the key 0 must give other pixels:
 * the scrambling is not vacuous. Returns the number of failures.
 */
#include <stdio.h>
#include <string.h>

#include "zline/zline.h"

uint32_t zt_mesh_key;
uint16_t zt_mesh_vertices;

#define W 64u
#define H 48u
#define GRID 9u /* vertices a side */
#define VERTS (GRID * GRID)
#define TRIS (2u * (GRID - 1u) * (GRID - 1u))
#define KEY 0xA7u

static zl_fixed positions[3 * VERTS], scrambled_positions[3 * VERTS];
static uint16_t indices[3 * TRIS], scrambled_indices[3 * TRIS];
static uint8_t vertex_colors[3 * VERTS], scrambled_vertex_colors[3 * VERTS];
static uint8_t face_colors[3 * TRIS], scrambled_face_colors[3 * TRIS];

/* A wavy sheet, 2.4 units a side, its colours a function of the vertex. */
static void make_mesh(void)
{
    unsigned i, j, k, t = 0;
    for (j = 0; j < GRID; j++) {
        for (i = 0; i < GRID; i++) {
            unsigned v = j * GRID + i;
            positions[3 * v] = (zl_fixed)((int32_t)i * 19661 - 78643);     /* -1.2 .. 1.2 */
            positions[3 * v + 1] = (zl_fixed)((int32_t)j * 19661 - 78643);
            positions[3 * v + 2] = (zl_fixed)(((int32_t)((i * 7u + j * 5u) % 11u) - 5) * 4000);
            vertex_colors[3 * v] = (uint8_t)(i * 30u);
            vertex_colors[3 * v + 1] = (uint8_t)(j * 30u);
            vertex_colors[3 * v + 2] = (uint8_t)(255u - i * j * 3u);
        }
    }
    for (j = 0; j + 1 < GRID; j++) {
        for (i = 0; i + 1 < GRID; i++) {
            uint16_t a = (uint16_t)(j * GRID + i), b = (uint16_t)(a + 1u), c = (uint16_t)(a + GRID),
                     d = (uint16_t)(c + 1u);
            uint16_t tri[6] = {a, b, d, a, d, c};
            for (k = 0; k < 6; k++)
                indices[3 * t + k] = tri[k];
            t += 2;
        }
    }
    for (k = 0; k < 3 * TRIS; k++)
        face_colors[k] = (uint8_t)(k * 37u + 11u);
    for (k = 0; k < 3 * VERTS; k++) {
        scrambled_positions[k] = (zl_fixed)((uint32_t)positions[k] ^ ZT_POSITION_MASK);
        scrambled_vertex_colors[k] = (uint8_t)(vertex_colors[k] ^ KEY);
    }
    for (k = 0; k < 3 * TRIS; k++) {
        scrambled_indices[k] = (uint16_t)(VERTS - 1u - indices[k]);
        scrambled_face_colors[k] = (uint8_t)(face_colors[k] ^ KEY);
    }
}

static zl_mesh mesh_of(int scrambled)
{
    zl_mesh m;
    m.positions = scrambled ? scrambled_positions : positions;
    m.indices = scrambled ? scrambled_indices : indices;
    m.vertex_colors = scrambled ? scrambled_vertex_colors : vertex_colors;
    m.face_colors = scrambled ? scrambled_face_colors : face_colors;
    m.vertex_count = (uint16_t)VERTS;
    m.triangle_count = (uint16_t)TRIS;
    return m;
}

/* The camera close enough that the sheet crosses the near plane and the
 * sides of the view: clipped triangles beside cached ones. */
static void scene(zl_mat4 *mvp, zl_state *st, int gouraud)
{
    zl_mat4 proj, view, turn;
    zl_vec3 eye = {ZL_FX_ONE / 3, -ZL_FX_ONE / 2, ZL_FX_ONE * 6 / 5}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_mat4 pv;
    (void)zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_ONE * 4 / 3, ZL_FX_ONE / 2,
                              ZL_FX_INT(10));
    (void)zl_mat4_look_at(&view, eye, target, up);
    zl_mat4_rotate_x(&turn, zl_angle_from_deg(ZL_FX_INT(-35)));
    zl_mat4_mul(&pv, &proj, &view);
    zl_mat4_mul(mvp, &pv, &turn);
    zl_state_default(st);
    st->cull = ZL_CULL_NONE;
    if (gouraud) {
        st->shading = ZL_SHADE_GOURAUD;
    } else {
        st->light_on = 1;
        st->ambient = 40;
        st->light_dir.x = -26214;
        st->light_dir.y = 39321;
        st->light_dir.z = 45875;
    }
}

static uint16_t color[W * H], depth[W * H];
static uint64_t cache[(ZL_VERTEX_CACHE_BYTES(VERTS) + 7u) / 8u];
static uint64_t draw_cache[4096];

/* Frame mode: 0 no cache (the general path), 1 vertex cache, 2 draw cache. */
static int draw_frame(int scrambled, int gouraud, int caching)
{
    zl_context ctx;
    zl_target t;
    zl_mesh m = mesh_of(scrambled);
    zl_mat4 mvp;
    zl_rgb bg = {1, 2, 3};
    t.color = color;
    t.color_stride = (int32_t)(W * 2u);
    t.depth = depth;
    t.depth_stride = (int32_t)(W * 2u);
    t.width = (uint16_t)W;
    t.height = (uint16_t)H;
    t.format = ZL_FORMAT_RGB565;
    if (zl_init(&ctx, &t) != ZL_OK)
        return -1;
    scene(&mvp, &ctx.state, gouraud);
    if (caching == 1) {
        ctx.vertex_cache = cache;
        ctx.vertex_cache_bytes = sizeof cache;
    } else if (caching == 2 && zl_draw_cache_bytes() <= sizeof draw_cache) {
        ctx.draw_cache = draw_cache;
        ctx.draw_cache_bytes = sizeof draw_cache;
    }
    if (zl_clear(&ctx, bg, 65535) != ZL_OK)
        return -1;
    return zl_draw_mesh(&ctx, &m, &mvp) == ZL_OK ? 0 : -1;
}

static int keep_rows(void *user, const zl_band *band)
{
    unsigned r;
    (void)user;
    for (r = 0; r < band->rows; r++)
        memcpy(&color[(band->first_row + r) * W], (const uint8_t *)band->color + r * (unsigned)band->color_stride,
               W * 2u);
    return 0;
}

/* Scanline (band_rows 1) or band mode; over: capacities below the need. */
static int draw_bands(int scrambled, int gouraud, uint16_t band_rows, int over, uint32_t *replans)
{
    static uint64_t work[32768];
    zl_frame_config c = {0};
    zl_frame f;
    zl_mesh m = mesh_of(scrambled);
    zl_mat4 mvp;
    zl_state st;
    zl_rgb bg = {1, 2, 3};
    int r;
    c.width = (uint16_t)W;
    c.height = (uint16_t)H;
    c.band_rows = band_rows;
    c.format = ZL_FORMAT_RGB565;
    c.color_buffers = 1;
    c.gouraud = (uint8_t)gouraud;
    c.max_meshes = 1;
    c.max_vertices = VERTS;
    c.max_triangles = over ? 24u : TRIS;
    c.max_active = over ? 10u : 4u * TRIS;
    scene(&mvp, &st, gouraud);
    if (zl_frame_bytes(&c) > sizeof work || zl_frame_begin(&f, &c, work, sizeof work, bg, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &m, &mvp, &st) != ZL_OK)
        return -1;
    r = zl_frame_render(&f, keep_rows, NULL);
    *replans = zl_frame_needs(&f).replans;
    return r;
}

static uint16_t plain[W * H];

/* Draw `what` plain (key 0) and scrambled (key KEY): the same pixels; and
 * the scrambled arrays read without the key: other pixels. */
static int check(const char *name, int (*draw)(int scrambled, int gouraud, int arg), int gouraud, int arg)
{
    int failed = 0;
    zt_mesh_vertices = (uint16_t)VERTS;
    zt_mesh_key = 0;
    if (draw(0, gouraud, arg) != 0) {
        printf("FAIL %s: the plain draw failed\n", name);
        return 1;
    }
    memcpy(plain, color, sizeof plain);
    zt_mesh_key = KEY;
    if (draw(1, gouraud, arg) != 0 || memcmp(plain, color, sizeof plain) != 0) {
        printf("FAIL %s: the scrambled mesh read through the hook differs from the plain one\n", name);
        failed = 1;
    }
    zt_mesh_key = 0;
    if (draw(1, gouraud, arg) == 0 && memcmp(plain, color, sizeof plain) == 0) {
        printf("FAIL %s: the scrambled mesh read without the key gives the same pixels\n", name);
        failed = 1;
    }
    if (!failed)
        printf("ok %s\n", name);
    return failed;
}

static int frame_mode(int scrambled, int gouraud, int caching)
{
    return draw_frame(scrambled, gouraud, caching);
}

/* arg: band rows times 2, plus 1 for over capacity. */
static int band_mode(int scrambled, int gouraud, int arg)
{
    uint32_t replans = 0;
    int over = arg & 1;
    int r = draw_bands(scrambled, gouraud, (uint16_t)(arg >> 1), over, &replans);
    if (r == 0 && over && replans == 0)
        return -1; /* the over-capacity case must be over capacity */
    return r;
}

int main(void)
{
    int failures = 0, gouraud;
    make_mesh();
    for (gouraud = 0; gouraud <= 1; gouraud++) {
        char name[64];
        const char *shade = gouraud ? "Gouraud" : "flat lit";
        sprintf(name, "zl_draw_mesh, %s, general path", shade);
        failures += check(name, frame_mode, gouraud, 0);
        sprintf(name, "zl_draw_mesh, %s, vertex cache", shade);
        failures += check(name, frame_mode, gouraud, 1);
        sprintf(name, "zl_draw_mesh, %s, draw cache", shade);
        failures += check(name, frame_mode, gouraud, 2);
        sprintf(name, "scanline mode, %s", shade);
        failures += check(name, band_mode, gouraud, 1 << 1);
        sprintf(name, "scanline mode over capacity, %s", shade);
        failures += check(name, band_mode, gouraud, (1 << 1) | 1);
        sprintf(name, "bands of 16 rows, %s", shade);
        failures += check(name, band_mode, gouraud, 16 << 1);
        sprintf(name, "bands of 16 rows over capacity, %s", shade);
        failures += check(name, band_mode, gouraud, (16 << 1) | 1);
    }
    printf("%d failures\n", failures);
    return failures;
}

/* SPDX-License-Identifier: MIT */
/*
 * Scanline and band modes against frame mode: byte-identical colour and
 * depth for random scenes (meshes, transforms through the near plane,
 * pixel-space triangles far into the guard band, every depth function and
 * mask, culling, flat and Gouraud, several meshes with their own state), for
 * band heights 1 (scanline), 2, 7 and the full height. Plus the frame API's
 * memory contract: exact sizes, capacity errors before any pixel.
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

#ifdef ZT_FRAME_DUAL
/* tests/host/test_frame_dual.c: this file's scenes rendered by two threads
 * (zl_frame_split at a random row); fn gets user_first from the first, and
 * user_second from the second. Returns zl_frame_render's results, or-ed. */
int zt_dual_render(zl_frame *f, zl_band_fn fn, void *user_first, void *user_second);
void zt_dual_tests(void);
#endif

enum { W = 48, H = 40, NV = 24, NT = 16, NMESH = 3 };

static uint32_t rng = 12345u;
static uint32_t next_rand(void)
{
    return zt_rand(&rng);
}
static int32_t rand_range(int32_t lo, int32_t hi) /* inclusive */
{
    return zt_rand_range(&rng, lo, hi);
}

typedef struct {
    zl_fixed pos[NV * 3];
    uint16_t idx[NT * 3];
    uint8_t vcol[NV * 3], fcol[NT * 3];
    zl_mesh mesh;
    zl_mat4 mvp;
    int use_mvp;
    zl_state state;
    /* styled scenes: a style, and some meshes are lines or points instead */
    zl_style style;
    int is_lines;
    zl_lines lines;
    zl_texture tex;
    zl_fixed uv[NV * 2];
    zl_mesh_edge edges[NT * 3];
    zl_outline outline; /* is_lines == 2: the mesh's outline instead of the mesh */
} scene_mesh;

static int styled; /* the scene uses styles and lines (test_random_styled_scenes...) */
static uint16_t tex_texels[16 * 8];
static const zl_rgb toon_table[4] = {{20, 10, 60}, {80, 40, 120}, {160, 120, 200}, {250, 240, 255}};

static scene_mesh scene[NMESH];
static uint8_t frame_color[W * H * 3];
static uint16_t frame_depth[W * H];
static uint64_t work[(200 * 1024) / 8];

static void random_state(zl_state *s)
{
    zl_state_default(s);
    s->depth_func = (uint8_t)rand_range(0, 7);
    if (rand_range(0, 2) != 0)
        s->depth_func = ZL_LESS;
    s->depth_test = rand_range(0, 5) != 0;
    s->depth_write = rand_range(0, 5) != 0;
    s->color_mask = (uint8_t)(rand_range(0, 3) == 0 ? rand_range(0, 7) : 7);
    s->cull = (uint8_t)rand_range(0, 2);
    s->front_face = (uint8_t)rand_range(0, 1);
    s->shading = (uint8_t)rand_range(0, 1);
    s->light_on = (uint8_t)rand_range(0, 1);
    s->ambient = (uint8_t)rand_range(0, 255);
    s->light_dir.x = ZL_FX_ONE / 2;
    s->light_dir.y = ZL_FX_ONE / 2;
    s->light_dir.z = 46341; /* ~ unit length */
}

static void random_mesh(scene_mesh *m)
{
    int i;
    m->use_mvp = rand_range(0, 2) != 0;
    for (i = 0; i < NV; i++) {
        if (m->use_mvp) {
            /* model space around the origin; some vertices behind the camera */
            m->pos[i * 3] = rand_range(-3 * ZL_FX_ONE, 3 * ZL_FX_ONE);
            m->pos[i * 3 + 1] = rand_range(-3 * ZL_FX_ONE, 3 * ZL_FX_ONE);
            m->pos[i * 3 + 2] = rand_range(-4 * ZL_FX_ONE, 4 * ZL_FX_ONE);
        } else {
            /* pixel space, sometimes far outside the target */
            int32_t reach = rand_range(0, 3) == 0 ? 60000 : 80; /* half-pixels */
            m->pos[i * 3] = rand_range(-reach, reach) * (ZL_FX_ONE / 2) + rand_range(0, 32767);
            m->pos[i * 3 + 1] = rand_range(-reach, reach) * (ZL_FX_ONE / 2) + rand_range(0, 32767);
            m->pos[i * 3 + 2] = rand_range(-ZL_FX_ONE / 4, ZL_FX_ONE + ZL_FX_ONE / 4);
        }
        m->vcol[i * 3] = (uint8_t)next_rand();
        m->vcol[i * 3 + 1] = (uint8_t)next_rand();
        m->vcol[i * 3 + 2] = (uint8_t)next_rand();
    }
    for (i = 0; i < NT * 3; i++)
        m->idx[i] = (uint16_t)rand_range(0, NV - 1);
    for (i = 0; i < NT * 3; i++)
        m->fcol[i] = (uint8_t)next_rand();
    memset(&m->mesh, 0, sizeof m->mesh);
    m->mesh.positions = m->pos;
    m->mesh.indices = m->idx;
    m->mesh.vertex_count = NV;
    m->mesh.triangle_count = NT;
    m->mesh.vertex_colors = m->vcol;
    m->mesh.face_colors = rand_range(0, 1) ? m->fcol : NULL;
    if (m->use_mvp) {
        zl_mat4 proj, view, rot;
        zl_vec3 eye = {rand_range(-ZL_FX_ONE, ZL_FX_ONE), rand_range(-ZL_FX_ONE, ZL_FX_ONE), ZL_FX_INT(3)};
        zl_vec3 target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, rand_range(5000, 20000), ZL_FX_INT(W) / H,
                                                         ZL_FX_ONE / 10, ZL_FX_INT(rand_range(5, 100))));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
        zl_mat4_rotate_y(&rot, rand_range(0, 65535));
        zl_mat4_mul(&view, &view, &rot);
        zl_mat4_mul(&m->mvp, &proj, &view);
    }
    random_state(&m->state);
    zl_style_default(&m->style);
    m->is_lines = 0;
    if (styled) {
        m->style.polygon_front = (uint8_t)rand_range(0, 2);
        m->style.polygon_back = (uint8_t)rand_range(0, 2);
        m->style.point_size = (uint8_t)(rand_range(0, 2) == 0 ? rand_range(1, 9) : 1);
        m->style.line_algo = (uint8_t)rand_range(0, 1);
        m->style.line_aa = (uint8_t)(rand_range(0, 3) == 0);
        if (rand_range(0, 1)) {
            m->style.offset_factor = rand_range(-4 * ZL_FX_ONE, 4 * ZL_FX_ONE);
            m->style.offset_units = rand_range(-2000 * ZL_FX_ONE, 2000 * ZL_FX_ONE);
        }
        if (rand_range(0, 1)) {
            for (i = 0; i < 16 * 8; i++)
                tex_texels[i] = (uint16_t)next_rand();
            for (i = 0; i < NV * 2; i++)
                m->uv[i] = rand_range(-2 * ZL_FX_ONE, 2 * ZL_FX_ONE);
            m->tex.texels = tex_texels;
            m->tex.width = (uint16_t)(1u << rand_range(0, 4));
            m->tex.height = (uint16_t)(1u << rand_range(0, 3));
            m->tex.stride = 16;
            m->tex.wrap_s = (uint8_t)rand_range(0, 1);
            m->tex.wrap_t = (uint8_t)rand_range(0, 1);
            m->style.texture = &m->tex;
            m->style.texcoords = m->uv;
            m->style.tex_mapping = (uint8_t)rand_range(0, 1);
            m->style.tex_every = (uint8_t)(rand_range(0, 1) ? 0 : 1u << rand_range(1, 6));
        }
        m->style.persp_gouraud = (uint8_t)rand_range(0, 1);
        if (rand_range(0, 3) == 0) {
            m->style.toon_bands = (uint8_t)rand_range(1, 4);
            m->style.toon_colors = toon_table;
        }
        if (rand_range(0, 3) == 0) {
            memset(&m->outline, 0, sizeof m->outline);
            m->outline.edges = m->edges;
            m->outline.edge_count = zl_mesh_edges(&m->mesh, m->edges, NT * 3);
            m->outline.silhouettes = (uint8_t)rand_range(0, 1);
            m->outline.creases = (uint8_t)rand_range(0, 1);
            m->outline.borders = (uint8_t)rand_range(0, 1);
            m->outline.crease_cos = rand_range(-ZL_FX_ONE, ZL_FX_ONE);
            m->outline.color.g = (uint8_t)next_rand();
            m->is_lines = 2;
        } else if (rand_range(0, 2) == 0) {
            m->is_lines = 1;
            memset(&m->lines, 0, sizeof m->lines);
            m->lines.positions = m->pos;
            m->lines.indices = rand_range(0, 1) ? m->idx : NULL;
            m->lines.colors = rand_range(0, 1) ? m->fcol : NULL;
            m->lines.vertex_count = NV;
            m->lines.count = (uint16_t)rand_range(0, NT); /* colours for NT primitives */
            m->lines.prim = (uint8_t)rand_range(0, 3);
        }
    }
}

static uint32_t frame_vcache[NV * 2]; /* ZL_VERTEX_CACHE_BYTES(NV) */

static void render_frame_mode(zl_format fmt, zl_rgb bg, uint16_t bgz)
{
    zl_target t;
    zl_context ctx;
    int i;
    zt_target_packed(&t, frame_color, frame_depth, W, H, fmt);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, bgz));
    /* Half the frames draw through the optional vertex cache: the band
     * comparison then checks that it does not change a pixel either. */
    if (next_rand() & 1u) {
        ctx.vertex_cache = frame_vcache;
        ctx.vertex_cache_bytes = sizeof frame_vcache;
    }
    for (i = 0; i < NMESH; i++) {
        const zl_mat4 *mvp = scene[i].use_mvp ? &scene[i].mvp : NULL;
        ctx.state = scene[i].state;
        ctx.style = scene[i].style;
        if (scene[i].is_lines == 2)
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_outlines(&ctx, &scene[i].mesh, mvp, &scene[i].outline));
        else if (scene[i].is_lines)
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &scene[i].lines, mvp));
        else
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &scene[i].mesh, mvp));
    }
}

static void config_for(zl_frame_config *c, zl_format fmt, uint16_t band)
{
    zt_frame_config_of(c, W, H, band, fmt);
    zt_frame_capacity(c, NMESH, NV * NMESH, NT * NMESH, NT * NMESH * 7);
    c->gouraud = 1;
    c->styled = (uint8_t)styled;
    c->textured = (uint8_t)styled;
    if (styled) /* outlines: a primitive per edge */
        c->max_triangles = NT * NMESH * 3;
#ifdef ZT_FRAME_DUAL
    c->parts = (uint8_t)((next_rand() & 1u) ? 2 : 0); /* the vertex transform in the parts or not */
#endif
}

typedef struct {
    zl_format fmt;
    int rows_seen;
    int mismatches;
} compare_ctx;

static int compare_band(void *user, const zl_band *b)
{
    compare_ctx *c = user;
    size_t bpp = zl_format_bytes(c->fmt);
    uint16_t r;
    for (r = 0; r < b->rows; r++) {
        const uint8_t *col = (const uint8_t *)b->color + (size_t)r * (size_t)b->color_stride;
        const uint16_t *dep = (const uint16_t *)(const void *)((const uint8_t *)b->depth + (size_t)r * (size_t)b->depth_stride);
        size_t y = (size_t)b->first_row + r;
        if (memcmp(col, frame_color + y * W * bpp, W * bpp) != 0 || memcmp(dep, frame_depth + y * W, W * 2) != 0)
            c->mismatches++;
        c->rows_seen++;
    }
    return 0;
}

/* Guard bytes around the work buffer: render_and_compare hands zline
 * exactly zl_frame_bytes() bytes starting WORK_GUARD bytes into `work`, and
 * the WORK_GUARD bytes on each side (colour and depth bands, vertex cache,
 * edge table: all of it lives in the work buffer) must keep their pattern. */
#define WORK_GUARD 64u

static uint8_t work_pattern(size_t i)
{
    return (uint8_t)(0x3Cu ^ (i * 29u));
}

static void work_guard_fill(size_t bytes)
{
    uint8_t *w = (uint8_t *)work;
    size_t i;
    for (i = 0; i < WORK_GUARD; i++) {
        w[i] = work_pattern(i);
        w[WORK_GUARD + bytes + i] = work_pattern(WORK_GUARD + bytes + i);
    }
}

static unsigned work_guard_damage(size_t bytes)
{
    const uint8_t *w = (const uint8_t *)work;
    unsigned bad = 0;
    size_t i;
    for (i = 0; i < WORK_GUARD; i++) {
        bad += w[i] != work_pattern(i);
        bad += w[WORK_GUARD + bytes + i] != work_pattern(WORK_GUARD + bytes + i);
    }
    return bad;
}

/* The scene's meshes, lines and outlines, in order, into frame f. */
static void add_scene(zl_frame *f)
{
    int i;
    for (i = 0; i < NMESH; i++) {
        const zl_mat4 *mvp = scene[i].use_mvp ? &scene[i].mvp : NULL;
        if (scene[i].is_lines == 2)
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_outlines(f, &scene[i].mesh, mvp, &scene[i].state,
                                                               &scene[i].style, &scene[i].outline));
        else if (scene[i].is_lines)
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_lines(f, &scene[i].lines, mvp, &scene[i].state,
                                                            &scene[i].style));
        else if (styled)
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(f, &scene[i].mesh, mvp, &scene[i].state,
                                                                  &scene[i].style));
        else
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(f, &scene[i].mesh, mvp, &scene[i].state));
    }
}

static void render_and_compare(zl_format fmt, uint16_t band, zl_rgb bg, uint16_t bgz)
{
    zl_frame_config cfg;
    zl_frame f;
    compare_ctx cc;
    size_t bytes;
    config_for(&cfg, fmt, band);
    bytes = zl_frame_bytes(&cfg);
    TEST_ASSERT_TRUE(bytes > 0 && bytes + 2 * WORK_GUARD <= sizeof work);
    work_guard_fill(bytes);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, (uint8_t *)work + WORK_GUARD, bytes, bg, bgz));
    add_scene(&f);
    cc.fmt = fmt;
    cc.rows_seen = 0;
    cc.mismatches = 0;
#ifdef ZT_FRAME_DUAL
    {
        compare_ctx second = cc;
        TEST_ASSERT_EQUAL_INT(0, zt_dual_render(&f, compare_band, &cc, &second));
        cc.rows_seen += second.rows_seen;
        cc.mismatches += second.mismatches;
    }
#else
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, compare_band, &cc));
#endif
    TEST_ASSERT_EQUAL_INT(H, cc.rows_seen);
    TEST_ASSERT_EQUAL_INT(0, cc.mismatches);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, work_guard_damage(bytes), "bytes around the work buffer written");
}

#ifndef ZT_FRAME_DUAL
/*
 * Over capacity (issue 25): the scene rendered with max_triangles and / or
 * max_active below its needs (by exactly 1, by 2x and by 10x; never below
 * what one primitive takes alone: 1 triangle, 9 records) must still come
 * out whole and byte-identical to frame mode, nothing written outside the
 * work buffer, the true needs reported and `replans` non-zero exactly when
 * it was over. (Split frames keep ZL_ERR_CAPACITY: not here.)
 */
enum { OVER_MIN_ACTIVE = 9 };

static uint32_t reduced(uint32_t need, unsigned how, uint32_t least)
{
    uint32_t v = how == 1 ? need - 1u : need / how;
    return need == 0 || v < least ? least : v;
}

static zl_frame_needs_t scene_needs(zl_format fmt, uint16_t band, zl_rgb bg, uint16_t bgz)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_band b;
    config_for(&cfg, fmt, band);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, bgz));
    add_scene(&f);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &b));
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_needs(&f).replans);
    return zl_frame_needs(&f);
}

/* One over-capacity render: which = 1 triangles, 2 active, 3 both. Returns
 * whether the capacities were below the needs. */
static int render_over_once(zl_format fmt, uint16_t band, zl_rgb bg, uint16_t bgz, zl_frame_needs_t need,
                            unsigned how, unsigned which)
{
    zl_frame_config cfg;
    zl_frame f;
    compare_ctx cc;
    size_t bytes;
    int over;
    config_for(&cfg, fmt, band);
    if (which & 1u)
        cfg.max_triangles = reduced(need.triangles, how, 1);
    if (which & 2u)
        cfg.max_active = reduced(need.active, how, OVER_MIN_ACTIVE);
    over = need.triangles > cfg.max_triangles || need.active > cfg.max_active;
    bytes = zl_frame_bytes(&cfg);
    TEST_ASSERT_TRUE(bytes > 0 && bytes + 2 * WORK_GUARD <= sizeof work);
    work_guard_fill(bytes);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, (uint8_t *)work + WORK_GUARD, bytes, bg, bgz));
    add_scene(&f);
    cc.fmt = fmt;
    cc.rows_seen = 0;
    cc.mismatches = 0;
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, compare_band, &cc));
    TEST_ASSERT_EQUAL_INT(H, cc.rows_seen);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, cc.mismatches, "over capacity: rows differ from frame mode");
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, work_guard_damage(bytes), "bytes around the work buffer written");
    TEST_ASSERT_EQUAL_UINT32(need.triangles, zl_frame_needs(&f).triangles);
    TEST_ASSERT_EQUAL_UINT32(need.active, zl_frame_needs(&f).active);
    if (over) /* at least one plan after the whole frame's */
        TEST_ASSERT_TRUE(zl_frame_needs(&f).replans >= 1);
    else
        TEST_ASSERT_EQUAL_UINT32(0, zl_frame_needs(&f).replans);
    return over;
}

static long over_frames; /* how many renders were over capacity */

/* A scene over capacity by 1, 2x and 10x, in scanline mode or 7-row bands
 * and in the capacities reduced (triangles, active records or both) by
 * turns from scene to scene: every combination comes up many times over
 * the random scenes, within the cross targets' time. */
static unsigned over_turn;

static void render_over_and_compare(zl_format fmt, zl_rgb bg, uint16_t bgz)
{
    static const unsigned hows[] = {1, 2, 10};
    uint16_t band = (over_turn & 1u) ? 7 : 1;
    unsigned which = (over_turn / 2u) % 3u + 1u, h;
    zl_frame_needs_t need = scene_needs(fmt, band, bg, bgz);
    for (h = 0; h < sizeof hows / sizeof hows[0]; h++)
        over_frames += render_over_once(fmt, band, bg, bgz, need, hows[h], which);
    over_turn++;
}
#else
static void render_over_and_compare(zl_format fmt, zl_rgb bg, uint16_t bgz)
{
    (void)fmt;
    (void)bg;
    (void)bgz;
}
#endif

static void test_random_scenes_identical_in_every_band_height(void)
{
    static const uint16_t bands[] = {1, 2, 7, H};
    int scene_no, i;
    long drawn = 0;
    for (scene_no = 0; scene_no < 150; scene_no++) {
        zl_format fmt = (zl_format)rand_range(0, 2);
        zl_rgb bg = {(uint8_t)next_rand(), (uint8_t)next_rand(), (uint8_t)next_rand()};
        uint16_t bgz = (uint16_t)(rand_range(0, 1) ? 65535 : rand_range(0, 65535));
        for (i = 0; i < NMESH; i++)
            random_mesh(&scene[i]);
        render_frame_mode(fmt, bg, bgz);
        for (i = 0; i < W * H; i++)
            drawn += frame_depth[i] != bgz;
        for (i = 0; i < (int)(sizeof bands / sizeof bands[0]); i++)
            render_and_compare(fmt, bands[i], bg, bgz);
        render_over_and_compare(fmt, bg, bgz);
    }
    /* The scenes must actually draw something for the comparison to mean anything. */
    TEST_ASSERT_GREATER_THAN(150L * W * H / 20, drawn);
#ifndef ZT_FRAME_DUAL
    TEST_ASSERT_GREATER_THAN(150L * 3 / 2, over_frames); /* most over-capacity renders were over */
#endif
}

/* The same with styles: polygon modes per face, offset, point sizes, both
 * line algorithms, and lines, strips, loops and points between the meshes. */
static void test_random_styled_scenes_identical_in_every_band_height(void)
{
    static const uint16_t bands[] = {1, 2, 7, H};
    int scene_no, i;
    long drawn = 0;
    styled = 1;
    for (scene_no = 0; scene_no < 200; scene_no++) {
        zl_format fmt = (zl_format)rand_range(0, 2);
        zl_rgb bg = {(uint8_t)next_rand(), (uint8_t)next_rand(), (uint8_t)next_rand()};
        uint16_t bgz = (uint16_t)(rand_range(0, 1) ? 65535 : rand_range(0, 65535));
        for (i = 0; i < NMESH; i++)
            random_mesh(&scene[i]);
        render_frame_mode(fmt, bg, bgz);
        for (i = 0; i < W * H; i++)
            drawn += frame_depth[i] != bgz;
        for (i = 0; i < (int)(sizeof bands / sizeof bands[0]); i++)
            render_and_compare(fmt, bands[i], bg, bgz);
        render_over_and_compare(fmt, bg, bgz);
    }
    styled = 0;
    TEST_ASSERT_GREATER_THAN(200L * W * H / 40, drawn);
}

/* A non-default style needs a frame sized for it; the default does not. */
static void test_styles_need_a_styled_frame(void)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_style sty;
    zl_state st;
    zl_rgb bg = {0, 0, 0};
    zl_lines l;
    styled = 0;
    config_for(&cfg, ZL_FORMAT_RGB565, 1);
    random_mesh(&scene[0]);
    zl_state_default(&st);
    zl_style_default(&sty);
    memset(&l, 0, sizeof l);
    l.positions = scene[0].pos;
    l.vertex_count = NV;
    l.count = 2;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&f, &scene[0].mesh, NULL, &st, &sty));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&f, &scene[0].mesh, NULL, &st, NULL));
    sty.polygon_back = ZL_POLY_LINE;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_frame_add_mesh_styled(&f, &scene[0].mesh, NULL, &st, &sty));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_frame_add_lines(&f, &l, NULL, &st, NULL));
    cfg.styled = 1;
    TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) > 0);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&f, &scene[0].mesh, NULL, &st, &sty));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_lines(&f, &l, NULL, &st, NULL));
    sty.point_size = 0;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_frame_add_mesh_styled(&f, &scene[0].mesh, NULL, &st, &sty));
}

static void test_sizes_are_exact_and_checked(void)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_rgb bg = {0, 0, 0};
    size_t need;
    config_for(&cfg, ZL_FORMAT_RGB565, 1);
    need = zl_frame_bytes(&cfg);
    TEST_ASSERT_TRUE(need > 0);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_frame_begin(&f, &cfg, work, need - 1, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, need, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_begin(&f, &cfg, (uint8_t *)work + 1, need, bg, 65535));
    cfg.band_rows = 0;
    TEST_ASSERT_EQUAL_INT(0, zl_frame_bytes(&cfg));
    cfg.band_rows = H + 1;
    TEST_ASSERT_EQUAL_INT(0, zl_frame_bytes(&cfg));
    config_for(&cfg, (zl_format)9, 1);
    TEST_ASSERT_EQUAL_INT(0, zl_frame_bytes(&cfg));
}

#ifndef ZT_FRAME_DUAL
/*
 * Over capacity with an independent reference (zt_ref's coverage, the
 * contract's blending formula): NT_TIES pixel-space triangles, all at the
 * same depth, most of them crossing every row, rendered in RGB888 with
 * capacities below the needs (by 1 record, by 2x and 10x, and by 1
 * triangle). Depth ties decide the image: LESS keeps the first triangle
 * covering a pixel, LEQUAL the last, ALPHA blending blends them all in
 * submission order. Each must equal the reference, which frame mode must
 * equal too.
 */
enum { NT_TIES = 40 };
static zl_fixed ties_pos[NT_TIES * 9];
static uint16_t ties_idx[NT_TIES * 3];
static uint8_t ties_col[NT_TIES * 3];
static uint8_t ties_ref[W * H * 3];

static void ties_scene(zl_mesh *m)
{
    int i, k;
    for (i = 0; i < NT_TIES; i++) {
        for (k = 0; k < 3; k++) {
            zl_fixed *v = &ties_pos[(i * 3 + k) * 3];
            v[0] = rand_range(-8 * ZL_FX_ONE, (W + 8) * ZL_FX_ONE);
            v[1] = k == 0 ? rand_range(-4 * ZL_FX_ONE, 0) : (k == 1 ? rand_range(H * ZL_FX_ONE, (H + 4) * ZL_FX_ONE)
                                                                    : rand_range(0, H * ZL_FX_ONE));
            v[2] = ZL_FX_ONE / 2; /* every triangle at the same depth: ties everywhere */
            ties_idx[i * 3 + k] = (uint16_t)(i * 3 + k);
            ties_col[i * 3 + k] = (uint8_t)next_rand();
        }
    }
    memset(m, 0, sizeof *m);
    m->positions = ties_pos;
    m->indices = ties_idx;
    m->vertex_count = NT_TIES * 3;
    m->triangle_count = NT_TIES;
    m->face_colors = ties_col;
}

/* The reference image: func ZL_LESS or ZL_LEQUAL, alpha 0 (opaque) or the
 * blending alpha. */
static void ties_reference(zl_rgb bg, unsigned func, unsigned alpha)
{
    int x, y, i, c;
    zt_tri tri[NT_TIES];
    for (i = 0; i < NT_TIES; i++)
        zt_tri_init(&tri[i], &ties_pos[i * 9], &ties_pos[i * 9 + 3], &ties_pos[i * 9 + 6]);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            uint8_t *px = &ties_ref[(y * W + x) * 3];
            int covered = 0;
            px[0] = bg.r;
            px[1] = bg.g;
            px[2] = bg.b;
            for (i = 0; i < NT_TIES; i++) {
                if (!zt_tri_covers(&tri[i], x, y) || (func == ZL_LESS && covered))
                    continue;
                covered = 1;
                for (c = 0; c < 3; c++) {
                    unsigned src = ties_col[i * 3 + c];
                    /* round((src a + old (255 - a)) / 255); 255 is odd: no halves */
                    px[c] = (uint8_t)(alpha == 0 ? src : (2u * (src * alpha + px[c] * (255u - alpha)) + 255u) / 510u);
                }
            }
        }
    }
}

static void ties_state(zl_state *st, zl_style *sty, unsigned func, unsigned alpha)
{
    zl_state_default(st);
    st->depth_func = (uint8_t)func;
    zl_style_default(sty);
    if (alpha != 0) {
        sty->blend = ZL_BLEND_ALPHA;
        sty->alpha = (uint8_t)alpha;
    }
}

static void test_over_capacity_ties_and_blending_match_reference(void)
{
    static const unsigned funcs[3] = {ZL_LESS, ZL_LEQUAL, ZL_LEQUAL}, alphas[3] = {0, 0, 100};
    zl_rgb bg = {40, 90, 160};
    int scene_no, k, drawn = 0;
    for (scene_no = 0; scene_no < 6; scene_no++) {
        zl_mesh m;
        ties_scene(&m);
        for (k = 0; k < 3; k++) {
            zl_state st;
            zl_style sty;
            zl_target t;
            zl_context ctx;
            zl_frame_config cfg;
            zl_frame f;
            zl_band b;
            zl_frame_needs_t need;
            unsigned c;
            ties_state(&st, &sty, funcs[k], alphas[k]);
            ties_reference(bg, funcs[k], alphas[k]);
            zt_target_packed(&t, frame_color, frame_depth, W, H, ZL_FORMAT_RGB888);
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
            ctx.state = st;
            ctx.style = sty;
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(ties_ref, frame_color, sizeof ties_ref, "frame mode against the reference");
            for (c = 0; c < W * H; c++)
                drawn += frame_depth[c] != 65535;
            zt_frame_config_of(&cfg, W, H, 1, ZL_FORMAT_RGB888);
            zt_frame_capacity(&cfg, 1, NT_TIES * 3, NT_TIES, NT_TIES);
            cfg.styled = cfg.textured = 1; /* blending takes the styled rows */
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&f, &m, NULL, &st, &sty));
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &b));
            need = zl_frame_needs(&f);
            TEST_ASSERT_TRUE(need.active > 20); /* most triangles cross every row */
            for (c = 0; c < 4; c++) {
                static const unsigned hows[4] = {1, 2, 10, 0};
                static const uint16_t bands[4] = {1, 7, 1, 3};
                compare_ctx cc;
                zt_frame_config_of(&cfg, W, H, bands[c], ZL_FORMAT_RGB888);
                zt_frame_capacity(&cfg, 1, NT_TIES * 3, hows[c] == 0 ? need.triangles - 1u : NT_TIES,
                                  hows[c] == 0 ? NT_TIES : reduced(need.active, hows[c], 1));
                cfg.styled = cfg.textured = 1;
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&f, &m, NULL, &st, &sty));
                cc.fmt = ZL_FORMAT_RGB888;
                cc.rows_seen = 0;
                cc.mismatches = 0;
                TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, compare_band, &cc));
                TEST_ASSERT_EQUAL_INT(H, cc.rows_seen);
                TEST_ASSERT_EQUAL_INT(0, cc.mismatches);
                TEST_ASSERT_TRUE(zl_frame_needs(&f).replans >= (uint32_t)(H + bands[c] - 1) / bands[c]);
                TEST_ASSERT_EQUAL_UINT32(need.active, zl_frame_needs(&f).active);
            }
        }
    }
    TEST_ASSERT_GREATER_THAN(6 * 3 * W * H / 2, drawn);
}

#endif

static int count_calls(void *user, const zl_band *b)
{
    (void)b;
    ++*(int *)user;
    return 0;
}

static void test_capacity_over_and_error(void)
{
    /* Ten overlapping full-height triangles need ten active records: with
     * nine (the frame over capacity by one) the frame still comes out
     * whole, as frame mode draws it; with no triangle record at all (one
     * primitive alone does not fit) ZL_ERR_CAPACITY before any row. */
    static zl_fixed pos[30 * 3];
    static uint16_t idx[30];
    zl_mesh m;
    zl_frame_config cfg;
    zl_frame f;
    zl_state st;
    zl_rgb bg = {0, 0, 0};
    zl_target t;
    zl_context ctx;
    zt_frame_copy copy;
    static uint8_t band_color[W * H * 2];
    static uint16_t band_depth[W * H];
    int i, calls = 0;
    for (i = 0; i < 10; i++) {
        zl_fixed x = ZL_FX_INT(i);
        zl_fixed tri[9] = {x, 0, 0, x + ZL_FX_INT(20), ZL_FX_INT(H / 2), 0, x, ZL_FX_INT(H), 0};
        memcpy(&pos[i * 9], tri, sizeof tri);
        idx[i * 3] = (uint16_t)(i * 3);
        idx[i * 3 + 1] = (uint16_t)(i * 3 + 1);
        idx[i * 3 + 2] = (uint16_t)(i * 3 + 2);
    }
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.vertex_count = 30;
    m.triangle_count = 10;
    zl_state_default(&st);
    zt_target_packed(&t, frame_color, frame_depth, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
    config_for(&cfg, ZL_FORMAT_RGB565, 1);
    cfg.max_active = 9;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st));
    copy.color = band_color;
    copy.depth = band_depth;
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, zt_band_copy_fn, &copy));
    TEST_ASSERT_EQUAL_MEMORY(frame_color, band_color, W * H * 2);
    TEST_ASSERT_EQUAL_MEMORY(frame_depth, band_depth, W * H * 2);
    TEST_ASSERT_EQUAL_UINT32(10, zl_frame_needs(&f).active);
    TEST_ASSERT_EQUAL_UINT32(10, zl_frame_needs(&f).triangles);
    TEST_ASSERT_EQUAL_UINT32(2 * H, zl_frame_needs(&f).replans); /* every row in two passes: 9, then 1 */
    /* over capacity too, a mesh after the first band is refused (the frame goes on) */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &(zl_band){0}));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_add_mesh(&f, &m, NULL, &st));
    TEST_ASSERT_EQUAL_UINT32(2, zl_frame_needs(&f).replans);
    cfg.max_active = 10;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st));
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, count_calls, &calls));
    TEST_ASSERT_EQUAL_INT(H, calls);
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_needs(&f).replans);
    cfg.max_triangles = 0;
    calls = 0;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_frame_render(&f, count_calls, &calls));
    TEST_ASSERT_EQUAL_INT(0, calls);
    TEST_ASSERT_EQUAL_UINT32(10, zl_frame_needs(&f).triangles);
    /* Gouraud needs a frame sized for it. */
    cfg.max_triangles = 10;
    cfg.gouraud = 0;
    st.shading = ZL_SHADE_GOURAUD;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_frame_add_mesh(&f, &m, NULL, &st));
}

/* Many triangles a row each, few active on any row: planning's first rows
 * do not all fit the spare work buffer (2 bytes a visible triangle against
 * a few records and one band), so the second pass places the triangles the
 * first marked visible. Some have a vertex beyond the cache's range (the
 * clipping path) and every third faces away (culled): the bands must equal
 * frame mode's image. */
enum { TW = 160, TH = 300, TK = 3, TN = TH * TK };
static zl_fixed tall_pos[TN * 9];
static uint16_t tall_idx[TN * 3];
static uint16_t tall_color[TW * TH], tall_depth[TW * TH];

static void tall_scene(zl_mesh *m)
{
    int r, k;
    for (r = 0; r < TH; r++) {
        for (k = 0; k < TK; k++) {
            int i = r * TK + k;
            zl_fixed x = ZL_FX_INT(k * 50 + r % 7), y = ZL_FX_INT(r) + ZL_FX_ONE / 5;
            zl_fixed far_x = (i % 11 == 5) ? ZL_FX_INT(3000) : x + ZL_FX_INT(40);
            zl_fixed z = ZL_FX_ONE / 4 + (zl_fixed)(i * 37 % 1000) * 40;
            zl_fixed tri[9] = {x, y, z, far_x, y + ZL_FX_ONE / 4, z, x + ZL_FX_INT(3), y + ZL_FX_ONE * 7 / 10, z};
            memcpy(&tall_pos[i * 9], tri, sizeof tri);
            tall_idx[i * 3] = (uint16_t)(i * 3);
            tall_idx[i * 3 + 1] = (uint16_t)(i % 3 != 2 ? i * 3 + 2 : i * 3 + 1);
            tall_idx[i * 3 + 2] = (uint16_t)(i % 3 != 2 ? i * 3 + 1 : i * 3 + 2);
        }
    }
    memset(m, 0, sizeof *m);
    m->positions = tall_pos;
    m->indices = tall_idx;
    m->vertex_count = TN * 3;
    m->triangle_count = TN;
}

static void test_many_triangles_few_active(void)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_mesh m;
    zl_state st;
    zl_target t;
    zl_context ctx;
    zl_rgb bg = {9, 8, 7};
    int y, drawn = 0;
    tall_scene(&m);
    zl_state_default(&st);
    st.cull = ZL_CULL_BACK;
    zt_target_packed(&t, tall_color, tall_depth, TW, TH, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
    ctx.state = st;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
    for (y = 0; y < TW * TH; y++)
        drawn += tall_depth[y] != 65535;
    TEST_ASSERT_GREATER_THAN(TW * TH / 8, drawn);
    zt_frame_config_of(&cfg, TW, TH, 1, ZL_FORMAT_RGB565);
    zt_frame_capacity(&cfg, 1, TN * 3, TN, 64);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &(zl_band){0}));
    cfg.max_active = (uint16_t)zl_frame_needs(&f).active;
    cfg.max_triangles = zl_frame_needs(&f).triangles;
    /* the case under test: more visible triangles than first rows fit */
    TEST_ASSERT_TRUE(cfg.max_triangles > 2 * TW + cfg.max_active * 64u);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st));
    for (y = 0; y < TH; y++) {
        zl_band b;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &b));
        TEST_ASSERT_EQUAL_INT(y, b.first_row);
        TEST_ASSERT_EQUAL_MEMORY(tall_color + (size_t)y * TW, b.color, TW * 2);
        TEST_ASSERT_EQUAL_MEMORY(tall_depth + (size_t)y * TW, b.depth, TW * 2);
    }
}

static void test_pull_form_and_double_buffering(void)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_band a, b;
    zl_rgb bg = {1, 2, 3};
    config_for(&cfg, ZL_FORMAT_RGB888, 4);
    cfg.color_buffers = 2;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &a));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &b));
    TEST_ASSERT_TRUE(a.color != b.color); /* the band being sent is not overwritten */
    TEST_ASSERT_EQUAL_INT(0, a.first_row);
    TEST_ASSERT_EQUAL_INT(4, b.first_row);
    TEST_ASSERT_EQUAL_UINT8(1, ((const uint8_t *)a.color)[0]);
    while (zl_frame_next_band(&f, &a) == ZL_OK)
        ;
    TEST_ASSERT_EQUAL_INT(ZL_DONE, zl_frame_next_band(&f, &a));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_scenes_identical_in_every_band_height);
    RUN_TEST(test_random_styled_scenes_identical_in_every_band_height);
    RUN_TEST(test_styles_need_a_styled_frame);
    RUN_TEST(test_sizes_are_exact_and_checked);
    RUN_TEST(test_capacity_over_and_error);
#ifndef ZT_FRAME_DUAL
    RUN_TEST(test_over_capacity_ties_and_blending_match_reference);
#endif
    RUN_TEST(test_pull_form_and_double_buffering);
    RUN_TEST(test_many_triangles_few_active);
#ifdef ZT_FRAME_DUAL
    zt_dual_tests();
#endif
    return UNITY_END();
}

/* SPDX-License-Identifier: MIT */
/*
 * The feature switches of zl_config.h (issue 23). Built against the default
 * library (every feature on) and against the minimal configuration
 * (test_features_minimal: ZL_FEATURE_TEXTURES, _BLEND, _LINES, _OUTLINES
 * all 0). For each switch, the API that needs the feature returns
 * ZL_ERR_UNSUPPORTED exactly when the feature is compiled out, in frame mode
 * and in scanline mode, and writes no pixel then; what stays (a flat and a
 * Gouraud triangle) draws what the test's own edge-function reference
 * says: the pixels whose centres are inside.
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 24, H = 16 };

static uint16_t color[W * H], depth[W * H];
static uint64_t work[4096];
/* a triangle in pixel space: (2, 2), (20, 3), (6, 15), z 0.5: no pixel centre
 * lies on an edge (test_triangles_stay) */
static const zl_fixed tri_pos[9] = {2 * ZL_FX_ONE,  2 * ZL_FX_ONE,  ZL_FX_ONE / 2, 20 * ZL_FX_ONE, 3 * ZL_FX_ONE,
                                    ZL_FX_ONE / 2, 6 * ZL_FX_ONE,  15 * ZL_FX_ONE, ZL_FX_ONE / 2};
static const uint16_t tri_idx[3] = {0, 1, 2};
static const uint8_t tri_vcol[9] = {255, 0, 0, 0, 255, 0, 0, 0, 255};
static const zl_fixed tri_uv[6] = {0, 0, ZL_FX_ONE, 0, 0, ZL_FX_ONE};
static const uint16_t texels[4] = {0xF800u, 0x07E0u, 0x001Fu, 0xFFFFu};

static zl_status expected(int feature_on)
{
    return feature_on ? ZL_OK : ZL_ERR_UNSUPPORTED;
}

static void mesh_of(zl_mesh *m)
{
    memset(m, 0, sizeof *m);
    m->positions = tri_pos;
    m->indices = tri_idx;
    m->vertex_count = 3;
    m->triangle_count = 1;
}

static void context_of(zl_context *ctx)
{
    zl_target tg;
    zl_rgb black = {0, 0, 0};
    zt_target_packed(&tg, color, depth, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(ctx, &tg));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(ctx, black, 65535));
}

static int pixels_written(void)
{
    int i, n = 0;
    for (i = 0; i < W * H; i++)
        n += depth[i] != 65535;
    return n;
}

/* A draw with the style of `set`: ZL_OK with pixels when the feature is on,
 * ZL_ERR_UNSUPPORTED and no pixel when it is off. */
static void check_style(void (*set)(zl_style *s, zl_texture *t), int feature_on)
{
    zl_context ctx;
    zl_mesh m;
    zl_texture tex;
    context_of(&ctx);
    mesh_of(&m);
    memset(&tex, 0, sizeof tex);
    tex.texels = texels;
    tex.width = tex.height = tex.stride = 2;
    set(&ctx.style, &tex);
    TEST_ASSERT_EQUAL_INT(expected(feature_on), zl_draw_mesh(&ctx, &m, NULL));
    TEST_ASSERT_EQUAL_INT(feature_on, pixels_written() > 0);
}

static void set_texture(zl_style *s, zl_texture *t)
{
    s->texture = t;
    s->texcoords = tri_uv;
}
static void set_blend(zl_style *s, zl_texture *t)
{
    (void)t;
    s->blend = ZL_BLEND_ALPHA;
    s->alpha = 128;
}
static void set_line_mode(zl_style *s, zl_texture *t)
{
    (void)t;
    s->polygon_front = s->polygon_back = ZL_POLY_LINE;
}

static void test_styles(void)
{
    check_style(set_texture, ZL_FEATURE_TEXTURES);
    check_style(set_blend, ZL_FEATURE_BLEND);
    check_style(set_line_mode, ZL_FEATURE_LINES);
}

static void test_lines_and_outlines(void)
{
    static const zl_fixed lpos[6] = {1 * ZL_FX_ONE, 1 * ZL_FX_ONE, 0, 20 * ZL_FX_ONE, 12 * ZL_FX_ONE, 0};
    static zl_mesh_edge edges[8];
    zl_context ctx;
    zl_lines l;
    zl_mesh m;
    zl_outline o;
    uint32_t n;
    memset(&l, 0, sizeof l);
    l.positions = lpos;
    l.vertex_count = 2;
    l.count = 2;
    l.prim = ZL_PRIM_LINES;
    context_of(&ctx);
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_LINES), zl_draw_lines(&ctx, &l, NULL));
    TEST_ASSERT_EQUAL_INT(ZL_FEATURE_LINES, pixels_written() > 0);
    mesh_of(&m);
    n = zl_mesh_edges(&m, edges, 8);
    TEST_ASSERT_EQUAL_UINT32(ZL_FEATURE_OUTLINES ? 3u : 0u, n);
    memset(&o, 0, sizeof o);
    o.edges = edges;
    o.edge_count = n;
    o.borders = 1;
    context_of(&ctx);
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_OUTLINES), zl_draw_outlines(&ctx, &m, NULL, &o));
}

static void test_scanline_mode(void)
{
    zl_frame f;
    zl_frame_config cfg;
    zl_style sty;
    zl_mesh m;
    zl_lines l;
    zl_state st;
    zl_rgb black = {0, 0, 0};
    static const zl_fixed lpos[6] = {1 * ZL_FX_ONE, 1 * ZL_FX_ONE, 0, 20 * ZL_FX_ONE, 12 * ZL_FX_ONE, 0};
    zt_frame_config_of(&cfg, W, H, 1, ZL_FORMAT_RGB565);
    zt_frame_capacity(&cfg, 4, 16, 16, 16);
    cfg.styled = 1;
    cfg.textured = 1; /* (blending in scanline mode needs it) */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, black, 65535));
    zl_state_default(&st);
    zl_style_default(&sty);
    mesh_of(&m);
    sty.blend = ZL_BLEND_ADD;
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_BLEND), zl_frame_add_mesh_styled(&f, &m, NULL, &st, &sty));
    zl_style_default(&sty);
    memset(&l, 0, sizeof l);
    l.positions = lpos;
    l.vertex_count = 2;
    l.count = 2;
    l.prim = ZL_PRIM_LINES;
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_LINES), zl_frame_add_lines(&f, &l, NULL, &st, &sty));
}

/* Twice the signed area of (a, b, p), pixel units. */
static long edge(const long *a, const long *b, long px2, long py2)
{
    return (b[0] * 2 - a[0] * 2) * (py2 - a[1] * 2) - (b[1] * 2 - a[1] * 2) * (px2 - a[0] * 2);
}

/* Flat and Gouraud triangles stay in every configuration: the pixels the
 * draw writes are those whose centres are strictly inside the triangle. */
static void test_triangles_stay(void)
{
    static const long v[3][2] = {{2, 2}, {20, 3}, {6, 15}};
    int shading, x, y;
    for (shading = 0; shading < 2; shading++) {
        zl_context ctx;
        zl_mesh m;
        context_of(&ctx);
        mesh_of(&m);
        if (shading) {
            ctx.state.shading = ZL_SHADE_GOURAUD;
            m.vertex_colors = tri_vcol;
        }
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                long px2 = 2 * x + 1, py2 = 2 * y + 1;
                long e0 = edge(v[0], v[1], px2, py2), e1 = edge(v[1], v[2], px2, py2), e2 = edge(v[2], v[0], px2, py2);
                int inside = (e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0);
                TEST_ASSERT_EQUAL_INT_MESSAGE(inside, depth[y * W + x] != 65535, "coverage differs from the reference");
            }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_styles);
    RUN_TEST(test_lines_and_outlines);
    RUN_TEST(test_scanline_mode);
    RUN_TEST(test_triangles_stay);
    return UNITY_END();
}

/* SPDX-License-Identifier: MIT */
/*
 * The feature switches of zl_config.h (issue 23). Built against the default
 * library (every feature on) and against the minimal configuration
 * (test_features_minimal: ZL_FEATURE_TEXTURES, _BLEND, _LINES, _OUTLINES,
 * _DEPTH_MAP, _EXACT_DEPTH, _LIGHTING, _OFFSET, _DEPTH_FUNCS, _FORMATS, _SPLIT all 0). For each
 * switch, the API that needs the feature returns ZL_ERR_UNSUPPORTED exactly
 * when the feature is compiled out, in frame mode and in scanline mode, and
 * writes no pixel then; what stays (a flat and a Gouraud triangle, RGB565,
 * depth LESS and LEQUAL) draws what the test's own edge-function reference
 * says: the pixels whose centres are inside, in the packed RGB565 colour,
 * kept or replaced at equal depth as the depth function says.
 */
#include <string.h>

#include "unity.h"
#include "zline/zl_camera.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_target.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 24, H = 16 };

static uint16_t color[W * H] ZT_ALIGNED(2), depth[W * H] ZT_ALIGNED(2);
/* Work buffers: room to spare, or, for the minimal configuration on a chip
 * of a few KB (the ATmega2560's minimal suite), what its frames need with a
 * margin (smaller capacities in test_scanline_mode). */
#if ZT_SMALL_RAM && !(ZL_FEATURE_TEXTURES || ZL_FEATURE_BLEND || ZL_FEATURE_LINES || ZL_FEATURE_SPLIT)
#define SMALL_FRAMES 1
enum { WORK_WORDS = 464, SECOND_WORK_WORDS = 1 };
#else
#define SMALL_FRAMES 0
enum { WORK_WORDS = 4096, SECOND_WORK_WORDS = 2048 };
#endif
static uint64_t work[WORK_WORDS] ZT_ALIGNED(8);
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

static void set_offset(zl_style *s, zl_texture *t)
{
    (void)t;
    s->offset_units = ZL_FX_INT(4);
}

static void test_styles(void)
{
    check_style(set_texture, ZL_FEATURE_TEXTURES);
    check_style(set_blend, ZL_FEATURE_BLEND);
    check_style(set_line_mode, ZL_FEATURE_LINES);
    check_style(set_offset, ZL_FEATURE_OFFSET);
}

/* A draw with the state of `set`, as check_style. */
static void check_state(void (*set)(zl_state *s), int feature_on)
{
    zl_context ctx;
    zl_mesh m;
    context_of(&ctx);
    mesh_of(&m);
    set(&ctx.state);
    TEST_ASSERT_EQUAL_INT(expected(feature_on), zl_state_check(&ctx.state));
    TEST_ASSERT_EQUAL_INT(expected(feature_on), zl_draw_mesh(&ctx, &m, NULL));
    TEST_ASSERT_EQUAL_INT(feature_on, pixels_written() > 0);
}

static void set_light(zl_state *s)
{
    s->light_on = 1;
}
static void set_notequal(zl_state *s)
{
    s->depth_func = ZL_NOTEQUAL; /* passes against the cleared 65535 */
}
static void set_always(zl_state *s)
{
    s->depth_func = ZL_ALWAYS; /* kept with the other functions off: it costs nothing */
}

static void set_depth_map(zl_state *s)
{
    s->near_z = ZL_FX_ONE / 4; /* the exact mapping's planes (ignored in pixel space when on) */
    s->far_z = 16 * ZL_FX_ONE;
}

/* A perspective camera's depth planes go to the state only with the
 * mapping compiled in; off, the state keeps z / w (near_z = far_z = 0). */
static void test_camera_depth(void)
{
    zl_camera cam;
    zl_state st;
    zl_camera_init(&cam);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_camera_perspective(&cam, ZL_ANGLE_TURN / 8, ZL_FX_ONE, ZL_FX_ONE / 4, 16 * ZL_FX_ONE));
    zl_state_default(&st);
    zl_camera_apply_depth(&cam, &st);
    TEST_ASSERT_EQUAL_INT32(ZL_FEATURE_DEPTH_MAP ? ZL_FX_ONE / 4 : 0, st.near_z);
    TEST_ASSERT_EQUAL_INT32(ZL_FEATURE_DEPTH_MAP ? 16 * ZL_FX_ONE : 0, st.far_z);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_state_check(&st));
}

static void test_states(void)
{
    zl_state st;
    check_state(set_light, ZL_FEATURE_LIGHTING);
    check_state(set_depth_map, ZL_FEATURE_DEPTH_MAP);
    check_state(set_notequal, ZL_FEATURE_DEPTH_FUNCS);
    check_state(set_always, 1);
    /* with the depth test off the function is not used: any is accepted */
    zl_state_default(&st);
    st.depth_test = 0;
    st.depth_func = ZL_GREATER;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_state_check(&st));
}

/* A split frame: zl_frame_begin with two parts, zl_frame_split and
 * zl_frame_prepare; with the feature off the begin refuses two parts and
 * the split and prepare refuse a one-part frame. */
static void test_split(void)
{
    static uint64_t second_work[SECOND_WORK_WORDS] ZT_ALIGNED(8);
    zl_frame f, second;
    zl_frame_config cfg;
    zl_mesh m;
    zl_state st;
    zl_rgb black = {0, 0, 0};
    zt_frame_config_of(&cfg, W, H, 1, ZL_FORMAT_RGB565);
    zt_frame_capacity(&cfg, 4, 16, 16, 16);
    cfg.parts = 2;
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_SPLIT), zl_frame_begin(&f, &cfg, work, sizeof work, black, 65535));
    if (!ZL_FEATURE_SPLIT) {
        cfg.parts = 1;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, black, 65535));
    }
    mesh_of(&m);
    zl_state_default(&st);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st));
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_SPLIT), zl_frame_split(&f, &second, second_work, sizeof second_work, 0));
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_SPLIT), zl_frame_prepare(&f));
}

/* RGB565 in both byte orders stays (panels take the big-endian one); the
 * other formats (RGB888) go with ZL_FEATURE_FORMATS. */
static void test_formats(void)
{
    static const zl_format others[2] = {ZL_FORMAT_RGB565_BE, ZL_FORMAT_RGB888};
    zl_rgb black = {0, 0, 0};
    int k;
    for (k = 0; k < 2; k++) {
        const zl_status want = others[k] == ZL_FORMAT_RGB565_BE ? ZL_OK : expected(ZL_FEATURE_FORMATS);
        zl_context ctx;
        zl_target tg;
        zl_frame f;
        zl_frame_config cfg;
        zt_target_packed(&tg, color, depth, W, H / 2, others[k]); /* 3 bytes a pixel fit in half the rows */
        TEST_ASSERT_EQUAL_INT(want, zl_init(&ctx, &tg));
        zt_frame_config_of(&cfg, W, H, 1, others[k]);
        zt_frame_capacity(&cfg, 4, 16, 16, 16);
        TEST_ASSERT_EQUAL_INT(want, zl_frame_begin(&f, &cfg, work, sizeof work, black, 65535));
    }
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
    if (SMALL_FRAMES)
        zt_frame_capacity(&cfg, 4, 16, 16, 16); /* one triangle, one line: room to spare */
    else
        zt_frame_capacity(&cfg, 8, 32, 32, 16);
    cfg.styled = 1;
    /* blending in scanline mode needs the planes' room (the minimal
     * configuration refuses the blended mesh before it looks) */
    cfg.textured = ZL_FEATURE_BLEND || ZL_FEATURE_TEXTURES;
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
    sty.offset_factor = ZL_FX_ONE;
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_OFFSET), zl_frame_add_mesh_styled(&f, &m, NULL, &st, &sty));
    st.light_on = 1;
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_LIGHTING), zl_frame_add_mesh(&f, &m, NULL, &st));
    zl_state_default(&st);
    st.depth_func = ZL_GEQUAL;
    TEST_ASSERT_EQUAL_INT(expected(ZL_FEATURE_DEPTH_FUNCS), zl_frame_add_mesh(&f, &m, NULL, &st));
}

/* Twice the signed area of (a, b, p), pixel units. */
static long edge(const long *a, const long *b, long px2, long py2)
{
    return (b[0] * 2 - a[0] * 2) * (py2 - a[1] * 2) - (b[1] * 2 - a[1] * 2) * (px2 - a[0] * 2);
}

static int inside_ref(int x, int y)
{
    static const long v[3][2] = {{2, 2}, {20, 3}, {6, 15}};
    long px2 = 2 * x + 1, py2 = 2 * y + 1;
    long e0 = edge(v[0], v[1], px2, py2), e1 = edge(v[1], v[2], px2, py2), e2 = edge(v[2], v[0], px2, py2);
    return (e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0);
}

/* Flat and Gouraud triangles stay in every configuration: the pixels the
 * draw writes are those whose centres are strictly inside the triangle. */
static void test_triangles_stay(void)
{
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
            for (x = 0; x < W; x++)
                TEST_ASSERT_EQUAL_INT_MESSAGE(inside_ref(x, y), depth[y * W + x] != 65535,
                                              "coverage differs from the reference");
    }
}

/* RGB565 of 8-bit channels, written out here (zline.h: the top bits). */
static uint16_t rgb565_ref(unsigned r, unsigned g, unsigned b)
{
    return (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}

/* Whether pixel i of the colour buffer holds v in format fmt (RGB565:
 * native byte order; RGB565_BE: high byte first). */
static int pixel_is(zl_format fmt, int i, uint16_t v)
{
    const uint8_t *b = (const uint8_t *)(const void *)color + 2 * i;
    if (fmt == ZL_FORMAT_RGB565_BE)
        return b[0] == (v >> 8) && b[1] == (v & 0xFFu);
    return color[i] == v;
}

/* The depth functions every configuration keeps, in frame and scanline
 * mode and both RGB565 byte orders: a second flat triangle at the same
 * depth replaces the first one's pixels with LEQUAL and leaves them with
 * LESS; outside, the clear colour. */
static void test_less_and_lequal(void)
{
    static const zl_rgb first = {40, 200, 90}, second = {250, 16, 128};
    zl_rgb clear = {8, 4, 24};
    int func, mode, be, x, y;
    for (be = 0; be < 2; be++)
        for (func = 0; func < 2; func++)
            for (mode = 0; mode < 2; mode++) {
                const zl_format fmt = be ? ZL_FORMAT_RGB565_BE : ZL_FORMAT_RGB565;
                zl_state st;
                zl_mesh m;
                uint16_t want_in = rgb565_ref(func ? second.r : first.r, func ? second.g : first.g,
                                              func ? second.b : first.b);
                mesh_of(&m);
                zl_state_default(&st);
                st.depth_func = func ? ZL_LEQUAL : ZL_LESS;
                if (mode == 0) {
                    zl_context ctx;
                    zl_target tg;
                    zt_target_packed(&tg, color, depth, W, H, fmt);
                    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
                    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, clear, 65535));
                    ctx.state = st;
                    ctx.state.color = first;
                    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
                    ctx.state.color = second;
                    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
                } else {
                    zl_frame f;
                    zl_frame_config cfg;
                    zl_state st2 = st;
                    zt_frame_copy to = {color, NULL};
                    zt_frame_config_of(&cfg, W, H, 1, fmt);
                    zt_frame_capacity(&cfg, 4, 16, 16, 16);
                    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, clear, 65535));
                    st.color = first;
                    st2.color = second;
                    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st));
                    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, &st2));
                    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, zt_band_copy_fn, &to));
                }
                for (y = 0; y < H; y++)
                    for (x = 0; x < W; x++)
                        TEST_ASSERT_TRUE_MESSAGE(
                            pixel_is(fmt, y * W + x, inside_ref(x, y) ? want_in : rgb565_ref(clear.r, clear.g, clear.b)),
                            mode ? "scanline mode" : "frame mode");
            }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_styles);
    RUN_TEST(test_states);
    RUN_TEST(test_camera_depth);
    RUN_TEST(test_formats);
    RUN_TEST(test_split);
    RUN_TEST(test_less_and_lequal);
    RUN_TEST(test_lines_and_outlines);
    RUN_TEST(test_scanline_mode);
    RUN_TEST(test_triangles_stay);
    return UNITY_END();
}

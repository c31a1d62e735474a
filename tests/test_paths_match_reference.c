/* SPDX-License-Identifier: MIT */
/*
 * Every pixel path against an independent model (issue 16).
 *
 * zline specialises its inner loops: RGB565 (both byte orders) with depth
 * LESS or LEQUAL, depth writes and every channel gets its own flat, Gouraud,
 * tiny-triangle and line loops; everything else takes the generic loop. A
 * differential test between two of these paths misses a bug they share, so
 * here every combination is checked against a model written from the
 * contract alone:
 *
 *   formats      RGB565, RGB565_BE, RGB888
 *   depth        test off, or each of the 8 functions; write mask on/off
 *   colour mask  all channels, and one random other mask per case
 *   primitives   flat triangles, Gouraud triangles, lines (LINE RULE)
 *   paths        zl_draw_mesh, zl_draw_mesh with the vertex cache, and
 *                zl_frame in scanline mode (band_rows = 1)
 *
 * The model: every primitive has a constant depth, one of a few levels far
 * apart (so the contract's +-1 never changes an ordering), and ties between
 * primitives of one level are common (LESS against LEQUAL). Coverage comes
 * from zt_ref (triangles) or the LINE RULE written out here (lines); the
 * depth test, the write mask and the colour mask are applied per pixel by
 * the model; a Gouraud pixel's channels are the exact barycentric mix e of
 * the vertex colours at the pixel centre, within GOURAUD_TOL in RGB888, and
 * in RGB565 the top 5/6/5 bits of a value within -0.6 .. +1.6 of e (zline.h,
 * Gouraud colour: lane colour). Depth values
 * must lie within the contract's +-1 of the level, and one level must be
 * stored as one value everywhere (same plane, same depth).
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

#define W 32
#define H 32
#define NTRI 10
#define NLINE 8
#define NLEVEL 4
#define CLEAR_DEPTH 30000u
#define GOURAUD_TOL 1 /* 8-bit units either side of the exact mix */

void setUp(void) {}
void tearDown(void) {}

enum { PATH_DRAW, PATH_DRAW_CACHED, PATH_SCANLINE, PATH_COUNT };
static const char *const path_names[PATH_COUNT] = {"draw", "draw+cache", "scanline"};
static const char *const format_names[3] = {"RGB565", "RGB565_BE", "RGB888"};

/* Level k's z in Q16.16: stored about 12000 k + 6000, the clear depth
 * (30000) in between levels 1 and 2. */
static zl_fixed level_z(unsigned k)
{
    return (zl_fixed)(6000 + 12000 * (int32_t)k);
}

static uint32_t rng = 0x16u;

/* --- the scene ------------------------------------------------------- */

typedef struct {
    zl_fixed pos[NTRI * 3 * 3];
    uint16_t idx[NTRI * 3];
    uint8_t vcol[NTRI * 3 * 3];
    uint8_t fcol[NTRI * 3];
    unsigned level[NTRI];
    zl_fixed lpos[NLINE * 2 * 3];
    uint8_t lcol[NLINE * 3];
    unsigned llevel[NLINE];
} scene;

static scene sc;

/* A coordinate on the 1/16 pixel grid, a little beyond the target at times. */
static zl_fixed rand_coord(int32_t lo, int32_t hi)
{
    return (zl_fixed)(zt_rand_range(&rng, lo * 16, hi * 16) * 4096);
}

static void random_scene(void)
{
    unsigned t, k;
    for (t = 0; t < NTRI; t++) {
        /* sizes from sub-pixel slivers to the whole target: tiny, small and long spans */
        int32_t size = (t % 3 == 0) ? 3 : (t % 3 == 1) ? 12 : 40;
        int32_t cx = zt_rand_range(&rng, -2, W + 1), cy = zt_rand_range(&rng, -2, H + 1);
        sc.level[t] = (unsigned)zt_rand_range(&rng, 0, NLEVEL - 1);
        for (k = 0; k < 3; k++) {
            zl_fixed *p = &sc.pos[(t * 3 + k) * 3];
            p[0] = rand_coord(cx - size / 2, cx + size / 2);
            p[1] = rand_coord(cy - size / 2, cy + size / 2);
            p[2] = level_z(sc.level[t]);
            sc.idx[t * 3 + k] = (uint16_t)(t * 3 + k);
        }
        for (k = 0; k < 9; k++)
            sc.vcol[t * 9 + k] = (uint8_t)zt_rand_range(&rng, 0, 255);
        for (k = 0; k < 3; k++)
            sc.fcol[t * 3 + k] = (uint8_t)zt_rand_range(&rng, 0, 255);
    }
    for (t = 0; t < NLINE; t++) {
        sc.llevel[t] = (unsigned)zt_rand_range(&rng, 0, NLEVEL - 1);
        for (k = 0; k < 2; k++) {
            zl_fixed *p = &sc.lpos[(t * 2 + k) * 3];
            /* inside the target: the model has no clipping for lines */
            p[0] = (zl_fixed)(zt_rand_range(&rng, 0, W - 1) * 65536 + zt_rand_range(&rng, 0, 15) * 4096);
            p[1] = (zl_fixed)(zt_rand_range(&rng, 0, H - 1) * 65536 + zt_rand_range(&rng, 0, 15) * 4096);
            p[2] = level_z(sc.llevel[t]);
        }
        for (k = 0; k < 3; k++)
            sc.lcol[t * 3 + k] = (uint8_t)zt_rand_range(&rng, 0, 255);
    }
}

/* --- the model --------------------------------------------------------- */

typedef struct {
    int level;         /* -1: the clear depth */
    uint8_t lo[3], hi[3]; /* each channel's allowed 8-bit range */
} model_px;

static model_px model[W * H];

static int level_value(int level)
{
    return level < 0 ? (int)CLEAR_DEPTH : 6000 + 12000 * level; /* order only */
}

static int depth_passes(unsigned func, int incoming, int stored)
{
    int a = level_value(incoming), b = level_value(stored);
    switch (func) {
    case ZL_NEVER: return 0;
    case ZL_LESS: return a < b;
    case ZL_EQUAL: return a == b;
    case ZL_LEQUAL: return a <= b;
    case ZL_GREATER: return a > b;
    case ZL_NOTEQUAL: return a != b;
    case ZL_GEQUAL: return a >= b;
    default: return 1;
    }
}

/* One fragment of level `level` and channel ranges lo..hi at pixel p. */
static void model_fragment(const zl_state *st, unsigned p, int level, const int *lo, const int *hi)
{
    model_px *m = &model[p];
    unsigned c;
    if (st->depth_test && !depth_passes(st->depth_func, level, m->level))
        return;
    if (st->depth_test && st->depth_write)
        m->level = level;
    for (c = 0; c < 3; c++)
        if (st->color_mask & (1u << c)) {
            m->lo[c] = (uint8_t)lo[c];
            m->hi[c] = (uint8_t)hi[c];
        }
}

static int clamp255(int64_t v)
{
    return v < 0 ? 0 : v > 255 ? 255 : (int)v;
}

/* Gouraud: the exact mix of the vertex colours at pixel (i, j)'s centre,
 * from the snapped vertices (half-subpixel units), as an 8-bit range: the
 * contract's for RGB888, or (lane) for RGB565 the range whose top bits the
 * stored channel may be, floor(e - 0.6) .. floor(e + 1.6). */
static void gouraud_range(const zl_fixed *p, const uint8_t *vc, int32_t i, int32_t j, int lane, int *lo, int *hi)
{
    int64_t x[3], y[3], e[3], area, cx = zt_centre2(i), cy = zt_centre2(j);
    unsigned k, c;
    for (k = 0; k < 3; k++) {
        x[k] = zt_snap2(p[k * 3]);
        y[k] = zt_snap2(p[k * 3 + 1]);
    }
    for (k = 0; k < 3; k++) {
        unsigned a = (k + 1) % 3, b = (k + 2) % 3;
        e[k] = (x[b] - x[a]) * (cy - y[a]) - (y[b] - y[a]) * (cx - x[a]);
    }
    area = e[0] + e[1] + e[2];
    if (area < 0) {
        area = -area;
        for (k = 0; k < 3; k++)
            e[k] = -e[k];
    }
    for (c = 0; c < 3; c++) {
        int64_t num = 0;
        for (k = 0; k < 3; k++)
            num += e[k] * vc[k * 3 + c];
        if (lane) {
            lo[c] = clamp255(zt_floor_div(10 * num - 6 * area, 10 * area));
            hi[c] = clamp255(zt_floor_div(10 * num + 16 * area, 10 * area));
        } else {
            lo[c] = clamp255(zt_floor_div(num, area) - GOURAUD_TOL);
            hi[c] = clamp255(zt_ceil_div(num, area) + GOURAUD_TOL);
        }
    }
}

static void model_triangles(const zl_state *st, zl_format fmt)
{
    unsigned t, k;
    int32_t i, j;
    for (t = 0; t < NTRI; t++) {
        const zl_fixed *p = &sc.pos[t * 9];
        zt_tri tri;
        zt_tri_init(&tri, p, p + 3, p + 6);
        for (j = 0; j < H; j++)
            for (i = 0; i < W; i++) {
                int lo[3], hi[3];
                if (!zt_tri_covers(&tri, i, j))
                    continue;
                if (st->shading == ZL_SHADE_GOURAUD) {
                    gouraud_range(p, &sc.vcol[t * 9], i, j, fmt != ZL_FORMAT_RGB888, lo, hi);
                } else {
                    for (k = 0; k < 3; k++)
                        lo[k] = hi[k] = sc.fcol[t * 3 + k];
                }
                model_fragment(st, (unsigned)(j * W + i), (int)sc.level[t], lo, hi);
            }
    }
}

/* The LINE RULE: endpoint pixels by floor, one pixel per major step at the
 * nearest minor coordinate, an exact half rounding down. */
static int32_t nearest_half_down(int64_t num, int64_t den) /* den > 0 */
{
    return (int32_t)zt_ceil_div(2 * num - den, 2 * den);
}

static void model_lines(const zl_state *st)
{
    unsigned s, k;
    for (s = 0; s < NLINE; s++) {
        const zl_fixed *a = &sc.lpos[s * 6], *b = a + 3;
        int32_t x0 = a[0] >> 16, y0 = a[1] >> 16, x1 = b[0] >> 16, y1 = b[1] >> 16;
        int32_t dx = x1 - x0, dy = y1 - y0, adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy, u;
        int lo[3];
        for (k = 0; k < 3; k++)
            lo[k] = sc.lcol[s * 3 + k];
        for (u = 0; u <= (adx >= ady ? adx : ady); u++) {
            int32_t x, y;
            if (adx >= ady) {
                x = x0 + (dx < 0 ? -u : u);
                y = adx == 0 ? y0 : y0 + nearest_half_down((int64_t)(x - x0) * dy * (dx < 0 ? -1 : 1), adx);
            } else {
                y = y0 + (dy < 0 ? -u : u);
                x = x0 + nearest_half_down((int64_t)(y - y0) * dx * (dy < 0 ? -1 : 1), ady);
            }
            model_fragment(st, (unsigned)(y * W + x), (int)sc.llevel[s], lo, lo);
        }
    }
}

/* --- rendering --------------------------------------------------------- */

static uint8_t color_buf[W * H * 3];
static uint16_t depth_buf[W * H];
static uint32_t vcache[NTRI * 3 * 2]; /* ZL_VERTEX_CACHE_BYTES(NTRI * 3) */
/* PATH_DRAW's draw cache (zl_context.draw_cache): the draw without a vertex
 * cache takes the small-cache path, as before issue 23 the default call did */
static uint64_t draw_cache[ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) / 8 + 1];
static uint64_t work[6000];
static const zl_rgb clear_rgb = {0x5A, 0xA5, 0x3C};

static void make_target(zl_target *tg, zl_format fmt)
{
    zt_target_packed(tg, color_buf, depth_buf, W, H, fmt);
}

static void meshes(zl_mesh *m, zl_lines *l, int gouraud)
{
    memset(m, 0, sizeof *m);
    m->positions = sc.pos;
    m->indices = sc.idx;
    m->vertex_count = NTRI * 3;
    m->triangle_count = NTRI;
    if (gouraud)
        m->vertex_colors = sc.vcol;
    else
        m->face_colors = sc.fcol;
    memset(l, 0, sizeof *l);
    l->positions = sc.lpos;
    l->colors = sc.lcol;
    l->vertex_count = NLINE * 2;
    l->count = NLINE * 2;
    l->prim = ZL_PRIM_LINES;
}

static void render_direct(zl_format fmt, const zl_state *st, int lines, int cached)
{
    zl_target tg;
    zl_context ctx;
    zl_mesh m;
    zl_lines l;
    make_target(&tg, fmt);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, clear_rgb, CLEAR_DEPTH));
    ctx.state = *st;
    if (cached) {
        ctx.vertex_cache = vcache;
        ctx.vertex_cache_bytes = sizeof vcache;
    } else {
        ctx.draw_cache = draw_cache;
        ctx.draw_cache_bytes = sizeof draw_cache;
    }
    meshes(&m, &l, st->shading == ZL_SHADE_GOURAUD);
    if (lines)
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
    else
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
}

/* Scanline output lands where frame mode draws, for the same checks. */
static zt_frame_copy to_buffers = {color_buf, depth_buf};

static void render_scanline(zl_format fmt, const zl_state *st, int lines)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_mesh m;
    zl_lines l;
    zl_style style;
    zt_frame_config_of(&cfg, W, H, 1, fmt);
    zt_frame_capacity(&cfg, 1, NTRI * 3, NTRI, NTRI * 8);
    cfg.gouraud = 1;
    cfg.styled = (uint8_t)lines;
    TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, clear_rgb, CLEAR_DEPTH));
    meshes(&m, &l, st->shading == ZL_SHADE_GOURAUD);
    zl_style_default(&style);
    if (lines)
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_lines(&f, &l, NULL, st, &style));
    else
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, st));
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, zt_band_copy_fn, &to_buffers));
}

/* --- comparison -------------------------------------------------------- */


static char msg[400];

static int check_against_model(zl_format fmt, const char *what)
{
    int32_t seen[NLEVEL];
    unsigned p, c, k;
    for (k = 0; k < NLEVEL; k++)
        seen[k] = -1;
    for (p = 0; p < W * H; p++) {
        const model_px *m = &model[p];
        unsigned ch[3], bits[3];
        uint16_t d = depth_buf[p];
        zt_read_channels(color_buf, fmt, p, ch, bits);
        for (c = 0; c < 3; c++) {
            unsigned lo = (unsigned)m->lo[c] >> (8 - bits[c]), hi = (unsigned)m->hi[c] >> (8 - bits[c]);
            if (ch[c] < lo || ch[c] > hi) {
                snprintf(msg, sizeof msg, "%s: pixel (%u,%u) channel %u is %u, the model says %u..%u", what,
                         p % W, p / W, c, ch[c], lo, hi);
                TEST_FAIL_MESSAGE(msg);
                return 1;
            }
        }
        if (m->level < 0 ? d != CLEAR_DEPTH : (seen[m->level] >= 0 && d != seen[m->level])) {
            snprintf(msg, sizeof msg, "%s: pixel (%u,%u) depth %u, the model says level %d (%s)", what, p % W,
                     p / W, d, m->level, m->level < 0 ? "the clear depth" : "as stored elsewhere");
            TEST_FAIL_MESSAGE(msg);
            return 1;
        }
        if (m->level >= 0) {
            /* within +-1 of the exact stored value z * 65535 / 65536 */
            int64_t exact2 = (int64_t)level_z((unsigned)m->level) * 65535 * 2 / 65536;
            if ((int64_t)d * 2 < exact2 - 2 || (int64_t)d * 2 > exact2 + 4) {
                snprintf(msg, sizeof msg, "%s: pixel (%u,%u) depth %u is not level %d's", what, p % W, p / W, d,
                         m->level);
                TEST_FAIL_MESSAGE(msg);
                return 1;
            }
            seen[m->level] = d;
        }
    }
    return 0;
}

static void model_reset(void)
{
    unsigned p;
    for (p = 0; p < W * H; p++) {
        model[p].level = -1;
        model[p].lo[0] = model[p].hi[0] = clear_rgb.r;
        model[p].lo[1] = model[p].hi[1] = clear_rgb.g;
        model[p].lo[2] = model[p].hi[2] = clear_rgb.b;
    }
}

/* One case: a fresh random scene, drawn by one path, against the model. */
static int run_case(zl_format fmt, unsigned path, int lines, const zl_state *st)
{
    char what[160];
    random_scene();
    model_reset();
    if (lines)
        model_lines(st);
    else
        model_triangles(st, fmt);
    if (path == PATH_SCANLINE)
        render_scanline(fmt, st, lines);
    else
        render_direct(fmt, st, lines, path == PATH_DRAW_CACHED);
    snprintf(what, sizeof what, "%s %s %s, depth test %u func %u write %u, colour mask %u", format_names[fmt],
             path_names[path], lines ? "lines" : st->shading == ZL_SHADE_GOURAUD ? "Gouraud" : "flat",
             st->depth_test, st->depth_func, st->depth_write, st->color_mask);
    return check_against_model(fmt, what);
}

/* Every format x path x depth state x two colour masks, for one kind of
 * primitive (0 flat, 1 Gouraud, 2 lines). */
static void sweep(int kind)
{
    unsigned fmt, path, func, write, mask_case;
    for (fmt = 0; fmt < 3; fmt++)
        for (path = 0; path < PATH_COUNT; path++) {
            if (kind == 2 && path == PATH_DRAW_CACHED)
                continue; /* lines have no vertex cache */
            for (func = 0; func <= 8; func++) /* 8: depth test off */
                for (write = 0; write < 2; write++)
                    for (mask_case = 0; mask_case < 2; mask_case++) {
                        zl_state st;
                        zl_state_default(&st);
                        st.depth_test = (uint8_t)(func < 8);
                        st.depth_func = (uint8_t)(func < 8 ? func : ZL_LESS);
                        st.depth_write = (uint8_t)write;
                        st.color_mask = (uint8_t)(mask_case == 0 ? (int32_t)ZL_MASK_RGB : zt_rand_range(&rng, 0, 6));
                        st.shading = (uint8_t)(kind == 1 ? ZL_SHADE_GOURAUD : ZL_SHADE_FLAT);
                        if (run_case((zl_format)fmt, path, kind == 2, &st))
                            return;
                    }
        }
}

static void test_flat_triangles_match_the_model_in_every_path(void)
{
    sweep(0);
}

static void test_gouraud_triangles_match_the_model_in_every_path(void)
{
    sweep(1);
}

static void test_lines_match_the_model_in_every_path(void)
{
    sweep(2);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_flat_triangles_match_the_model_in_every_path);
    RUN_TEST(test_gouraud_triangles_match_the_model_in_every_path);
    RUN_TEST(test_lines_match_the_model_in_every_path);
    return UNITY_END();
}

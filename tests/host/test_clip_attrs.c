/* SPDX-License-Identifier: MIT */
/*
 * Texture coordinates and perspective-correct Gouraud colour of clipped
 * triangles (zline.h, Clipping): at every pixel a clipped triangle covers
 * they are those of the ORIGINAL triangle (before clipping) at the pixel
 * centre, not of the clipped pieces. The reference is computed here,
 * independently of the core: b = M^-1 n in long double (M the clip-space
 * x, y, w of the three vertices as the transform gives them, n the pixel
 * centre in device coordinates), then
 *     perspective-correct a = sum a_i b_i / sum b_i
 *     screen-linear a       = sum a_i lambda_i, lambda_i = w_i b_i / sum w_j b_j
 * (screen-linear only where every w_i > 0; a triangle across the eye plane
 * maps an affine texture perspective-correctly).
 *   colour (perspective Gouraud): within +-1 of the exact value;
 *   texture (nearest texel, a 32 x 32 texture whose texels name their own
 *     indices): the sampled texel is the one containing the reference
 *     coordinate c, except where c lies within a tolerance of a texel
 *     boundary: 1/32 texel (the vertex coordinates' 1/256 texel, the
 *     division's rounding) + |c| / 2^14 (the reciprocal's relative error),
 *     plus what the stepped planes drift: each of the at most 1 + W + H
 *     steps from the anchor pixel (zline.h: in the target) is rounded to
 *     half a unit of the plane, 2^-16 texel for an affine plane, 2^12 / Q
 *     texel for u q, Q = 2^28 w_min / w the pixel's scaled 1/w (w_min the
 *     least w of the clipped polygon, here of the triangle clipped to the
 *     near and far planes: a lower bound). The printed worst distance
 *     shows how much of that is used.
 * Triangles cross the near plane, the far plane, both and the eye plane, in
 * pixel space and with perspective. Frame mode, scanline and band mode give
 * the same bytes; textures are checked in RGB888 (the general span loop)
 * and RGB565 (the fast texture loop).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_linear.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

#define W 61
#define H 47
#define TS 32

static uint64_t rng = 0xC0FFEE1234567891ull;

static int32_t rnd_range(int32_t lo, int32_t hi)
{
    return zt_rand64_range(&rng, lo, hi);
}

static uint8_t color_buf[W * H * 3], color_ref[W * H * 3];
static uint16_t c565[W * H], depth_buf[W * H];
static uint64_t work[200000 / 8];
static uint16_t texels[TS * TS];
static zl_texture texture;

/* Texel (i, j): red i, green j (RGB565 keeps both exactly). */
static void make_texture(void)
{
    unsigned i, j;
    for (j = 0; j < TS; j++)
        for (i = 0; i < TS; i++)
            texels[j * TS + i] = (uint16_t)((i << 11) | (j << 5) | 31u);
    memset(&texture, 0, sizeof texture);
    texture.texels = texels;
    texture.width = TS;
    texture.height = TS;
    texture.stride = TS;
    texture.wrap_s = ZL_WRAP_REPEAT;
    texture.wrap_t = ZL_WRAP_REPEAT;
}

typedef struct {
    unsigned tris, clipped, near, far, both, eye;
    unsigned pixels, checked, boundary;
    double worst_color, worst_texel; /* texels from the reference coordinate to the sampled texel */
    double worst_any;                /* the same over every pixel, those near a boundary too */
} stats;

typedef struct {
    zl_vec4 v[3];        /* clip space as the transform gives it */
    long double a[3][5]; /* per vertex: r, g, b (0..255), u, v (texels) */
    int pixel_space;
    long double wmin;    /* least w of the triangle clipped to near and far */
} tri_ref;

/* The least w of the triangle's part with 0 <= z <= w (zt_clip_near_far). */
static long double clipped_wmin(const zl_vec4 v[3])
{
    long double p[ZT_CLIP_MAX][4];
    int made[ZT_CLIP_MAX], n = zt_clip_near_far(v, p, made), k;
    long double best = 1e30L;
    for (k = 0; k < n; k++)
        best = p[k][3] < best ? p[k][3] : best;
    return best;
}

/* The five attributes at the centre of pixel (i, j): perspective-correct,
 * or screen-linear when `linear` (and every w_i > 0); out[5] the clip w
 * there. */
static int reference(const tri_ref *t, int i, int j, int linear, long double out[6])
{
    long double m[3][3], r[3], b[3], X = i + 0.5L, Y = j + 0.5L, sb = 0, sw = 0;
    int k, c;
    for (k = 0; k < 3; k++) {
        m[0][k] = t->v[k].x;
        m[1][k] = t->v[k].y;
        m[2][k] = t->v[k].w;
    }
    r[0] = t->pixel_space ? X : 2 * X / W - 1;
    r[1] = t->pixel_space ? Y : 1 - 2 * Y / H;
    r[2] = 1;
    if (!zt_solve3(m, r, b))
        return 0;
    for (k = 0; k < 3; k++) {
        sb += b[k];
        sw += b[k] * t->v[k].w;
    }
    for (c = 0; c < 5; c++) {
        long double s = 0;
        for (k = 0; k < 3; k++)
            s += t->a[k][c] * (linear ? b[k] * t->v[k].w / sw : b[k] / sb);
        out[c] = s;
    }
    out[5] = 1 / sb;
    return 1;
}

enum { KIND_PERSP_COLOR, KIND_TEX_PERSP, KIND_TEX_AFFINE };

static void setup_style(int kind, const zl_fixed *uv, zl_state *st, zl_style *sty)
{
    zl_state_default(st);
    zl_style_default(sty);
    st->depth_func = ZL_ALWAYS;
    st->shading = kind == KIND_PERSP_COLOR ? ZL_SHADE_GOURAUD : ZL_SHADE_FLAT;
    sty->persp_gouraud = kind == KIND_PERSP_COLOR;
    if (kind != KIND_PERSP_COLOR) {
        sty->texture = &texture;
        sty->texcoords = uv;
        sty->tex_mapping = kind == KIND_TEX_PERSP ? ZL_TEX_PERSPECTIVE : ZL_TEX_AFFINE;
    }
}

static void target_of(zl_target *tg, int rgb565)
{
    if (rgb565)
        zt_target_packed(tg, c565, depth_buf, W, H, ZL_FORMAT_RGB565);
    else
        zt_target_packed(tg, color_buf, depth_buf, W, H, ZL_FORMAT_RGB888);
}

/* Frame mode into color_buf, then scanline and bands of 5 through zl_frame:
 * the same bytes; textures also into c565 (the fast texture loop: RGB565,
 * LEQUAL with writes). */
static void draw_all(const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *st, const zl_style *sty)
{
    static const uint16_t bands[2] = {1, 5};
    zl_context ctx;
    zl_target tg;
    zl_rgb black = {0, 0, 0};
    unsigned b;
    target_of(&tg, 0);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    ctx.state = *st;
    ctx.style = *sty;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 0xFFFF));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, mesh, mvp));
    for (b = 0; b < 2; b++) {
        static const zt_frame_copy to_ref = {color_ref, NULL};
        zl_frame_config cfg;
        zl_frame fr;
        zt_frame_config_of(&cfg, W, H, bands[b], ZL_FORMAT_RGB888);
        zt_frame_capacity(&cfg, 1, 3, 1, 8);
        cfg.gouraud = 1;
        cfg.styled = 1;
        cfg.textured = 1;
        TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&fr, &cfg, work, sizeof work, black, 0xFFFF));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&fr, mesh, mvp, st, sty));
        zt_frame_drain(&fr, &to_ref);
        TEST_ASSERT_EQUAL_MEMORY(color_buf, color_ref, sizeof color_buf);
    }
    if (sty->texture != NULL) {
        target_of(&tg, 1);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
        ctx.state = *st;
        ctx.state.depth_func = ZL_LEQUAL;
        ctx.style = *sty;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 0xFFFF));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, mesh, mvp));
    }
}

/* Distance (texels) from coordinate c to texel i of the wrapped axis; 0
 * inside it. */
static long double texel_distance(long double c, int i)
{
    long double f = c - floorl(c / TS) * TS; /* 0 .. TS */
    long double best = 1e30L;
    int k;
    for (k = -1; k <= 1; k++) {
        long double lo = (long double)i + k * TS, d = f < lo ? lo - f : (f > lo + 1 ? f - lo - 1 : 0);
        best = d < best ? d : best;
    }
    return best;
}

/* Whether c is within tol of a texel boundary. */
static int near_boundary(long double c, long double tol)
{
    long double f = c - floorl(c);
    return f < tol || f > 1 - tol;
}

/* The tolerance (texels) at a pixel whose clip w is w (see the top). */
static long double tolerance(const tri_ref *t, long double c, long double w, int linear)
{
    long double unit = linear ? 1.0L / 65536 : 4096.0L / (268435456.0L * t->wmin / w);
    return 1.0L / 32 + fabsl(c) / 16384 + (1 + W + H) * unit / 2;
}

static void check_texel(const tri_ref *t, int i, int j, unsigned iu, unsigned iv, int linear, stats *st,
                        const char *what)
{
    long double want[6], du, dv, w;
    char msg[220];
    TEST_ASSERT_TRUE(reference(t, i, j, linear, want));
    w = want[5];
    du = texel_distance(want[3], (int)iu);
    dv = texel_distance(want[4], (int)iv);
    if ((double)(du > dv ? du : dv) > st->worst_any)
        st->worst_any = (double)(du > dv ? du : dv);
    if (near_boundary(want[3], tolerance(t, want[3], w, linear)) ||
        near_boundary(want[4], tolerance(t, want[4], w, linear))) {
        st->boundary++;
        return;
    }
    if ((double)du > st->worst_texel)
        st->worst_texel = (double)du;
    if ((double)dv > st->worst_texel)
        st->worst_texel = (double)dv;
    snprintf(msg, sizeof msg, "%s at (%d, %d): texel (%u, %u), reference (%.4f, %.4f)%s", what, i, j, iu, iv,
             (double)want[3], (double)want[4], linear ? ", screen-linear" : "");
    if (!(du == 0 && dv == 0)) {
        int k;
        for (k = 0; k < 3; k++)
            printf("v%d clip %d %d %d %d  uv %.4f %.4f\n", k, t->v[k].x, t->v[k].y, t->v[k].z, t->v[k].w, (double)t->a[k][3], (double)t->a[k][4]);
    }
    TEST_ASSERT_TRUE_MESSAGE(du == 0 && dv == 0, msg);
    st->checked++;
}

/* Draw one triangle in a style and check every covered pixel. */
static void check_triangle(const zl_fixed p[9], const uint8_t rgb[9], const zl_fixed uv[6], const zl_mat4 *mvp, int kind,
                           stats *st)
{
    static const uint16_t idx[3] = {0, 1, 2};
    zl_mesh mesh;
    zl_state state;
    zl_style style;
    tri_ref t;
    int k, i, j, ch, clip_near = 0, clip_far = 0, eye = 0, linear;
    char msg[200];
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = p;
    mesh.indices = idx;
    mesh.vertex_colors = rgb;
    mesh.vertex_count = 3;
    mesh.triangle_count = 1;
    setup_style(kind, uv, &state, &style);
    memset(&t, 0, sizeof t);
    t.pixel_space = mvp == NULL;
    for (k = 0; k < 3; k++) {
        zl_vec3 v = {p[k * 3], p[k * 3 + 1], p[k * 3 + 2]};
        if (mvp != NULL) {
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_transform_point(mvp, v, &t.v[k]));
        } else {
            t.v[k].x = v.x;
            t.v[k].y = v.y;
            t.v[k].z = v.z;
            t.v[k].w = ZL_FX_ONE;
        }
        for (ch = 0; ch < 3; ch++)
            t.a[k][ch] = rgb[k * 3 + ch];
        t.a[k][3] = (long double)uv[k * 2] * TS / 65536;
        t.a[k][4] = (long double)uv[k * 2 + 1] * TS / 65536;
        clip_near |= t.v[k].z < 0;
        clip_far |= t.v[k].z > t.v[k].w;
        eye |= t.v[k].w <= 0;
    }
    st->tris++;
    if (!clip_near && !clip_far)
        return; /* not clipped: the snapped triangle's own planes (test_texture) */
    linear = kind == KIND_TEX_AFFINE && !eye;
    t.wmin = clipped_wmin(t.v);
    draw_all(&mesh, mvp, &state, &style);
    st->clipped++;
    st->near += clip_near && !clip_far;
    st->far += clip_far && !clip_near;
    st->both += clip_near && clip_far;
    st->eye += eye;
    for (j = 0; j < H; j++) {
        for (i = 0; i < W; i++) {
            const uint8_t *c = &color_buf[(j * W + i) * 3];
            long double want[6];
            if (c[0] == 0 && c[1] == 0 && c[2] == 0)
                continue; /* not covered: every colour here is at least 16 (blue 31 in textures) */
            st->pixels++;
            if (kind == KIND_PERSP_COLOR) {
                TEST_ASSERT_TRUE(reference(&t, i, j, 0, want));
                for (ch = 0; ch < 3; ch++) {
                    long double wc = want[ch] < 0 ? 0 : (want[ch] > 255 ? 255 : want[ch]);
                    double err = fabs((double)(c[ch] - wc));
                    if (err > st->worst_color)
                        st->worst_color = err;
                    snprintf(msg, sizeof msg, "colour %d at (%d, %d): %u, exact %.3f; near %d far %d eye %d", ch, i, j,
                             c[ch], (double)wc, clip_near, clip_far, eye);
                    TEST_ASSERT_TRUE_MESSAGE(err <= 1.0, msg);
                }
                st->checked++;
            } else {
                uint16_t px = c565[j * W + i];
                check_texel(&t, i, j, c[0] >> 3, c[1] >> 2, linear, st, "RGB888");
                check_texel(&t, i, j, px >> 11, (px >> 5) & 63u, linear, st, "RGB565");
            }
        }
    }
}

static void random_attrs(uint8_t rgb[9], zl_fixed uv[6])
{
    int k;
    for (k = 0; k < 9; k++)
        rgb[k] = (uint8_t)rnd_range(16, 255);
    for (k = 0; k < 6; k++)
        uv[k] = rnd_range(-2 * 65536, 2 * 65536);
}

static void print_stats(const char *name, const stats *st)
{
    printf("%s: %u triangles, %u clipped (near %u, far %u, both %u, eye plane %u); %u pixels, %u checks, %u within "
           "the tolerance of a texel boundary; worst colour error %.3f, worst texel distance %.4f (%.4f with those)\n",
           name, st->tris, st->clipped, st->near, st->far, st->both, st->eye, st->pixels, st->checked, st->boundary,
           st->worst_color, st->worst_texel, st->worst_any);
}

static void pixel_space_case(int kind, stats *st)
{
    int r;
    for (r = 0; r < 600; r++) {
        zl_fixed p[9], uv[6];
        uint8_t rgb[9];
        int k;
        for (k = 0; k < 3; k++) {
            p[k * 3] = rnd_range(-30 * 65536, 90 * 65536);
            p[k * 3 + 1] = rnd_range(-30 * 65536, 77 * 65536);
            p[k * 3 + 2] = rnd_range(-3 * 65536 / 2, 5 * 65536 / 2);
        }
        random_attrs(rgb, uv);
        check_triangle(p, rgb, uv, NULL, kind, st);
    }
}

/* A camera at the origin looking down -z (model space is eye space). */
static void perspective_case(int kind, int close, stats *st)
{
    zl_mat4 proj;
    int32_t n = close ? 65536 / 20 : 65536 / 2, f = close ? 65536 * 4 : 65536 * 20;
    int r;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, ZL_ANGLE_TURN / 6,
                                                     (zl_fixed)(((int64_t)W * 65536 + H / 2) / H), n, f));
    for (r = 0; r < 600; r++) {
        zl_fixed p[9], uv[6];
        uint8_t rgb[9];
        int k;
        for (k = 0; k < 3; k++) {
            int32_t e = close ? 65536 : 12 * 65536;
            p[k * 3] = rnd_range(-e, e);
            p[k * 3 + 1] = rnd_range(-e, e);
            p[k * 3 + 2] = close ? rnd_range(-6 * 65536, 65536 / 4) : rnd_range(-30 * 65536, 2 * 65536);
        }
        random_attrs(rgb, uv);
        check_triangle(p, rgb, uv, &proj, kind, st);
    }
}

static void run_kind(const char *name, int kind)
{
    stats st;
    char label[80];
    make_texture();
    memset(&st, 0, sizeof st);
    pixel_space_case(kind, &st);
    snprintf(label, sizeof label, "%s, pixel space", name);
    print_stats(label, &st);
    TEST_ASSERT_TRUE(st.near > 30 && st.far > 30 && st.both > 30 && st.checked > 10000);
    memset(&st, 0, sizeof st);
    perspective_case(kind, 0, &st);
    perspective_case(kind, 1, &st);
    snprintf(label, sizeof label, "%s, perspective", name);
    print_stats(label, &st);
    TEST_ASSERT_TRUE(st.near > 30 && st.far > 30 && st.both > 10 && st.eye > 30 && st.checked > 10000);
}

static void test_perspective_colour(void)
{
    run_kind("perspective Gouraud", KIND_PERSP_COLOR);
}

static void test_texture_perspective(void)
{
    run_kind("perspective texture", KIND_TEX_PERSP);
}

static void test_texture_affine(void)
{
    run_kind("affine texture", KIND_TEX_AFFINE);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_perspective_colour);
    RUN_TEST(test_texture_perspective);
    RUN_TEST(test_texture_affine);
    return UNITY_END();
}

/* SPDX-License-Identifier: MIT */
/*
 * Depth and Gouraud colour of clipped triangles (zline.h, Clipping): at
 * every pixel a clipped triangle covers, the stored depth is within +-1 of
 * round(65535 z_w) and the colour within +-1 of the exact value, where z_w
 * and the colour are those of the ORIGINAL triangle (before clipping) at the
 * pixel centre. The reference is computed here, independently of the core's
 * integer solve: the 3x3 system M b = n (M the clip-space x, y, w of the
 * three vertices as the transform gives them, n the pixel centre in device
 * coordinates) by Gaussian elimination in long double (64-bit mantissa),
 * then the textbook perspective formulas
 *     z_w = (sum b_i z_i) / (sum b_i w_i)               (z_clip / w_clip)
 *     z_w = f (1 - n / w_p) / (f - n), w_p = (sum b_i w_i) / (sum b_i)
 *                                                     (exact mapping)
 *     colour = sum c_i lambda_i, lambda_i = b_i w_i / sum b_j w_j
 * Triangles cross the near plane, the far plane, both, and (with a
 * perspective camera) the eye plane; in pixel space (NULL matrix, z
 * crossing 0 and 1) and with perspective, with and without the exact depth
 * mapping. Each is drawn alone in frame mode and through zl_frame in
 * scanline and band mode, which must give the same bytes. The colour is
 * checked where every vertex is in front of the eye (else the pieces keep
 * their own colour planes: see zline.h).
 *
 * Built with ZL_FEATURE_EXACT_CLIP 0 (CTest test_clip_planes_exact_clip_off),
 * each piece takes the plane through its snapped vertices with the depths
 * the clipper gives them, and the test checks that contract's bound instead
 * (zline.h, Clipping; piece_depth_slack below): the exact gradient times
 * the snapping (1/32 pixel an axis) and the clipper's Q16.16 rounding, on
 * top of the +-1; the colour, in every channel, within the vertex colours
 * (+-1): each piece interpolates between colours on the original triangle.
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

static uint64_t rng = 0x9E3779B97F4A7C15ull;

static int32_t rnd_range(int32_t lo, int32_t hi)
{
    return zt_rand64_range(&rng, lo, hi);
}

static uint8_t color_buf[W * H * 3], color_ref[W * H * 3];
static uint16_t depth_buf[W * H], depth_ref[W * H];
static uint64_t work[200000 / 8];

typedef struct {
    unsigned tris, clipped_tris, pixels, color_pixels, steep;
    unsigned near_tris, far_tris, both_tris, eye_tris;
    double max_depth_err, max_color_err, max_bound_ratio;
} stats;

typedef struct {
    zl_vec4 v[3];      /* clip space as the core computes it */
    uint8_t rgb[3][3]; /* vertex colours */
    int pixel_space;
    int32_t n, f;      /* exact mapping (0: z_clip / w_clip) */
    /* The vertices clipping makes (clip_made): the least clip w (Q16.16
     * units) and the largest |x / w|, |y / w| among them. */
    long double made_w, made_reach;
} tri_ref;

/* Reference depth (steps, unrounded) and colour at pixel (i, j); 0 if the
 * system is singular there. */
static int reference(const tri_ref *t, int i, int j, long double *depth, long double rgb[3])
{
    long double m[3][3], r[3], b[3], X = i + 0.5L, Y = j + 0.5L, sw = 0, sb = 0, sz = 0;
    int k, ch;
    for (k = 0; k < 3; k++) {
        m[0][k] = t->v[k].x;
        m[1][k] = t->v[k].y;
        m[2][k] = t->v[k].w;
    }
    if (t->pixel_space) {
        r[0] = X;
        r[1] = Y;
    } else {
        r[0] = 2 * X / W - 1;
        r[1] = 1 - 2 * Y / H;
    }
    r[2] = 1;
    if (!zt_solve3(m, r, b))
        return 0;
    for (k = 0; k < 3; k++) {
        sw += b[k] * t->v[k].w;
        sb += b[k];
        sz += b[k] * t->v[k].z;
    }
    if (t->n != 0) {
        long double wp = sw / sb, nn = t->n, ff = t->f;
        *depth = 65535.0L * ff * (1 - nn / wp) / (ff - nn);
    } else {
        *depth = 65535.0L * sz / sw;
    }
    for (ch = 0; ch < 3; ch++) {
        long double c = 0;
        for (k = 0; k < 3; k++)
            c += t->rgb[k][ch] * (b[k] * t->v[k].w / sw);
        rgb[ch] = c;
    }
    return 1;
}

/* The RGB565 LESS paths (the flat span loops of both modes): the same
 * depth as the RGB888 ALWAYS draw in depth_buf, into a target cleared to
 * 65535 (a fragment of 65535 fails LESS there and leaves the same value). */
static void draw_565_less(const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *st)
{
    static uint16_t c565[W * H], d565[W * H];
    zl_context ctx;
    zl_target tg;
    zl_rgb black = {0, 0, 0};
    zl_frame_config cfg;
    zl_frame fr;
    zl_band band;
    zl_status rc;
    zl_state s = *st;
    s.depth_func = ZL_LESS;
    zt_target_packed(&tg, c565, d565, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    ctx.state = s;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 0xFFFF));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, mesh, mvp));
    TEST_ASSERT_EQUAL_MEMORY(depth_buf, d565, sizeof d565);
    zt_frame_config_of(&cfg, W, H, 1, ZL_FORMAT_RGB565);
    zt_frame_capacity(&cfg, 1, 3, 1, 8);
    cfg.gouraud = 1;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&fr, &cfg, work, sizeof work, black, 0xFFFF));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&fr, mesh, mvp, &s));
    while ((rc = zl_frame_next_band(&fr, &band)) == ZL_OK) {
        TEST_ASSERT_EQUAL_MEMORY(&c565[band.first_row * W], band.color, W * 2);
        TEST_ASSERT_EQUAL_MEMORY(&d565[band.first_row * W], band.depth, W * 2);
    }
    TEST_ASSERT_EQUAL_INT(ZL_DONE, rc);
}

/* Frame mode, then scanline (band 1) and band 5 through zl_frame: the same
 * bytes; then the RGB565 LESS paths. */
static void draw_all_modes(const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *st)
{
    zl_context ctx;
    zl_target tg;
    zl_rgb black = {0, 0, 0};
    static const uint16_t bands[2] = {1, 5};
    unsigned b;
    zt_target_packed(&tg, color_buf, depth_buf, W, H, ZL_FORMAT_RGB888);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    ctx.state = *st;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 0xFFFF));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, mesh, mvp));
    for (b = 0; b < 2; b++) {
        static const zt_frame_copy to_ref = {color_ref, depth_ref};
        zl_frame_config cfg;
        zl_frame fr;
        zt_frame_config_of(&cfg, W, H, bands[b], ZL_FORMAT_RGB888);
        zt_frame_capacity(&cfg, 1, 3, 1, 8);
        cfg.gouraud = 1;
        TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&fr, &cfg, work, sizeof work, black, 0xFFFF));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&fr, mesh, mvp, st));
        zt_frame_drain(&fr, &to_ref);
        TEST_ASSERT_EQUAL_MEMORY(color_buf, color_ref, sizeof color_buf);
        TEST_ASSERT_EQUAL_MEMORY(depth_buf, depth_ref, sizeof depth_buf);
    }
    draw_565_less(mesh, mvp, st);
}

/* The vertices clipping makes from t's (zt_clip_near_far: against z >= 0
 * and z <= w, as zline's clipper does in Q16.16): made_w and made_reach of t. */
static void clip_made(tri_ref *t)
{
    long double p[ZT_CLIP_MAX][4];
    int made[ZT_CLIP_MAX], n = zt_clip_near_far(t->v, p, made), k, c;
    t->made_w = 1e30L;
    t->made_reach = 0;
    for (k = 0; k < n; k++) {
        if (!made[k] || p[k][3] <= 0)
            continue;
        t->made_w = p[k][3] < t->made_w ? p[k][3] : t->made_w;
        for (c = 0; c < 2; c++)
            t->made_reach = fabsl(p[k][c] / p[k][3]) > t->made_reach ? fabsl(p[k][c] / p[k][3]) : t->made_reach;
    }
}

/*
 * How far from the exact depth the plane a pixel takes may be, in steps,
 * at a pixel whose exact depth changes by g steps a pixel (|d/dx| +
 * |d/dy|): 0 with the original planes; ZL_FEATURE_EXACT_CLIP off, the plane
 * through a piece's snapped vertices is, at any point of the piece, within
 * max |grad . delta_i| of the exact one (a convex combination of the
 * vertices' displacements delta_i), delta_i the snapping (1/32 pixel an
 * axis) plus the move of a vertex the clipper makes by one Q16.16 unit of
 * its x, y and w ((W/2) (1 + R) / w pixels, R the made vertices' largest
 * |x / w|, |y / w|, w their least clip w: clip_made); the vertex depth is
 * off by one unit of its z and w, 65535 * 2 / w steps (z / w within 0 .. 1;
 * the exact mapping's slope f / (f - n) times that). The stored depth is
 * then within +-1 of the rounded depth of such a plane (as it is of the
 * exact one with the original planes).
 */
static long double piece_depth_slack(const tri_ref *t, long double g)
{
#if ZL_FEATURE_EXACT_CLIP
    (void)t;
    (void)g;
    return 0.0L;
#else
    const long double half = (W > H ? W : H) / 2.0L;
    long double e_pos, e_z;
    if (t->pixel_space) {
        e_pos = 1.0L / 65536;
        e_z = 65535.0L / 65536;
    } else {
        e_pos = half * (1 + t->made_reach) / t->made_w;
        e_z = 2 * 65535.0L / t->made_w * (t->n != 0 ? (long double)t->f / (t->f - t->n) : 1.0L);
    }
    return g * (1.0L / 32 + e_pos) + e_z;
#endif
}

static long double clamp_depth(long double z)
{
    return z < 0 ? 0 : (z > 65535 ? 65535 : z);
}

/* Colour channel ch at a covered pixel: the exact value (+-1) with the
 * original planes; without (ZL_FEATURE_EXACT_CLIP 0) within the range of
 * the vertex colours (+-1). */
static void check_colour(const tri_ref *t, int ch, unsigned got, long double want, int i, int j, stats *st)
{
    char msg[200];
    long double lo = want, hi = want;
    double err;
    if (!ZL_FEATURE_EXACT_CLIP) {
        int k;
        lo = hi = t->rgb[0][ch];
        for (k = 1; k < 3; k++) {
            lo = t->rgb[k][ch] < lo ? t->rgb[k][ch] : lo;
            hi = t->rgb[k][ch] > hi ? t->rgb[k][ch] : hi;
        }
    }
    lo = lo < 0 ? 0 : (lo > 255 ? 255 : lo);
    hi = hi < 0 ? 0 : (hi > 255 ? 255 : hi);
    err = got < lo ? (double)(lo - got) : (got > hi ? (double)(got - hi) : 0.0);
    if (err > st->max_color_err)
        st->max_color_err = err;
    snprintf(msg, sizeof msg, "colour %d at (%d, %d): %u, exact %.3f .. %.3f", ch, i, j, got, (double)lo,
             (double)hi);
    TEST_ASSERT_TRUE_MESSAGE(err <= 1.0, msg);
}

/* Draw triangle t (positions p, colours) and check every covered pixel. */
static void check_triangle(const zl_fixed p[9], const uint8_t rgb[9], const zl_mat4 *mvp, int32_t n, int32_t f,
                           int gouraud, stats *st)
{
    static const uint16_t idx[3] = {0, 1, 2};
    zl_mesh mesh;
    zl_state state;
    tri_ref t;
    int k, i, j, ch, clip_near = 0, clip_far = 0, eye = 0;
    char msg[200];
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = p;
    mesh.indices = idx;
    mesh.vertex_colors = rgb;
    mesh.vertex_count = 3;
    mesh.triangle_count = 1;
    zl_state_default(&state);
    state.depth_func = ZL_ALWAYS;
    state.shading = gouraud ? ZL_SHADE_GOURAUD : ZL_SHADE_FLAT;
    state.color.r = state.color.g = state.color.b = 200;
    state.near_z = n;
    state.far_z = f;
    memset(&t, 0, sizeof t);
    t.pixel_space = mvp == NULL;
    t.n = mvp != NULL ? n : 0;
    t.f = f;
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
            t.rgb[k][ch] = rgb[k * 3 + ch];
        clip_near |= t.v[k].z < 0;
        clip_far |= t.v[k].z > t.v[k].w;
        eye |= t.v[k].w <= 0;
    }
    st->tris++;
    if (!clip_near && !clip_far)
        return; /* the unclipped contract: the snapped plane (other tests) */
    clip_made(&t);
    draw_all_modes(&mesh, mvp, &state);
    st->clipped_tris++;
    st->near_tris += clip_near && !clip_far;
    st->far_tris += clip_far && !clip_near;
    st->both_tris += clip_near && clip_far;
    st->eye_tris += eye;
    for (j = 0; j < H; j++) {
        for (i = 0; i < W; i++) {
            const uint8_t *c = &color_buf[(j * W + i) * 3];
            long double want, want_rgb[3], gx, gy, tmp[3], slack, lo, hi;
            unsigned stored = depth_buf[j * W + i];
            double err;
            if (c[0] == 0 && c[1] == 0 && c[2] == 0)
                continue; /* not covered: every colour is at least 16 */
            TEST_ASSERT_TRUE(reference(&t, i, j, &want, want_rgb));
            /* the contract's exception: more than 2^16 steps per pixel (a
             * full depth range) is clamped; skip such pixels */
            TEST_ASSERT_TRUE(reference(&t, i + 1, j, &gx, tmp));
            TEST_ASSERT_TRUE(reference(&t, i, j + 1, &gy, tmp));
            if (fabsl(gx - want) > 65536.0L || fabsl(gy - want) > 65536.0L) {
                st->steep++;
                continue;
            }
            slack = piece_depth_slack(&t, fabsl(gx - want) + fabsl(gy - want));
            lo = roundl(clamp_depth(want - slack)) - 1;
            hi = roundl(clamp_depth(want + slack)) + 1;
            want = clamp_depth(want);
            err = fabs((double)stored - (double)roundl(want));
            st->pixels++;
            if (err > st->max_depth_err)
                st->max_depth_err = err;
            if (err / (double)(1 + slack) > st->max_bound_ratio)
                st->max_bound_ratio = err / (double)(1 + slack);
            snprintf(msg, sizeof msg, "depth at (%d, %d): stored %u, exact %.3f, allowed %.0f .. %.0f; near %d far %d eye %d",
                     i, j, stored, (double)want, (double)lo, (double)hi, clip_near, clip_far, eye);
            TEST_ASSERT_TRUE_MESSAGE(stored >= lo && stored <= hi, msg);
            if (gouraud && !eye) {
                for (ch = 0; ch < 3; ch++)
                    check_colour(&t, ch, c[ch], want_rgb[ch], i, j, st);
                st->color_pixels++;
            }
        }
    }
}

static void random_colors(uint8_t rgb[9])
{
    int k;
    for (k = 0; k < 9; k++)
        rgb[k] = (uint8_t)rnd_range(16, 255);
}

static void print_stats(const char *name, const stats *st)
{
    printf("%s: %u triangles, %u clipped (near %u, far %u, both %u, eye plane %u), %u pixels checked "
           "(%u for colour, %u skipped: over 65536 steps per pixel): max depth error %.3f steps, max colour "
           "error %.3f; the largest depth error is %.3f of 1 + the plane's slack (ZL_FEATURE_EXACT_CLIP %d)\n",
           name, st->tris, st->clipped_tris, st->near_tris, st->far_tris, st->both_tris, st->eye_tris, st->pixels,
           st->color_pixels, st->steep, st->max_depth_err, st->max_color_err, st->max_bound_ratio,
           ZL_FEATURE_EXACT_CLIP);
}

/* Pixel space: x, y pixels, z window depth, crossing 0 and 1. */
static void test_pixel_space(void)
{
    stats st;
    int r;
    memset(&st, 0, sizeof st);
    for (r = 0; r < 1500; r++) {
        zl_fixed p[9];
        uint8_t rgb[9];
        int k;
        for (k = 0; k < 3; k++) {
            p[k * 3] = rnd_range(-30 * 65536, 90 * 65536);
            p[k * 3 + 1] = rnd_range(-30 * 65536, 77 * 65536);
            p[k * 3 + 2] = rnd_range(-3 * 65536 / 2, 5 * 65536 / 2);
            if (r % 4 == 1) /* steep: a small depth range each side of 0 or 1 */
                p[k * 3 + 2] = (r % 8 == 1 ? 0 : 65536) + rnd_range(-4000, 4000);
        }
        random_colors(rgb);
        check_triangle(p, rgb, NULL, 0, 0, r & 1, &st);
        if (r % 3 == 0) /* grazing: two vertices close, the third far in depth */
        {
            p[3] = p[0] + rnd_range(-65536 * 2, 65536 * 2);
            p[4] = p[1] + rnd_range(-65536 * 2, 65536 * 2);
            p[2] = -65536 * 3;
            p[5] = 65536 * 4;
            check_triangle(p, rgb, NULL, 0, 0, 1, &st);
        }
    }
    print_stats("pixel space", &st);
    TEST_ASSERT_TRUE(st.near_tris > 50 && st.far_tris > 50 && st.both_tris > 50);
}

/* A perspective camera at the origin looking down -z (the view is the
 * identity): model space is eye space. */
static void perspective_case(int exact, int close, stats *st)
{
    zl_mat4 proj;
    int32_t n = close ? 65536 / 20 : 65536 / 2, f = close ? 65536 * 4 : 65536 * 20;
    int r;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, ZL_ANGLE_TURN / 6,
                                                     (zl_fixed)(((int64_t)W * 65536 + H / 2) / H), n, f));
    for (r = 0; r < 1500; r++) {
        zl_fixed p[9];
        uint8_t rgb[9];
        int k;
        for (k = 0; k < 3; k++) {
            int32_t z = close ? rnd_range(-6 * 65536, 65536 / 4) : rnd_range(-30 * 65536, 2 * 65536);
            int32_t e = close ? 65536 : 12 * 65536;
            p[k * 3] = rnd_range(-e, e);
            p[k * 3 + 1] = rnd_range(-e, e);
            p[k * 3 + 2] = z;
            if (close && r % 2 == 0) { /* the eye near the near plane, grazing faces */
                p[k * 3 + 1] = -65536 / 30 + rnd_range(-300, 300);
                p[k * 3 + 2] = -rnd_range(0, 3 * 65536);
            }
        }
        random_colors(rgb);
        check_triangle(p, rgb, &proj, exact ? n : 0, exact ? f : 0, r & 1, st);
    }
}

/* The perspective cases, far and close, with one depth mapping; each kind
 * of crossing must occur often enough to mean something. */
static void perspective_both_distances(int exact, const char *name)
{
    stats st;
    memset(&st, 0, sizeof st);
    perspective_case(exact, 0, &st);
    perspective_case(exact, 1, &st);
    print_stats(name, &st);
    TEST_ASSERT_TRUE(st.near_tris > 50 && st.far_tris > 50 && st.both_tris > 20 && st.eye_tris > 50);
}

static void test_perspective(void)
{
    perspective_both_distances(0, "perspective, z_clip / w_clip");
}

static void test_perspective_exact(void)
{
    perspective_both_distances(1, "perspective, exact mapping");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_pixel_space);
    RUN_TEST(test_perspective);
    RUN_TEST(test_perspective_exact);
    return UNITY_END();
}

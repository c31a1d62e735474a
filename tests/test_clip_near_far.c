/* SPDX-License-Identifier: MIT */
/*
 * Near and far clipping of untextured triangles against exact geometry.
 *
 * A pixel-space triangle (NULL matrix) whose depth runs beyond 0 .. 1 is
 * clipped at z = 0 and z = 1 (the raster contract). The reference is the
 * unclipped triangle: zt_ref's coverage and the exact depth plane of its
 * snapped vertices at each pixel centre. A covered pixel whose exact depth
 * is inside 0 .. 1 by more than the clip edge can move (its new vertices
 * are snapped to 1/16 pixel: the plane's change over two pixels, plus a
 * little) must be drawn; one outside by as much must not be. Both frame mode
 * and scanline mode are checked, with the depth test off so that clipping
 * alone decides.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

#define W 48
#define H 40
#define CASES 300

void setUp(void) {}
void tearDown(void) {}

static uint8_t color[W * H * 3];
static uint16_t depth[W * H];
static uint64_t work[4000];
static const zl_rgb bg = {0, 0, 0}, fg = {255, 255, 255};

typedef struct {
    int64_t x[3], y[3], z[3]; /* half subpixels; raw Q16.16 depth */
} plane_tri;

/* Exact depth at pixel (i, j)'s centre as num / den (den > 0), and the
 * plane's steepest change per pixel, by Cramer's rule on the snapped vertices. */
static void plane_at(const plane_tri *t, int32_t i, int32_t j, int64_t *num, int64_t *den, int64_t *slope,
                     int *near_edge)
{
    int64_t cx = zt_centre2(i), cy = zt_centre2(j), e[3], a = 0, n = 0, gx = 0, gy = 0, px = 2 * ZT_SUB;
    unsigned k;
    *near_edge = 0;
    for (k = 0; k < 3; k++) {
        unsigned p = (k + 1) % 3, q = (k + 2) % 3;
        int64_t ex = t->x[q] - t->x[p], ey = t->y[q] - t->y[p];
        e[k] = ex * (cy - t->y[p]) - ey * (cx - t->x[p]);
        /* within 1/8 pixel of an edge: the clipped polygon's edges run
         * between snapped new vertices, up to 1/32 pixel off the original */
        if (e[k] * e[k] < (int64_t)(ZT_SUB / 4) * (ZT_SUB / 4) * (ex * ex + ey * ey))
            *near_edge = 1;
        a += e[k];
        n += e[k] * t->z[k];
        gx += -(t->y[q] - t->y[p]) * t->z[k]; /* d(e_k)/dx times z_k */
        gy += (t->x[q] - t->x[p]) * t->z[k];
    }
    if (a < 0) {
        a = -a;
        n = -n;
        gx = -gx;
        gy = -gy;
    }
    *num = n;
    *den = a;
    gx = gx < 0 ? -gx : gx;
    gy = gy < 0 ? -gy : gy;
    *slope = a == 0 ? 0 : zt_ceil_div((gx > gy ? gx : gy) * px, a); /* per pixel, raw Q16 */
}

/* Scanline mode's colour lands where frame mode draws (the depth test is
 * off, so only the colour is checked). */
static zt_frame_copy to_color = {color, NULL};

static void render(const zl_mesh *m, int scanline)
{
    zl_state st;
    zl_state_default(&st);
    st.depth_test = 0;
    st.color = fg;
    if (scanline) {
        zl_frame_config cfg;
        zl_frame f;
        zt_frame_config_of(&cfg, W, H, 1, ZL_FORMAT_RGB888);
        zt_frame_capacity(&cfg, 1, 3, 1, 8);
        TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, m, NULL, &st));
        TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, zt_band_copy_fn, &to_color));
    } else {
        zl_target tg;
        zl_context ctx;
        zt_target_packed(&tg, color, depth, W, H, ZL_FORMAT_RGB888);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
        ctx.state = st;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, m, NULL));
    }
}

/* One random triangle crossing z = 0 (near) or z = 1 (far); returns the
 * number of pixels where the drawing contradicts the exact geometry. */
static unsigned check_case(uint32_t *rng, int far, int scanline, unsigned *decided)
{
    zl_fixed pos[9];
    uint16_t idx[3] = {0, 1, 2};
    zl_mesh m;
    zt_tri tri;
    plane_tri pt;
    unsigned k, bad = 0;
    int32_t i, j;
    for (k = 0; k < 3; k++) {
        pos[k * 3] = (zl_fixed)zt_rand_range(rng, -4 * 65536, (W + 4) * 65536);
        pos[k * 3 + 1] = (zl_fixed)zt_rand_range(rng, -4 * 65536, (H + 4) * 65536);
        /* near: depth from -1 to 1; far: from 0 to 2 */
        pos[k * 3 + 2] = (zl_fixed)zt_rand_range(rng, far ? 0 : -65536, far ? 2 * 65536 : 65536);
        pt.x[k] = zt_snap2(pos[k * 3]);
        pt.y[k] = zt_snap2(pos[k * 3 + 1]);
        pt.z[k] = pos[k * 3 + 2];
    }
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.vertex_count = 3;
    m.triangle_count = 1;
    render(&m, scanline);
    zt_tri_init(&tri, pos, pos + 3, pos + 6);
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) {
            int drawn = color[(j * W + i) * 3] != 0, inside, outside;
            int64_t num, den, slope, margin;
            int near_edge;
            plane_at(&pt, i, j, &num, &den, &slope, &near_edge);
            if (!zt_tri_covers(&tri, i, j)) {
                if (drawn && !near_edge) {
                    printf("%s %s: pixel (%ld,%ld) outside the triangle drawn\n", scanline ? "scanline" : "draw",
                           far ? "far" : "near", (long)i, (long)j);
                    bad++; /* clipping never adds pixels */
                }
                continue;
            }
            margin = 2 * slope + 16;
            inside = !near_edge && num >= margin * den && num <= (65536 - margin) * den;
            outside = num < -margin * den || num > (65536 + margin) * den;
            if ((inside && !drawn) || (outside && drawn)) {
                if (bad == 0) {
                    char msg[160];
                    snprintf(msg, sizeof msg, "%s %s: pixel (%ld,%ld) depth %ld/65536 %s", scanline ? "scanline" : "draw",
                             far ? "far" : "near", (long)i, (long)j, (long)zt_floor_div(num, den),
                             drawn ? "drawn" : "not drawn");
                    printf("%s\n", msg);
                }
                bad++;
            }
            *decided += (unsigned)(inside || outside);
        }
    return bad;
}

static void sweep(int far)
{
    uint32_t rng = far ? 0xFA4u : 0x4EA4u;
    unsigned n, bad = 0, decided = 0;
    for (n = 0; n < CASES; n++)
        bad += check_case(&rng, far, (int)(n & 1u), &decided);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, bad, "pixels contradicting the exact clipped geometry");
    /* the margins must leave most pixels decided, or the test proves little */
    TEST_ASSERT_TRUE(decided > CASES * 100u);
}

static void test_near_plane_clips_untextured_triangles_exactly(void)
{
    sweep(0);
}

static void test_far_plane_clips_untextured_triangles_exactly(void)
{
    sweep(1);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_near_plane_clips_untextured_triangles_exactly);
    RUN_TEST(test_far_plane_clips_untextured_triangles_exactly);
    return UNITY_END();
}

/* SPDX-License-Identifier: MIT */
/*
 * Exact coverage of single triangles against the RASTER CONTRACT (zline.h):
 * snapping to 1/16 px with ties towards +infinity, pixel centres, the
 * top-left rule, zero area, both windings.
 *
 * Part 1: hand-made triangles whose expected coverage is written below as a
 * picture ('#' covered, '.' not), derived by hand from the contract (the
 * derivation is in the comment of each case). Every case is drawn with all
 * six orders of its vertices (both windings, every starting vertex) and must
 * give the same picture. The pictures also check the reference rasteriser
 * of tests/support/zt_ref.c.
 *
 * Part 2: thousands of random triangles on the 1/16 grid (and some off it)
 * in a 64x64 target: zl_draw_mesh's coverage must equal the reference's,
 * pixel for pixel.
 *
 * Drawing: pixel space (NULL matrix), one triangle per mesh with a face
 * colour, depth test off, no culling, RGB888 target with padded rows;
 * guards and row padding are checked after every draw.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_guard.h"
#include "zt_ref.h"

#define RW 64
#define RH 64

/* raw Q16.16 from sixteenths of a pixel (independent of ZL_SUBPIXEL_BITS) */
#define S16(n) ((zl_fixed)((n) * 4096))
/* raw Q16.16 from thirty-seconds of a pixel (half-way between two 1/16 steps) */
#define S32(n) ((zl_fixed)((n) * 2048))
/* raw Q16.16 from whole pixels, and from half pixels (PXH(3) = 1.5 px) */
#define PX(n) ((zl_fixed)((n) * 65536))
#define PXH(n) ((zl_fixed)((n) * 32768))

static zt_surface surf;
static zl_context ctx;
static uint8_t got[RW * RH], want[RW * RH];
static char msg[1400];

static const uint8_t face_id[3] = {0x5A, 0xC3, 0x96};
#define ID_PACKED 0x5AC396u
#define BACKGROUND 0x000000u

void setUp(void)
{
    zt_guard_reset();
}

void tearDown(void)
{
}

/* A w x h RGB888 target with padded rows and a depth buffer (unused: depth
 * test off), ready to draw. */
static void make_target(unsigned w, unsigned h)
{
    TEST_ASSERT_EQUAL_INT(0, zt_surface_make(&surf, w, h, ZL_FORMAT_RGB888, 1, 1, 5, 6, 1));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &surf.target));
    ctx.state.depth_test = 0;
    ctx.state.depth_write = 0;
    ctx.state.cull = ZL_CULL_NONE;
    ctx.state.shading = ZL_SHADE_FLAT;
}

/* Draw one triangle (xyz each, Q16.16) and read back the coverage mask. */
static unsigned draw_and_read(const zl_fixed *a, const zl_fixed *b, const zl_fixed *c)
{
    zl_fixed pos[9];
    static const uint16_t idx[3] = {0, 1, 2};
    zl_mesh mesh;
    zl_status st;
    memcpy(pos, a, 3 * sizeof *pos);
    memcpy(pos + 3, b, 3 * sizeof *pos);
    memcpy(pos + 6, c, 3 * sizeof *pos);
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = pos;
    mesh.indices = idx;
    mesh.face_colors = face_id;
    mesh.vertex_count = 3;
    mesh.triangle_count = 1;
    zt_fill_px(&surf, BACKGROUND);
    st = zl_draw_mesh(&ctx, &mesh, NULL);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OK, st, "zl_draw_mesh status");
    ZT_ASSERT_SURFACE_INTACT(&surf);
    {
        /* nothing but the id colour and the background may appear */
        unsigned x, y;
        for (y = 0; y < surf.height; y++)
            for (x = 0; x < surf.width; x++) {
                uint32_t v = zt_get_px(&surf, x, y);
                if (v != ID_PACKED && v != BACKGROUND) {
                    snprintf(msg, sizeof msg, "pixel (%u,%u) has colour 0x%06lX", x, y,
                             (unsigned long)v);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
    }
    return zt_mask_of_px(&surf, ID_PACKED, got);
}

/* Append a picture of mask (w x h) to msg. */
static void append_picture(const char *title, const uint8_t *mask, unsigned w, unsigned h)
{
    unsigned x, y;
    size_t len = strlen(msg);
    len += (size_t)snprintf(msg + len, sizeof msg - len, "\n%s:", title);
    for (y = 0; y < h && len + w + 4 < sizeof msg; y++) {
        msg[len++] = '\n';
        msg[len++] = ' ';
        for (x = 0; x < w; x++)
            msg[len++] = mask[y * w + x] ? '#' : '.';
        msg[len] = '\0';
    }
}

/* ---------------------------------------------------------------- pictures */

/*
 * Check one hand-made case: the picture rows (all the same length) give the
 * target size; the triangle is x, y of three vertices in Q16.16 (z = 0).
 */
static void check_picture(const char *name, const char *const *rows, unsigned h, zl_fixed x0,
                          zl_fixed y0, zl_fixed x1, zl_fixed y1, zl_fixed x2, zl_fixed y2)
{
    static const int perm[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
    unsigned w = (unsigned)strlen(rows[0]);
    zl_fixed v[3][3];
    unsigned x, y, p;
    zt_tri t;
    zt_guard_reset();
    make_target(w, h);
    for (y = 0; y < h; y++) {
        TEST_ASSERT_EQUAL_UINT_MESSAGE(w, strlen(rows[y]), name);
        for (x = 0; x < w; x++)
            want[y * w + x] = rows[y][x] == '#';
    }
    v[0][0] = x0;
    v[0][1] = y0;
    v[1][0] = x1;
    v[1][1] = y1;
    v[2][0] = x2;
    v[2][1] = y2;
    v[0][2] = v[1][2] = v[2][2] = 0;

    /* the reference must agree with the hand derivation */
    zt_tri_init(&t, v[0], v[1], v[2]);
    zt_tri_mask(&t, got, w, h);
    if (memcmp(got, want, (size_t)w * h) != 0) {
        snprintf(msg, sizeof msg, "%s: REFERENCE disagrees with the hand-made picture", name);
        append_picture("expected", want, w, h);
        append_picture("reference", got, w, h);
        TEST_FAIL_MESSAGE(msg);
    }

    for (p = 0; p < 6; p++) {
        draw_and_read(v[perm[p][0]], v[perm[p][1]], v[perm[p][2]]);
        if (memcmp(got, want, (size_t)w * h) != 0) {
            snprintf(msg, sizeof msg, "%s, vertex order %d%d%d (%s)", name, perm[p][0], perm[p][1],
                     perm[p][2], t.orient * (p < 3 ? 1 : -1) > 0 ? "clockwise" : "counter-clockwise");
            append_picture("expected", want, w, h);
            append_picture("zl_draw_mesh", got, w, h);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

#define PICTURE(name, rows, x0, y0, x1, y1, x2, y2) \
    check_picture(name, rows, (unsigned)(sizeof rows / sizeof rows[0]), x0, y0, x1, y1, x2, y2)

/*
 * (0,0) (4,0) (0,4): interior x > 0, y > 0, x + y < 4; centres have
 * x + y = i + j + 1, so i + j <= 2 (i + j = 3 lies on the hypotenuse, a right
 * edge: not covered).
 */
static void test_picture_basic(void)
{
    static const char *const rows[] = {
        "###.....", "##......", "#.......", "........",
        "........", "........", "........", "........",
    };
    PICTURE("basic", rows, PX(0), PX(0), PX(4), PX(0), PX(0), PX(4));
}

/*
 * Left edge through centres: (1.5,0) (5.5,4) (1.5,8). The vertical edge
 * x = 1.5 is a left edge: column 1 is covered in every row. The other edges
 * are y = x - 1.5 (interior below: i <= j + 1) and x + y = 9.5 (interior
 * above: i + j <= 8); no centre lies on those.
 */
static void test_picture_left_edge_tie(void)
{
    static const char *const rows[] = {
        ".#......", ".##.....", ".###....", ".####...",
        ".####...", ".###....", ".##.....", ".#......",
    };
    PICTURE("left edge tie", rows, PXH(3), PX(0), PXH(11), PX(4), PXH(3), PX(8));
}

/*
 * Right edge through centres: the mirror image (6.5,0) (2.5,4) (6.5,8). The
 * vertical edge x = 6.5 is now a right edge: column 6 is never covered.
 * Other edges: i + j >= 6 and i >= j - 1; and i <= 5.
 */
static void test_picture_right_edge_tie(void)
{
    static const char *const rows[] = {
        "........", ".....#..", "....##..", "...###..",
        "...###..", "....##..", ".....#..", "........",
    };
    PICTURE("right edge tie", rows, PXH(13), PX(0), PXH(5), PX(4), PXH(13), PX(8));
}

/*
 * Top edge through centres: (0,1.5) (8,1.5) (4,5.5). y = 1.5 is horizontal
 * with the interior below: a top edge, so all of row 1 is covered. Others:
 * i + j <= 8 and i >= j - 1.
 */
static void test_picture_top_edge_tie(void)
{
    static const char *const rows[] = {
        "........", "########", ".######.", "..####..",
        "...##...", "........", "........", "........",
    };
    PICTURE("top edge tie", rows, PX(0), PXH(3), PX(8), PXH(3), PX(4), PXH(11));
}

/*
 * Bottom edge through centres: (0,5.5) (4,1.5) (8,5.5). y = 5.5 has the
 * interior above: a bottom edge, row 5 is not covered. Others: i + j >= 5,
 * i <= j + 2.
 */
static void test_picture_bottom_edge_tie(void)
{
    static const char *const rows[] = {
        "........", "........", "...##...", "..####..",
        ".######.", "........", "........", "........",
    };
    PICTURE("bottom edge tie", rows, PX(0), PXH(11), PX(4), PXH(3), PX(8), PXH(11));
}

/*
 * Vertices on pixel centres: (1.5,1.5) (5.5,1.5) (1.5,5.5). The vertex
 * (1.5,1.5) lies on the top edge and the left edge: covered. (5.5,1.5) and
 * (1.5,5.5) lie on the hypotenuse x + y = 7, a right edge: not covered, nor
 * is any centre with i + j = 6 on it.
 */
static void test_picture_vertices_on_centres(void)
{
    static const char *const rows[] = {
        "........", ".####...", ".###....", ".##.....",
        ".#......", "........", "........", "........",
    };
    PICTURE("vertices on centres", rows, PXH(3), PXH(3), PXH(11), PXH(3), PXH(3), PXH(11));
}

/*
 * The other half of the square of the previous case: (5.5,5.5) (1.5,5.5)
 * (5.5,1.5). Now the hypotenuse is a left edge (covered: i + j = 6), the
 * horizontal y = 5.5 a bottom edge and x = 5.5 a right edge (not covered).
 * Both halves together give the 4x4 square exactly once.
 */
static void test_picture_vertices_on_centres_other_half(void)
{
    static const char *const rows[] = {
        "........", "........", "....#...", "...##...",
        "..###...", "........", "........", "........",
    };
    PICTURE("other half", rows, PXH(11), PXH(11), PXH(3), PXH(11), PXH(11), PXH(3));
}

/*
 * Pointing left: (1.5,3.5) (5.5,1.5) (5.5,5.5). Both edges at the vertex
 * (1.5,3.5) are left edges, so that centre is covered; the vertical x = 5.5
 * is a right edge. Upper edge: i + 2j >= 7 (ties covered: (3,2)); lower
 * edge: i >= 2j - 5 (tie (3,4) covered).
 */
static void test_picture_vertex_between_left_edges(void)
{
    static const char *const rows[] = {
        "........", "........", "...##...", ".####...",
        "...##...", "........", "........", "........",
    };
    PICTURE("point left", rows, PXH(3), PXH(7), PXH(11), PXH(3), PXH(11), PXH(11));
}

/*
 * Pointing right: (5.5,3.5) (1.5,1.5) (1.5,5.5). Both edges at (5.5,3.5) are
 * right edges: not covered; nor (1.5,1.5) and (1.5,5.5), which lie on a right
 * edge too. Column 1 (x = 1.5, left edge) is covered in rows 2..4.
 */
static void test_picture_vertex_between_right_edges(void)
{
    static const char *const rows[] = {
        "........", "........", ".##.....", ".####...",
        ".##.....", "........", "........", "........",
    };
    PICTURE("point right", rows, PXH(11), PXH(7), PXH(3), PXH(3), PXH(3), PXH(11));
}

/*
 * Sub-pixel offsets of 1/16 px. A right triangle with legs of 20 px has its
 * hypotenuse outside the 8x8 target, so only the two legs decide: the
 * top-left corner at (xl, yt) covers columns with i + 0.5 >= xl and rows with
 * j + 0.5 >= yt; the bottom-right corner at (xr, yb) covers i + 0.5 < xr and
 * j + 0.5 < yb.
 */
static void test_picture_subpixel_offsets(void)
{
    static const char *const a[] = {
        "........", "..######", "..######", "..######",
        "..######", "..######", "..######", "..######",
    };
    static const char *const b[] = {
        "........", "........", ".#######", ".#######",
        ".#######", ".#######", ".#######", ".#######",
    };
    static const char *const c[] = {
        "........", ".#######", ".#######", ".#######",
        ".#######", ".#######", ".#######", ".#######",
    };
    static const char *const d[] = {
        "#####...", "#####...", "#####...", "#####...",
        "#####...", "........", "........", "........",
    };
    static const char *const e[] = {
        "######..", "######..", "######..", "######..",
        "######..", "######..", "........", "........",
    };
    /* xl = 1.5 + 1/16, yt = 1.5 - 1/16 */
    PICTURE("top-left corner +1/16,-1/16", a, S16(25), S16(23), S16(25 + 320), S16(23), S16(25),
            S16(23 + 320));
    /* xl = 1.5 - 1/16, yt = 1.5 + 1/16 */
    PICTURE("top-left corner -1/16,+1/16", b, S16(23), S16(25), S16(23 + 320), S16(25), S16(23),
            S16(25 + 320));
    /* exactly on the centres */
    PICTURE("top-left corner on centres", c, S16(24), S16(24), S16(24 + 320), S16(24), S16(24),
            S16(24 + 320));
    /* xr = yb = 5.5: right and bottom ties not covered */
    PICTURE("bottom-right corner on centres", d, S16(88), S16(88), S16(88 - 320), S16(88), S16(88),
            S16(88 - 320));
    /* xr = yb = 5.5 + 1/16 */
    PICTURE("bottom-right corner +1/16", e, S16(89), S16(89), S16(89 - 320), S16(89), S16(89),
            S16(89 - 320));
    /* xr = yb = 5.5 - 1/16 */
    PICTURE("bottom-right corner -1/16", d, S16(87), S16(87), S16(87 - 320), S16(87), S16(87),
            S16(87 - 320));
}

/*
 * A diagonal moved by 1/16 px: (1.5,1.5) (5.5,1.5) (1.5,5.5 + 1/16). In
 * sixteenths A = (24,24), B = (88,24), C = (24,89); the edge B -> C has
 * E(p) = -64 (py - 24) - 65 (px - 88), positive (inside) at the centres
 * (72,40), (56,56), (40,72), (24,88) that the unshifted hypotenuse passed
 * through, and 0 at B, a right-edge tie: not covered.
 */
static void test_picture_subpixel_diagonal(void)
{
    static const char *const rows[] = {
        "........", ".####...", ".####...", ".###....",
        ".##.....", ".#......", "........", "........",
    };
    PICTURE("diagonal +1/16", rows, S16(24), S16(24), S16(88), S16(24), S16(24), S16(89));
}

/*
 * Snapping ties: a coordinate exactly half-way between two 1/16 steps rounds
 * towards +infinity. x = 24.5/16 snaps to 25/16 (right of the centre 1.5 of
 * column 1: not covered); x = 23.5/16 snaps to 24/16 = 1.5 (a left-edge tie:
 * covered). The same in y with a top edge. Rounding half to even, or down,
 * would give the other picture in the first case.
 */
static void test_picture_snap_ties_positive(void)
{
    static const char *const cols2[] = {
        "..######", "..######", "..######", "..######",
        "..######", "..######", "..######", "..######",
    };
    static const char *const cols1[] = {
        ".#######", ".#######", ".#######", ".#######",
        ".#######", ".#######", ".#######", ".#######",
    };
    static const char *const rows2[] = {
        "........", "........", "########", "########",
        "########", "########", "########", "########",
    };
    static const char *const rows1[] = {
        "........", "########", "########", "########",
        "########", "########", "########", "########",
    };
    PICTURE("x tie 24.5/16", cols2, S32(49), PX(0), S32(49 + 640), PX(0), S32(49), PX(20));
    PICTURE("x tie 23.5/16", cols1, S32(47), PX(0), S32(47 + 640), PX(0), S32(47), PX(20));
    PICTURE("y tie 24.5/16", rows2, PX(0), S32(49), PX(20), S32(49), PX(0), S32(49 + 640));
    PICTURE("y tie 23.5/16", rows1, PX(0), S32(47), PX(20), S32(47), PX(0), S32(47 + 640));
}

/*
 * A negative tie: P = (-7.5, -8)/16 snaps to (-7, -8)/16 (towards +infinity;
 * rounding away from zero, half to even or down give -8). Triangle P,
 * Q = (40,40)/16, R = (40,-8)/16. With the correct snap the edge Q -> P is
 * E(p) = -47 (py - 40) + 48 (px - 40): at centre (24,24) (pixel (1,1)) it is
 * -16, outside; at (24,8) (pixel (1,0)) 736, inside. Column 0 is outside
 * (E < 0) and x = 40/16 = 2.5 is a right edge, so only pixel (1,0) is
 * covered. With P at (-8,-8)/16 the edge would pass through (24,24), a
 * left-edge tie, and cover (1,1) too.
 */
static void test_picture_snap_tie_negative(void)
{
    static const char *const rows[] = {
        ".#......", "........", "........", "........",
        "........", "........", "........", "........",
    };
    PICTURE("negative tie", rows, S32(-15), S16(-8), S16(40), S16(40), S16(40), S16(-8));
}

/*
 * Tiny triangles: one inside pixel (3,2) around its centre (56,40)/16; one
 * with no centre inside; one whose top-left vertex is exactly the centre of
 * pixel (2,2) (top and left edge: covered); its mirror image, whose vertex
 * (2.5,2.5) lies on a bottom and a right edge (not covered).
 */
static void test_picture_tiny(void)
{
    static const char *const one32[] = {"......", "......", "...#..", "......"};
    static const char *const none[] = {"......", "......", "......", "......"};
    static const char *const one22[] = {"......", "......", "..#...", "......"};
    PICTURE("tiny around a centre", one32, S16(54), S16(38), S16(60), S16(38), S16(56), S16(44));
    PICTURE("tiny between centres", none, S16(16), S16(16), S16(20), S16(16), S16(16), S16(20));
    PICTURE("tiny, top-left vertex on a centre", one22, S16(40), S16(40), S16(41), S16(40), S16(40),
            S16(41));
    PICTURE("tiny, bottom-right vertex on a centre", none, S16(40), S16(40), S16(39), S16(40),
            S16(40), S16(39));
}

/*
 * Zero area covers nothing: collinear vertices through centres, a repeated
 * vertex, all three equal, and a triangle that becomes collinear only after
 * snapping ((0,0.5) (8,0.5) (4, 0.5 + 1/64)).
 */
static void test_picture_zero_area(void)
{
    static const char *const none[] = {"........", "........", "........", "........",
                                       "........", "........", "........", "........"};
    PICTURE("collinear diagonal", none, PXH(1), PXH(1), PXH(7), PXH(7), PXH(15), PXH(15));
    PICTURE("collinear row", none, PX(0), PXH(5), PXH(7), PXH(5), PX(8), PXH(5));
    PICTURE("repeated vertex", none, PXH(3), PXH(3), PXH(13), PXH(5), PXH(3), PXH(3));
    PICTURE("single point", none, PXH(5), PXH(5), PXH(5), PXH(5), PXH(5), PXH(5));
    PICTURE("collinear after snapping", none, PX(0), PXH(1), PX(8), PXH(1), PX(4),
            PXH(1) + 1024);
}

/* --------------------------------------------------------- reference check */

/* The triangle rule and the independent polygon rule agree (a check of the
 * reference itself, no zline code involved). */
static void test_reference_self_consistent(void)
{
    uint32_t seed = 0x1234567u;
    unsigned n, mismatches = 0;
    for (n = 0; n < 3000; n++) {
        int64_t x2[3], y2[3];
        int32_t i, j;
        zt_tri t;
        int k;
        int span = (n % 3 == 0) ? 40 : (n % 3 == 1 ? 160 : 640);
        for (k = 0; k < 3; k++) {
            /* half-subpixel units on the snapped grid */
            x2[k] = 2 * (int64_t)zt_rand_range(&seed, -span, span);
            y2[k] = 2 * (int64_t)zt_rand_range(&seed, -span, span);
            if (n % 5 == 0)
                x2[k] = x2[k] / (2 * ZT_SUB) * (2 * ZT_SUB) + ZT_SUB; /* on centres */
        }
        zt_tri_init_snapped2(&t, x2, y2);
        for (j = -6; j < 6; j++)
            for (i = -6; i < 6; i++) {
                int a = zt_tri_covers(&t, i, j);
                int b = t.area != 0 ? zt_poly_covers(x2, y2, 3, i, j) : 0;
                if (a != b)
                    mismatches++;
            }
    }
    TEST_ASSERT_EQUAL_UINT(0, mismatches);
}

/* ------------------------------------------------------------ random tests */

/* One random vertex coordinate pair in sixteenths, by category. */
static void random_triangle(uint32_t *seed, unsigned cat, int32_t *x, int32_t *y)
{
    int k;
    switch (cat) {
    case 0: /* big, around the target */
        for (k = 0; k < 3; k++) {
            x[k] = zt_rand_range(seed, -32 * 16, 96 * 16);
            y[k] = zt_rand_range(seed, -32 * 16, 96 * 16);
        }
        break;
    case 1: { /* tiny: within 3 px */
        int32_t bx = zt_rand_range(seed, -2 * 16, 66 * 16), by = zt_rand_range(seed, -2 * 16, 66 * 16);
        int32_t r = zt_rand_range(seed, 1, 48);
        for (k = 0; k < 3; k++) {
            x[k] = bx + zt_rand_range(seed, -r, r);
            y[k] = by + zt_rand_range(seed, -r, r);
        }
        break;
    }
    case 2: { /* sliver: the third vertex within a few sixteenths of the
                 line through the other two */
        int32_t num, den;
        for (k = 0; k < 2; k++) {
            x[k] = zt_rand_range(seed, -16 * 16, 80 * 16);
            y[k] = zt_rand_range(seed, -16 * 16, 80 * 16);
        }
        den = zt_rand_range(seed, 2, 16);
        num = zt_rand_range(seed, -den, 2 * den);
        x[2] = x[0] + (x[1] - x[0]) * num / den + zt_rand_range(seed, -3, 3);
        y[2] = y[0] + (y[1] - y[0]) * num / den + zt_rand_range(seed, -3, 3);
        break;
    }
    case 3: /* partly or wholly off-screen */
        for (k = 0; k < 3; k++) {
            x[k] = zt_rand_range(seed, -96 * 16, 160 * 16);
            y[k] = zt_rand_range(seed, -96 * 16, 160 * 16);
        }
        break;
    case 4: { /* an axis-aligned edge, often through centres */
        int32_t c = zt_rand_range(seed, -4, 68) * 16 + (zt_rand(seed) & 1 ? 8 : zt_rand_range(seed, 0, 15));
        for (k = 0; k < 3; k++) {
            x[k] = zt_rand_range(seed, -8 * 16, 72 * 16);
            y[k] = zt_rand_range(seed, -8 * 16, 72 * 16);
        }
        if (zt_rand(seed) & 1) {
            y[0] = c;
            y[1] = c;
        } else {
            x[0] = c;
            x[1] = c;
        }
        break;
    }
    case 5: /* every vertex on a pixel centre or corner: many exact ties */
        for (k = 0; k < 3; k++) {
            x[k] = zt_rand_range(seed, -8 * 2, 72 * 2) * 8;
            y[k] = zt_rand_range(seed, -8 * 2, 72 * 2) * 8;
        }
        break;
    default: { /* medium, inside */
        int32_t bx = zt_rand_range(seed, 0, 64 * 16), by = zt_rand_range(seed, 0, 64 * 16);
        int32_t r = zt_rand_range(seed, 16, 16 * 16);
        for (k = 0; k < 3; k++) {
            x[k] = bx + zt_rand_range(seed, -r, r);
            y[k] = by + zt_rand_range(seed, -r, r);
        }
        break;
    }
    }
}

static void compare_with_reference(const zl_fixed v[3][3], unsigned n)
{
    zt_tri t;
    unsigned x, y;
    draw_and_read(v[0], v[1], v[2]);
    zt_tri_init(&t, v[0], v[1], v[2]);
    zt_tri_mask(&t, want, RW, RH);
    for (y = 0; y < RH; y++)
        for (x = 0; x < RW; x++)
            if (got[y * RW + x] != want[y * RW + x]) {
                snprintf(msg, sizeof msg,
                         "triangle %u: (%ld,%ld) (%ld,%ld) (%ld,%ld) raw Q16.16 = "
                         "(%ld/16,%ld/16) (%ld/16,%ld/16) (%ld/16,%ld/16) px: pixel (%u,%u) "
                         "expected %s, zl_draw_mesh %s",
                         n, (long)v[0][0], (long)v[0][1], (long)v[1][0], (long)v[1][1],
                         (long)v[2][0], (long)v[2][1], (long)zt_snap(v[0][0]),
                         (long)zt_snap(v[0][1]), (long)zt_snap(v[1][0]), (long)zt_snap(v[1][1]),
                         (long)zt_snap(v[2][0]), (long)zt_snap(v[2][1]), x, y,
                         want[y * RW + x] ? "covered" : "empty", got[y * RW + x] ? "covered" : "empty");
                TEST_FAIL_MESSAGE(msg);
            }
}

/* 5000 triangles with vertices on the 1/16 grid, seven categories. */
static void test_random_on_grid(void)
{
    uint32_t seed = 0x2545F491u;
    unsigned n;
    make_target(RW, RH);
    for (n = 0; n < 5000; n++) {
        int32_t x[3], y[3];
        zl_fixed v[3][3];
        int k;
        random_triangle(&seed, n % 7, x, y);
        for (k = 0; k < 3; k++) {
            v[k][0] = S16(x[k]);
            v[k][1] = S16(y[k]);
            v[k][2] = 0;
        }
        compare_with_reference((const zl_fixed(*)[3])v, n);
    }
}

/* 2000 triangles with arbitrary raw Q16.16 coordinates, a quarter of them
 * exactly half-way between two 1/16 steps (snapping ties, both signs). */
static void test_random_off_grid(void)
{
    uint32_t seed = 0x9E3779B9u;
    unsigned n;
    make_target(RW, RH);
    for (n = 0; n < 2000; n++) {
        int32_t x[3], y[3];
        zl_fixed v[3][3];
        int k;
        random_triangle(&seed, n % 7, x, y);
        for (k = 0; k < 3; k++) {
            int32_t fx = zt_rand_range(&seed, -2048, 2047), fy = zt_rand_range(&seed, -2048, 2047);
            if ((zt_rand(&seed) & 3) == 0)
                fx = (zt_rand(&seed) & 1) ? 2048 : -2048;
            if ((zt_rand(&seed) & 3) == 0)
                fy = (zt_rand(&seed) & 1) ? 2048 : -2048;
            v[k][0] = S16(x[k]) + fx;
            v[k][1] = S16(y[k]) + fy;
            v[k][2] = 0;
        }
        compare_with_reference((const zl_fixed(*)[3])v, n);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_reference_self_consistent);
    if (ZL_SUBPIXEL_BITS == 4) {
        /* the pictures are derived for 1/16 px snapping */
        RUN_TEST(test_picture_basic);
        RUN_TEST(test_picture_left_edge_tie);
        RUN_TEST(test_picture_right_edge_tie);
        RUN_TEST(test_picture_top_edge_tie);
        RUN_TEST(test_picture_bottom_edge_tie);
        RUN_TEST(test_picture_vertices_on_centres);
        RUN_TEST(test_picture_vertices_on_centres_other_half);
        RUN_TEST(test_picture_vertex_between_left_edges);
        RUN_TEST(test_picture_vertex_between_right_edges);
        RUN_TEST(test_picture_subpixel_offsets);
        RUN_TEST(test_picture_subpixel_diagonal);
        RUN_TEST(test_picture_snap_ties_positive);
        RUN_TEST(test_picture_snap_tie_negative);
        RUN_TEST(test_picture_tiny);
        RUN_TEST(test_picture_zero_area);
    }
    RUN_TEST(test_random_on_grid);
    RUN_TEST(test_random_off_grid);
    return UNITY_END();
}

/* SPDX-License-Identifier: MIT */
/*
 * Watertightness (RASTER CONTRACT, zline.h: "two triangles sharing an edge
 * never both cover a pixel, and a mesh without holes leaves none").
 *
 * Meshes without holes: triangle fans around a point, grids of quads split
 * in two (either diagonal), jittered grids, each also rotated by random
 * angles (integer rotation in the test) and moved by random sub-pixel
 * offsets, some partly off-screen, some with random triangles given in the
 * opposite winding. Each mesh is drawn with depth test off and a distinct id
 * colour per triangle, once in submission order and once in reverse order,
 * in one zl_draw_mesh call each, and small meshes also one triangle per
 * draw with a per-pixel coverage count. Checks:
 *   - no pixel is covered twice: the two orders agree on every pixel (a
 *     pixel covered by triangles a < b shows b forwards and a backwards),
 *     and the per-triangle count never exceeds 1;
 *   - no holes: the covered pixels are exactly those the outline polygon
 *     covers by the top-left rule (zt_poly_covers, which does not look at the
 *     triangles at all);
 *   - each pixel is covered by the very triangle the reference says.
 * Every generated mesh is checked to be a valid triangulation after
 * snapping (all triangles keep one orientation, non-zero area); the rare
 * random mesh that is not is regenerated.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_guard.h"
#include "zt_ref.h"

#define TW 96
#define TH 80
#define MAXV 1400
#define MAXT 2600
#define MAXO 800
#define PX(n) ((zl_fixed)((n) * 65536))
#define PXH(n) ((zl_fixed)((n) * 32768))

static zt_surface surf;
static zl_context ctx;

/* the mesh under test */
static zl_fixed pos[MAXV * 3];
static uint16_t idx[MAXT * 3];
static uint16_t ridx[MAXT * 3];       /* reverse submission order */
static uint8_t fcol[MAXT * 3], rfcol[MAXT * 3];
static uint16_t outline[MAXO];
static uint8_t flipped[MAXT];         /* given in the opposite winding on purpose */
static unsigned nv, nt, no;
static int32_t sx2[MAXV], sy2[MAXV]; /* snapped, half subpixels */

/* per pixel */
static uint16_t fwd[TW * TH], rev[TW * TH], refid[TW * TH];
static uint8_t refcount[TW * TH], count[TW * TH], inside[TW * TH];
static char msg[400];

static uint32_t seed = 0xC0FFEE11u;

void setUp(void)
{
    zt_guard_reset();
    TEST_ASSERT_EQUAL_INT(0, zt_surface_make(&surf, TW, TH, ZL_FORMAT_RGB888, 1, 1, 3, 4, 0));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &surf.target));
    ctx.state.depth_test = 0;
    ctx.state.cull = ZL_CULL_NONE;
    ctx.state.shading = ZL_SHADE_FLAT;
}

void tearDown(void)
{
}

/* ----------------------------------------------------------- mesh building */

static void mesh_reset(void)
{
    nv = nt = no = 0;
}

static uint16_t add_vertex(zl_fixed x, zl_fixed y)
{
    TEST_ASSERT_LESS_THAN(MAXV, nv);
    pos[nv * 3 + 0] = x;
    pos[nv * 3 + 1] = y;
    pos[nv * 3 + 2] = 0;
    return (uint16_t)nv++;
}

static void add_tri(uint16_t a, uint16_t b, uint16_t c)
{
    TEST_ASSERT_LESS_THAN(MAXT, nt);
    flipped[nt] = 0;
    idx[nt * 3 + 0] = a;
    idx[nt * 3 + 1] = b;
    idx[nt * 3 + 2] = c;
    nt++;
}

static void add_outline(uint16_t v)
{
    TEST_ASSERT_LESS_THAN(MAXO, no);
    outline[no++] = v;
}

/* Rotate every vertex about (cx, cy) by the direction (a, b) (an angle with
 * cos : sin = a : b), in 64-bit integers with rounding. */
static void rotate_mesh(zl_fixed cx, zl_fixed cy, int32_t a, int32_t b)
{
    int64_t len = (int64_t)zt_isqrt((uint64_t)((int64_t)a * a + (int64_t)b * b));
    unsigned k;
    for (k = 0; k < nv; k++) {
        int64_t x = (int64_t)pos[k * 3] - cx, y = (int64_t)pos[k * 3 + 1] - cy;
        int64_t rx = x * a - y * b, ry = x * b + y * a;
        pos[k * 3] = (zl_fixed)(cx + zt_floor_div(2 * rx + len, 2 * len));
        pos[k * 3 + 1] = (zl_fixed)(cy + zt_floor_div(2 * ry + len, 2 * len));
    }
}

static void translate_mesh(zl_fixed dx, zl_fixed dy)
{
    unsigned k;
    for (k = 0; k < nv; k++) {
        pos[k * 3] += dx;
        pos[k * 3 + 1] += dy;
    }
}

/* Random rotation and sub-pixel translation. */
static void random_motion(zl_fixed cx, zl_fixed cy)
{
    int32_t a = zt_rand_range(&seed, -1024, 1024), b = zt_rand_range(&seed, -1024, 1024);
    if (a == 0 && b == 0)
        a = 1;
    rotate_mesh(cx, cy, a, b);
    translate_mesh(zt_rand_range(&seed, -65536, 65536), zt_rand_range(&seed, -65536, 65536));
}

/* Give random triangles the opposite winding (same triangle, same coverage). */
static void random_flips(void)
{
    unsigned t;
    for (t = 0; t < nt; t++)
        if ((zt_rand(&seed) & 3) == 0) {
            uint16_t s = idx[t * 3 + 1];
            idx[t * 3 + 1] = idx[t * 3 + 2];
            idx[t * 3 + 2] = s;
            flipped[t] = 1;
        }
}

/*
 * Grid of nx x ny quads from (ox, oy), cell size (cw, ch), each vertex moved
 * by up to +-jitter raw units in x and y. diag: 0 '\', 1 '/', 2 random.
 * Triangles are clockwise on screen before any flips.
 */
static void build_grid(zl_fixed ox, zl_fixed oy, zl_fixed cw, zl_fixed ch, unsigned nx, unsigned ny,
                       int32_t jitter, int diag)
{
    unsigned i, j;
    mesh_reset();
    TEST_ASSERT_TRUE((nx + 1) * (ny + 1) <= MAXV && 2 * nx * ny <= MAXT);
    for (j = 0; j <= ny; j++)
        for (i = 0; i <= nx; i++) {
            zl_fixed jx = jitter ? zt_rand_range(&seed, -jitter, jitter) : 0;
            zl_fixed jy = jitter ? zt_rand_range(&seed, -jitter, jitter) : 0;
            add_vertex(ox + (zl_fixed)i * cw + jx, oy + (zl_fixed)j * ch + jy);
        }
    for (j = 0; j < ny; j++)
        for (i = 0; i < nx; i++) {
            uint16_t a = (uint16_t)(j * (nx + 1) + i), b = (uint16_t)(a + 1);
            uint16_t d = (uint16_t)(a + nx + 1), c = (uint16_t)(d + 1);
            int which = diag == 2 ? (int)(zt_rand(&seed) & 1) : diag;
            if (which == 0) {
                add_tri(a, b, c);
                add_tri(a, c, d);
            } else {
                add_tri(a, b, d);
                add_tri(b, c, d);
            }
        }
    for (i = 0; i < nx; i++)
        add_outline((uint16_t)i);
    for (j = 0; j < ny; j++)
        add_outline((uint16_t)(j * (nx + 1) + nx));
    for (i = nx; i > 0; i--)
        add_outline((uint16_t)(ny * (nx + 1) + i));
    for (j = ny; j > 0; j--)
        add_outline((uint16_t)(j * (nx + 1)));
}

/*
 * Fan of k triangles around (cx, cy): ring points walk clockwise (on screen)
 * round a square of half-side r, at perimeter steps of 8r/k each moved by up
 * to jitter_frac/1024 of a step, then pulled towards the centre by a random
 * factor of at least min_scale/1024 (radial moves keep the angular order).
 */
static void build_fan(zl_fixed cx, zl_fixed cy, zl_fixed r, unsigned k, int32_t jitter_frac,
                      int32_t min_scale)
{
    unsigned i;
    const int64_t R = r, per = 8 * R;
    uint16_t c;
    mesh_reset();
    TEST_ASSERT_TRUE(k >= 3 && k + 1 <= MAXV && k <= MAXT && k <= MAXO);
    c = add_vertex(cx, cy);
    for (i = 0; i < k; i++) {
        int64_t u = per * i / k, sxv, syv;
        int32_t scale = min_scale < 1024 ? zt_rand_range(&seed, min_scale, 1024) : 1024;
        if (jitter_frac)
            u += (per / k) * zt_rand_range(&seed, -jitter_frac, jitter_frac) / 1024;
        if (u < 0)
            u += per;
        if (u < 2 * R) {
            sxv = -R + u;
            syv = -R;
        } else if (u < 4 * R) {
            sxv = R;
            syv = -R + (u - 2 * R);
        } else if (u < 6 * R) {
            sxv = R - (u - 4 * R);
            syv = R;
        } else {
            sxv = -R;
            syv = R - (u - 6 * R);
        }
        add_vertex((zl_fixed)(cx + sxv * scale / 1024), (zl_fixed)(cy + syv * scale / 1024));
        add_outline((uint16_t)(c + 1 + i));
    }
    for (i = 0; i < k; i++)
        add_tri(c, (uint16_t)(c + 1 + i), (uint16_t)(c + 1 + (i + 1) % k));
}

/* After snapping: every triangle has non-zero area and the same orientation
 * (undoing the deliberate flips). */
static int mesh_valid(void)
{
    unsigned k, t;
    int orient0 = 0;
    for (k = 0; k < nv; k++) {
        sx2[k] = (int32_t)zt_snap2(pos[k * 3]);
        sy2[k] = (int32_t)zt_snap2(pos[k * 3 + 1]);
    }
    for (t = 0; t < nt; t++) {
        zt_tri tri;
        int o;
        zt_tri_init(&tri, &pos[idx[t * 3] * 3], &pos[idx[t * 3 + 1] * 3], &pos[idx[t * 3 + 2] * 3]);
        o = flipped[t] ? -tri.orient : tri.orient;
        if (o == 0)
            return 0;
        if (orient0 == 0)
            orient0 = o;
        else if (o != orient0)
            return 0;
    }
    return 1;
}

/* ------------------------------------------------------------------- check */

static void draw_ids(const uint16_t *indices, const uint8_t *colors, unsigned count_tris,
                     uint16_t *ids)
{
    zl_mesh mesh;
    unsigned x, y;
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = pos;
    mesh.indices = indices;
    mesh.face_colors = colors;
    mesh.vertex_count = (uint16_t)nv;
    mesh.triangle_count = (uint16_t)count_tris;
    zt_fill_px(&surf, 0);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, NULL));
    ZT_ASSERT_SURFACE_INTACT(&surf);
    if (ids == NULL)
        return;
    for (y = 0; y < TH; y++)
        for (x = 0; x < TW; x++) {
            uint32_t v = zt_get_px(&surf, x, y);
            if (v > nt) {
                snprintf(msg, sizeof msg, "pixel (%u,%u) has colour 0x%06lX, not a triangle id", x,
                         y, (unsigned long)v);
                TEST_FAIL_MESSAGE(msg);
            }
            ids[y * TW + x] = (uint16_t)v;
        }
}

static void describe_tri(char *out, size_t size, unsigned t)
{
    unsigned k;
    size_t len = (size_t)snprintf(out, size, "triangle %u (raw Q16.16):", t);
    for (k = 0; k < 3 && len < size; k++) {
        const zl_fixed *p = &pos[idx[t * 3 + k] * 3];
        len += (size_t)snprintf(out + len, size - len, " (%ld,%ld)", (long)p[0], (long)p[1]);
    }
}

static void check_mesh(const char *name, int per_triangle)
{
    unsigned t, x, y, k;
    static int64_t ox[MAXO], oy[MAXO];
    int64_t bx0, bx1, by0, by1;
    char tri_text[160];

    TEST_ASSERT_TRUE_MESSAGE(mesh_valid(), name);
    for (t = 0; t < nt; t++) {
        uint32_t id = t + 1;
        fcol[t * 3 + 0] = (uint8_t)(id >> 16);
        fcol[t * 3 + 1] = (uint8_t)(id >> 8);
        fcol[t * 3 + 2] = (uint8_t)id;
        /* reverse order: triangle nt-1-t of ridx is triangle t */
        memcpy(&ridx[(nt - 1 - t) * 3], &idx[t * 3], 3 * sizeof *idx);
        memcpy(&rfcol[(nt - 1 - t) * 3], &fcol[t * 3], 3);
    }

    /* reference: which triangle covers each pixel, by bounding boxes */
    memset(refcount, 0, sizeof refcount);
    memset(refid, 0, sizeof refid);
    for (t = 0; t < nt; t++) {
        zt_tri tri;
        int32_t i, j;
        zt_tri_init(&tri, &pos[idx[t * 3] * 3], &pos[idx[t * 3 + 1] * 3], &pos[idx[t * 3 + 2] * 3]);
        for (j = tri.py0 < 0 ? 0 : tri.py0; j <= tri.py1 && j < TH; j++)
            for (i = tri.px0 < 0 ? 0 : tri.px0; i <= tri.px1 && i < TW; i++)
                if (zt_tri_covers(&tri, i, j)) {
                    refcount[j * TW + i]++;
                    refid[j * TW + i] = (uint16_t)(t + 1);
                }
    }
    /* outline polygon (snapped), bounding box, coverage by the polygon rule */
    for (k = 0; k < no; k++) {
        ox[k] = sx2[outline[k]];
        oy[k] = sy2[outline[k]];
    }
    bx0 = bx1 = ox[0];
    by0 = by1 = oy[0];
    for (k = 1; k < no; k++) {
        bx0 = ox[k] < bx0 ? ox[k] : bx0;
        bx1 = ox[k] > bx1 ? ox[k] : bx1;
        by0 = oy[k] < by0 ? oy[k] : by0;
        by1 = oy[k] > by1 ? oy[k] : by1;
    }
    for (y = 0; y < TH; y++)
        for (x = 0; x < TW; x++) {
            int64_t cx = zt_centre2((int32_t)x), cy = zt_centre2((int32_t)y);
            int in = 0;
            if (cx >= bx0 && cx <= bx1 && cy >= by0 && cy <= by1)
                in = zt_poly_covers(ox, oy, no, (int32_t)x, (int32_t)y);
            inside[y * TW + x] = (uint8_t)in;
        }
    /* the reference itself must tile the outline exactly */
    for (y = 0; y < TH; y++)
        for (x = 0; x < TW; x++)
            if (refcount[y * TW + x] != inside[y * TW + x]) {
                snprintf(msg, sizeof msg,
                         "%s: REFERENCE covers pixel (%u,%u) %u times, outline says %u", name, x, y,
                         refcount[y * TW + x], inside[y * TW + x]);
                TEST_FAIL_MESSAGE(msg);
            }

    draw_ids(idx, fcol, nt, fwd);
    draw_ids(ridx, rfcol, nt, rev);
    for (y = 0; y < TH; y++)
        for (x = 0; x < TW; x++) {
            unsigned p = y * TW + x;
            if (fwd[p] != rev[p]) {
                describe_tri(tri_text, sizeof tri_text, (unsigned)(fwd[p] ? fwd[p] - 1 : rev[p] - 1));
                snprintf(msg, sizeof msg,
                         "%s: pixel (%u,%u) covered twice or order-dependent: last writer %u "
                         "forwards, %u backwards (ids are triangle+1); %s",
                         name, x, y, fwd[p], rev[p], tri_text);
                TEST_FAIL_MESSAGE(msg);
            }
            if ((fwd[p] != 0) != (inside[p] != 0)) {
                snprintf(msg, sizeof msg, "%s: pixel (%u,%u) %s", name, x, y,
                         inside[p] ? "is a HOLE (inside the outline, not covered)"
                                   : "is covered outside the outline");
                TEST_FAIL_MESSAGE(msg);
            }
            if (fwd[p] != refid[p]) {
                describe_tri(tri_text, sizeof tri_text, (unsigned)(fwd[p] - 1));
                snprintf(msg, sizeof msg,
                         "%s: pixel (%u,%u) covered by triangle %u, the reference says %u; %s",
                         name, x, y, fwd[p] - 1u, refid[p] - 1u, tri_text);
                TEST_FAIL_MESSAGE(msg);
            }
        }

    if (per_triangle) {
        /* one triangle per draw, counting coverage per pixel */
        memset(count, 0, sizeof count);
        zt_fill_px(&surf, 0);
        for (t = 0; t < nt; t++) {
            zl_mesh mesh;
            memset(&mesh, 0, sizeof mesh);
            mesh.positions = pos;
            mesh.indices = &idx[t * 3];
            mesh.face_colors = &fcol[t * 3];
            mesh.vertex_count = (uint16_t)nv;
            mesh.triangle_count = 1;
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, NULL));
            ZT_ASSERT_SURFACE_INTACT(&surf);
            for (y = 0; y < TH; y++) {
                /* RGB888 bytes directly: this loop runs once per triangle */
                uint8_t *row = surf.color + (size_t)y * (size_t)surf.target.color_stride;
                for (x = 0; x < TW; x++, row += 3)
                    if ((row[0] | row[1] | row[2]) != 0) {
                        count[y * TW + x]++;
                        row[0] = row[1] = row[2] = 0;
                    }
            }
        }
        for (y = 0; y < TH; y++)
            for (x = 0; x < TW; x++)
                if (count[y * TW + x] != inside[y * TW + x]) {
                    snprintf(msg, sizeof msg,
                             "%s: one triangle per draw, pixel (%u,%u) covered %u times, outline says %u",
                             name, x, y, count[y * TW + x], inside[y * TW + x]);
                    TEST_FAIL_MESSAGE(msg);
                }
    }
}

/* ------------------------------------------------------------------- tests */

/* Fans whose centre and ring points sit on pixel centres (and on pixel
 * corners): spokes run horizontally, vertically and diagonally through
 * centres, so nearly every shared edge has exact ties. */
static void test_fan_on_centres(void)
{
    static const unsigned spokes[] = {4, 8, 16, 32, 64};
    unsigned s;
    for (s = 0; s < sizeof spokes / sizeof spokes[0]; s++) {
        build_fan(PXH(81), PXH(79), PX(20), spokes[s], 0, 1024);
        check_mesh("fan on centres", 1);
        build_fan(PX(40), PX(40), PX(20), spokes[s], 0, 1024);
        check_mesh("fan on corners", 1);
        /* partly off-screen */
        build_fan(PXH(5), PXH(151), PX(30), spokes[s], 0, 1024);
        check_mesh("fan off-screen", 1);
    }
}

/* Random fans: 4..300 spokes (very thin triangles), jittered, star-shaped
 * rings, random rotations and sub-pixel moves. */
static void test_fan_random(void)
{
    unsigned n, made = 0, tries = 0;
    for (n = 0; made < 60 && tries < 600; n++, tries++) {
        zl_fixed cx = zt_rand_range(&seed, PX(-10), PX(TW + 10));
        zl_fixed cy = zt_rand_range(&seed, PX(-10), PX(TH + 10));
        zl_fixed r = zt_rand_range(&seed, PX(2), PX(70));
        unsigned k = (unsigned)zt_rand_range(&seed, 4, (n & 1) ? 24 : 300);
        build_fan(cx, cy, r, k, 256, (n & 2) ? 460 : 1024);
        if (n % 3 != 0)
            random_motion(cx, cy);
        if (!mesh_valid())
            continue;
        random_flips();
        check_mesh("random fan", nt <= 120);
        made++;
    }
    TEST_ASSERT_EQUAL_UINT(60, made);
}

/* Grids with vertices on pixel centres, on pixel corners and on 1/16 steps,
 * both diagonals, partly off-screen, and one covering the whole target. */
static void test_grid_aligned(void)
{
    build_grid(PXH(1), PXH(1), PX(4), PX(4), 20, 16, 0, 0);
    check_mesh("grid on centres, \\", 1);
    build_grid(PXH(1), PXH(1), PX(4), PX(4), 20, 16, 0, 1);
    check_mesh("grid on centres, /", 1);
    build_grid(PX(0), PX(0), PX(3), PX(2), 32, 40, 0, 2);
    check_mesh("grid on corners, whole target", 0);
    build_grid(PX(-8), PX(-6), PX(7), PX(5), 17, 19, 0, 2);
    check_mesh("grid beyond the target", 0);
    build_grid(PXH(-7), PXH(-9), PX(1), PX(1), 40, 30, 0, 2);
    check_mesh("1 px grid on centres", 0);
    build_grid(4096 * 3, 4096 * 5, 4096 * 7, 4096 * 9, 30, 30, 0, 2);
    check_mesh("grid on 1/16 steps", 0);
    build_grid(PX(20), PX(10), PXH(1), PXH(1), 40, 30, 0, 2);
    check_mesh("half-pixel grid", 0);
}

/* Random grids: random origin (sub-pixel), cell size 0.4 .. 12 px, random
 * diagonals and windings, rotated by random angles. */
static void test_grid_random(void)
{
    unsigned n, made = 0, tries = 0;
    for (n = 0; made < 50 && tries < 500; n++, tries++) {
        zl_fixed cw = zt_rand_range(&seed, PX(1) * 2 / 5, PX(12));
        zl_fixed ch = (n & 1) ? cw : zt_rand_range(&seed, PX(1) * 2 / 5, PX(12));
        unsigned nx = (unsigned)zt_rand_range(&seed, 1, 36), ny = (unsigned)zt_rand_range(&seed, 1, 36);
        zl_fixed ox = zt_rand_range(&seed, PX(-20), PX(TW - 10));
        zl_fixed oy = zt_rand_range(&seed, PX(-20), PX(TH - 10));
        build_grid(ox, oy, cw, ch, nx, ny, 0, 2);
        if (n % 4 != 0)
            random_motion(ox + cw * (zl_fixed)nx / 2, oy + ch * (zl_fixed)ny / 2);
        if (!mesh_valid())
            continue;
        random_flips();
        check_mesh("random grid", nt <= 120);
        made++;
    }
    TEST_ASSERT_EQUAL_UINT(50, made);
}

/* Random point sets triangulated: grids with every point (boundary too)
 * jittered by up to 30 % of a cell, random diagonals, rotated. */
static void test_jittered_random(void)
{
    unsigned n, made = 0, tries = 0;
    for (n = 0; made < 50 && tries < 800; n++, tries++) {
        zl_fixed cell = zt_rand_range(&seed, PX(1), PX(10));
        unsigned nx = (unsigned)zt_rand_range(&seed, 1, 30), ny = (unsigned)zt_rand_range(&seed, 1, 30);
        zl_fixed ox = zt_rand_range(&seed, PX(-15), PX(TW - 15));
        zl_fixed oy = zt_rand_range(&seed, PX(-15), PX(TH - 15));
        build_grid(ox, oy, cell, cell, nx, ny, cell * 3 / 10, 2);
        if (n % 3 != 0)
            random_motion(ox + cell * (zl_fixed)nx / 2, oy + cell * (zl_fixed)ny / 2);
        if (!mesh_valid())
            continue;
        random_flips();
        check_mesh("jittered grid", nt <= 120);
        made++;
    }
    TEST_ASSERT_EQUAL_UINT(50, made);
}

/*
 * Huge meshes: fans whose spokes reach 1000 .. 22000 px from a centre in
 * the target, and coarse jittered grids 8000 .. 30000 px across around it,
 * rotated: long shared edges cross the viewport at arbitrary slopes (still
 * far inside the guard band, so nothing is clipped).
 */
static void test_huge_meshes(void)
{
    unsigned n, made = 0, tries = 0;
    for (n = 0; made < 40 && tries < 400; n++, tries++) {
        zl_fixed cx = zt_rand_range(&seed, PX(0), PX(TW));
        zl_fixed cy = zt_rand_range(&seed, PX(0), PX(TH));
        if (n & 1) {
            build_fan(cx, cy, PX(zt_rand_range(&seed, 1000, 22000)),
                      (unsigned)zt_rand_range(&seed, 4, 200), 256, 600);
        } else {
            int32_t size = zt_rand_range(&seed, 8000, 30000);
            unsigned nx = (unsigned)zt_rand_range(&seed, 1, 5), ny = (unsigned)zt_rand_range(&seed, 1, 5);
            zl_fixed cw = PX(size / (int32_t)nx), ch = PX(size / (int32_t)ny);
            build_grid(cx - cw * (zl_fixed)nx / 2, cy - ch * (zl_fixed)ny / 2, cw, ch, nx, ny,
                       cw / 4 < ch / 4 ? cw / 4 : ch / 4, 2);
        }
        random_motion(cx, cy);
        if (!mesh_valid())
            continue;
        random_flips();
        check_mesh("huge mesh", 1);
        made++;
    }
    TEST_ASSERT_EQUAL_UINT(40, made);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_fan_on_centres);
    RUN_TEST(test_fan_random);
    RUN_TEST(test_grid_aligned);
    RUN_TEST(test_grid_random);
    RUN_TEST(test_jittered_random);
    RUN_TEST(test_huge_meshes);
    return UNITY_END();
}

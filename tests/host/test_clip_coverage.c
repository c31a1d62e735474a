/* SPDX-License-Identifier: MIT */
/*
 * Coverage of clipped triangles (zline.h, Clipping: "Clipping decides
 * coverage only"): it must not change when the attributes of clipped
 * triangles change, and a closed mesh cut by the near or far plane stays
 * watertight.
 *
 * 1. Watertight, against an independent reference. A closed box, each face
 *    a grid of jittered triangles (so that many shared edges cross the clip
 *    planes), is drawn twice with additive blending of colour 1 and no depth
 *    test: the front faces (back faces culled) into red, the back faces into
 *    green, so each pixel counts its front and back fragments; and each
 *    triangle alone, unblended (blending takes the textured triangles' clip
 *    path, this the plain one), its pixels counted here. The
 *    reference, in long double and without the library: the part of the
 *    pixel centre's line of sight between the near and the far plane (two
 *    3x3 solves in model space with the matrix's own Q16.16 entries) is a
 *    segment; each triangle it crosses (Moller-Trumbore) counts as a front
 *    fragment when the segment enters the box through it, a back fragment
 *    when it leaves. A pixel is checked when the counts are the same at its
 *    centre and 0.3 pixel around it (clip edges and the box's outline move
 *    by a snapped 1/16 pixel; shared edges inside the mesh are not such
 *    places, a crack or a double fragment there is caught). Boxes cut by the
 *    near plane, the far plane, both, with the eye inside the box (triangles
 *    across the eye plane), and in pixel space (z crossing 0 and 1).
 * 2. Pinned: the coverage of every triangle of a set of clipped scenes,
 *    drawn alone (flat, Gouraud, perspective Gouraud, affine and
 *    perspective textures; frame mode, scanline and band mode), hashed into
 *    one digest per scene, recorded from the library before clipped
 *    triangles took their texture planes from the original triangle: any
 *    change of coverage changes it.
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

#define W 64
#define H 48
#define MAXV 1200
#define MAXT 1200

static uint8_t color_buf[W * H * 3];
static uint64_t work[600000 / 8];

static uint64_t rng;

static uint32_t rnd32(void)
{
    return zt_rand64(&rng);
}

static int32_t rnd_range(int32_t lo, int32_t hi)
{
    return zt_rand64_range(&rng, lo, hi);
}

/* ------------------------------------------------------------ meshes */

typedef struct {
    zl_fixed pos[MAXV * 3];
    uint16_t idx[MAXT * 3];
    uint8_t rgb[MAXV * 3];
    zl_fixed uv[MAXV * 2];
    unsigned nv, nt;
} mesh_buf;

static mesh_buf mb;

static void mesh_of(const mesh_buf *b, zl_mesh *m)
{
    memset(m, 0, sizeof *m);
    m->positions = b->pos;
    m->indices = b->idx;
    m->vertex_colors = b->rgb;
    m->vertex_count = (uint16_t)b->nv;
    m->triangle_count = (uint16_t)b->nt;
}

static uint16_t add_vertex(mesh_buf *b, const long double p[3])
{
    unsigned k;
    for (k = 0; k < 3; k++) {
        b->pos[b->nv * 3 + k] = (zl_fixed)llroundl(p[k] * 65536.0L);
        b->rgb[b->nv * 3 + k] = (uint8_t)rnd_range(16, 255);
    }
    b->uv[b->nv * 2] = rnd_range(-3 * 65536, 3 * 65536);
    b->uv[b->nv * 2 + 1] = rnd_range(-3 * 65536, 3 * 65536);
    return (uint16_t)b->nv++;
}

static void add_tri(mesh_buf *b, uint16_t i0, uint16_t i1, uint16_t i2)
{
    b->idx[b->nt * 3] = i0;
    b->idx[b->nt * 3 + 1] = i1;
    b->idx[b->nt * 3 + 2] = i2;
    b->nt++;
}

/* A box centred at c with half sizes h, turned by angle a about the y axis
 * and b about the x axis, then its depth scaled by zs about c; each face a g x g grid of quads whose inner
 * points are jittered in the face's plane, both diagonals used. Faces wind
 * counter-clockwise seen from outside. Points on a face's border are
 * computed from the same grid numbers on both faces: the same positions. */
static void make_box(mesh_buf *m, const long double c[3], const long double h[3], long double a, long double b,
                     long double zs, int g)
{
    uint16_t grid[9][9];
    int f, i, j;
    m->nv = m->nt = 0;
    for (f = 0; f < 6; f++) {
        /* the fixed axis and its side; the in-plane axes u, v such that u x v is outward */
        int ax = f / 2, s = f % 2 ? -1 : 1, u = (ax + 1) % 3, v = (ax + 2) % 3;
        if (s < 0) { /* swapped: u x v along -ax */
            int t = u;
            u = v;
            v = t;
        }
        for (j = 0; j <= g; j++) {
            for (i = 0; i <= g; i++) {
                long double q[3], r[3], jit = (i > 0 && i < g && j > 0 && j < g) ? 0.35L : 0;
                long double fu = (long double)i / g + jit * ((long double)rnd_range(-1000, 1000) / 1000) / g;
                long double fv = (long double)j / g + jit * ((long double)rnd_range(-1000, 1000) / 1000) / g;
                q[ax] = s * h[ax];
                q[u] = (2 * fu - 1) * h[u];
                q[v] = (2 * fv - 1) * h[v];
                /* turn: about y by a, then about x by b */
                r[0] = q[0] * cosl(a) + q[2] * sinl(a);
                r[2] = -q[0] * sinl(a) + q[2] * cosl(a);
                r[1] = q[1] * cosl(b) - r[2] * sinl(b);
                r[2] = (q[1] * sinl(b) + r[2] * cosl(b)) * zs;
                r[0] += c[0];
                r[1] += c[1];
                r[2] += c[2];
                grid[j][i] = add_vertex(m, r);
            }
        }
        for (j = 0; j < g; j++) {
            for (i = 0; i < g; i++) {
                uint16_t p00 = grid[j][i], p10 = grid[j][i + 1], p01 = grid[j + 1][i], p11 = grid[j + 1][i + 1];
                if ((i + j) & 1) {
                    add_tri(m, p00, p10, p11);
                    add_tri(m, p00, p11, p01);
                } else {
                    add_tri(m, p00, p10, p01);
                    add_tri(m, p10, p11, p01);
                }
            }
        }
    }
}

/* ------------------------------------------------------- the reference */

/* Clip-space rows of the projection, in model units (a pixel-space mesh:
 * x, y, z, 1 with the window position as its "device" position). */
typedef struct {
    long double m[4][4];
    int pixel_space;
} proj_ref;

static void proj_of(const zl_mat4 *mvp, proj_ref *p)
{
    int r, c;
    memset(p, 0, sizeof *p);
    p->pixel_space = mvp == NULL;
    for (r = 0; r < 4; r++)
        for (c = 0; c < 4; c++)
            p->m[r][c] = mvp != NULL ? (long double)mvp->m[r * 4 + c] / 65536.0L : (r == c ? 1.0L : 0.0L);
}

/* The point of the line of sight through window position (X, Y) on the
 * plane row . (x, y, z, 1) = 0. */
static int sight_point(const proj_ref *p, long double X, long double Y, const long double row[4], long double out[3])
{
    long double a[3][3], r[3], xn = p->pixel_space ? X : 2 * X / W - 1, yn = p->pixel_space ? Y : 1 - 2 * Y / H;
    int k;
    for (k = 0; k < 3; k++) {
        a[0][k] = p->m[0][k] - xn * p->m[3][k];
        a[1][k] = p->m[1][k] - yn * p->m[3][k];
        a[2][k] = row[k];
    }
    r[0] = -(p->m[0][3] - xn * p->m[3][3]);
    r[1] = -(p->m[1][3] - yn * p->m[3][3]);
    r[2] = -row[3];
    return zt_solve3(a, r, out);
}

static void sub3(const long double *a, const long double *b, long double *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

static void cross3(const long double *a, const long double *b, long double *r)
{
    r[0] = a[1] * b[2] - a[2] * b[1];
    r[1] = a[2] * b[0] - a[0] * b[2];
    r[2] = a[0] * b[1] - a[1] * b[0];
}

static long double dot3(const long double *a, const long double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The visible segment of the line of sight through (X, Y): from its point
 * on the near plane (z_clip = 0) to its point on the far plane
 * (z_clip = w_clip). */
static int segment_of(const proj_ref *p, long double X, long double Y, long double pn[3], long double d[3])
{
    long double nrow[4], frow[4], pf[3];
    unsigned k;
    for (k = 0; k < 4; k++) {
        nrow[k] = p->m[2][k];
        frow[k] = p->m[3][k] - p->m[2][k];
    }
    if (!sight_point(p, X, Y, nrow, pn) || !sight_point(p, X, Y, frow, pf))
        return 0;
    sub3(pf, pn, d);
    return 1;
}

/* The triangles in long double model units, made once per mesh. */
typedef struct {
    long double v0[3], e1[3], e2[3], n[3]; /* n = e1 x e2: outward */
} ref_tri;

static ref_tri ref_tris[MAXT];

static void ref_tris_of(const mesh_buf *m)
{
    unsigned t, k, c;
    for (t = 0; t < m->nt; t++) {
        long double q[3][3];
        for (k = 0; k < 3; k++)
            for (c = 0; c < 3; c++)
                q[k][c] = (long double)m->pos[m->idx[t * 3 + k] * 3 + c] / 65536.0L;
        for (c = 0; c < 3; c++)
            ref_tris[t].v0[c] = q[0][c];
        sub3(q[1], q[0], ref_tris[t].e1);
        sub3(q[2], q[0], ref_tris[t].e2);
        cross3(ref_tris[t].e1, ref_tris[t].e2, ref_tris[t].n);
    }
}

/* Where the line pn + s d meets the plane of triangle t: s and the
 * barycentrics u, v (Moller-Trumbore); the sign of the crossing (front:
 * the segment enters through the outward face); 0 when parallel. */
static int hit_of(unsigned t, const long double pn[3], const long double d[3], long double *s, long double *u,
                  long double *v, int *front)
{
    const ref_tri *r = &ref_tris[t];
    long double pv[3], tv[3], qv[3], det;
    cross3(d, r->e2, pv);
    det = dot3(r->e1, pv);
    if (det == 0)
        return 0;
    sub3(pn, r->v0, tv);
    *u = dot3(tv, pv) / det;
    cross3(tv, r->e1, qv);
    *v = dot3(d, qv) / det;
    *s = dot3(r->e2, qv) / det;
    *front = dot3(r->n, d) < 0;
    return 1;
}

static int side_of(long double s)
{
    return s < 0 ? -1 : (s > 1 ? 1 : 0);
}

/* Front and back crossings of the visible segment through pixel (i, j)'s
 * centre; 0 when the pixel is too close to a place where clipping or the
 * snapped outline may move coverage: the counts differ 0.3 pixel away, or
 * a triangle met at the centre has its near or far crossing within 0.3
 * pixel (a steep sliver can be far thinner than the 5 samples' spacing). */
static int ref_pixel(const mesh_buf *m, const proj_ref *p, int i, int j, int *front, int *back)
{
    static const long double off[5][2] = {{0, 0}, {0.3L, 0}, {-0.3L, 0}, {0, 0.3L}, {0, -0.3L}};
    long double pn[5][3], d[5][3];
    int fk[5], bk[5], k;
    unsigned t;
    for (k = 0; k < 5; k++) {
        fk[k] = bk[k] = 0;
        if (!segment_of(p, i + 0.5L + off[k][0], j + 0.5L + off[k][1], pn[k], d[k]))
            return 0;
    }
    for (t = 0; t < m->nt; t++) {
        int centre_in = 0, side = 0;
        for (k = 0; k < 5; k++) {
            long double s, u, v;
            int f;
            if (!hit_of(t, pn[k], d[k], &s, &u, &v, &f))
                continue;
            if (u >= 0 && v >= 0 && u + v <= 1) {
                if (side_of(s) == 0) {
                    fk[k] += f;
                    bk[k] += !f;
                }
                if (k == 0) {
                    centre_in = 1;
                    side = side_of(s);
                }
            }
            if (k > 0 && centre_in && side_of(s) != side)
                return 0;
        }
    }
    for (k = 1; k < 5; k++)
        if (fk[k] != fk[0] || bk[k] != bk[0])
            return 0;
    *front = fk[0];
    *back = bk[0];
    return 1;
}

/* -------------------------------------------------------------- drawing */

static void target_of(zl_target *tg)
{
    zt_target_packed(tg, color_buf, NULL, W, H, ZL_FORMAT_RGB888);
}

/* Front (red) and back (green) fragment counts of a mesh. */
static void draw_counts(const zl_mesh *mesh, const zl_mat4 *mvp)
{
    zl_context ctx;
    zl_target tg;
    zl_rgb black = {0, 0, 0};
    int pass;
    target_of(&tg);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 0xFFFF));
    ctx.state.depth_test = 0;
    ctx.state.depth_write = 0;
    ctx.state.cull = ZL_CULL_BACK;
    ctx.style.blend = ZL_BLEND_ADD;
    ctx.style.alpha = 255;
    for (pass = 0; pass < 2; pass++) {
        ctx.state.cull = pass == 0 ? ZL_CULL_BACK : ZL_CULL_FRONT;
        ctx.state.color.r = pass == 0 ? 1 : 0;
        ctx.state.color.g = pass == 0 ? 0 : 1;
        ctx.state.color.b = 0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, mesh, mvp));
    }
}

/* The same counts from each triangle drawn alone, unblended (the path of
 * untextured triangles), added up here. */
static uint8_t count_front[W * H], count_back[W * H];

static void draw_counts_each(const zl_mesh *mesh, const zl_mat4 *mvp)
{
    zl_context ctx;
    zl_target tg;
    zl_rgb black = {0, 0, 0};
    zl_mesh one = *mesh;
    unsigned t, k;
    int pass;
    memset(count_front, 0, sizeof count_front);
    memset(count_back, 0, sizeof count_back);
    target_of(&tg);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    ctx.state.depth_test = 0;
    ctx.state.depth_write = 0;
    ctx.state.color.r = ctx.state.color.g = ctx.state.color.b = 255;
    one.triangle_count = 1;
    for (t = 0; t < mesh->triangle_count; t++) {
        one.indices = &mesh->indices[t * 3];
        for (pass = 0; pass < 2; pass++) {
            uint8_t *count = pass == 0 ? count_front : count_back;
            ctx.state.cull = pass == 0 ? ZL_CULL_BACK : ZL_CULL_FRONT;
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 0xFFFF));
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &one, mvp));
            for (k = 0; k < W * H; k++)
                count[k] = (uint8_t)(count[k] + (color_buf[k * 3] != 0));
        }
    }
}

typedef struct {
    unsigned checked, skipped, front, back;
} wt_stats;

static void check_watertight(const mesh_buf *m, const zl_mat4 *mvp, wt_stats *st)
{
    zl_mesh mesh;
    proj_ref p;
    int i, j;
    char msg[160];
    mesh_of(m, &mesh);
    mesh.vertex_colors = NULL;
    proj_of(mvp, &p);
    ref_tris_of(m);
    draw_counts_each(&mesh, mvp);
    draw_counts(&mesh, mvp);
    for (j = 0; j < H; j++) {
        for (i = 0; i < W; i++) {
            const uint8_t *c = &color_buf[(j * W + i) * 3];
            int f0, b0;
            if (!ref_pixel(m, &p, i, j, &f0, &b0)) {
                st->skipped++;
                continue;
            }
            snprintf(msg, sizeof msg, "pixel (%d, %d): %u front, %u back fragments blended, %u, %u drawn alone; the reference %d, %d",
                     i, j, c[0], c[1], count_front[j * W + i], count_back[j * W + i], f0, b0);
            TEST_ASSERT_TRUE_MESSAGE(c[0] == f0 && c[1] == b0 && count_front[j * W + i] == f0 && count_back[j * W + i] == b0,
                                     msg);
            st->checked++;
            st->front += (unsigned)f0;
            st->back += (unsigned)b0;
        }
    }
}

static void perspective(zl_mat4 *proj, zl_fixed n, zl_fixed f)
{
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(proj, ZL_ANGLE_TURN / 6,
                                                     (zl_fixed)(((int64_t)W * 65536 + H / 2) / H), n, f));
}

static void box_case(const char *name, const long double c[3], const long double h[3], long double zs,
                     const zl_mat4 *mvp, int turns, unsigned min_front)
{
    wt_stats st;
    int r;
    memset(&st, 0, sizeof st);
    for (r = 0; r < turns; r++) {
        long double a = 0.3L + 0.7L * r, b = 0.2L + 0.45L * r;
        make_box(&mb, c, h, a, b, zs, 4 + r);
        check_watertight(&mb, mvp, &st);
    }
    printf("%s: %u pixels checked (%u front, %u back fragments), %u skipped at clip edges and outlines\n", name,
           st.checked, st.front, st.back, st.skipped);
    TEST_ASSERT_TRUE(st.checked > (unsigned)turns * W * H / 2 && st.front >= min_front && st.back > 200);
}

/* The near plane at 1 cuts through a box from z = -0.2 to -3. */
static void test_watertight_near(void)
{
    static const long double c[3] = {0.1L, -0.05L, -1.6L}, h[3] = {0.9L, 0.7L, 1.4L};
    zl_mat4 proj;
    rng = 0x1234567887654321ull;
    perspective(&proj, 65536, 65536 * 40);
    box_case("near", c, h, 1, &proj, 4, 200);
}

static void test_watertight_far(void)
{
    static const long double c[3] = {0.2L, 0.1L, -5.0L}, h[3] = {2.0L, 1.5L, 2.0L};
    zl_mat4 proj;
    rng = 0x2345678987654321ull;
    perspective(&proj, 65536 / 2, 65536 * 5);
    box_case("far", c, h, 1, &proj, 4, 200);
}

static void test_watertight_both(void)
{
    static const long double c[3] = {0.0L, 0.05L, -3.0L}, h[3] = {1.2L, 0.9L, 3.0L};
    zl_mat4 proj;
    rng = 0x3456789987654321ull;
    perspective(&proj, 65536, 65536 * 4);
    box_case("near and far", c, h, 1, &proj, 4, 200);
}

/* The eye inside the box: triangles across the eye plane everywhere. */
static void test_watertight_eye(void)
{
    static const long double c[3] = {0.3L, -0.2L, -0.5L}, h[3] = {2.0L, 1.6L, 2.5L};
    zl_mat4 proj;
    rng = 0x4567899987654321ull;
    perspective(&proj, 65536 / 4, 65536 * 3);
    box_case("eye inside", c, h, 1, &proj, 4, 0);
}

/* Pixel space: a box 40 pixels wide whose depth runs about -0.7 .. 1.7. */
static void test_watertight_pixel_space(void)
{
    static const long double c[3] = {31.0L, 23.0L, 0.5L}, h[3] = {20.0L, 17.0L, 20.0L};
    rng = 0x5678999987654321ull;
    box_case("pixel space", c, h, 0.04L, NULL, 4, 200);
}

/* ------------------------------------------------------- pinned coverage */

static uint16_t texels[16 * 16];
static zl_texture texture;

static void make_texture(void)
{
    unsigned k;
    for (k = 0; k < 16 * 16; k++)
        texels[k] = (uint16_t)(0x0841u | (rnd32() & 0xF7BEu)); /* every channel non-zero */
    memset(&texture, 0, sizeof texture);
    texture.texels = texels;
    texture.width = 16;
    texture.height = 16;
    texture.stride = 16;
    texture.wrap_s = ZL_WRAP_REPEAT;
    texture.wrap_t = ZL_WRAP_REPEAT;
}

enum { STYLE_FLAT, STYLE_GOURAUD, STYLE_PERSP_GOURAUD, STYLE_AFFINE, STYLE_PERSP, STYLE_COUNT };

static void style_of(int k, const mesh_buf *m, zl_state *st, zl_style *sty)
{
    zl_state_default(st);
    zl_style_default(sty);
    st->depth_func = ZL_ALWAYS;
    st->color.r = 200;
    st->color.g = 100;
    st->color.b = 50;
    st->shading = k == STYLE_GOURAUD || k == STYLE_PERSP_GOURAUD ? ZL_SHADE_GOURAUD : ZL_SHADE_FLAT;
    sty->persp_gouraud = k == STYLE_PERSP_GOURAUD;
    if (k == STYLE_AFFINE || k == STYLE_PERSP) {
        sty->texture = &texture;
        sty->texcoords = m->uv;
        sty->tex_mapping = k == STYLE_PERSP ? ZL_TEX_PERSPECTIVE : ZL_TEX_AFFINE;
    }
}

static uint64_t fnv(uint64_t h, uint8_t byte)
{
    return (h ^ byte) * 0x100000001B3ull;
}

/* The covered pixels (non-black: every colour of these scenes is) hashed. */
static uint64_t mask_digest(uint64_t h, const uint8_t *rgb, int32_t stride, unsigned first_row, unsigned rows)
{
    unsigned i, j;
    for (j = 0; j < rows; j++)
        for (i = 0; i < W; i++) {
            const uint8_t *c = rgb + (size_t)j * (size_t)stride + i * 3u;
            (void)first_row;
            h = fnv(h, (uint8_t)((c[0] | c[1] | c[2]) != 0));
        }
    return h;
}

/* Triangle t of the scene alone, in mode 0 (frame), 1 (scanline) or 2
 * (bands of 5 rows): its coverage hashed into h. */
static uint64_t triangle_digest(uint64_t h, const mesh_buf *m, unsigned t, const zl_mat4 *mvp, int style, int mode)
{
    zl_mesh mesh;
    zl_state st;
    zl_style sty;
    zl_rgb black = {0, 0, 0};
    mesh_of(m, &mesh);
    mesh.indices = &m->idx[t * 3];
    mesh.triangle_count = 1;
    style_of(style, m, &st, &sty);
    if (mode == 0) {
        zl_context ctx;
        zl_target tg;
        target_of(&tg);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
        ctx.state = st;
        ctx.style = sty;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 0xFFFF));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, mvp));
        return mask_digest(h, color_buf, W * 3, 0, H);
    } else {
        zl_frame_config cfg;
        zl_frame fr;
        zl_band band;
        zl_status rc;
        zt_frame_config_of(&cfg, W, H, mode == 1 ? 1 : 5, ZL_FORMAT_RGB888);
        zt_frame_capacity(&cfg, 1, m->nv, 1, 16);
        cfg.gouraud = 1;
        cfg.styled = 1;
        cfg.textured = 1;
        TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&fr, &cfg, work, sizeof work, black, 0xFFFF));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&fr, &mesh, mvp, &st, &sty));
        while ((rc = zl_frame_next_band(&fr, &band)) == ZL_OK)
            h = mask_digest(h, (const uint8_t *)band.color, band.color_stride, band.first_row, band.rows);
        TEST_ASSERT_EQUAL_INT(ZL_DONE, rc);
        return h;
    }
}

/* Every style and mode gives the scene's digest. */
static void check_pinned(const char *name, const mesh_buf *m, const zl_mat4 *mvp, uint64_t want)
{
    uint64_t first = 0;
    int style, mode;
    for (style = 0; style < STYLE_COUNT; style++) {
        for (mode = 0; mode < 3; mode++) {
            uint64_t h = 0xCBF29CE484222325ull;
            unsigned t;
            char msg[160];
            for (t = 0; t < m->nt; t++)
                h = triangle_digest(h, m, t, mvp, style, mode);
            if (style == 0 && mode == 0) {
                first = h;
                printf("%s: coverage digest 0x%016llxull\n", name, (unsigned long long)h);
            }
            snprintf(msg, sizeof msg, "%s, style %d, mode %d: coverage digest 0x%016llx, pinned 0x%016llx", name,
                     style, mode, (unsigned long long)h, (unsigned long long)want);
            TEST_ASSERT_TRUE_MESSAGE(h == want && h == first, msg);
        }
    }
}

/* Random triangles in eye space crossing the near, far and eye planes. */
static void random_scene(mesh_buf *m, int close, int count)
{
    int r, k;
    m->nv = m->nt = 0;
    for (r = 0; r < count; r++) {
        uint16_t v[3];
        for (k = 0; k < 3; k++) {
            long double p[3];
            long double e = close ? 1.0L : 12.0L;
            p[0] = e * rnd_range(-1000, 1000) / 1000;
            p[1] = e * rnd_range(-1000, 1000) / 1000;
            p[2] = close ? (long double)rnd_range(-6000, 250) / 1000 : (long double)rnd_range(-30000, 2000) / 1000;
            v[k] = add_vertex(m, p);
        }
        add_tri(m, v[0], v[1], v[2]);
    }
}

/* A textured ground grid under a low camera: crosses the near plane and,
 * far off, the far plane. */
static void ground_scene(mesh_buf *m)
{
    uint16_t grid[9][9];
    int i, j;
    m->nv = m->nt = 0;
    for (j = 0; j <= 8; j++)
        for (i = 0; i <= 8; i++) {
            long double p[3];
            p[0] = -6.0L + 1.5L * i + 0.1L * j;
            p[1] = -0.4L;
            p[2] = 1.5L - 3.0L * j;
            grid[j][i] = add_vertex(m, p);
        }
    for (j = 0; j < 8; j++)
        for (i = 0; i < 8; i++) {
            add_tri(m, grid[j][i], grid[j + 1][i], grid[j][i + 1]);
            add_tri(m, grid[j + 1][i], grid[j + 1][i + 1], grid[j][i + 1]);
        }
}

static void pixel_scene(mesh_buf *m, int count)
{
    int r, k;
    m->nv = m->nt = 0;
    for (r = 0; r < count; r++) {
        uint16_t v[3];
        for (k = 0; k < 3; k++) {
            long double p[3];
            p[0] = (long double)rnd_range(-30000, 95000) / 1000;
            p[1] = (long double)rnd_range(-30000, 80000) / 1000;
            p[2] = (long double)rnd_range(-1500, 2500) / 1000;
            v[k] = add_vertex(m, p);
        }
        add_tri(m, v[0], v[1], v[2]);
    }
}

static void test_pinned_coverage(void)
{
    zl_mat4 proj;
    rng = 0x6789ABCDEF012345ull;
    make_texture();
    perspective(&proj, 65536 / 2, 65536 * 20);
    random_scene(&mb, 0, 120);
    check_pinned("random, perspective", &mb, &proj, 0xa326ff6ab556f514ull);
    perspective(&proj, 65536 / 20, 65536 * 4);
    random_scene(&mb, 1, 120);
    check_pinned("random, close", &mb, &proj, 0x1160f54202a09849ull);
    perspective(&proj, 65536 / 4, 65536 * 12);
    ground_scene(&mb);
    check_pinned("ground", &mb, &proj, 0xb41b2819ac8a2386ull);
    pixel_scene(&mb, 120);
    check_pinned("pixel space", &mb, NULL, 0x59360daa08a5cb15ull);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_watertight_near);
    RUN_TEST(test_watertight_far);
    RUN_TEST(test_watertight_both);
    RUN_TEST(test_watertight_eye);
    RUN_TEST(test_watertight_pixel_space);
    RUN_TEST(test_pinned_coverage);
    return UNITY_END();
}

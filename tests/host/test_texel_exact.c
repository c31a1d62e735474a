/* SPDX-License-Identifier: MIT */
/*
 * Texture coordinates exact to the texel (zline.h, TEXTURES; issue 22):
 * every covered pixel of perspective floors, seen from above, at a grazing
 * angle and with the floor running behind the eye (near-plane clipping),
 * against a reference computed here in long double, independently of the
 * core: for each triangle b = M^-1 n (M the clip-space x, y, w of its
 * vertices as the exact product of the Q16.16 matrix and positions, n the
 * pixel centre in device coordinates); a triangle whose b are all >= 0
 * (and whose point lies between the near and far planes) covers the
 * centre, and its texture coordinate there is
 *     perspective  c = sum c_i b_i / sum b_i
 *     affine       c = sum c_i w_i b_i / sum w_j b_j
 * (perspective-correct for a triangle across the eye plane). The snapped
 * coverage may give a pixel within 1/16 pixel of an edge to either
 * triangle: each triangle covering a point within 1/16 pixel of the centre
 * is a candidate, its coordinate taken at the centre itself.
 *   Nearest (RGB565 target): the sampled texel is floor(c) of a candidate,
 *     or c is within 1/64 texel of a texel boundary, or within the drift of
 *     the stepped planes (zline.h: half a plane unit for each of up to
 *     1 + W + H steps, a unit 2^-16 texel affine, 2^-16 w / w_min texel
 *     perspective), counted and printed apart; on these floors no pixel
 *     needs the drift (asserted: with the 12 fraction bits of before, 0.1
 *     to 0.5 % of the pixels did).
 *   Bilinear (RGB888 target): each channel within 1 of the exact blend
 *     with each weight within 1/16 (plus that drift) of exact.
 *   Pixels where the coordinate changes by more than 16 texels from one
 *     pixel to the next (the horizon of the grazing floor) are counted and
 *     not checked: there a pixel spans 16 texels or more.
 * Textures: random 64 x 64 and 48 x 40, RGB565 and RGBA4444 (their texels
 * all distinct, so a pixel names its texel), repeat; frame mode and
 * scanline mode (zl_frame, band_rows 1), which must give the same bytes.
 * The state sets near_z and far_z (the exact depth mapping): the texture
 * planes go through the unsnapped vertex positions only then, and only
 * with ZL_FEATURE_EXACT_DEPTH (else through the snapped vertices, which
 * this bound does not hold for: the test reports itself skipped).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_linear.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

#define W 160
#define H 120
#define GRID 8                 /* quads per side of the floor */
#define NV ((GRID + 1) * (GRID + 1))
#define NT (GRID * GRID * 2)
#define BOUNDARY (1.0L / 64)  /* nearest: skipped within this of a texel boundary */
#define WEIGHT_TOL (1.0L / 16) /* bilinear: per-axis weight bound */
#define MINIFIED 16            /* texels per pixel beyond which a pixel is not checked */

static uint64_t rng = 0x5EED7E8E1ull;
static uint16_t texels[64 * 64];
static int16_t texel_of_pixel[65536]; /* RGB565 pixel -> texel index (-1: none) */
static zl_texture texture;
static zl_fixed positions[NV * 3], uvs[NV * 2];
static uint16_t indices[NT * 3];
static zl_mesh mesh;
static uint16_t c565[W * H], c565_ref[W * H], depth_buf[W * H], depth_ref[W * H];
static uint8_t c888[W * H * 3], c888_ref[W * H * 3];
static uint64_t work[400000 / 8];

typedef struct {
    long double inv[3][3]; /* M^-1 */
    long double w[3], z[3], c[3][2];
    int ok;
} tri_ref;
static tri_ref refs[NT];

typedef struct {
    unsigned long pixels, checked, boundary, wrong, uncovered, drift, minified;
    double worst; /* texels from the reference coordinate to the sampled texel, beyond every tolerance */
    double worst_drift; /* the same within the drift tolerance */
    double worst_ch; /* bilinear: worst channel error beyond the bound's range part */
} stats;

/* The RGB565 pixel a texel gives (unlit, nearest): RGBA4444 channels widen
 * as v * 17 and pack to their top bits. */
static uint16_t pixel_of_texel(uint16_t t, unsigned format)
{
    if (format == ZL_TEXEL_RGBA4444) {
        unsigned r = (unsigned)(t >> 12) * 17u, g = (unsigned)((t >> 8) & 15u) * 17u, b = (unsigned)((t >> 4) & 15u) * 17u;
        return (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
    }
    return t;
}

/* A random texture of distinct texels (a shuffled 0 .. 4095, as RGBA4444
 * colour bits or as RGB565). */
static void make_texture(uint16_t tw, uint16_t th, unsigned format)
{
    static uint16_t perm[4096];
    unsigned i, n = (unsigned)tw * th;
    for (i = 0; i < 4096; i++)
        perm[i] = (uint16_t)i;
    for (i = 4095; i > 0; i--) {
        unsigned j = (unsigned)zt_rand64_range(&rng, 0, (int32_t)i);
        uint16_t t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    for (i = 0; i < 65536; i++)
        texel_of_pixel[i] = -1;
    for (i = 0; i < n; i++) {
        texels[i] = format == ZL_TEXEL_RGBA4444 ? (uint16_t)((perm[i] << 4) | 15u) : perm[i];
        texel_of_pixel[pixel_of_texel(texels[i], format)] = (int16_t)i;
    }
    memset(&texture, 0, sizeof texture);
    texture.texels = texels;
    texture.width = tw;
    texture.height = th;
    texture.stride = tw;
    texture.format = (uint8_t)format;
    texture.wrap_s = ZL_WRAP_REPEAT;
    texture.wrap_t = ZL_WRAP_REPEAT;
}

/* A floor y = 0 of GRID x GRID quads over x, z in [-half, half], with
 * texture coordinates of random scale and offset (several repeats). */
static void make_floor(int32_t half)
{
    int i, j;
    int32_t su = zt_rand64_range(&rng, 65536 / 5, 65536 / 2), sv = zt_rand64_range(&rng, 65536 / 5, 65536 / 2);
    int32_t ou = zt_rand64_range(&rng, 0, 65535), ov = zt_rand64_range(&rng, 0, 65535);
    for (j = 0; j <= GRID; j++)
        for (i = 0; i <= GRID; i++) {
            int k = j * (GRID + 1) + i;
            int32_t x = -half + (int32_t)(((int64_t)2 * half * i) / GRID), z = -half + (int32_t)(((int64_t)2 * half * j) / GRID);
            positions[k * 3] = x;
            positions[k * 3 + 1] = 0;
            positions[k * 3 + 2] = z;
            uvs[k * 2] = (zl_fixed)(((int64_t)x * su >> 16) + ou);
            uvs[k * 2 + 1] = (zl_fixed)(((int64_t)z * sv >> 16) + ov);
        }
    for (j = 0; j < GRID; j++)
        for (i = 0; i < GRID; i++) {
            uint16_t a = (uint16_t)(j * (GRID + 1) + i), b = (uint16_t)(a + 1), c = (uint16_t)(a + GRID + 1),
                     d = (uint16_t)(c + 1);
            uint16_t *t = &indices[(j * GRID + i) * 6];
            t[0] = a, t[1] = c, t[2] = b, t[3] = b, t[4] = c, t[5] = d;
        }
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.vertex_count = NV;
    mesh.triangle_count = NT;
}

/* Clip-space vertices as the exact product (long double) and each
 * triangle's inverse. */
static void make_refs(const zl_mat4 *mvp)
{
    unsigned t, k, r, c;
    for (t = 0; t < NT; t++) {
        long double m[3][3], e[3];
        tri_ref *f = &refs[t];
        for (k = 0; k < 3; k++) {
            unsigned v = indices[t * 3 + k];
            long double clip[4];
            for (r = 0; r < 4; r++) {
                clip[r] = 0;
                for (c = 0; c < 3; c++)
                    clip[r] += (long double)mvp->m[r * 4 + c] * positions[v * 3 + c] / 65536.0L / 65536.0L;
                clip[r] += (long double)mvp->m[r * 4 + 3] / 65536.0L;
            }
            m[0][k] = clip[0];
            m[1][k] = clip[1];
            m[2][k] = clip[3];
            f->w[k] = clip[3];
            f->z[k] = clip[2];
            f->c[k][0] = (long double)uvs[v * 2] * texture.width / 65536.0L;
            f->c[k][1] = (long double)uvs[v * 2 + 1] * texture.height / 65536.0L;
        }
        f->ok = 1;
        for (c = 0; c < 3; c++) { /* the inverse, column by column */
            long double mm[3][3];
            for (r = 0; r < 3; r++) {
                for (k = 0; k < 3; k++)
                    mm[r][k] = m[r][k];
                e[r] = r == c;
            }
            {
                long double x[3];
                if (!zt_solve3(mm, e, x))
                    f->ok = 0;
                for (r = 0; r < 3; r++)
                    f->inv[r][c] = x[r];
            }
        }
    }
}

/* Barycentrics b of device point (x, y) in triangle t; 1 when it covers
 * the point (every b >= 0, in front of the eye, between near and far). */
static int covers(const tri_ref *f, long double x, long double y, long double b[3])
{
    long double sb = 0, sz = 0;
    unsigned k, r;
    for (r = 0; r < 3; r++)
        b[r] = f->inv[r][0] * x + f->inv[r][1] * y + f->inv[r][2];
    for (k = 0; k < 3; k++) {
        sb += b[k];
        sz += b[k] * f->z[k];
    }
    return f->ok && b[0] >= 0 && b[1] >= 0 && b[2] >= 0 && sb > 0 && sz >= 0 && sz <= 1;
}

/* Triangle t's coordinate (texels) at the device point with barycentrics
 * b, and (w_px) its clip w there. */
static void coordinate(const tri_ref *f, const long double b[3], int affine, long double out[2], long double *w_px)
{
    long double sb = b[0] + b[1] + b[2], sw = 0;
    unsigned k, r;
    for (k = 0; k < 3; k++)
        sw += b[k] * f->w[k];
    if (f->w[0] <= 0 || f->w[1] <= 0 || f->w[2] <= 0)
        affine = 0; /* across the eye plane: affine is perspective-correct (zline.h, Clipping) */
    for (r = 0; r < 2; r++) {
        long double s = 0;
        for (k = 0; k < 3; k++)
            s += f->c[k][r] * (affine ? b[k] * f->w[k] / sw : b[k] / sb);
        out[r] = s;
    }
    *w_px = 1 / sb;
}

#define MAX_CAND 4
typedef struct {
    int n;
    long double c[MAX_CAND][2]; /* coordinate (texels) in each candidate triangle */
    long double tol[MAX_CAND];  /* and the tolerance there (texels) */
    long double grad[MAX_CAND]; /* |dc/dx| + |dc/dy| (texels per pixel), the larger axis */
} candidates;

/* The tolerance at a pixel of clip w w_px in triangle f: 1/64 texel plus
 * the stepped planes' drift, half a unit for each of up to 1 + W + H steps
 * (zline.h, TEXTURES), a unit 2^-16 texel (affine) or 2^-16 w / w_min
 * texel (perspective; w_min, the least w of the triangle clipped to the
 * near plane, is at least max(least vertex w, near)). */
static long double tolerance(const tri_ref *f, long double w_px, int affine)
{
    long double wmin = f->w[0] < f->w[1] ? f->w[0] : f->w[1], unit;
    wmin = f->w[2] < wmin ? f->w[2] : wmin;
    wmin = wmin < 0.25L ? 0.25L : wmin;
    unit = affine && f->w[0] > 0 && f->w[1] > 0 && f->w[2] > 0 ? 1.0L / 65536 : w_px / wmin / 65536;
    return BOUNDARY + (1 + W + H) * unit / 2;
}

/* The triangles that cover the centre of pixel (i, j) or a point within
 * 1/16 pixel of it (the snapped coverage may give the pixel to either of
 * two triangles there; an affine texture differs between them), with
 * their coordinates at the centre itself. 0 when none covers it. */
static int reference(int i, int j, int affine, candidates *cd)
{
    static const long double off[5][2] = {{0, 0}, {1.0L / 16, 0}, {-1.0L / 16, 0}, {0, 1.0L / 16}, {0, -1.0L / 16}};
    long double cx = i + 0.5L, cy = j + 0.5L;
    unsigned t, p;
    cd->n = 0;
    for (t = 0; t < NT && cd->n < MAX_CAND; t++) {
        long double b[3], w_px;
        const tri_ref *f = &refs[t];
        unsigned r;
        int far_off = 0;
        for (r = 0; r < 3; r++) { /* b moves by at most this within 1/16 pixel on an axis: skip the far ones */
            long double bc = f->inv[r][0] * (2 * cx / W - 1) + f->inv[r][1] * (1 - 2 * cy / H) + f->inv[r][2];
            far_off |= bc < -(fabsl(f->inv[r][0]) * 2 / W + fabsl(f->inv[r][1]) * 2 / H) / 8;
        }
        if (far_off || !f->ok)
            continue;
        for (p = 0; p < 5; p++)
            if (covers(&refs[t], 2 * (cx + off[p][0]) / W - 1, 1 - 2 * (cy + off[p][1]) / H, b))
                break;
        if (p == 5)
            continue;
        (void)covers(&refs[t], 2 * cx / W - 1, 1 - 2 * cy / H, b);
        coordinate(&refs[t], b, affine, cd->c[cd->n], &w_px);
        cd->tol[cd->n] = tolerance(&refs[t], w_px, affine);
        {
            long double g = 0, cx1[2], bx[3];
            int ax, d;
            for (d = 0; d < 2; d++) {
                (void)covers(&refs[t], 2 * (cx + (d == 0)) / W - 1, 1 - 2 * (cy + (d == 1)) / H, bx);
                coordinate(&refs[t], bx, affine, cx1, &w_px);
                for (ax = 0; ax < 2; ax++)
                    g = fabsl(cx1[ax] - cd->c[cd->n][ax]) > g ? fabsl(cx1[ax] - cd->c[cd->n][ax]) : g;
            }
            cd->grad[cd->n] = g;
        }
        cd->n++;
    }
    return cd->n > 0;
}

/* Distance (texels) from c to texel i of an axis of `size` texels that
 * repeats; 0 inside it. */
static long double texel_distance(long double c, int i, int size)
{
    long double f = c - floorl(c / size) * size, best = 1e30L; /* 0 .. size */
    int k;
    for (k = -1; k <= 1; k++) {
        long double lo = (long double)i + (long double)k * size, d = f < lo ? lo - f : (f > lo + 1 ? f - lo - 1 : 0);
        best = d < best ? d : best;
    }
    return best;
}

static int wrap(long double c, int size)
{
    long double f = floorl(c);
    long long i = (long long)f % size;
    return (int)(i < 0 ? i + size : i);
}

/* Whether c is within d of a texel boundary. */
static int near_boundary(long double c, long double d)
{
    long double f = c - floorl(c);
    return f < d || f > 1 - d;
}

/* The frame mode and scanline mode images (they must agree). */
static void draw_both(const zl_mat4 *mvp, const zl_state *st, const zl_style *sty, int rgb888)
{
    zl_context ctx;
    zl_target tg;
    zl_rgb black = {0, 0, 0};
    zl_frame_config cfg;
    zl_frame fr;
    zt_frame_copy to_ref;
    zl_format fmt = rgb888 ? ZL_FORMAT_RGB888 : ZL_FORMAT_RGB565;
    zt_target_packed(&tg, rgb888 ? (void *)c888 : (void *)c565, depth_buf, W, H, fmt);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    ctx.state = *st;
    ctx.style = *sty;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 0xFFFF));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, mvp));
    zt_frame_config_of(&cfg, W, H, 1, fmt);
    zt_frame_capacity(&cfg, 1, NV, NT, 64);
    cfg.styled = 1;
    cfg.textured = 1;
    TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&fr, &cfg, work, sizeof work, black, 0xFFFF));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&fr, &mesh, mvp, st, sty));
    to_ref.color = rgb888 ? (void *)c888_ref : (void *)c565_ref;
    to_ref.depth = depth_ref;
    zt_frame_drain(&fr, &to_ref);
    if (rgb888)
        TEST_ASSERT_EQUAL_MEMORY(c888, c888_ref, sizeof c888);
    else
        TEST_ASSERT_EQUAL_MEMORY(c565, c565_ref, sizeof c565);
    TEST_ASSERT_EQUAL_MEMORY(depth_buf, depth_ref, sizeof depth_buf);
}

/* Whether a candidate's coordinate changes by more than MINIFIED texels
 * from the pixel to its neighbour (a pixel spans that many texels: not
 * covered by the bound, see the top). */
static int minified(const candidates *cd)
{
    int k;
    for (k = 0; k < cd->n; k++)
        if (cd->grad[k] > MINIFIED)
            return 1;
    return 0;
}

/* Nearest: the sampled texel is floor(c) in one of the candidates, or c
 * is within 1/64 texel of a boundary (skipped), or within the drift
 * tolerance of the sampled texel (counted apart: the stepped planes). */
static void check_nearest(int affine, stats *s)
{
    int i, j, k;
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) {
            candidates cd;
            int tx, got_u, got_v, boundary = 0, drift = 0;
            long double worst = 1;
            if (depth_buf[j * W + i] == 0xFFFF)
                continue;
            s->pixels++;
            if (!reference(i, j, affine, &cd)) {
                s->uncovered++;
                continue;
            }
            tx = texel_of_pixel[c565[j * W + i]];
            TEST_ASSERT_TRUE(tx >= 0);
            got_u = tx % texture.width;
            got_v = tx / texture.width;
            for (k = 0; k < cd.n; k++) {
                const long double *c = cd.c[k];
                long double du, dv;
                if (near_boundary(c[0], BOUNDARY) || near_boundary(c[1], BOUNDARY))
                    boundary = 1;
                du = texel_distance(c[0], got_u, texture.width);
                dv = texel_distance(c[1], got_v, texture.height);
                du = du > dv ? du : dv;
                worst = du < worst ? du : worst;
                if (du <= cd.tol[k])
                    drift = 1;
            }
            if (worst == 0) {
                s->checked++;
                continue;
            }
            if (minified(&cd)) {
                s->minified++;
                continue;
            }
            if (boundary) {
                s->boundary++;
                continue;
            }
            s->checked++;
            if (drift) {
                s->drift++;
                if ((double)worst > s->worst_drift)
                    s->worst_drift = (double)worst;
                continue;
            }
            if ((double)worst > s->worst)
                s->worst = (double)worst;
            s->wrong++;
            if (getenv("ZT_DEBUG"))
                printf("  (%d, %d) ref %.4Lf %.4Lf got %d %d n %d tol %.4Lf worst %.4Lf grad %.2Lf %.2Lf\n", i, j, cd.c[0][0], cd.c[0][1], got_u, got_v, cd.n, cd.tol[0], worst, cd.grad[0], cd.grad[1]);
        }
}

static void texel_rgb(int u, int v, unsigned out[3])
{
    uint16_t t = texels[wrap(v, texture.height) * texture.width + wrap(u, texture.width)];
    if (texture.format == ZL_TEXEL_RGBA4444) {
        out[0] = (unsigned)(t >> 12) * 17u;
        out[1] = (unsigned)((t >> 8) & 15u) * 17u;
        out[2] = (unsigned)((t >> 4) & 15u) * 17u;
    } else {
        unsigned r5 = t >> 11, g6 = (t >> 5) & 63u, b5 = t & 31u;
        out[0] = (r5 << 3) | (r5 >> 2);
        out[1] = (g6 << 2) | (g6 >> 4);
        out[2] = (b5 << 3) | (b5 >> 2);
    }
}

/* The exact bilinear blend (8-bit channels) at coordinate (cu, cv). */
static void bilinear_at(long double cu, long double cv, long double out[3])
{
    long double pu = cu - 0.5L, pv = cv - 0.5L, fu, fv;
    unsigned t[4][3];
    int iu = (int)floorl(pu), iv = (int)floorl(pv), ch;
    fu = pu - iu;
    fv = pv - iv;
    texel_rgb(iu, iv, t[0]);
    texel_rgb(iu + 1, iv, t[1]);
    texel_rgb(iu, iv + 1, t[2]);
    texel_rgb(iu + 1, iv + 1, t[3]);
    for (ch = 0; ch < 3; ch++)
        out[ch] = (t[0][ch] * (1 - fu) + t[1][ch] * fu) * (1 - fv) + (t[2][ch] * (1 - fu) + t[3][ch] * fu) * fv;
}

/* How far (8-bit units) the pixel's channels are beyond the bilinear
 * bound for coordinate c: the blend with each weight within wt of exact,
 * i.e. at c moved by up to wt texel per axis (the range of its values over
 * that square), plus 1 for the rounding; 0 when within it. */
static long double bilinear_excess(const uint8_t *px, const long double c[2], long double wt)
{
    long double lo[3] = {1e30L, 1e30L, 1e30L}, hi[3] = {-1e30L, -1e30L, -1e30L}, v[3], worst = 0;
    long double at[2][4]; /* per axis: the square's ends, its middle, and the kink where p is whole */
    int a, b, ch, n[2];
    for (a = 0; a < 2; a++) {
        long double kink = floorl(c[a] - 0.5L + wt) + 0.5L; /* p = c - 1/2 whole */
        at[a][0] = c[a] - wt;
        at[a][1] = c[a];
        at[a][2] = c[a] + wt;
        n[a] = 3;
        if (kink > at[a][0] && kink < at[a][2])
            at[a][n[a]++] = kink;
    }
    /* bilinear between kinks: the extremes are at these grid points */
    for (a = 0; a < n[0]; a++)
        for (b = 0; b < n[1]; b++) {
            bilinear_at(at[0][a], at[1][b], v);
            for (ch = 0; ch < 3; ch++) {
                lo[ch] = v[ch] < lo[ch] ? v[ch] : lo[ch];
                hi[ch] = v[ch] > hi[ch] ? v[ch] : hi[ch];
            }
        }
    for (ch = 0; ch < 3; ch++) {
        long double e = px[ch] < lo[ch] ? lo[ch] - px[ch] : (px[ch] > hi[ch] ? px[ch] - hi[ch] : 0);
        e -= 1;
        worst = e > worst ? e : worst;
    }
    return worst;
}

/* Bilinear (RGB888): each channel within the bound of the exact blend
 * for one of the candidates. */
static void check_bilinear(int affine, stats *s)
{
    int i, j, k;
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) {
            candidates cd;
            long double best = 1e30L;
            if (depth_buf[j * W + i] == 0xFFFF)
                continue;
            s->pixels++;
            if (!reference(i, j, affine, &cd)) {
                s->uncovered++;
                continue;
            }
            for (k = 0; k < cd.n; k++) {
                /* weights within 1/16 plus the stepped planes' drift (tolerance's part beyond 1/64) */
                long double e = bilinear_excess(&c888[(j * W + i) * 3], cd.c[k], WEIGHT_TOL + cd.tol[k] - BOUNDARY);
                best = e < best ? e : best;
            }
            if (best > 0 && minified(&cd)) {
                s->minified++;
                continue;
            }
            s->checked++;
            if (best > 0) {
                if (getenv("ZT_DEBUG"))
                    printf("  bilinear (%d, %d) ref %.4Lf %.4Lf n %d excess %.3Lf grad %.2Lf\n", i, j, cd.c[0][0], cd.c[0][1], cd.n, best, cd.grad[0]);
                s->wrong++;
                if ((double)best > s->worst_ch)
                    s->worst_ch = (double)best;
            }
        }
}

typedef struct {
    const char *name;
    int32_t eye[3], target[3];
    int32_t half; /* floor half size */
} camera;

static const camera cameras[] = {
    {"above", {65536 / 3, 6 * 65536, 5 * 65536}, {0, 0, -65536}, 8 * 65536},
    {"grazing", {65536 / 5, 65536 * 2 / 5, 9 * 65536}, {0, 0, -8 * 65536}, 10 * 65536},
    {"near clipped", {65536 / 7, 65536 / 3, 0}, {65536 / 2, 0, -6 * 65536}, 6 * 65536},
};

static unsigned long total_wrong, total_drift;

static void run_case(const camera *cam, uint16_t tw, uint16_t th, unsigned format, int affine, int bilinear)
{
    zl_mat4 proj, view, mvp;
    zl_vec3 eye = {cam->eye[0], cam->eye[1], cam->eye[2]}, target = {cam->target[0], cam->target[1], cam->target[2]},
            up = {0, 65536, 0};
    zl_state st;
    zl_style sty;
    stats s;
    int rep;
    memset(&s, 0, sizeof s);
    for (rep = 0; rep < 2; rep++) {
        make_texture(tw, th, format);
        make_floor(cam->half);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, ZL_ANGLE_TURN / 6, (zl_fixed)(65536 * W / H), 65536 / 4,
                                                         40 * 65536));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
        zl_mat4_mul(&mvp, &proj, &view);
        zl_state_default(&st);
        st.cull = ZL_CULL_NONE;
        st.near_z = 65536 / 4;
        st.far_z = 40 * 65536;
        zl_style_default(&sty);
        sty.texture = &texture;
        sty.texcoords = uvs;
        sty.tex_mapping = affine ? ZL_TEX_AFFINE : ZL_TEX_PERSPECTIVE;
        sty.tex_filter = bilinear ? ZL_FILTER_BILINEAR : ZL_FILTER_NEAREST;
        make_refs(&mvp);
        draw_both(&mvp, &st, &sty, bilinear);
        if (bilinear)
            check_bilinear(affine, &s);
        else
            check_nearest(affine, &s);
        eye.x += 65536 / 9; /* a slightly different view each time */
        target.x -= 65536 / 5;
    }
    printf("%-12s %2ux%-2u %-8s %-11s %-8s: %lu pixels, %lu checked, %lu within 1/64 texel of a boundary, "
           "%lu off by the drift (%.3f %%, worst %.4f texel), %lu minified beyond %d:1, %lu wrong (worst %.4f)\n",
           cam->name, tw, th, format == ZL_TEXEL_RGBA4444 ? "RGBA4444" : "RGB565", affine ? "affine" : "perspective",
           bilinear ? "bilinear" : "nearest", s.pixels, s.checked, s.boundary, s.drift,
           s.checked ? 100.0 * (double)s.drift / (double)s.checked : 0.0, s.worst_drift, s.minified, MINIFIED, s.wrong,
           bilinear ? s.worst_ch : s.worst);
    TEST_ASSERT_TRUE(s.checked > 1000);
    TEST_ASSERT_TRUE(s.uncovered * 50 < s.pixels);
    total_wrong += s.wrong;
    total_drift += s.drift;
}

static void test_texels(void)
{
    unsigned c, size, format, affine, bilinear;
#if !ZL_FEATURE_EXACT_DEPTH
    TEST_IGNORE_MESSAGE("ZL_FEATURE_EXACT_DEPTH=0: no residuals, the texture planes go through the snapped vertices");
#endif
    for (c = 0; c < sizeof cameras / sizeof cameras[0]; c++)
        for (size = 0; size < 2; size++)
            for (format = 0; format < 2; format++)
                for (affine = 0; affine < 2; affine++)
                    for (bilinear = 0; bilinear < 2; bilinear++)
                        run_case(&cameras[c], size ? 48 : 64, size ? 40 : 64,
                                 format ? ZL_TEXEL_RGBA4444 : ZL_TEXEL_RGB565, (int)affine, (int)bilinear);
    printf("total wrong: %lu, off by the drift: %lu\n", total_wrong, total_drift);
    TEST_ASSERT_EQUAL_UINT32(0, total_wrong);
    /* the bound itself (1/64 texel, no drift) on these floors */
    TEST_ASSERT_EQUAL_UINT32(0, total_drift);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_texels);
    return UNITY_END();
}

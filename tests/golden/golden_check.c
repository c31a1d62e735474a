/* SPDX-License-Identifier: MIT */
/*
 * golden_check: checks an image written by zline-render against the test
 * reference (tests/support/zt_ref.h), not against zline's rasteriser.
 *
 *   golden_check IMAGE.ppm MODEL.obj [zline-render options]
 *
 * Understood options: --size WxH, --orbit YAW,PITCH,D, --cull none|back|front,
 * --shade flat|depth|vertex, --format rgb888|rgb565|rgb565be, --bg R,G,B,
 * --no-light, --mode (ignored: every mode draws the same image) (the rest of
 * zline-render's defaults: camera at 0,0,3.5 looking
 * at the origin, fov 60, near 0.1, far 100, CCW front faces, white model,
 * light -1,2,2, ambient 48, model normalised).
 *
 * The vertices go through the library's matrix functions (the transform is
 * tested on its own in test_fixed); from the clip-space positions on, every
 * step is the reference's: window coordinates, snapping, culling by winding,
 * coverage by the top-left rule, the exact depth plane (through the
 * unsnapped vertices, tri_depth), the nearest triangle
 * per pixel, and the pixel's colour from the contract in double precision:
 *   flat    ambient + (255 - ambient) * max(0, n . l), n the model-space face
 *           normal, times the model colour;
 *   depth   zline-render's grey ramp over the model's depth range, applied to
 *           the reference depth range lo .. hi of the pixel;
 *   vertex  the screen-space barycentric mix of the vertex colours.
 * The reference's window coordinates may round differently from zline's by a
 * subpixel, so a triangle whose edge passes within 1/4 pixel of a centre may
 * or may not cover it, and triangles within 8 depth steps of the nearest may
 * win the depth test: every such triangle is a candidate, and the pixel must
 * have the colour of one of its candidates (within 2 of 255, or 8 for
 * RGB565), or the background when no triangle surely covers it. A pixel with
 * no candidate must be the background exactly. Prints the first mismatches
 * and a summary; exit status 1 on any mismatch, or when too few pixels were
 * covered for the check to mean anything.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zl_obj.h"
#include "zl_pnm.h"
#include "zline/zline.h"
#include "zt_ref.h"

typedef struct {
    int w, h, cull, shade, rgb565, light;
    double orbit[3];
    int have_orbit;
    int bg[3];
} options;

enum { SHADE_FLAT, SHADE_DEPTH, SHADE_VERTEX };

static int parse(int argc, char **argv, options *o)
{
    int i;
    memset(o, 0, sizeof *o);
    o->w = 320;
    o->h = 240;
    o->cull = ZL_CULL_BACK;
    o->light = 1;
    for (i = 3; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : "";
        if (strcmp(a, "--no-light") == 0)
            o->light = 0;
        else if (strcmp(a, "--mode") == 0 && i + 1 < argc)
            i++; /* every mode gives the same image (render_modes_* tests) */
        else if (strcmp(a, "--size") == 0 && sscanf(v, "%dx%d", &o->w, &o->h) == 2)
            i++;
        else if (strcmp(a, "--orbit") == 0 && sscanf(v, "%lf,%lf,%lf", &o->orbit[0], &o->orbit[1], &o->orbit[2]) == 3)
            o->have_orbit = 1, i++;
        else if (strcmp(a, "--bg") == 0 && sscanf(v, "%d,%d,%d", &o->bg[0], &o->bg[1], &o->bg[2]) == 3)
            i++;
        else if (strcmp(a, "--cull") == 0 && (strcmp(v, "none") == 0 || strcmp(v, "back") == 0 || strcmp(v, "front") == 0))
            o->cull = strcmp(v, "none") == 0 ? ZL_CULL_NONE : strcmp(v, "back") == 0 ? ZL_CULL_BACK : ZL_CULL_FRONT, i++;
        else if (strcmp(a, "--shade") == 0 && (strcmp(v, "flat") == 0 || strcmp(v, "depth") == 0 || strcmp(v, "vertex") == 0))
            o->shade = strcmp(v, "flat") == 0 ? SHADE_FLAT : strcmp(v, "depth") == 0 ? SHADE_DEPTH : SHADE_VERTEX, i++;
        else if (strcmp(a, "--format") == 0 && strncmp(v, "rgb", 3) == 0)
            o->rgb565 = strncmp(v, "rgb565", 6) == 0, i++;
        else {
            fprintf(stderr, "golden_check: option '%s' not understood\n", a);
            return 0;
        }
    }
    return o->w > 0 && o->h > 0;
}

static zl_fixed fx(double v)
{
    return (zl_fixed)floor(v * 65536.0 + 0.5);
}

/* zline-render's camera, through the library's matrix functions. */
static int camera(const options *o, zl_mat4 *mvp, zl_fixed *near_z, zl_fixed *far_z)
{
    zl_vec3 eye = {0, 0, fx(3.5)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_mat4 view, proj;
    if (o->have_orbit) {
        zl_angle yaw = zl_angle_from_deg(fx(o->orbit[0])), pitch = zl_angle_from_deg(fx(o->orbit[1]));
        zl_fixed d = fx(o->orbit[2]), cp = zl_cos(pitch);
        eye.x = zl_fx_mul(d, zl_fx_mul(cp, zl_sin(yaw)));
        eye.y = zl_fx_mul(d, zl_sin(pitch));
        eye.z = zl_fx_mul(d, zl_fx_mul(cp, zl_cos(yaw)));
    }
    if (((int64_t)llabs(eye.x) + llabs(eye.z)) * 64 < llabs(eye.y)) {
        up.y = 0;
        up.z = -ZL_FX_ONE;
    }
    *near_z = fx(0.1);
    *far_z = fx(100.0);
    if (zl_mat4_look_at(&view, eye, target, up) != ZL_OK ||
        zl_mat4_perspective(&proj, zl_angle_from_deg(fx(60.0)),
                            (zl_fixed)(((int64_t)o->w * 65536 + o->h / 2) / o->h), *near_z, *far_z) != ZL_OK)
        return 0;
    zl_mat4_mul(mvp, &proj, &view);
    return 1;
}

#define MAX_CAND 12
#define MARGIN (ZT_SUB / 2) /* 1/4 pixel, in half subpixels */
#define DEPTH_SLACK 8

/* Per pixel: the nearest sure cover, then every candidate near it. */
typedef struct {
    int32_t zsure;           /* nearest stored depth of a triangle covering the centre */
    uint8_t n, overflow;
    uint8_t near_border;     /* within the margin of a border edge of the visible surface */
    uint32_t cand[MAX_CAND];
} px_state;

typedef struct {
    int64_t raw[9];       /* window x, y (2^-16 px) and z (Q16) per vertex, mesh order */
    int64_t sx[3], sy[3]; /* snapped, half subpixels */
    zt_tri t;
    int visible;
    uint8_t border[3];    /* edge k (opposite vertex k) has no visible neighbour */
    int32_t bx0, by0, bx1, by1;
} tri_rec;

/*
 * The stored depth range at pixel (i, j) by the contract (issue 22): the
 * triangle's depth plane through its unsnapped window vertices (raw, 2^-16
 * px), not the snapped ones zt_tri_depth takes, in long double (64-bit
 * mantissa: far below a step here), within +-1 of it. zt_tri_depth's
 * steep triangles keep its clamped range.
 */
static void tri_depth(const tri_rec *r, int32_t i, int32_t j, zt_depth_ref *d)
{
    const int64_t *v = r->raw;
    long double x1 = (long double)(v[3] - v[0]), y1 = (long double)(v[4] - v[1]), x2 = (long double)(v[6] - v[0]);
    long double y2 = (long double)(v[7] - v[1]), z1 = (long double)(v[5] - v[2]), z2 = (long double)(v[8] - v[2]);
    long double c = x1 * y2 - x2 * y1, px, py, z;
    zt_tri_depth(&r->t, i, j, d);
    if (d->steep || r->t.area == 0 || c == 0)
        return;
    px = (i + 0.5L) * 65536.0L - (long double)v[0];
    py = (j + 0.5L) * 65536.0L - (long double)v[1];
    z = (long double)v[2] + (px * (z1 * y2 - z2 * y1) + py * (x1 * z2 - x2 * z1)) / c;
    z = z * 65535.0L / 65536.0L; /* raw Q16 window depth to stored steps */
    d->lo = (int32_t)ceill(z - 1.0L);
    d->hi = (int32_t)floorl(z + 1.0L);
    d->nearest = (int32_t)floorl(z + 0.5L);
    d->lo = d->lo < 0 ? 0 : (d->lo > 65535 ? 65535 : d->lo);
    d->hi = d->hi < 0 ? 0 : (d->hi > 65535 ? 65535 : d->hi);
    d->nearest = d->nearest < 0 ? 0 : (d->nearest > 65535 ? 65535 : d->nearest);
}

static int64_t edge_fn(const tri_rec *r, unsigned k, int64_t cx, int64_t cy, int64_t *len2)
{
    unsigned p = (k + 1) % 3, q = (k + 2) % 3;
    int64_t ex = r->sx[q] - r->sx[p], ey = r->sy[q] - r->sy[p];
    *len2 = ex * ex + ey * ey;
    return ex * (cy - r->sy[p]) - ey * (cx - r->sx[p]);
}

/* 2: the centre is inside by more than the margin; 1: within the margin of
 * the triangle (inside or out); 0: farther outside. *near_border is set when
 * the centre is within the margin of a border edge. */
static int coverage(const tri_rec *r, int32_t x, int32_t y, int *near_border)
{
    int64_t e[3], len2[3], area, cx = zt_centre2(x), cy = zt_centre2(y);
    unsigned k;
    int sure = 1;
    for (k = 0; k < 3; k++)
        e[k] = edge_fn(r, k, cx, cy, &len2[k]);
    area = e[0] + e[1] + e[2]; /* doubled signed area: its sign is the winding */
    *near_border = 0;
    for (k = 0; k < 3; k++) {
        int64_t ek = area < 0 ? -e[k] : e[k]; /* positive inside for either winding */
        if (ek < 0 && ek * ek >= (int64_t)MARGIN * MARGIN * len2[k])
            return 0;
    }
    for (k = 0; k < 3; k++) {
        int64_t ek = area < 0 ? -e[k] : e[k];
        if (ek < 0 || ek * ek < (int64_t)MARGIN * MARGIN * len2[k]) {
            sure = 0;
            *near_border |= r->border[k];
        }
    }
    return sure ? 2 : 1;
}

static int clamp255(double v)
{
    return v < 0 ? 0 : v > 255 ? 255 : (int)floor(v + 0.5);
}

typedef struct {
    options o;
    zl_obj obj;
    tri_rec *tris;
    uint16_t dmin, dmax;
    double light[3];
    int tol;
} scene;

/* The colour range triangle t gives pixel (x, y); 0 when not judged. */
static int expected(const scene *sc, uint32_t t, int32_t x, int32_t y, int *lo, int *hi)
{
    const tri_rec *r = &sc->tris[t];
    int c, tol = sc->tol;
    if (sc->o.shade == SHADE_DEPTH) {
        zt_depth_ref d;
        uint32_t span = sc->dmax > sc->dmin ? (uint32_t)(sc->dmax - sc->dmin) : 1u;
        double g_near, g_far;
        tri_depth(r, x, y, &d);
        g_near = d.lo <= sc->dmin ? 255 : d.lo >= sc->dmax ? 64 : 255.0 - (d.lo - sc->dmin) * 191.0 / span;
        g_far = d.hi <= sc->dmin ? 255 : d.hi >= sc->dmax ? 64 : 255.0 - (d.hi - sc->dmin) * 191.0 / span;
        for (c = 0; c < 3; c++) {
            lo[c] = clamp255(g_far) - 1 - (sc->o.rgb565 ? tol : 0);
            hi[c] = clamp255(g_near) + 1 + (sc->o.rgb565 ? tol : 0);
        }
        return 1;
    }
    if (sc->o.shade == SHADE_VERTEX && sc->obj.vertex_colors != NULL) {
        int64_t e[3], area = 0, len2, cx = zt_centre2(x), cy = zt_centre2(y);
        unsigned k;
        for (k = 0; k < 3; k++) {
            e[k] = edge_fn(r, k, cx, cy, &len2);
            area += e[k];
        }
        for (c = 0; c < 3; c++) {
            double v = 0;
            for (k = 0; k < 3; k++)
                v += (double)e[k] / (double)area * sc->obj.vertex_colors[3 * sc->obj.indices[3 * t + k] + c];
            lo[c] = clamp255(v) - tol;
            hi[c] = clamp255(v) + tol;
        }
        return 1;
    }
    {
        /* flat: the lit white model, model-space normal of the front side */
        const zl_fixed *p0 = &sc->obj.positions[3 * sc->obj.indices[3 * t]];
        const zl_fixed *p1 = &sc->obj.positions[3 * sc->obj.indices[3 * t + 1]];
        const zl_fixed *p2 = &sc->obj.positions[3 * sc->obj.indices[3 * t + 2]];
        double a[3], b[3], n[3], nl, ln, cosv, v = 255.0;
        if (sc->o.light && r->t.orient > 0)
            return 0; /* a back face seen (cull none): which side is lit is zline's choice */
        for (c = 0; c < 3; c++) {
            a[c] = (p1[c] - p0[c]) / 65536.0;
            b[c] = (p2[c] - p0[c]) / 65536.0;
        }
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
        nl = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        ln = sqrt(sc->light[0] * sc->light[0] + sc->light[1] * sc->light[1] + sc->light[2] * sc->light[2]);
        if (sc->o.light) {
            cosv = nl > 0 ? (n[0] * sc->light[0] + n[1] * sc->light[1] + n[2] * sc->light[2]) / (nl * ln) : 0;
            v = 48.0 + (255.0 - 48.0) * (cosv > 0 ? cosv : 0);
        }
        for (c = 0; c < 3; c++) {
            lo[c] = clamp255(v) - tol;
            hi[c] = clamp255(v) + tol;
        }
        return 1;
    }
}

static int setup_triangles(scene *sc, const zl_mat4 *mvp)
{
    uint32_t t;
    unsigned k;
    for (t = 0; t < sc->obj.triangle_count; t++) {
        tri_rec *r = &sc->tris[t];
        int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
        for (k = 0; k < 3; k++) {
            uint32_t v = sc->obj.indices[3 * t + k];
            zl_vec3 p = {sc->obj.positions[3 * v], sc->obj.positions[3 * v + 1], sc->obj.positions[3 * v + 2]};
            zl_vec4 c;
            if (zl_transform_point(mvp, p, &c) != ZL_OK || c.w <= 0 || c.z < 0 || c.z > c.w) {
                fprintf(stderr, "golden_check: triangle %u needs clipping, which this checker does not model\n",
                        (unsigned)t);
                return 0;
            }
            /* window x = (x/w + 1) W/2, y = (1 - y/w) H/2, z = z/w, in 2^-16 px and Q16 */
            r->raw[3 * k] = zt_floor_div(((int64_t)c.x + c.w) * sc->o.w * 32768, c.w);
            r->raw[3 * k + 1] = zt_floor_div(((int64_t)c.w - c.y) * sc->o.h * 32768, c.w);
            r->raw[3 * k + 2] = zt_floor_div((int64_t)c.z * 65536, c.w);
            r->sx[k] = 2 * zt_snap64(r->raw[3 * k]);
            r->sy[k] = 2 * zt_snap64(r->raw[3 * k + 1]);
            x0 = r->sx[k] < x0 ? r->sx[k] : x0;
            x1 = r->sx[k] > x1 ? r->sx[k] : x1;
            y0 = r->sy[k] < y0 ? r->sy[k] : y0;
            y1 = r->sy[k] > y1 ? r->sy[k] : y1;
        }
        zt_tri_init64(&r->t, r->raw);
        /* orient +1: clockwise on screen; CCW is the front */
        r->visible = r->t.orient != 0 && !(sc->o.cull == ZL_CULL_BACK && r->t.orient > 0) &&
                     !(sc->o.cull == ZL_CULL_FRONT && r->t.orient < 0);
        r->bx0 = (int32_t)zt_floor_div(x0, 2 * ZT_SUB) - 1;
        r->bx1 = (int32_t)zt_floor_div(x1, 2 * ZT_SUB) + 1;
        r->by0 = (int32_t)zt_floor_div(y0, 2 * ZT_SUB) - 1;
        r->by1 = (int32_t)zt_floor_div(y1, 2 * ZT_SUB) + 1;
    }
    return 1;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static uint64_t edge_key(const scene *sc, uint32_t t, unsigned k)
{
    uint32_t a = sc->obj.indices[3 * t + (k + 1) % 3], b = sc->obj.indices[3 * t + (k + 2) % 3];
    return a < b ? ((uint64_t)a << 32) | b : ((uint64_t)b << 32) | a;
}

/* Border edges: used by one visible triangle only (the silhouette, holes). */
static int find_borders(scene *sc)
{
    uint64_t *keys = malloc(((size_t)sc->obj.triangle_count * 3 + 1) * sizeof *keys);
    size_t n = 0;
    uint32_t t;
    unsigned k;
    if (keys == NULL)
        return 0;
    for (t = 0; t < sc->obj.triangle_count; t++)
        for (k = 0; k < 3 && sc->tris[t].visible; k++)
            keys[n++] = edge_key(sc, t, k);
    qsort(keys, n, sizeof *keys, cmp_u64);
    for (t = 0; t < sc->obj.triangle_count; t++)
        for (k = 0; k < 3 && sc->tris[t].visible; k++) {
            uint64_t key = edge_key(sc, t, k);
            size_t lo = 0, hi = n;
            while (lo < hi) { /* first key >= key */
                size_t mid = (lo + hi) / 2;
                if (keys[mid] < key)
                    lo = mid + 1;
                else
                    hi = mid;
            }
            sc->tris[t].border[k] = (uint8_t)(lo + 1 >= n || keys[lo + 1] != key);
        }
    free(keys);
    return 1;
}

/* Pass 0: the nearest cover of every pixel, and whether a border edge passes
 * near; pass 1: the candidates (near the border, any depth). */
static void visit(scene *sc, px_state *px, int pass)
{
    uint32_t t;
    int32_t x, y;
    for (t = 0; t < sc->obj.triangle_count; t++) {
        const tri_rec *r = &sc->tris[t];
        if (!r->visible)
            continue;
        for (y = r->by0 < 0 ? 0 : r->by0; y <= r->by1 && y < sc->o.h; y++)
            for (x = r->bx0 < 0 ? 0 : r->bx0; x <= r->bx1 && x < sc->o.w; x++) {
                px_state *s = &px[y * sc->o.w + x];
                int near_border, cov = coverage(r, x, y, &near_border);
                zt_depth_ref d;
                if (cov == 0)
                    continue;
                tri_depth(r, x, y, &d);
                if (pass == 0) {
                    s->near_border |= (uint8_t)near_border;
                    if (zt_tri_covers(&r->t, x, y) && d.nearest < s->zsure)
                        s->zsure = d.nearest;
                } else if (s->near_border || d.nearest <= s->zsure + DEPTH_SLACK) {
                    if (s->n < MAX_CAND)
                        s->cand[s->n++] = t;
                    else
                        s->overflow = 1;
                }
            }
    }
}

static int in_range(const uint16_t *got, const int *lo, const int *hi)
{
    int c;
    for (c = 0; c < 3; c++)
        if (got[c] < lo[c] || got[c] > hi[c])
            return 0;
    return 1;
}

int main(int argc, char **argv)
{
    static scene sc;
    zl_obj_options lopt;
    zl_pnm_image img;
    zl_mat4 mvp;
    zl_fixed near_z, far_z;
    px_state *px;
    char msg[512];
    uint32_t i;
    int32_t x, y;
    long judged = 0, skipped = 0, bad = 0, covered = 0;
    if (argc < 3 || !parse(argc, argv, &sc.o)) {
        fprintf(stderr, "usage: golden_check IMAGE.ppm MODEL.obj [zline-render options]\n");
        return 2;
    }
    sc.tol = sc.o.rgb565 ? 8 : 2;
    sc.light[0] = -1.0;
    sc.light[1] = 2.0;
    sc.light[2] = 2.0;
    zl_obj_options_default(&lopt);
    lopt.normalize = 1;
    if (zl_obj_load_file(&sc.obj, argv[2], &lopt, msg, sizeof msg) != ZL_OBJ_OK ||
        zl_pnm_read(&img, argv[1], msg, sizeof msg) != ZL_PNM_OK) {
        fprintf(stderr, "golden_check: %s\n", msg);
        return 2;
    }
    if (img.width != (uint32_t)sc.o.w || img.height != (uint32_t)sc.o.h || img.channels != 3 || img.maxval != 255 ||
        !camera(&sc.o, &mvp, &near_z, &far_z)) {
        fprintf(stderr, "golden_check: %s is not a %dx%d P6 image (or the camera is invalid)\n", argv[1], sc.o.w,
                sc.o.h);
        return 2;
    }
    /* zline-render's grey ramp spans the vertices' depth range */
    sc.dmin = 65535;
    sc.dmax = 0;
    for (i = 0; i < sc.obj.vertex_count; i++) {
        zl_vec3 p = {sc.obj.positions[3 * i], sc.obj.positions[3 * i + 1], sc.obj.positions[3 * i + 2]};
        zl_vec4 c;
        uint16_t d;
        if (zl_transform_point(&mvp, p, &c) != ZL_OK)
            continue;
        d = zl_depth_of_distance(near_z, far_z, c.w);
        sc.dmin = d < sc.dmin ? d : sc.dmin;
        sc.dmax = d > sc.dmax ? d : sc.dmax;
    }
    sc.tris = calloc(sc.obj.triangle_count + 1u, sizeof *sc.tris);
    px = calloc((size_t)sc.o.w * (size_t)sc.o.h, sizeof *px);
    if (sc.tris == NULL || px == NULL)
        return 2;
    if (!setup_triangles(&sc, &mvp) || !find_borders(&sc))
        return 2;
    for (i = 0; i < (uint32_t)(sc.o.w * sc.o.h); i++)
        px[i].zsure = 1 << 30;
    visit(&sc, px, 0);
    visit(&sc, px, 1);
    for (y = 0; y < sc.o.h; y++)
        for (x = 0; x < sc.o.w; x++) {
            const px_state *s = &px[y * sc.o.w + x];
            const uint16_t *got = &img.samples[((size_t)y * sc.o.w + x) * 3];
            int lo[3], hi[3], c, ok = 0, any = 0;
            unsigned k;
            if (s->overflow) {
                skipped++;
                continue;
            }
            if (s->zsure == 1 << 30 || s->near_border) { /* the background is possible */
                for (c = 0; c < 3; c++) {
                    lo[c] = sc.o.bg[c] - (sc.o.rgb565 ? sc.tol : 0);
                    hi[c] = sc.o.bg[c] + (sc.o.rgb565 ? sc.tol : 0);
                }
                ok |= in_range(got, lo, hi);
                any = 1;
            }
            covered += s->zsure != 1 << 30;
            for (k = 0; k < s->n && !ok; k++) {
                if (!expected(&sc, s->cand[k], x, y, lo, hi)) {
                    ok = 1; /* a candidate not judged: the pixel is not judged */
                    skipped++;
                    judged--;
                    break;
                }
                ok |= in_range(got, lo, hi);
                any = 1;
            }
            judged++;
            if (!ok && any) {
                if (bad < 5)
                    fprintf(stderr, "pixel (%d,%d): %u,%u,%u, none of its %u candidate(s)%s matches\n", (int)x, (int)y,
                            got[0], got[1], got[2], (unsigned)s->n, s->zsure == 1 << 30 ? " or the background" : "");
                bad++;
            }
        }
    printf("golden_check %s: %ld pixels judged (%ld covered), %ld not judged, %ld wrong\n", argv[1], judged, covered,
           skipped, bad);
    zl_pnm_image_free(&img);
    zl_obj_free(&sc.obj);
    free(sc.tris);
    free(px);
    /* a check that judged almost nothing proves nothing */
    if (judged * 10 < 9L * sc.o.w * sc.o.h || covered * 20 < judged) {
        fprintf(stderr, "golden_check: too few pixels judged\n");
        return 1;
    }
    return bad != 0;
}

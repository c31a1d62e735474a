/* SPDX-License-Identifier: MIT */
/*
 * Stage 4, primitives: lines and points (the LINE RULE of zline.h), the style, and the pieces a
 * triangle becomes under the polygon modes.
 *
 * A segment is set up once into an active record that is then walked row by
 * row (zl_prim_row), so frame mode and the scanline/band modes draw it with
 * the same steps. Along the major axis u = 0 .. DM from the endpoint with
 * the smaller major coordinate, the minor coordinate is
 *     minor(u) = N0 + ceil((C + u a) / D)
 * with (Bresenham) a = 2 DN, D = 2 DM, C = -DM: the nearest integer to
 * N0 + u DN / DM, halves rounding down; or (DDA) a = DN / DM in 16.16,
 * D = 2^16, C = 1/2 - 1 in 16.16: floor of the fixed-point value + 1/2.
 * Either is kept as quotient and remainder and stepped by addition with a
 * carry, exactly like a triangle edge (zl_edge): Bresenham's decision
 * variable is the remainder. The record starts at the end nearer the top
 * row, after skipping (by one division at setup) what lies outside the
 * target, so rows come top to bottom and cost only their own pixels.
 */
#include "../1_base/zl_internal.h"

void zl_style_default(zl_style *s)
{
    s->polygon_front = ZL_POLY_FILL;
    s->polygon_back = ZL_POLY_FILL;
    s->point_size = 1;
    s->line_algo = ZL_LINE_BRESENHAM;
    s->offset_factor = 0;
    s->offset_units = 0;
    s->texture = NULL;
    s->texcoords = NULL;
    s->tex_mapping = ZL_TEX_AFFINE;
    s->tex_every = 0;
    s->persp_gouraud = 0;
    s->toon_bands = 0;
    s->toon_colors = NULL;
    s->line_aa = 0;
    s->blend = ZL_BLEND_OFF;
    s->alpha = 255;
    s->tex_filter = ZL_FILTER_NEAREST;
}

static int tex_size(uint16_t n)
{
    return n >= 1 && n <= 4096;
}

zl_status zl_style_check(const zl_style *s)
{
    if (s == NULL)
        return ZL_ERR_ARG;
    if (s->polygon_front > ZL_POLY_POINT || s->polygon_back > ZL_POLY_POINT || s->line_algo > ZL_LINE_DDA)
        return ZL_ERR_ARG;
    if (s->point_size < 1 || s->point_size > ZL_MAX_POINT_SIZE)
        return ZL_ERR_RANGE;
    if (s->offset_factor > ZL_FX_INT(256) || s->offset_factor < -ZL_FX_INT(256))
        return ZL_ERR_RANGE;
    if (s->tex_mapping > ZL_TEX_PERSPECTIVE || s->persp_gouraud > 1 || s->line_aa > 1 || (s->toon_bands > 0 && s->toon_colors == NULL))
        return ZL_ERR_ARG;
    if (s->blend > ZL_BLEND_ADD || s->tex_filter > ZL_FILTER_BILINEAR)
        return ZL_ERR_ARG;
    if (s->tex_every > 1 && (s->tex_every > 64 || (s->tex_every & (s->tex_every - 1u)) != 0))
        return ZL_ERR_RANGE;
    if ((!ZL_FEATURE_TEXTURES && (s->texture != NULL || s->persp_gouraud)) ||
        (!ZL_FEATURE_BLEND && s->blend != ZL_BLEND_OFF) ||
        (!ZL_FEATURE_LINES && (s->polygon_front != ZL_POLY_FILL || s->polygon_back != ZL_POLY_FILL)) ||
        (!ZL_FEATURE_OFFSET && (s->offset_factor != 0 || s->offset_units != 0)))
        return ZL_ERR_UNSUPPORTED; /* compiled out (zl_config.h) */
    if (s->texture != NULL) {
        const zl_texture *t = s->texture;
        if (t->texels == NULL || s->texcoords == NULL || t->wrap_s > ZL_WRAP_CLAMP || t->wrap_t > ZL_WRAP_CLAMP ||
            t->format > ZL_TEXEL_RGBA4444)
            return ZL_ERR_ARG;
        if (!tex_size(t->width) || !tex_size(t->height) || t->stride < t->width)
            return ZL_ERR_SIZE;
    }
    return ZL_OK;
}

uint32_t zl_lines_primitives(const zl_lines *l)
{
    if (l == NULL)
        return 0;
    switch (l->prim) {
    case ZL_PRIM_LINES:
        return l->count / 2u;
    case ZL_PRIM_LINE_STRIP:
        return l->count >= 2 ? l->count - 1u : 0u;
    case ZL_PRIM_LINE_LOOP:
        return l->count >= 2 ? l->count : 0u;
    case ZL_PRIM_POINTS:
        return l->count;
    default:
        return 0;
    }
}

static int64_t max64(int64_t a, int64_t b)
{
    return a > b ? a : b;
}

static int64_t min64(int64_t a, int64_t b)
{
    return a < b ? a : b;
}

/* Narrow [*lo, *hi] to the u with u a > c. */
static void keep_greater(int64_t a, int64_t c, int64_t *lo, int64_t *hi)
{
    if (a > 0)
        *lo = max64(*lo, zl_floor_div64(c, a) + 1);
    else if (a < 0)
        *hi = min64(*hi, zl_ceil_div64(-c, -a) - 1);
    else if (!(0 > c))
        *hi = *lo - 1;
}

/* Narrow [*lo, *hi] to the u with u a <= c. */
static void keep_at_most(int64_t a, int64_t c, int64_t *lo, int64_t *hi)
{
    if (a > 0)
        *hi = min64(*hi, zl_floor_div64(c, a));
    else if (a < 0)
        *lo = max64(*lo, zl_ceil_div64(-c, -a));
    else if (!(0 <= c))
        *hi = *lo - 1;
}

static int32_t pixel_of(int32_t sub)
{
    return (int32_t)zl_floor_shift64(sub, ZL_SUB_BITS);
}

/* Endpoint depth plus an offset (Q20 steps), clamped to the range, Q16. */
static int64_t offset_depth(uint32_t z, int64_t offset_q20)
{
    int64_t v = (int64_t)z + zl_floor_shift64(offset_q20, ZL_ATTR_FRAC - 16);
    const int64_t top = (int64_t)65535 << 16;
    return v < 0 ? 0 : (v > top ? top : v);
}

int zl_line_setup(zl_active *t, const zl_segment *seg, unsigned algo, int64_t offset_q20, uint16_t width,
                  uint16_t height)
{
    if (!ZL_FEATURE_LINES) /* unreachable then (zl_style_check, zl_check_lines): the code goes */
        return 0;
    int32_t xa = pixel_of(seg->a.x), ya = pixel_of(seg->a.y), xb = pixel_of(seg->b.x), yb = pixel_of(seg->b.y);
    int64_t za = offset_depth(seg->a.z, offset_q20), zb = offset_depth(seg->b.z, offset_q20);
    int64_t dxab = (int64_t)xb - xa, dyab = (int64_t)yb - ya;
    int xmajor = (dxab < 0 ? -dxab : dxab) >= (dyab < 0 ? -dyab : dyab);
    int64_t m0, n0, dm, dn, z0, z1, a, d, c, lo, hi, us, ue, n, q, as, step, dz;
    int64_t lmaj = xmajor ? width : height, lmin = xmajor ? height : width;
    unsigned skip0, skip1;
    int dir;
    /* Canonical start: the end with the smaller major coordinate. */
    int a_first = xmajor ? xa <= xb : ya <= yb;
    if (xmajor) {
        m0 = a_first ? xa : xb;
        n0 = a_first ? ya : yb;
        dm = a_first ? dxab : -dxab;
        dn = a_first ? dyab : -dyab;
    } else {
        m0 = a_first ? ya : yb;
        n0 = a_first ? xa : xb;
        dm = a_first ? dyab : -dyab;
        dn = a_first ? dxab : -dxab;
    }
    z0 = a_first ? za : zb;
    z1 = a_first ? zb : za;
    skip0 = a_first ? (seg->skip & 1u) : (seg->skip & 2u);
    skip1 = a_first ? (seg->skip & 2u) : (seg->skip & 1u);
    if (dm == 0) {
        a = 0;
        d = 1;
        c = 0;
    } else if (algo == ZL_LINE_DDA) {
        a = zl_round_div64(dn * 65536, dm);
        d = 65536;
        c = -32767;
    } else {
        a = 2 * dn;
        d = 2 * dm;
        c = -dm;
    }
    /* Visible u: the segment minus skipped ends, major and minor in view. */
    lo = skip0 ? 1 : 0;
    hi = skip1 ? dm - 1 : dm;
    lo = max64(lo, -m0);
    hi = min64(hi, lmaj - 1 - m0);
    keep_greater(a, (-n0 - 1) * d - c, &lo, &hi);  /* minor >= 0 */
    keep_at_most(a, (lmin - 1 - n0) * d - c, &lo, &hi); /* minor <= lmin - 1 */
    if (lo > hi)
        return 0;
    /* Walk from the end nearer the top row. */
    dir = (xmajor && a < 0) ? -1 : 1;
    us = dir > 0 ? lo : hi;
    ue = dir > 0 ? hi : lo;
    n = c + us * a;
    q = zl_ceil_div64(n, d);
    as = dir * a;
    step = zl_floor_div64(as, d);
    t->left.x = (int32_t)(n0 + q);
    t->left.rem = (int32_t)(q * d - n);
    t->left.den = (int32_t)d;
    t->left.step = (int32_t)step;
    t->left.rstep = (int32_t)(as - step * d);
    t->ax = (int32_t)(m0 + us);
    t->right.x = (int32_t)(hi - lo + 1);
    t->right.step = dir;
    t->right.rem = 0;
    t->right.rstep = 0;
    t->right.den = 0;
    /* Depth Q32 (Q16 scale times 2^16), stepped exactly from u = 0, so it is
     * the same value whichever end the walk starts from. */
    dz = dm == 0 ? 0 : zl_round_div64((z1 - z0) * 65536, dm);
    t->z.row = z0 * 65536 + us * dz;
    t->z.dx = dir * dz;
    t->z.dy = 0;
    if (xmajor) {
        t->row = (int16_t)t->left.x;
        t->end = (int16_t)(n0 + zl_ceil_div64(c + ue * a, d) + 1);
    } else {
        t->row = (int16_t)(m0 + lo);
        t->end = (int16_t)(m0 + hi + 1);
    }
    t->mid = t->end;
    t->lower_is_left = (uint8_t)xmajor;
    t->zlo = 0;
    t->zhi = 0;
    t->kind = ZL_KIND_LINE;
    t->rgb[0] = seg->rgb.r;
    t->rgb[1] = seg->rgb.g;
    t->rgb[2] = seg->rgb.b;
    return 1;
}

int zl_line_setup_aa(zl_active *t, const zl_segment *seg, int64_t offset_q20, uint16_t width, uint16_t height)
{
    if (!ZL_FEATURE_LINES) /* compiled out (zl_config.h): unreachable, the code goes */
        return 0;
    int32_t xa = pixel_of(seg->a.x), ya = pixel_of(seg->a.y), xb = pixel_of(seg->b.x), yb = pixel_of(seg->b.y);
    int64_t za = offset_depth(seg->a.z, offset_q20), zb = offset_depth(seg->b.z, offset_q20);
    int64_t dxab = (int64_t)xb - xa, dyab = (int64_t)yb - ya;
    int xmajor = (dxab < 0 ? -dxab : dxab) >= (dyab < 0 ? -dyab : dyab);
    int a_first = xmajor ? xa <= xb : ya <= yb;
    int64_t m0 = xmajor ? (a_first ? xa : xb) : (a_first ? ya : yb);
    int64_t n0 = xmajor ? (a_first ? ya : yb) : (a_first ? xa : xb);
    int64_t dm = xmajor ? (a_first ? dxab : -dxab) : (a_first ? dyab : -dyab);
    int64_t dn = xmajor ? (a_first ? dyab : -dyab) : (a_first ? dxab : -dxab);
    int64_t z0 = a_first ? za : zb, z1 = a_first ? zb : za;
    unsigned skip0 = a_first ? (seg->skip & 1u) : (seg->skip & 2u), skip1 = a_first ? (seg->skip & 2u) : (seg->skip & 1u);
    int64_t lmaj = xmajor ? width : height, lmin = xmajor ? height : width;
    /* floor(n) = N0 + floor(u DN / DM) = N0 + ceil((u DN - (DM - 1)) / DM) */
    int64_t a = dm == 0 ? 0 : dn, d = dm == 0 ? 1 : dm, c = -(d - 1);
    int64_t lo = skip0 ? 1 : 0, hi = skip1 ? dm - 1 : dm, us, ue, n, q, as, step, dz;
    int dir;
    lo = max64(lo, -m0);
    hi = min64(hi, lmaj - 1 - m0);
    keep_greater(a, (-n0 - 2) * d - c, &lo, &hi);   /* floor(n) >= -1 */
    keep_at_most(a, (lmin - 1 - n0) * d - c, &lo, &hi); /* floor(n) <= lmin - 1 */
    if (lo > hi)
        return 0;
    dir = (xmajor && a < 0) ? -1 : 1;
    us = dir > 0 ? lo : hi;
    ue = dir > 0 ? hi : lo;
    n = c + us * a;
    q = zl_ceil_div64(n, d);
    as = dir * a;
    step = zl_floor_div64(as, d);
    t->left.x = (int32_t)(n0 + q);
    t->left.rem = (int32_t)(q * d - n);
    t->left.den = (int32_t)d;
    t->left.step = (int32_t)step;
    t->left.rstep = (int32_t)(as - step * d);
    t->ax = (int32_t)(m0 + us);
    t->right.x = (int32_t)(hi - lo + 1);
    t->right.step = dir;
    t->right.rem = t->right.rstep = t->right.den = 0;
    dz = dm == 0 ? 0 : zl_round_div64((z1 - z0) * 65536, dm);
    t->z.row = z0 * 65536 + us * dz;
    t->z.dx = dir * dz;
    t->z.dy = 0;
    if (xmajor) {
        int64_t last = n0 + zl_ceil_div64(c + ue * a, d) + 2;
        t->row = (int16_t)max64(t->left.x, 0);
        t->end = (int16_t)min64(last, height);
    } else {
        t->row = (int16_t)(m0 + lo);
        t->end = (int16_t)(m0 + hi + 1);
    }
    if (t->row >= t->end)
        return 0;
    t->mid = t->end;
    t->lower_is_left = (uint8_t)xmajor;
    t->zlo = t->zhi = 0;
    t->kind = ZL_KIND_LINE_AA;
    t->rgb[0] = seg->rgb.r;
    t->rgb[1] = seg->rgb.g;
    t->rgb[2] = seg->rgb.b;
    return 1;
}

int zl_point_setup(zl_active *t, const zl_lvert *p, zl_rgb rgb, unsigned size, int64_t offset_q20, uint16_t width,
                   uint16_t height)
{
    if (!ZL_FEATURE_LINES) /* compiled out (zl_config.h): unreachable, the code goes */
        return 0;
    /* Centres in (x - N/2, x + N/2]: the first index is
     * floor((x - N/2 - 1/2) / 1) + 1, the last floor(x + N/2 - 1/2). */
    int64_t half = (int64_t)size * ZL_SUB_HALF;
    int64_t x0 = zl_floor_shift64((int64_t)p->x - half - ZL_SUB_HALF, ZL_SUB_BITS) + 1;
    int64_t y0 = zl_floor_shift64((int64_t)p->y - half - ZL_SUB_HALF, ZL_SUB_BITS) + 1;
    int64_t x1 = x0 + size, y1 = y0 + size; /* exclusive */
    x0 = max64(x0, 0);
    y0 = max64(y0, 0);
    x1 = min64(x1, width);
    y1 = min64(y1, height);
    if (x0 >= x1 || y0 >= y1)
        return 0;
    t->left.x = (int32_t)x0;
    t->right.x = (int32_t)x1;
    t->row = (int16_t)y0;
    t->end = (int16_t)y1;
    t->mid = t->end;
    t->z.row = offset_depth(p->z, offset_q20) * 65536;
    t->z.dx = 0;
    t->z.dy = 0;
    t->kind = ZL_KIND_POINT;
    t->rgb[0] = rgb.r;
    t->rgb[1] = rgb.g;
    t->rgb[2] = rgb.b;
    return 1;
}

/* Offset of lines and points without a polygon: units only. */
static int64_t units_offset(const zl_style *sty)
{
    return (int64_t)sty->offset_units * (1 << (ZL_ATTR_FRAC - 16));
}

int zl_lines_record(const zl_source *s, const zl_lines *l, const zl_style *sty, const zl_state *st, uint32_t k,
                    zl_active *out)
{
    if (!ZL_FEATURE_LINES) /* compiled out (zl_config.h): unreachable, the code goes */
        return 0;
    zl_rgb rgb = st->color;
    uint32_t ia, ib;
    if (l->colors != NULL) {
        rgb.r = l->colors[k * 3];
        rgb.g = l->colors[k * 3 + 1];
        rgb.b = l->colors[k * 3 + 2];
    }
    if (l->prim == ZL_PRIM_POINTS) {
        zl_lvert p;
        uint16_t idx = l->indices ? l->indices[k] : (uint16_t)k;
        if (!zl_point_make(s, idx, &p))
            return 0;
        return zl_point_setup(out, &p, rgb, sty->point_size, units_offset(sty), s->width, s->height);
    } else {
        zl_segment seg;
        int skip_a = 0, skip_b = 0;
        if (l->prim == ZL_PRIM_LINES) {
            ia = 2 * k;
            ib = 2 * k + 1;
        } else {
            ia = k;
            ib = k + 1 < l->count ? k + 1 : 0; /* a loop closes on index 0 */
            skip_a = k > 0;
            skip_b = l->prim == ZL_PRIM_LINE_LOOP && k + 1 == l->count;
        }
        if (l->indices != NULL) {
            ia = l->indices[ia];
            ib = l->indices[ib];
        }
        if (!zl_segment_make(s, (uint16_t)ia, (uint16_t)ib, skip_a, skip_b, &seg))
            return 0;
        seg.rgb = rgb;
        if (sty->line_aa)
            return zl_line_setup_aa(out, &seg, units_offset(sty), s->width, s->height);
        return zl_line_setup(out, &seg, sty->line_algo, units_offset(sty), s->width, s->height);
    }
}

/* ------------------------------------------------------ polygon modes */

/* Mode of a triangle under the style, or -1 when it is culled or has no
 * area; *plane gets its first fan triangle with area (for the offset). */
static int tri_mode(const zl_source *s, const zl_style *sty, const zl_poly *poly, unsigned *plane)
{
    const zl_state *st = s->state;
    unsigned k;
    for (k = 1; k + 1 < poly->n; k++) {
        const zl_wvert *a = &poly->v[0], *b = &poly->v[k], *c = &poly->v[k + 1];
        int64_t area = ((int64_t)b->x - a->x) * ((int64_t)c->y - a->y) - ((int64_t)c->x - a->x) * ((int64_t)b->y - a->y);
        int front;
        if (area == 0)
            continue;
        front = (area < 0) == (st->front_face == ZL_FRONT_CCW);
        if ((st->cull == ZL_CULL_BACK && !front) || (st->cull == ZL_CULL_FRONT && front))
            return -1;
        *plane = k;
        return front ? sty->polygon_front : sty->polygon_back;
    }
    return -1;
}

static int uses_modes(const zl_style *sty)
{
    /* (compiled out with ZL_FEATURE_LINES: zl_style_check refuses the modes) */
    return ZL_FEATURE_LINES && sty != NULL && (sty->polygon_front != ZL_POLY_FILL || sty->polygon_back != ZL_POLY_FILL);
}

unsigned zl_tri_pieces(const zl_source *s, const zl_style *sty, uint32_t tri, const zl_poly *poly)
{
    unsigned plane;
    int mode;
    (void)tri;
    if (!uses_modes(sty))
        return (unsigned)poly->n - 2u;
    mode = tri_mode(s, sty, poly, &plane);
    if (mode < 0)
        return 0;
    return mode == ZL_POLY_FILL ? (unsigned)poly->n - 2u : 3u;
}

/* The flat colour of a triangle: toon band or its lit colour. */
static zl_rgb flat_of(const zl_style *sty, const zl_poly *poly)
{
    if (sty != NULL && sty->toon_bands > 0) {
        unsigned band = (unsigned)poly->light * sty->toon_bands / 256u;
        return sty->toon_colors[band];
    }
    return poly->flat;
}

/* Move the anchor column of a set-up record's planes to ax: the same
 * planes, exactly (no rounding: value plus whole pixels of change). */
static ZL_NOINLINE void reanchor(zl_active *t, zl_gouraud *g, zl_texplanes *tp, int32_t ax)
{
    int64_t d = (int64_t)ax - t->ax;
    unsigned k;
    t->z.row += d * t->z.dx;
    if (g != NULL)
        for (k = 0; k < 3; k++)
            g->c[k].row += d * g->c[k].dx;
    tp->u.row += d * tp->u.dx;
    tp->v.row += d * tp->v.dx;
    tp->q.row += d * tp->q.dx;
    t->ax = ax;
}

/* The least clip w of a textured polygon (poly is the p of a zl_tpoly:
 * zl_tri_setup_ex's contract when the style needs planes). Out of line, as
 * reanchor: nothing of it is on the stack under the plane solves. */
static ZL_NOINLINE int32_t poly_wmin(const zl_poly *poly)
{
    const zl_tpoly *tpoly = (const zl_tpoly *)(const void *)poly;
    int32_t wmin = tpoly->w[0];
    unsigned k;
    for (k = 1; k < poly->n; k++)
        wmin = tpoly->w[k] < wmin ? tpoly->w[k] : wmin;
    return wmin;
}

/* A piece of a clipped polygon, set up from its own (clipped, snapped)
 * vertices: give it the depth, colour and texture planes of the original
 * triangle instead (zline.h, Clipping). Out of line: its frame is not on
 * the stack of the unclipped path. */
ZL_NOINLINE void zl_tri_orig_piece(const zl_source *s, const zl_style *sty, uint32_t tri, const zl_poly *poly,
                                   const zl_wvert *a, const zl_wvert *b, const zl_wvert *c, zl_active *t, zl_gouraud *g,
                                   zl_texplanes *tp)
{
    zl_attr z, col[3];
    int planes = (ZL_FEATURE_TEXTURES || ZL_FEATURE_BLEND) && tp != NULL && zl_style_needs_planes(sty);
    int gouraud = g != NULL && s->state->shading == ZL_SHADE_GOURAUD;
    int persp_colour = gouraud && sty != NULL && sty->persp_gouraud;
    int got;
    /* The texture span loops step u q and q from the anchor column by their
     * rounded change per pixel, in units of 2^16 / q texel: at far pixels
     * (small q) of a piece reaching into the guard band, hundreds of pixels
     * from its anchor, that added up to texels. An anchor in the target
     * keeps every pixel within a row's width of it. */
    if (planes && (t->ax < 0 || t->ax >= (int32_t)s->width))
        reanchor(t, gouraud ? g : NULL, tp, t->ax < 0 ? 0 : (int32_t)s->width - 1); /* g: set up when Gouraud */
    got = zl_tri_orig_planes(s, tri, t->ax, t->row, gouraud && !persp_colour, poly->light, &z, col);
    if (got == 0)
        return;
    zl_tri_set_planes(t, g, a, b, c, &z, (got & 2) ? col : NULL, !zl_style_needs_planes(sty));
    if (planes)
        (void)zl_tri_orig_texplanes(s, sty, tri, t, poly_wmin(poly), tp, persp_colour ? g->c : NULL);
}

int zl_tri_piece(const zl_source *s, const zl_style *sty, uint32_t tri, const zl_poly *poly, unsigned k,
                 zl_active *t, zl_gouraud *g, zl_texplanes *tp)
{
    unsigned plane = 1;
    int mode = ZL_POLY_FILL;
    int64_t off;
    zl_rgb flat = flat_of(sty, poly);
    if (uses_modes(sty)) {
        mode = tri_mode(s, sty, poly, &plane);
        if (mode < 0)
            return 0;
    }
    if (mode == ZL_POLY_FILL) {
        if (!zl_tri_setup_ex(t, g, tp, sty, &poly->v[0], &poly->v[k + 1], &poly->v[k + 2], poly, s->state,
                             s->width, s->height))
            return 0;
        t->rgb[0] = flat.r;
        t->rgb[1] = flat.g;
        t->rgb[2] = flat.b;
        if (ZL_FEATURE_EXACT_CLIP && poly->clipped) { /* off: the piece's own planes (zl_config.h) */
            zl_tri_orig_piece(s, sty, tri, poly, &poly->v[0], &poly->v[k + 1], &poly->v[k + 2], t, g, tp);
            off = ZL_FEATURE_OFFSET ? zl_tri_offset_plane(&t->z, sty) : 0; /* off: none (zl_style_check) */
        } else {
            off = ZL_FEATURE_OFFSET ? zl_tri_offset(&poly->v[0], &poly->v[k + 1], &poly->v[k + 2], sty) : 0;
        }
        if (off != 0)
            zl_tri_apply_offset(t, off);
        return 1;
    }
    if (!ZL_FEATURE_LINES) /* compiled out (zl_config.h): no line or point modes (zl_style_check) */
        return 0;
    /* Line and point pieces: offset by the slope of the triangle's plane. */
    off = zl_tri_offset(&poly->v[0], &poly->v[plane], &poly->v[plane + 1], sty);
    {
        const uint16_t *idx = &s->mesh->indices[tri * 3u];
        if (mode == ZL_POLY_LINE) {
            zl_segment seg;
            if (!zl_segment_make(s, idx[k], idx[(k + 1) % 3u], 0, 0, &seg))
                return 0;
            seg.rgb = flat;
            if (sty->line_aa)
                return zl_line_setup_aa(t, &seg, off, s->width, s->height);
            return zl_line_setup(t, &seg, sty->line_algo, off, s->width, s->height);
        } else {
            zl_lvert p;
            if (!zl_point_make(s, idx[k], &p))
                return 0;
            return zl_point_setup(t, &p, flat, sty->point_size, off, s->width, s->height);
        }
    }
}

/* A mesh view of a zl_lines, for the vertex transform. */
void zl_lines_mesh(const zl_lines *l, zl_mesh *m)
{
    m->positions = l->positions;
    m->indices = NULL;
    m->vertex_colors = NULL;
    m->face_colors = NULL;
    m->vertex_count = 0; /* nothing to cache: lines are transformed per segment */
    m->triangle_count = (uint16_t)zl_lines_primitives(l);
}

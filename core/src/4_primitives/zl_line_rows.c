/* SPDX-License-Identifier: MIT */
/*
 * Stage 4, primitives: the rows of lines and points (the LINE RULE of
 * zline.h): one record per segment stepped along its major axis, depth
 * tested and written per pixel, and the anti-aliased coverage blend.
 */
#include <string.h>

#include "../3_raster/zl_raster.h"

/* ------------------------------------------------------ lines and points */

/* Stored depth of a Q32 line depth, clamped to the range. */
static inline uint32_t line_depth(int64_t zq32)
{
    int64_t d = zl_floor_shift64(zq32 + ((int64_t)1 << 31), 32);
    return (uint32_t)clamp64(d, 0, 65535);
}

static inline void plot(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t x, uint32_t d,
                        const uint8_t *pix)
{
    unsigned func = ss->func;
    if (x < 0 || x >= ss->width)
        return;
    if (func != ZL_ALWAYS && !depth_pass(func, d, zrow[x]))
        return;
    if (ss->zwrite)
        zrow[x] = (uint16_t)d;
    if (ss->bpp != 0)
        put_pixel(crow + (size_t)x * ss->bpp, ss->bpp, pix, ss->keep);
}

/* floor(x / 255) for 0 <= x <= 65534, without a division: exact there
 * (checked for every such x), and for two 16-bit lanes at once (below). */
static ZL_ALWAYS_INLINE uint32_t div255_floor(uint32_t x)
{
    return (x + 1u + (x >> 8)) >> 8;
}

/* The coverage blend of a native RGB565 pixel with all channels written:
 * blend()'s values, (old (255 - w) + c w + 127) / 255 per channel, with red
 * and blue in the two 16-bit lanes of one word (each sum is at most
 * 255 * 255 + 127, so no lane carries into the other) and no division. */
static ZL_ALWAYS_INLINE uint16_t blend565(uint16_t v, uint32_t crb, uint32_t cg, unsigned w)
{
    uint32_t r5 = (uint32_t)v >> 11, g6 = ((uint32_t)v >> 5) & 63u, b5 = (uint32_t)v & 31u;
    uint32_t orb = (((r5 << 3) | (r5 >> 2)) << 16) | ((b5 << 3) | (b5 >> 2));
    uint32_t og = (g6 << 2) | (g6 >> 4);
    uint32_t xrb = orb * (255u - w) + crb * w + UINT32_C(0x007F007F);
    uint32_t xg = og * (255u - w) + cg * w + 127u;
    uint32_t rb = ((xrb + UINT32_C(0x00010001) + ((xrb >> 8) & UINT32_C(0x00FF00FF))) >> 8) & UINT32_C(0x00FF00FF);
    uint32_t g = div255_floor(xg);
    return (uint16_t)(((rb >> 19) << 11) | ((g >> 2) << 5) | ((rb & 0xFFu) >> 3));
}

/* Blend colour (r, g, b) into pixel x with weight w (0..255), after the
 * depth test; antialiased lines never write depth. */
static void blend(const zl_span_state *ss, const zl_active *t, uint8_t *crow, uint16_t *zrow, int32_t x, uint32_t d,
                  unsigned w)
{
    uint8_t *p, pix[3] = {0, 0, 0};
    unsigned old[3], k;
    if (w == 0 || x < 0 || x >= ss->width || ss->bpp == 0)
        return;
    if (ss->func != ZL_ALWAYS && !depth_pass(ss->func, d, zrow[x]))
        return;
    p = crow + (size_t)x * ss->bpp;
    if (ss->format == ZL_FORMAT_RGB565 && ss->keep[0] == 0 && ss->keep[1] == 0) {
        uint16_t v;
        memcpy(&v, p, 2);
        v = blend565(v, ((uint32_t)t->rgb[0] << 16) | t->rgb[2], t->rgb[1], w);
        memcpy(p, &v, 2);
        return;
    }
    if (ss->format == ZL_FORMAT_RGB888) {
        old[0] = p[0];
        old[1] = p[1];
        old[2] = p[2];
    } else {
        uint16_t v;
        unsigned r5, g6, b5;
        if (ss->format == ZL_FORMAT_RGB565)
            memcpy(&v, p, 2);
        else
            v = (uint16_t)(((unsigned)p[0] << 8) | p[1]);
        r5 = v >> 11;
        g6 = (v >> 5) & 63u;
        b5 = v & 31u;
        old[0] = (r5 << 3) | (r5 >> 2);
        old[1] = (g6 << 2) | (g6 >> 4);
        old[2] = (b5 << 3) | (b5 >> 2);
    }
    for (k = 0; k < 3; k++)
        old[k] = (unsigned)div255_floor(old[k] * (255u - w) + t->rgb[k] * w + 127u);
    pack_color((zl_format)ss->format, old[0], old[1], old[2], pix);
    put_pixel(p, ss->bpp, pix, ss->keep);
}

/* Weight (0..255) of the pixel below the ideal line: its distance to the
 * upper pixel's centre, the fraction f / D of a pixel, rounded:
 * floor((255 f + D / 2) / D), in 32 bits when it fits. */
static inline unsigned aa_weight(const zl_edge *e)
{
    int64_t f = (int64_t)e->den - 1 - e->rem;
    if (e->den < (INT32_C(1) << 23))
        return (unsigned)(((uint32_t)f * 255u + (uint32_t)e->den / 2u) / (uint32_t)e->den);
    return (unsigned)((f * 255 + e->den / 2) / e->den);
}

/* aa_weight stepped along a run without a division: with
 * 255 f + D / 2 = w D + r (0 <= r < D) and 255 rstep = qs D + rs, a step
 * (f += rstep, less D where the edge's remainder wraps) adds qs to w and rs
 * to r, carries one when r reaches D, and takes 255 off at a wrap. */
typedef struct {
    int32_t w, r, qs, rs;
} zl_aa_weight;

static void aa_weight_init(zl_aa_weight *a, const zl_edge *e)
{
    int64_t f = (int64_t)e->den - 1 - e->rem, num = f * 255 + e->den / 2, s = (int64_t)e->rstep * 255;
    if (e->den < (INT32_C(1) << 23)) { /* 0 <= f, rstep < den: 32 bits hold both */
        uint32_t d = (uint32_t)e->den, n32 = (uint32_t)num, s32 = (uint32_t)s;
        a->w = (int32_t)(n32 / d);
        a->r = (int32_t)(n32 - (uint32_t)a->w * d);
        a->qs = (int32_t)(s32 / d);
        a->rs = (int32_t)(s32 - (uint32_t)a->qs * d);
        return;
    }
    a->w = (int32_t)(num / e->den);
    a->r = (int32_t)(num - (int64_t)a->w * e->den);
    a->qs = (int32_t)(s / e->den);
    a->rs = (int32_t)(s - (int64_t)a->qs * e->den);
}

static void aa_step(zl_active *t)
{
    t->ax += t->right.step;
    edge_step(&t->left);
    t->z.row += t->z.dx;
    t->right.x--;
}

/* aa_step with the run's weight (zl_aa_weight) stepped along. */
static ZL_ALWAYS_INLINE void aa_step_weight(zl_active *t, zl_aa_weight *a)
{
    zl_edge *e = &t->left;
    t->ax += t->right.step;
    e->x += e->step;
    e->rem -= e->rstep;
    a->w += a->qs;
    a->r += a->rs;
    if (a->r >= e->den) {
        a->r -= e->den;
        a->w++;
    }
    if (e->rem < 0) {
        e->rem += e->den;
        e->x += 1;
        a->w -= 255;
    }
    t->z.row += t->z.dx;
    t->right.x--;
}

/* The columns of x-major row r (see aa_row): from the record on, those
 * whose floor(n) is r - 1 (lower pixels) then r (upper ones: the first of
 * them is where the next row starts); floor(n) never falls along a run. */
static void aa_walk(zl_active *t, const zl_span_state *ss, uint8_t *crow, uint16_t *zrow)
{
    int32_t r = t->row;
    zl_active l = *t;
    zl_aa_weight aw;
    int saved = 0;
    aa_weight_init(&aw, &l.left);
    while (l.right.x > 0 && l.left.x <= r) {
        unsigned w = (unsigned)aw.w;
        uint32_t d = line_depth(l.z.row);
        if (l.left.x == r - 1) {
            blend(ss, t, crow, zrow, l.ax, d, w);
        } else {
            if (!saved) {
                t->left = l.left;
                t->ax = l.ax;
                t->right.x = l.right.x;
                t->z.row = l.z.row;
                saved = 1;
            }
            blend(ss, t, crow, zrow, l.ax, d, 255u - w);
        }
        aa_step_weight(&l, &aw);
    }
    if (!saved) {
        /* nothing of this run reaches the next row's upper pixels */
        t->left = l.left;
        t->ax = l.ax;
        t->right.x = l.right.x;
        t->z.row = l.z.row;
        if (l.right.x == 0)
            t->row = t->end;
    }
}

/* The columns of a phase of aa_walk565: k of them, from column ax (stepped
 * by dir), weight w stepped as zl_aa_weight steps it (no wrap within the
 * phase), flip 255 for upper pixels (255 - w = w ^ 255). */
typedef struct {
    int32_t ax, dir, w, wr, qs, rs, den;
    int64_t z, dz;
} zl_aa_run;

static ZL_ALWAYS_INLINE void aa_phase565_loop(int exact, unsigned func, zl_aa_run *ru, int32_t k, unsigned flip,
                                              uint16_t *crow, const uint16_t *zrow, uint32_t width, uint32_t crb,
                                              uint32_t cg)
{
    int32_t ax = ru->ax, dir = ru->dir, w = ru->w, wr = ru->wr, qs = ru->qs, rs = ru->rs, den = ru->den;
    int64_t z = ru->z, dz = ru->dz;
    /* exact: the depth is the high word of z + 1/2 on every column */
    uint64_t zu = (uint64_t)(z + ((int64_t)1 << 31)), dzu = (uint64_t)dz;
    int32_t j;
    for (j = 0; j < k; j++) {
        unsigned wv = (unsigned)w ^ flip;
        if (wv != 0 && (uint32_t)ax < width) {
            uint32_t d = exact ? (uint32_t)(zu >> 32) : line_depth(z + (int64_t)j * dz);
            if (func == ZL_ALWAYS || depth_pass(func, d, zrow[ax]))
                crow[ax] = blend565(crow[ax], crb, cg, wv);
        }
        ax += dir;
        zu += dzu;
        w += qs;
        wr += rs;
        if (wr >= den) {
            wr -= den;
            w++;
        }
    }
    ru->ax = ax;
    ru->w = w;
    ru->wr = wr;
    ru->z = z + (int64_t)k * dz;
}

/* Columns per pass of aa_chunk565 (its weights on the stack). */
enum { ZL_AA_CHUNK = 32 };

/* The pixel pass of aa_phase565_fast over n <= ZL_AA_CHUNK columns from
 * ax0, DIR a constant: depth LESS on the high word of zu, the coverage
 * blend with the weights wt. A weight of 0 blends to the old pixel itself
 * (blend565: (o 255 + 127) / 255 = o), so it needs no test. */
static ZL_ALWAYS_INLINE void aa_pixels565(int dir, int32_t ax0, int32_t n, const uint8_t *wt, uint64_t zu, uint64_t dzu,
                                          uint16_t *crow, const uint16_t *zrow, uint32_t crb, uint32_t cg)
{
    int32_t j;
    for (j = 0; j < n; j++) {
        int32_t x = ax0 + dir * j;
        if ((uint32_t)(zu >> 32) < zrow[x])
            crow[x] = blend565(crow[x], crb, cg, wt[j]);
        zu += dzu;
    }
}

static ZL_NOINLINE void aa_pixels565_forward(int32_t ax0, int32_t n, const uint8_t *wt, uint64_t zu, uint64_t dzu,
                                             uint16_t *crow, const uint16_t *zrow, uint32_t crb, uint32_t cg)
{
    aa_pixels565(1, ax0, n, wt, zu, dzu, crow, zrow, crb, cg);
}

static ZL_NOINLINE void aa_pixels565_backward(int32_t ax0, int32_t n, const uint8_t *wt, uint64_t zu, uint64_t dzu,
                                              uint16_t *crow, const uint16_t *zrow, uint32_t crb, uint32_t cg)
{
    aa_pixels565(-1, ax0, n, wt, zu, dzu, crow, zrow, crb, cg);
}

/*
 * aa_phase565_loop for depth LESS on a phase whose depth is exact (the high
 * word of z + 1/2) and whose columns are all inside the row: in chunks, the
 * weights first (stepped as zl_aa_weight steps them, flipped for upper
 * pixels), then the pixels in a loop of their own. Split in two, each loop
 * keeps its values in registers (the single loop spilled a third of them:
 * 67 instructions a pixel on Cortex-M4).
 */
static void aa_phase565_fast(zl_aa_run *ru, int32_t k, unsigned flip, uint16_t *crow, const uint16_t *zrow,
                             uint32_t crb, uint32_t cg)
{
    uint8_t wt[ZL_AA_CHUNK];
    /* in locals: the byte stores to wt may alias *ru as far as C knows */
    int32_t w = ru->w, wr = ru->wr, qs = ru->qs, rs = ru->rs, den = ru->den, done, j;
    uint64_t zu = (uint64_t)(ru->z + ((int64_t)1 << 31)), dzu = (uint64_t)ru->dz;
    for (done = 0; done < k; done += ZL_AA_CHUNK) {
        int32_t n = k - done < ZL_AA_CHUNK ? k - done : ZL_AA_CHUNK;
        for (j = 0; j < n; j++) {
            wt[j] = (uint8_t)((unsigned)w ^ flip);
            w += qs;
            wr += rs;
            if (wr >= den) {
                wr -= den;
                w++;
            }
        }
        if (ru->dir > 0)
            aa_pixels565_forward(ru->ax + done, n, wt, zu, dzu, crow, zrow, crb, cg);
        else
            aa_pixels565_backward(ru->ax - done, n, wt, zu, dzu, crow, zrow, crb, cg);
        zu += (uint64_t)(uint32_t)n * dzu;
    }
    ru->ax += ru->dir * k;
    ru->w = w;
    ru->wr = wr;
    ru->z += (int64_t)k * ru->dz;
}

static ZL_NOINLINE void aa_phase565(unsigned func, zl_aa_run *ru, int32_t k, unsigned flip, uint16_t *crow,
                                    const uint16_t *zrow, uint32_t width, uint32_t crb, uint32_t cg)
{
    int64_t zb = ru->z + ((int64_t)1 << 31), ze = zb + (int64_t)(k - 1) * ru->dz, top = (int64_t)65536 << 32;
    int32_t last = ru->ax + ru->dir * (k - 1);
    if (zb >= 0 && zb < top && ze >= 0 && ze < top) {
        if (func == ZL_LESS && (uint32_t)ru->ax < width && (uint32_t)last < width && (ru->dir == 1 || ru->dir == -1))
            aa_phase565_fast(ru, k, flip, crow, zrow, crb, cg);
        else
            aa_phase565_loop(1, func, ru, k, flip, crow, zrow, width, crb, cg);
    } else {
        aa_phase565_loop(0, func, ru, k, flip, crow, zrow, width, crb, cg);
    }
}

/* aa_walk for native RGB565 with all channels, depth LESS, and an edge of
 * step 0 (all but exact diagonals): the same pixels and values, the run cut where
 * floor(n) changes (one division a phase), each phase a tight loop. */
static ZL_NOINLINE void aa_walk565(zl_active *t, const zl_span_state *ss, uint8_t *crow8, uint16_t *zrow)
{
    int32_t r = t->row, count = t->right.x;
    uint16_t *crow = (uint16_t *)(void *)crow8;
    zl_edge e = t->left;
    zl_aa_weight aw;
    zl_aa_run ru;
    uint32_t crb = ((uint32_t)t->rgb[0] << 16) | t->rgb[2], cg = t->rgb[1];
    int saved = 0;
    aa_weight_init(&aw, &e);
    ru.ax = t->ax;
    ru.dir = t->right.step;
    ru.w = aw.w;
    ru.wr = aw.r;
    ru.qs = aw.qs;
    ru.rs = aw.rs;
    ru.den = e.den;
    ru.z = t->z.row;
    ru.dz = t->z.dx;
    while (count > 0 && e.x <= r) {
        int upper = e.x != r - 1;
        /* the columns left before the remainder wraps (floor(n) + 1) */
        int32_t k = e.rstep > 0 ? e.rem / e.rstep + 1 : count;
        if (k > count)
            k = count;
        if (upper && !saved) {
            t->left = e;
            t->ax = ru.ax;
            t->right.x = count;
            t->z.row = ru.z;
            saved = 1;
        }
        aa_phase565(ZL_LESS, &ru, k, upper ? 255u : 0u, crow, zrow, ss->width, crb, cg);
        count -= k;
        e.rem -= k * e.rstep;
        if (e.rem < 0) {
            e.rem += e.den;
            e.x++;
            ru.w -= 255;
        }
    }
    if (!saved) {
        t->left = e;
        t->ax = ru.ax;
        t->right.x = count;
        t->z.row = ru.z;
        if (count == 0)
            t->row = t->end;
    }
}

/* Antialiased line row: two pixels per column (x-major) or row (y-major),
 * rows floor(n) and floor(n) + 1 of the ideal minor coordinate n, weighted
 * by their distance to it. An x-major row r takes the columns whose floor(n)
 * is r - 1 (as the lower pixel) or r (as the upper one); the record stays at
 * the first column of the row's run. */
static int aa_row(zl_active *t, const zl_span_state *ss, uint8_t *crow, uint16_t *zrow)
{
    if (!t->lower_is_left) {
        unsigned w = aa_weight(&t->left);
        uint32_t d = line_depth(t->z.row);
        blend(ss, t, crow, zrow, t->left.x, d, 255u - w);
        blend(ss, t, crow, zrow, t->left.x + 1, d, w);
        if (t->right.x > 1)
            aa_step(t);
        else
            t->row = t->end;
    } else if (ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && ss->keep[0] == 0 && ss->keep[1] == 0 &&
               ((uintptr_t)crow & 1u) == 0 && ss->func == ZL_LESS && t->left.step == 0) {
        aa_walk565(t, ss, crow, zrow);
    } else { /* blend() has the RGB565 lanes too */
        aa_walk(t, ss, crow, zrow);
    }
    if (t->row < t->end)
        t->row++;
    return t->row < t->end;
}

/* Pixels j0 .. j1 - 1 of a run whose depth is the high word of zu + j dzu
 * on each of them, columns ax0 + j DIR, all inside the row: the loop of
 * line_run565 with the bounds test hoisted (the caller clipped j0 .. j1)
 * and DIR a constant, so it keeps its values in registers. */
static ZL_ALWAYS_INLINE void run565_pixel(uint16_t *crow, uint16_t *zrow, int32_t x, uint32_t d, uint16_t pixel)
{
    if (d < zrow[x]) {
        zrow[x] = (uint16_t)d;
        crow[x] = pixel;
    }
}

static ZL_ALWAYS_INLINE void run565_inside(int dir, int32_t ax0, int32_t j0, int32_t j1, uint64_t zu, uint64_t dzu,
                                           uint16_t *crow, uint16_t *zrow, uint16_t pixel)
{
    int32_t j = j0;
    if (j0 != 0) /* a run clipped on its left (rare): no 64-bit multiply otherwise, ARMv6-M calls one */
        zu += (uint64_t)(uint32_t)j0 * dzu;
    if (((j1 - j0) & 1) != 0) { /* the odd pixel first, so the pairs need no count after them */
        run565_pixel(crow, zrow, ax0 + dir * j, (uint32_t)(zu >> 32), pixel);
        zu += dzu;
        j++;
    }
    for (; j < j1; j += 2) { /* two a turn: the loop's test on half of them */
        run565_pixel(crow, zrow, ax0 + dir * j, (uint32_t)(zu >> 32), pixel);
        zu += dzu;
        run565_pixel(crow, zrow, ax0 + dir * (j + 1), (uint32_t)(zu >> 32), pixel);
        zu += dzu;
    }
}

/* run565_inside for each direction, out of line so that its loop has the
 * registers to itself (inlined into zl_prim_row it spilled the bound). */
static ZL_NOINLINE void run565_forward(int32_t ax0, int32_t j0, int32_t j1, uint64_t zu, uint64_t dzu, uint16_t *crow,
                                       uint16_t *zrow, uint16_t pixel)
{
    run565_inside(1, ax0, j0, j1, zu, dzu, crow, zrow, pixel);
}

static ZL_NOINLINE void run565_backward(int32_t ax0, int32_t j0, int32_t j1, uint64_t zu, uint64_t dzu, uint16_t *crow,
                                        uint16_t *zrow, uint16_t pixel)
{
    run565_inside(-1, ax0, j0, j1, zu, dzu, crow, zrow, pixel);
}

/* The j with ax + j dir inside 0 .. width - 1, as [*j0, *j1) within 0 .. k. */
static void run_inside(int32_t ax, int32_t dir, int32_t k, int32_t width, int32_t *j0, int32_t *j1)
{
    int32_t lo = dir > 0 ? -ax : ax - (width - 1), hi = dir > 0 ? width - ax : ax + 1;
    *j0 = lo > 0 ? lo : 0;
    *j1 = hi < k ? hi : k;
    if (*j1 < *j0)
        *j1 = *j0;
}

/* The pixels of an x-major run in row t->row of a line whose edge steps by
 * 0 (all but exact diagonals), from the run's first column (left.x is the
 * row), RGB565, LESS with writes: zl_prim_row's
 * loop below with the record in locals, the run's length from one
 * division (the columns before the edge's remainder wraps, as in
 * aa_walk565), and the depth as the high word of a 64-bit stepper biased
 * by 1/2 (line_depth), clamped only where the run leaves 0 .. 65535. */
static int line_run565(zl_active *t, int32_t width, uint16_t *crow, uint16_t *zrow, uint16_t pixel)
{
    zl_edge e = t->left;
    int32_t count = t->right.x, ax = t->ax, dir = t->right.step, k, j;
    int64_t zq = t->z.row, dzq = t->z.dx, zb;
    k = e.rstep > 0 ? e.rem / e.rstep + 1 : count;
    if (k > count)
        k = count;
    zb = zq + ((int64_t)1 << 31);
    if (zb >= 0 && zb + (int64_t)(k - 1) * dzq >= 0 && zb < ((int64_t)65536 << 32) &&
        zb + (int64_t)(k - 1) * dzq < ((int64_t)65536 << 32)) {
        /* the high word is the depth on every pixel of the run */
        int32_t j0, j1;
        run_inside(ax, dir, k, width, &j0, &j1);
        if (dir > 0)
            run565_forward(ax, j0, j1, (uint64_t)zb, (uint64_t)dzq, crow, zrow, pixel);
        else
            run565_backward(ax, j0, j1, (uint64_t)zb, (uint64_t)dzq, crow, zrow, pixel);
        ax += k * dir;
    } else {
        for (j = 0; j < k; j++) {
            uint32_t d = line_depth(zq + (int64_t)j * dzq);
            if ((uint32_t)ax < (uint32_t)width && d < zrow[ax]) {
                zrow[ax] = (uint16_t)d;
                crow[ax] = pixel;
            }
            ax += dir;
        }
    }
    count -= k;
    if (count == 0) {
        t->row = t->end;
        return 0;
    }
    e.rem -= k * e.rstep;
    if (e.rem < 0) {
        e.rem += e.den;
        e.x++;
    }
    t->left = e;
    t->ax = ax;
    t->right.x = count;
    t->z.row = zq + (int64_t)k * dzq;
    t->row++;
    return t->row < t->end;
}

int zl_prim_row(zl_active *t, const zl_span_state *ss, uint8_t *color_row, uint16_t *depth_row)
{
    if (!ZL_FEATURE_LINES) /* compiled out (zl_config.h): unreachable, the code goes */
        return 0;
    uint8_t pix[3] = {0, 0, 0};
    if (t->kind == ZL_KIND_LINE_AA)
        return aa_row(t, ss, color_row, depth_row);
    pack_color((zl_format)ss->format, t->rgb[0], t->rgb[1], t->rgb[2], pix);
    if (t->kind == ZL_KIND_POINT) {
        uint32_t d = line_depth(t->z.row);
        int32_t x;
        for (x = t->left.x; x < t->right.x; x++)
            plot(ss, color_row, depth_row, x, d, pix);
        t->row++;
        return t->row < t->end;
    }
    /* Line: the pixels of this row, walking the major axis. A y-major line
     * has one per row; an x-major one a run, until its minor coordinate
     * (the row) changes. */
    if (ss->bpp == 2 && ss->format == ZL_FORMAT_RGB565 && ss->zwrite && ss->func == ZL_LESS && ss->keep[0] == 0 &&
        ss->keep[1] == 0 && ((uintptr_t)color_row & 1u) == 0) {
        /* The common case in its own loop (RGB565, all channels, LESS with
         * writes): the same pixels and values as plot() below. */
        uint16_t *crow = (uint16_t *)(void *)color_row, pixel;
        memcpy(&pixel, pix, 2);
        if (t->lower_is_left && t->left.step == 0 && t->left.x == t->row)
            return line_run565(t, ss->width, crow, depth_row, pixel);
        for (;;) {
            int32_t x = t->lower_is_left ? t->ax : t->left.x;
            uint32_t d = line_depth(t->z.row);
            if (x >= 0 && x < ss->width && d < depth_row[x]) {
                depth_row[x] = (uint16_t)d;
                crow[x] = pixel;
            }
            if (--t->right.x == 0) {
                t->row = t->end;
                return 0;
            }
            t->ax += t->right.step;
            edge_step(&t->left);
            t->z.row += t->z.dx;
            if (!t->lower_is_left || t->left.x != t->row)
                break;
        }
        t->row++;
        return t->row < t->end;
    }
    for (;;) {
        int32_t x = t->lower_is_left ? t->ax : t->left.x;
        plot(ss, color_row, depth_row, x, line_depth(t->z.row), pix);
        if (--t->right.x == 0) {
            t->row = t->end;
            return 0;
        }
        t->ax += t->right.step;
        edge_step(&t->left);
        t->z.row += t->z.dx;
        if (!t->lower_is_left || t->left.x != t->row)
            break;
    }
    t->row++;
    return t->row < t->end;
}

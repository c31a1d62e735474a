/* SPDX-License-Identifier: MIT */
/* Reference rasteriser for the RASTER CONTRACT: see zt_ref.h. */
#include "zt_ref.h"

int64_t zt_floor_div(int64_t n, int64_t d)
{
    int64_t q = n / d;
    if (n % d != 0 && n < 0)
        q -= 1;
    return q;
}

int64_t zt_ceil_div(int64_t n, int64_t d)
{
    int64_t q = n / d;
    if (n % d != 0 && n > 0)
        q += 1;
    return q;
}

int64_t zt_snap64(int64_t raw)
{
    /* one subpixel is 2^(16 - bits) raw units; nearest, ties up */
    const int64_t step = (int64_t)1 << (16 - ZL_SUBPIXEL_BITS);
    return zt_floor_div(raw + step / 2, step);
}

int64_t zt_snap(zl_fixed v)
{
    return zt_snap64(v);
}

int64_t zt_snap2(zl_fixed v)
{
    return 2 * zt_snap(v);
}

int64_t zt_centre2(int32_t i)
{
    return (2 * (int64_t)i + 1) * ZT_SUB;
}

/* Edge function of a -> b at p: > 0 on the interior side of a clockwise
 * (on screen, y down) triangle. */
static int64_t edge(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

static int64_t min3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a < b ? a : b;
    return m < c ? m : c;
}

static int64_t max3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a > b ? a : b;
    return m > c ? m : c;
}

static int32_t clamp_index(int64_t v)
{
    if (v > INT32_MAX / 2)
        return INT32_MAX / 2;
    if (v < INT32_MIN / 2)
        return INT32_MIN / 2;
    return (int32_t)v;
}

static void setup(zt_tri *t, const int64_t *x2, const int64_t *y2, const int64_t *z)
{
    int64_t a = edge(x2[0], y2[0], x2[1], y2[1], x2[2], y2[2]);
    int order[3] = {0, 1, 2};
    int k;
    if (a < 0) {
        /* counter-clockwise on screen: swap two vertices to get clockwise */
        order[1] = 2;
        order[2] = 1;
    }
    for (k = 0; k < 3; k++) {
        t->x[k] = x2[order[k]];
        t->y[k] = y2[order[k]];
        t->z[k] = z[order[k]];
    }
    t->orient = a > 0 ? 1 : (a < 0 ? -1 : 0);
    t->area = a < 0 ? -a : a;
    if (t->area == 0) {
        t->px0 = t->py0 = 0;
        t->px1 = t->py1 = -1;
        return;
    }
    /* centres (2i + 1) * SUB inside [min, max] */
    t->px0 = clamp_index(zt_ceil_div(min3(t->x[0], t->x[1], t->x[2]) - ZT_SUB, 2 * ZT_SUB));
    t->px1 = clamp_index(zt_floor_div(max3(t->x[0], t->x[1], t->x[2]) - ZT_SUB, 2 * ZT_SUB));
    t->py0 = clamp_index(zt_ceil_div(min3(t->y[0], t->y[1], t->y[2]) - ZT_SUB, 2 * ZT_SUB));
    t->py1 = clamp_index(zt_floor_div(max3(t->y[0], t->y[1], t->y[2]) - ZT_SUB, 2 * ZT_SUB));
}

void zt_tri_init(zt_tri *t, const zl_fixed *p0, const zl_fixed *p1, const zl_fixed *p2)
{
    int64_t x2[3], y2[3], z[3];
    x2[0] = zt_snap2(p0[0]);
    y2[0] = zt_snap2(p0[1]);
    z[0] = p0[2];
    x2[1] = zt_snap2(p1[0]);
    y2[1] = zt_snap2(p1[1]);
    z[1] = p1[2];
    x2[2] = zt_snap2(p2[0]);
    y2[2] = zt_snap2(p2[1]);
    z[2] = p2[2];
    setup(t, x2, y2, z);
}

void zt_tri_init64(zt_tri *t, const int64_t *xyz)
{
    int64_t x2[3], y2[3], z[3];
    int k;
    for (k = 0; k < 3; k++) {
        x2[k] = 2 * zt_snap64(xyz[3 * k]);
        y2[k] = 2 * zt_snap64(xyz[3 * k + 1]);
        z[k] = xyz[3 * k + 2];
    }
    setup(t, x2, y2, z);
}

void zt_tri_init_snapped2(zt_tri *t, const int64_t *x2, const int64_t *y2)
{
    static const int64_t z[3] = {0, 0, 0};
    setup(t, x2, y2, z);
}

/* Top-left rule for edge a -> b of a clockwise (y down) triangle: the interior
 * is on the side where the edge function grows, i.e. gradient (-dy, dx).
 *   top edge:  dy == 0 and interior below  (dx > 0)
 *   left edge: interior to the right       (-dy > 0) */
static int top_left(int64_t ax, int64_t ay, int64_t bx, int64_t by)
{
    int64_t dx = bx - ax, dy = by - ay;
    return dy < 0 || (dy == 0 && dx > 0);
}

static int inside_edge(const zt_tri *t, int a, int b, int64_t px, int64_t py)
{
    int64_t e = edge(t->x[a], t->y[a], t->x[b], t->y[b], px, py);
    if (e > 0)
        return 1;
    if (e < 0)
        return 0;
    return top_left(t->x[a], t->y[a], t->x[b], t->y[b]);
}

int zt_tri_covers(const zt_tri *t, int32_t i, int32_t j)
{
    int64_t px = zt_centre2(i), py = zt_centre2(j);
    if (t->area == 0)
        return 0;
    return inside_edge(t, 0, 1, px, py) && inside_edge(t, 1, 2, px, py) &&
           inside_edge(t, 2, 0, px, py);
}

unsigned zt_tri_mask(const zt_tri *t, uint8_t *mask, unsigned w, unsigned h)
{
    unsigned i, j, n = 0;
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i++) {
            uint8_t c = 0;
            if ((int32_t)i >= t->px0 && (int32_t)i <= t->px1 && (int32_t)j >= t->py0 &&
                (int32_t)j <= t->py1)
                c = (uint8_t)zt_tri_covers(t, (int32_t)i, (int32_t)j);
            mask[j * w + i] = c;
            n += c;
        }
    return n;
}

static int32_t clamp_depth(int64_t v)
{
    return v < 0 ? 0 : (v > 65535 ? 65535 : (int32_t)v);
}

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

void zt_tri_depth(const zt_tri *t, int32_t i, int32_t j, zt_depth_ref *out)
{
    int64_t px = zt_centre2(i), py = zt_centre2(j);
    int64_t a = t->area;
    int64_t w0, w1, w2, n, q, r, rt, t1, t2, m, fl, lo, hi;
    int64_t gx, gy, zmin, zmax;
    int k;
    if (a == 0) {
        out->lo = out->hi = out->nearest = 0;
        out->steep = 0;
        return;
    }
    /* barycentric weights times the doubled area: edge opposite each vertex */
    w0 = edge(t->x[1], t->y[1], t->x[2], t->y[2], px, py);
    w1 = edge(t->x[2], t->y[2], t->x[0], t->y[0], px, py);
    w2 = edge(t->x[0], t->y[0], t->x[1], t->y[1], px, py);
    /* plane value on the stored scale = n * 65535 / (65536 * a), exactly */
    n = w0 * t->z[0] + w1 * t->z[1] + w2 * t->z[2];
    q = zt_floor_div(n, a);
    r = n - q * a;           /* 0 <= r < a */
    rt = r * 65535;
    t1 = zt_floor_div(rt, a);
    t2 = rt - t1 * a;        /* value = (m + t2 / a) / 65536, 0 <= t2 < a */
    m = q * 65535 + t1;
    fl = zt_floor_div(m, 65536); /* floor(value) */
    hi = fl + 1;                 /* floor(value + 1) */
    lo = (t2 == 0 && m - fl * 65536 == 0) ? fl - 1 : fl; /* ceil(value - 1) */
    out->nearest = clamp_depth(zt_floor_div(m + 32768, 65536));

    /* steepness: per-pixel change of the plane in x and in y (2 * SUB half
     * subpixels per pixel), compared with 2^19 without the 65535/65536 factor */
    gx = -((t->y[2] - t->y[1]) * t->z[0] + (t->y[0] - t->y[2]) * t->z[1] +
           (t->y[1] - t->y[0]) * t->z[2]);
    gy = (t->x[2] - t->x[1]) * t->z[0] + (t->x[0] - t->x[2]) * t->z[1] +
         (t->x[1] - t->x[0]) * t->z[2];
    out->steep = 0;
    if (a <= ((int64_t)1 << 43)) {
        int64_t limit = a << 19;
        if (abs64(gx) * 2 * ZT_SUB > limit || abs64(gy) * 2 * ZT_SUB > limit)
            out->steep = 1;
    }
    if (out->steep) {
        zmin = zmax = t->z[0];
        for (k = 1; k < 3; k++) {
            if (t->z[k] < zmin)
                zmin = t->z[k];
            if (t->z[k] > zmax)
                zmax = t->z[k];
        }
        /* vertex depths on the stored scale: z * 65535 / 65536 */
        if (zt_floor_div(zmin * 65535, 65536) < lo)
            lo = zt_floor_div(zmin * 65535, 65536);
        if (zt_ceil_div(zmax * 65535, 65536) > hi)
            hi = zt_ceil_div(zmax * 65535, 65536);
    }
    out->lo = clamp_depth(lo);
    out->hi = clamp_depth(hi);
}

int zt_poly_covers(const int64_t *x2, const int64_t *y2, unsigned n, int32_t i, int32_t j)
{
    /* Even-odd test of the point (cx + e, cy + e^2), e -> 0+, with a ray
     * towards +x. An edge a -> b meets the line y = cy + e^2 when exactly one
     * end lies strictly below cy (y > cy, y down); there its x exceeds cx + e
     * exactly when its x at y = cy exceeds cx, i.e. when the edge function
     * (b - a) x (c - a) is non-zero with the sign of b.y - a.y. */
    int64_t cx = zt_centre2(i), cy = zt_centre2(j);
    unsigned k, crossings = 0;
    for (k = 0; k < n; k++) {
        unsigned l = (k + 1 == n) ? 0 : k + 1;
        int64_t ax = x2[k], ay = y2[k], bx = x2[l], by = y2[l];
        if ((ay > cy) != (by > cy)) {
            int64_t e = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
            if (e != 0 && ((e > 0) == (by - ay > 0)))
                crossings++;
        }
    }
    return (int)(crossings & 1u);
}

uint32_t zt_rand(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

int32_t zt_rand_range(uint32_t *state, int32_t lo, int32_t hi)
{
    uint32_t span = (uint32_t)((int64_t)hi - lo + 1);
    return (int32_t)((int64_t)lo + (int64_t)(zt_rand(state) % span));
}

uint32_t zt_rand64(uint64_t *state)
{
    uint64_t x = *state;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    *state = x;
    return (uint32_t)(x >> 32);
}

int32_t zt_rand64_range(uint64_t *state, int32_t lo, int32_t hi)
{
    uint32_t span = (uint32_t)((int64_t)hi - lo + 1);
    return (int32_t)((int64_t)lo + (int64_t)(zt_rand64(state) % span));
}

uint64_t zt_isqrt(uint64_t v)
{
    uint64_t r = 0, bit = (uint64_t)1 << 62;
    while (bit > v)
        bit >>= 2;
    while (bit != 0) {
        if (v >= r + bit) {
            v -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
        bit >>= 2;
    }
    return r;
}

/* SPDX-License-Identifier: MIT */
/*
 * Stage 1, base: the zline internals shared by every stage. The immediate
 * (frame) mode and the scanline/band mode (stage 5) run every triangle through
 * the same three functions, which is why their pixels are identical:
 *
 *   zl_tri_polygon   fetch/transform the vertices, clip if needed, project and
 *                    snap: a convex polygon in window space (3..9 vertices)
 *   zl_tri_setup     one fan triangle of it: cull, row range, edge steppers,
 *                    attribute planes
 *   zl_tri_row       fill the span of the current row, then step to the next
 */
#ifndef ZLINE_INTERNAL_H
#define ZLINE_INTERNAL_H

#include "zline/zline.h"

#define ZL_SUB_BITS ZL_SUBPIXEL_BITS
#define ZL_SUB_ONE (1 << ZL_SUB_BITS)        /* subpixels per pixel */
#define ZL_SUB_HALF (ZL_SUB_ONE / 2)         /* offset of a pixel centre */
#define ZL_MAX_POLY 10                       /* 3 vertices + one per clip plane (7) */
#define ZL_ATTR_FRAC 20                      /* fraction bits of stepped attributes */
/* Texture coordinate planes (issue 22: texels exact): an affine plane
 * steps Q16 texels (ZL_TEX_FRAC), a perspective one u q in units 2^-16 q
 * texel, read back as (u q r) >> ZL_PERSP_SHIFT in 1/256 texel. With the
 * 12 fraction bits of before, half a unit of rounding per pixel step added
 * up to 0.056 texel across a 160x120 target (tests/host/test_texel_exact.c
 * counted 0.1 to 0.5 % of pixels beyond 1/64 texel of a boundary in a
 * neighbouring texel); 16 bits make it 1/16 of that. */
#define ZL_TEX_FRAC 16
#define ZL_TEX_SHIFT (ZL_TEX_FRAC - 8)       /* Q16 texels to 1/256 texel */
#define ZL_PERSP_SHIFT 24
#define ZL_GRAD_LIMIT ((int64_t)1 << 43)     /* clamp of a per-pixel attribute gradient */

/* Element i of a caller mesh array (positions, indices, vertex or face
 * colours), through zl_config.h's read hook: a plain p[i] by default. */
#define ZL_MESH_POS(p, i) ZL_MESH_READ_FIXED(&(p)[i])
#define ZL_MESH_IDX(p, i) ZL_MESH_READ_U16(&(p)[i])
#define ZL_MESH_U8(p, i) ZL_MESH_READ_U8(&(p)[i])

/* Window-space vertex, after projection and snapping. */
typedef struct {
    int32_t x, y;       /* subpixels */
    uint32_t z;         /* window depth * 65535 * 65536, i.e. Q16 of the stored scale */
    uint16_t r, g, b;   /* colour, Q8 (0 .. 255 * 256) */
} zl_wvert;

/* The depth plane goes through the vertices at their unsnapped window
 * positions, kept to 2^-ZL_FINE_BITS subpixel (2^-16 pixel) as residuals
 * from the snapped position (zl_poly and zl_cached_vertex fx, fy: within
 * +-1/2 subpixel plus the rounding of the clip coordinates, saturated to
 * int16). */
#define ZL_FINE_BITS 12
/* fx of a vertex drawn without the exact depth mapping (state near_z, far_z
 * 0, or pixel space): its depth plane is solved through the snapped
 * vertices, as the mapping z_clip / w_clip is biased by its Q16.16 matrix
 * anyway, and the draw pays for no residual. */
#define ZL_FINE_NONE INT16_MIN

/* Clip-space vertex carried through clipping. */
typedef struct {
    int32_t x, y, z, w; /* Q16.16 */
    uint16_t r, g, b;   /* colour, Q8: 0 .. 255 * 256 (16 bits keep the struct
                           at 28 bytes with zd: the clipper's stack) */
    uint32_t zd;        /* window depth in 1/65536 steps of the exact mapping
                           (state near_z, far_z), or ZL_ZD_NONE: z / w */
} zl_cvert;
#define ZL_ZD_NONE 0xFFFFFFFFu
/* Does state st (not NULL) ask for the exact depth mapping (near_z, far_z)?
 * Always 0 when ZL_FEATURE_DEPTH_MAP is off (zl_config.h; zl_state_check
 * refuses such a state then): the mapping's code is unreachable and goes. */
#define ZL_DEPTH_MAPPED(st) (ZL_FEATURE_DEPTH_MAP && (st)->far_z != 0)

/* Cached window vertex of scanline mode: 12 bytes, 8 without
 * ZL_FEATURE_EXACT_DEPTH. x == ZL_CACHE_COMPLEX marks a
 * vertex outside a clip plane or outside the int16 window range; triangles
 * using it take the clipping path, which recomputes it exactly. */
typedef struct {
    int16_t x, y;
    uint32_t z;
#if ZL_FEATURE_EXACT_DEPTH
    int16_t fx, fy; /* zl_wvert's */
#endif
} zl_cached_vertex;
/* A cached vertex's residuals (ZL_FINE_NONE where they are not kept). */
#if ZL_FEATURE_EXACT_DEPTH
#define ZL_CV_FX(c) ((c)->fx)
#define ZL_CV_FY(c) ((c)->fy)
#define ZL_CV_SET_FINE(c, x, y) ((c)->fx = (int16_t)(x), (c)->fy = (int16_t)(y))
#else
#define ZL_CV_FX(c) ((void)(c), (int16_t)ZL_FINE_NONE)
#define ZL_CV_FY(c) ((void)(c), (int16_t)ZL_FINE_NONE)
#define ZL_CV_SET_FINE(c, x, y) ((void)(c), (void)(x), (void)(y))
#endif
#define ZL_CACHE_COMPLEX INT16_MIN
#define ZL_CACHE_INVALID (INT16_MIN + 1) /* transform out of range: triangles dropped */

/* Where a draw's vertices come from and how they are projected. */
typedef struct {
    const zl_mesh *mesh;
    const zl_mat4 *mvp;              /* NULL: positions are in pixel space */
    const zl_state *state;
    const zl_cached_vertex *cache;   /* NULL in immediate mode */
    uint16_t width, height;
} zl_source;

/* The window-space polygon of one source triangle. */
typedef struct {
    zl_wvert v[ZL_MAX_POLY];
    uint8_t n;
    uint8_t clipped;    /* made by clipping: its pieces take the original
                           triangle's planes (zl_tri_orig_planes); n and it
                           in one byte each, so zl_poly stays 208 bytes */
    zl_rgb flat;        /* lit flat colour */
    uint8_t light;      /* lighting intensity 0..255 (255 with the light off) */
    int16_t fx[3], fy[3]; /* residuals (ZL_FINE_BITS) of v[0..2] when n = 3 and not clipped: kept here,
                             not in zl_wvert, so the polygon grows by 12 bytes, not 40 (stack bound) */
} zl_poly;

/* A polygon with texture attributes per vertex, for styles that need
 * texture or perspective planes (kept apart so that zl_poly, which every
 * triangle path holds on its stack, does not grow). */
typedef struct {
    zl_poly p;
    int32_t u[ZL_MAX_POLY], v[ZL_MAX_POLY]; /* texture coordinates, 1/256 texel */
    int32_t w[ZL_MAX_POLY];                 /* clip w, Q16.16, >= 1 */
} zl_tpoly;

/* Exact DDA edge stepper: at each row, x is the first pixel index whose centre
 * is at or right of the edge: x = ceil(N / den) with N = x * den - rem,
 * 0 <= rem < den. Stepping a row adds `step` and subtracts `rstep` from rem,
 * with a carry: integer part plus error term, no division per row. */
typedef struct {
    int32_t x, rem, step, rstep, den;
} zl_edge;

/* A linear attribute: value (Q20) at the centre of pixel (ax, current row),
 * plus its change per pixel (dx) and per row (dy). */
typedef struct {
    int64_t row, dx, dy;
} zl_attr;

typedef struct {
    zl_attr c[3];       /* r, g, b, Q20 of 0..255 (times q, see zl_texplanes, when perspective) */
} zl_gouraud;

/* Texture and perspective planes of a triangle (zl_style textures,
 * perspective Gouraud): u, v in 1/16 of 1/256 texel (affine) or u q, v q
 * (perspective), and q = 1/w scaled so the triangle's nearest vertex has
 * 2^24, all times 16 (Q20 planes of Q16 inputs). */
typedef struct {
    zl_attr u, v, q;
    uint8_t persp; /* u, v perspective-correct although the style maps them
                      affinely: a clipped triangle with a vertex behind the
                      eye (zline.h, Clipping) */
} zl_texplanes;

struct zl_active {
    zl_edge left, right;   /* edges bounding the current rows */
    zl_edge lower;         /* replaces the short edge from row `mid` on */
    uint32_t dz14;         /* z.dx as the 32-bit Q14 span stepper (in the padding before z) */
    zl_attr z;
    int32_t ax;            /* anchor column of the attribute planes */
    uint32_t zlo, zhi;     /* vertex depth range, Q16 (same scale as zl_wvert.z) */
    int16_t row, mid, end; /* next row, row where `lower` takes over, end row */
    uint8_t lower_is_left;
    uint8_t mesh;          /* index of the frame mesh (scanline mode) */
    uint8_t rgb[3];        /* flat colour */
    uint16_t id;           /* source triangle: the drawing order */
    uint16_t next;         /* active-list link (scanline mode) */
    uint8_t kind;          /* ZL_KIND_*: in the tail padding, so the record does not grow */
    uint8_t light;         /* lighting intensity 0..255, for textures (tail padding too) */
    uint16_t pix565;       /* rgb as a native RGB565 pixel, scanline mode's plain records (tail padding too) */
};

/*
 * Kinds of active record. Lines and points live in the same pool as
 * triangles (so they sort with them by id) and reuse its fields:
 *   line:  left      minor-axis stepper: left.x is the minor coordinate of
 *                    the current pixel (an exact DDA, as a triangle edge)
 *          ax        major coordinate of the current pixel
 *          right.x   pixels left to plot; right.step major step (+1 or -1)
 *          z.row     depth of the current pixel, Q32 of the stored scale;
 *          z.dx      its change per major step
 *          lower_is_left  1 when x is the major axis
 *   point: left.x, right.x  first and end column (clamped); z.row depth Q32
 *   both:  row, end, rgb, id, next, mesh as for triangles
 */
#define ZL_KIND_TRI 0
#define ZL_KIND_LINE 1
#define ZL_KIND_POINT 2
#define ZL_KIND_LINE_AA 3 /* as a line; left is the floor of the minor coordinate, rem its fraction */
/* A small flat triangle of scanline mode (zl_tiny_setup, RGB565 meshes of
 * render_row_plain's walks): left, right and lower hold the long, current
 * short and lower short zl_tiny_edge (n in x, inc in step, d in den; at row
 * mid those three of lower go to right); the 32-bit plane, as int32 bits:
 * left.rem zbase, left.rstep zdx, right.rem zr (this row), right.rstep zdy;
 * zlo, zhi, dz14, ax, row (first), mid, end as zl_tiny's; lower_is_left is
 * long_left. z is not used. Where ZL_MUL32_ONLY, left.x and right.x hold
 * their columns once active and lower.rem, lower.rstep their remainders
 * (zl_frame_rows.c, tiny_walk_start). */
#define ZL_KIND_TINY 4
/* A small Gouraud triangle of scanline mode (zl_tiny_gouraud_setup, plain
 * Gouraud RGB565 meshes, MESH_GOURAUD565): its edges and depth plane as a
 * ZL_KIND_TINY record, its colour planes (zl_tiny_colour) in the record's
 * zl_gouraud slot. */
#define ZL_KIND_TINY_GOURAUD 5

/* How the spans of one draw write their pixels. */
typedef struct {
    uint8_t func;          /* zl_depth_func, ZL_ALWAYS when the test is off */
    uint8_t zwrite;        /* write depth */
    uint8_t bpp;           /* colour bytes per pixel, 0 for no colour */
    uint8_t format;
    uint8_t gouraud;
    uint8_t keep[3];       /* per colour byte: bits kept from the old pixel (colour mask) */
    uint16_t width;
} zl_span_state;

/*
 * Division by a divisor fixed for a whole triangle (Moller and Granlund,
 * "Improved division by invariant integers", IEEE TC 2011, algorithm 4):
 * one 64-by-32 division makes a reciprocal, then every quotient is a
 * multiply-add and two rarely taken corrections, where zl_udiv64_32 costs
 * two divisions and normalisation each time.
 */
typedef struct {
    uint32_t d;     /* the divisor shifted left until its top bit is set */
    uint32_t v;     /* floor((2^64 - 1) / d) - 2^32 */
    unsigned shift; /* that shift */
} zl_div_inv;

static inline void zl_div_inv_init(zl_div_inv *di, uint32_t c) /* c != 0 */
{
    unsigned s = 0;
#if defined(__GNUC__) && __SIZEOF_INT__ >= 4 /* __builtin_clz counts in an unsigned int */
    s = (unsigned)__builtin_clz(c);
#else
    while ((c << s & 0x80000000u) == 0)
        s++;
#endif
    di->d = c << s;
    di->shift = s;
    /* (2^64 - 1) - d 2^32 has a high word below d: the precondition. */
    di->v = zl_udiv64_32(~(uint64_t)0 - ((uint64_t)di->d << 32), di->d, NULL);
}

/* floor(n / c) for n < c 2^32 (so n << shift fits 64 bits). */
static inline uint32_t zl_div_inv_q(const zl_div_inv *di, uint64_t n)
{
    uint64_t u = n << di->shift, q = (uint64_t)di->v * (uint32_t)(u >> 32) + u; /* modulo 2^64 */
    uint32_t q1 = (uint32_t)(q >> 32) + 1u, r = (uint32_t)u - q1 * di->d;
    if (r > (uint32_t)q) {
        q1--;
        r += di->d;
    }
    if (r >= di->d)
        q1++;
    return q1;
}

#define ZL_LIST_END 0xFFFFu

/* Keep a function out of its caller, so a big local (a polygon) of one
 * branch does not add to the stack of every path through the caller. */
#if defined(__GNUC__)
#define ZL_NOINLINE __attribute__((noinline))
#else
#define ZL_NOINLINE
#endif

/* Out of line without the fast paths (ZL_FAST_PATHS=0, zl_config.h): a
 * small helper that -Os copies into each of its callers, where on Cortex-M0
 * a copy of 64-bit arithmetic is libgcc calls and register moves; with the
 * fast paths the compiler decides, as before. */
#if ZL_FAST_PATHS
#define ZL_SMALL_NOINLINE
#else
#define ZL_SMALL_NOINLINE ZL_NOINLINE
#endif

/* A static helper defined in a stage's internal header with no inline hint,
 * so each file that uses it gets the same inlining decision as when the
 * helper was in that file (the hint changes GCC's choice, and with it the
 * stack bound and the measured instruction counts); files that do not use
 * it get no warning. */
#if defined(__GNUC__)
#define ZL_SHARED_STATIC static __attribute__((unused))
#else
#define ZL_SHARED_STATIC static
#endif

/* Force a tiny helper of the span loops inline even at -Os, where GCC stops
 * inlining a function once it has many callers (and each span loop would
 * then make a call per pixel). */
#if defined(__GNUC__)
#define ZL_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ZL_ALWAYS_INLINE inline
#endif

/* 1 on targets without a 32x32->64 multiply or a divide instruction
 * (ARMv6-M: Cortex-M0/M0+), where libgcc's __aeabi_lmul costs about 40
 * instructions a product and a division 60 to 70: some hot paths then take
 * exact 32-bit forms of the same numbers (bit-identical results). A host
 * build may define ZL_MUL32_ONLY=1 to test those forms. Without the fast
 * paths (ZL_FAST_PATHS=0, zl_config.h) those forms are speed alone: 0. */
#ifndef ZL_MUL32_ONLY
#if defined(__ARM_ARCH_6M__) && ZL_FAST_PATHS
#define ZL_MUL32_ONLY 1
#else
#define ZL_MUL32_ONLY 0
#endif
#endif

/* floor(x / 255) for x <= 65152 (255 * 255 + 127, what colour scaling
 * divides), by a multiply: GCC keeps the division (a libgcc call) where it
 * has no 32x32->64 multiply to use. x 0x8081 stays below 2^32 there, and
 * the quotient is exact for every such x (tests/test_fastdiv.c checks all). */
static inline uint32_t zl_div255_small(uint32_t x)
{
    return (x * 0x8081u) >> 23;
}

/* floor(x / 255) for x < 2^31 without a divide instruction: x / 256 +
 * x / 2^16 + x / 2^24, floored, is at most 4 below the quotient (checked
 * for every such x), then the remainder corrects it. */
static inline uint32_t zl_div255_31(uint32_t x)
{
    uint32_t q = (x >> 8) + (x >> 16) + (x >> 24), r = x - q * 255u;
    while (r >= 255u) {
        q++;
        r -= 255u;
    }
    return q;
}

/* 1 when the four edge-vector components are each within +-2^14, so that
 * each product of two is within 2^28 and a cross product (the window area
 * of a triangle from the int16 vertex cache) is exact in 32 bits: the
 * common case, taken where ZL_MUL32_ONLY instead of two __aeabi_lmul. */
static inline int zl_area_fits32(int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
    return ((uint32_t)(ax + 16384) | (uint32_t)(ay + 16384) | (uint32_t)(bx + 16384) | (uint32_t)(by + 16384)) <
           32768u;
}

/* a b for 32-bit a, b from four 16x16-bit products (each fits 32 bits:
 * the halves are floor(v / 2^16) and v mod 2^16), for cores without a
 * 32x32->64 multiply, where GCC calls __aeabi_lmul (about 42 instructions)
 * for (int64_t)a * b. Used where ZL_MUL32_ONLY; defined everywhere, so the
 * tests check it on every build. */
static inline int64_t zl_mul_s32_split(int32_t a, int32_t b)
{
    int32_t ah = zl_floor_shift32(a, 16), bh = zl_floor_shift32(b, 16);
    int32_t al = (int32_t)((uint32_t)a & 0xFFFFu), bl = (int32_t)((uint32_t)b & 0xFFFFu);
    int64_t mid = (int64_t)(ah * bl) + (int64_t)(al * bh); /* each within 2^31 in magnitude */
    return (int64_t)(ah * bh) * 4294967296 + mid * 65536 + (int64_t)((uint32_t)al * (uint32_t)bl);
}

/* ---- stage 2, geometry: 2_geometry/zl_vertex.c, zl_light.c, zl_clip.c */
/* Transform vertex `idx` of the source's mesh to clip space (colour
 * included). Returns 0 if the transform leaves its range. */
int zl_vertex_clip(const zl_source *s, uint16_t idx, zl_cvert *out);
/* Bit mask of the clip planes the vertex is outside of (0 = inside all). */
unsigned zl_outcode(const zl_source *s, const zl_cvert *v);
/* Project and snap an inside vertex to window space. */
void zl_project(const zl_source *s, const zl_cvert *v, zl_wvert *out);
/* The residuals (fx, fy) of w, zl_project's window vertex of mesh vertex
 * idx (unclipped), from the unrounded transform. */
void zl_vertex_residuals(const zl_source *s, uint16_t idx, const zl_wvert *w, int16_t *fx, int16_t *fy);
/*
 * A draw's transform to window space with the per-draw work done once
 * (2_geometry/zl_vertex.c): zl_vx_prepare fills it (0 when a matrix entry
 * is outside +-16384.0), then zl_vx_vertex(s, vx, idx, out) sets *out
 * to exactly zl_cache_vertex(s, idx).
 */
typedef struct {
    zl_fixed m[16];      /* the matrix (a copy: no reloads after each store); every entry within +-COORD_LIMIT */
    int64_t bias[4];     /* translation column * 2^16 + 2^15: rounding folded in */
    uint32_t wd, ht;     /* viewport */
    uint32_t gx, gy;     /* W + 2G, H + 2G: the guard-band planes */
    uint32_t hx, hy;     /* W * 2^SUB / 2, H * 2^SUB / 2: the window centre */
    uint32_t pfast;      /* P: positions within [-P, P) need no range checks */
    uint32_t qx, qy;     /* window quotients below these are inside and in range */
    const zl_state *exact; /* the state when it asks for the exact depth mapping, else NULL */
} zl_vx;
int zl_vx_prepare(const zl_source *s, zl_vx *vx);
void zl_vx_vertex(const zl_source *s, const zl_vx *vx, uint16_t idx, zl_cached_vertex *out);
/* Project one mesh vertex into a cache entry (scanline mode). */
zl_cached_vertex zl_cache_vertex(const zl_source *s, uint16_t idx);
/* cache[v] = zl_cache_vertex(s, v) for v = first .. first + count - 1 (within
 * the mesh), with the per-draw work done once. Returns ZL_ERR_RANGE when one
 * of them is ZL_CACHE_INVALID, or when the matrix has an entry outside
 * +-16384.0 (then all are), else ZL_OK. Over all vertices (first 0, count
 * vertex_count) that is exactly zl_check_positions(positions, vertex_count,
 * mvp) for non-NULL positions. Every entry is written either way. */
zl_status zl_cache_vertices(const zl_source *s, zl_cached_vertex *cache, uint16_t first, uint16_t count);
/* The window-space polygon of triangle t; 0 if nothing of it is left. */
int zl_tri_polygon(const zl_source *s, uint32_t t, zl_poly *out);
/* The same with a style: texture coordinates and w carried to the polygon
 * when the style has a texture or perspective Gouraud (sty may be NULL). */
int zl_tri_polygon_ex(const zl_source *s, const zl_style *sty, uint32_t t, zl_poly *out);
/* Geometry (not shaded) and texture attributes of triangle t. */
int zl_tri_polygon_tex(const zl_source *s, const zl_style *sty, uint32_t t, zl_tpoly *out);
/* The same without the colours: geometry only, for classification. A polygon
 * that turns out to be drawn gets its flat colour and lighting from
 * zl_tri_shade (lighting costs a square root: only for drawn triangles). */
int zl_tri_polygon_geom(const zl_source *s, const zl_style *sty, uint32_t t, zl_poly *out);
void zl_tri_shade(const zl_source *s, uint32_t t, zl_poly *poly);
/* The depth plane (and with `colour` the screen-linear colour planes, times
 * light / 255) of triangle t of the source as it is before clipping, at the
 * centre of pixel (ax, ay): Q20 planes in zl_active's scales, computed from
 * its clip-space vertices by homogeneous 2D interpolation
 * (2_geometry/zl_clip_planes.c). Returns 0 when there is no such plane
 * (degenerate), else 1, plus 2 when the colour planes were set (every
 * vertex in front of the eye). */
int zl_tri_orig_planes(const zl_source *s, uint32_t t, int32_t ax, int32_t ay, int colour, uint8_t light,
                       zl_attr *z, zl_attr col[3]);
/* The original triangle's depth (Q16 of the stored scale, not clamped: it
 * leaves 0 .. 65535 beyond the near and far planes) at three subpixel
 * positions; 0 when it has no plane. */
int zl_tri_orig_depths3(const zl_source *s, uint32_t t, const int32_t x[3], const int32_t y[3], int64_t z[3]);
/* The same for an unclipped triangle (a, b, c): the values (Q16, unclamped)
 * of the depth plane the set-up gives it (through its unsnapped vertices,
 * zl_depth_plane_exact) at the subpixel points (x[k], y[k]); 0 when the
 * set-up would take the plane through the snapped vertices. */
int zl_tri_exact_depths3(const zl_poly *poly, const zl_wvert *a, const zl_wvert *b, const zl_wvert *c,
                         const int32_t x[3], const int32_t y[3], int64_t z[3]);
/* The texture and perspective planes of triangle tri before clipping (the
 * scales of zl_texplanes, q scaled so that 2^24 is at clip w = wmin, the
 * least w of the clipped polygon), at the anchor of record t (t->ax,
 * t->row); with col (not NULL) also the perspective-correct colour planes
 * (times t->light / 255). Returns 0 when there is no plane, else 1, plus 2
 * with the colour planes. */
int zl_tri_orig_texplanes(const zl_source *s, const zl_style *sty, uint32_t tri, const zl_active *t, int32_t wmin,
                          zl_texplanes *tp, zl_attr col[3]);
/* The light of a state as zl_tri_shade_lit takes it (Q14, clamped, with the
 * front face's sign), once per draw instead of once per triangle. */
void zl_light_prepare(const zl_state *st, int32_t lq[3]);
/* zl_tri_shade with the light prepared from s->state by zl_light_prepare. */
void zl_tri_shade_lit(const zl_source *s, uint32_t t, zl_poly *poly, const int32_t lq[3]);
/* The lit flat colour of triangle t as a native RGB565 pixel: what
 * zl_tri_shade_lit and pack_color give for a flat triangle. */
uint16_t zl_tri_pixel565_lit(const zl_source *s, uint32_t t, const int32_t lq[3]);

/* ---- stage 3, raster: 3_raster/zl_setup.c, zl_setup_fast.c, zl_rows.c,
 * zl_rows_styled.c (and 4_primitives/zl_line_rows.c for zl_prim_row) */
/* Cull and bound fan triangle (a, b, c). Returns 1 and the row range
 * [*first, *end) when it may cover pixels of the width x height target. */
int zl_tri_classify(const zl_wvert *a, const zl_wvert *b, const zl_wvert *c, const zl_state *st,
                    uint16_t width, uint16_t height, int32_t *first, int32_t *end);
/* Full setup of a classified triangle into *t (and *g for Gouraud). */
int zl_tri_setup(zl_active *t, zl_gouraud *g, const zl_wvert *a, const zl_wvert *b,
                 const zl_wvert *c, const zl_poly *poly, const zl_state *st, uint16_t width,
                 uint16_t height);
/* zl_tri_setup plus the texture / perspective planes into tp when the style
 * asks for them (tp and sty may be NULL); then poly must be the p of a
 * zl_tpoly and a, b, c vertices of it. */
int zl_tri_setup_ex(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_wvert *a,
                    const zl_wvert *b, const zl_wvert *c, const zl_poly *poly, const zl_state *st,
                    uint16_t width, uint16_t height);
/* zl_tri_setup_ex for a triangle zl_tri_classify accepted with rows
 * [first, end): the same record, without classifying it again. poly may be
 * NULL without texture planes: then the caller sets rgb and light. */
void zl_tri_setup_rows(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_wvert *a,
                       const zl_wvert *b, const zl_wvert *c, const zl_poly *poly, const zl_state *st, int32_t first,
                       int32_t end);
/* zl_tri_setup_rows with the residuals of a, b, c given (res: fx, fy of
 * each, ZL_FINE_BITS; NULL: the depth plane through the snapped vertices)
 * instead of taken from poly. */
void zl_tri_setup_rows_res(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_wvert *a,
                           const zl_wvert *b, const zl_wvert *c, const zl_poly *poly, const int16_t *res,
                           const zl_state *st, int32_t first, int32_t end);
/* zl_tri_row for a triangle set up by zl_tri_setup_ex with the same style. */
int zl_tri_row_ex(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_span_state *ss,
                  uint8_t *color_row, uint16_t *depth_row);
/* Give a set-up fan triangle (a, b, c) of a clipped polygon the depth plane
 * z (and the colour planes col, when not NULL and g is) of its original
 * triangle, both at the record's anchor (t->ax, t->row). With `wrap` (rows
 * drawn by zl_tri_row or the flat span loops, not zl_tri_row_ex) and a
 * plane within -1 .. 2 depth ranges at a, b, c, its depth range is
 * inverted (zlo > zhi: span starts are not clamped, see zl_span.h), else
 * it is the plane's values at a, b, c within 0 .. 65535. */
void zl_tri_set_planes(zl_active *t, zl_gouraud *g, const zl_wvert *a, const zl_wvert *b, const zl_wvert *c,
                       const zl_attr *z, const zl_attr *col, int wrap);
/* Does the style need texture planes (a texture or perspective Gouraud)? */
int zl_style_needs_planes(const zl_style *sty);
/* zl_style_needs_planes, 0 when no feature that needs planes is compiled in
 * (zl_config.h): then the callers' plane code is unreachable and goes. */
static inline int zl_style_planes(const zl_style *sty)
{
    return (ZL_FEATURE_TEXTURES || ZL_FEATURE_BLEND) ? zl_style_needs_planes(sty) : 0;
}
/* zl_tri_classify's bounds and zl_tri_setup_rows' record of a flat triangle
 * from three cached vertices whose culling the caller settled, under state
 * st; colour and light are the caller's. 1: set up; 0: not in the target.
 * In 32 bits where the numbers allow, else by the general setup. */
int zl_tri_setup_flat(zl_active *t, const zl_cached_vertex *a, const zl_cached_vertex *b,
                      const zl_cached_vertex *c, const zl_state *st, uint16_t width, uint16_t height);
/* A small flat triangle for frame mode, without a zl_active (zl_raster.c):
 * edges evaluated per row as ceil(n / d), n advancing by inc per row. */
typedef struct {
    int32_t n, inc, d;
} zl_tiny_edge;
typedef struct {
    zl_tiny_edge lng, up, low; /* v0-v2, v0-v1 (rows first..mid), v1-v2 (rows mid..end) */
    /* depth plane, Q20, relative to a multiple of 64 at the lowest vertex
     * depth: value at (ax, first), change per row and per pixel (modulo
     * 2^32), the vertex range, and what the shifted value adds back */
    uint32_t zr, zdy, zdx;
    int32_t zlo, zhi;
    uint32_t zbase, dz14;      /* zbase includes the rounding half; dz14: span stepper, Q14 */
    int32_t ax, first, mid, end;
    int long_left;             /* the long edge bounds the spans on the left */
} zl_tiny;
/* A small Gouraud triangle of frame mode: its zl_tiny, and each colour
 * plane (r, g, b; Q20 of 0..255, modulo 2^32) at (ax, first) with its
 * change per row and per pixel, its Q16 span step (step32) and lane step
 * (zl_span.h's lane colour). A ZL_KIND_TINY_GOURAUD record of scanline mode
 * keeps its zl_tiny_colour in the record's zl_gouraud slot of the work
 * buffer (it fits; cr then at the record's current row). */
typedef struct {
    uint32_t cr[3], cdy[3], cdx[3], dc16[3];
    int32_t dl[3];
} zl_tiny_colour;
typedef struct {
    zl_tiny t;
    zl_tiny_colour c;
} zl_tiny_gouraud;
/* Draw a zl_tiny_gouraud_setup triangle: exactly the pixels the general
 * path writes for it (row_span). */
void zl_tiny_gouraud_draw(const zl_tiny_gouraud *tg, const zl_span_state *ss, uint8_t *color, int32_t color_stride,
                          uint8_t *depth, int32_t depth_stride);
/* The span [x0, x1) (clipped, x0 < x1) of a ZL_KIND_TINY_GOURAUD record on
 * its current row: the pixels zl_tiny_gouraud_draw writes on that row. */
void zl_tiny_gouraud_span(const zl_active *a, const zl_tiny_colour *tc, const zl_span_state *ss, int32_t x0,
                          int32_t x1, uint8_t *crow, uint16_t *zrow);
#if ZL_SMALL_TRIANGLE_SETUP
/* zl_tiny_setup of cached vertices v[0..2] with vertex colours col[0..2]
 * (3 bytes each), and the colour planes zl_tri_setup_rows makes: same
 * returns. */
int zl_tiny_gouraud_setup(zl_tiny_gouraud *tg, const zl_cached_vertex *const *v, const uint8_t *const *col,
                          uint16_t height);
/* zl_tri_setup_flat's bounds and numbers as a zl_tiny: 1 set up, 0 not in
 * the target, -1 beyond 32 bits (use zl_tri_setup_flat). */
int zl_tiny_setup(zl_tiny *tt, const zl_cached_vertex *a, const zl_cached_vertex *b, const zl_cached_vertex *c,
                  uint16_t width, uint16_t height);
/* zl_tiny_gouraud_setup into a scanline record of kind ZL_KIND_TINY_GOURAUD
 * and its colour planes (same returns). */
int zl_tiny_gouraud_setup_record(zl_active *r, zl_tiny_colour *tc, const zl_cached_vertex *const *v,
                                 const uint8_t *const *col, uint16_t height);
/* zl_tiny_setup into a scanline record of kind ZL_KIND_TINY (same returns). */
int zl_tiny_setup_record(zl_active *r, const zl_cached_vertex *a, const zl_cached_vertex *b, const zl_cached_vertex *c,
                         uint16_t width, uint16_t height);
#else
/* Compiled out (zl_config.h): each set-up answers -1, "take the general
 * path", at compile time, so no small-triangle draw or record is reachable
 * and section garbage collection drops them (the same pixels). */
static ZL_ALWAYS_INLINE int zl_tiny_gouraud_setup(zl_tiny_gouraud *tg, const zl_cached_vertex *const *v,
                                                  const uint8_t *const *col, uint16_t height)
{
    (void)tg, (void)v, (void)col, (void)height;
    return -1;
}
static ZL_ALWAYS_INLINE int zl_tiny_setup(zl_tiny *tt, const zl_cached_vertex *a, const zl_cached_vertex *b,
                                          const zl_cached_vertex *c, uint16_t width, uint16_t height)
{
    (void)tt, (void)a, (void)b, (void)c, (void)width, (void)height;
    return -1;
}
static ZL_ALWAYS_INLINE int zl_tiny_gouraud_setup_record(zl_active *r, zl_tiny_colour *tc,
                                                         const zl_cached_vertex *const *v, const uint8_t *const *col,
                                                         uint16_t height)
{
    (void)r, (void)tc, (void)v, (void)col, (void)height;
    return -1;
}
static ZL_ALWAYS_INLINE int zl_tiny_setup_record(zl_active *r, const zl_cached_vertex *a, const zl_cached_vertex *b,
                                                 const zl_cached_vertex *c, uint16_t width, uint16_t height)
{
    (void)r, (void)a, (void)b, (void)c, (void)width, (void)height;
    return -1;
}
#endif
/* Whether zl_tiny_draw can write this target: RGB565, aligned rows, every
 * channel, depth LESS or LEQUAL with writes. */
int zl_tiny_span_state(const zl_span_state *ss, const void *color, int32_t color_stride, const void *depth);
/* Draw a zl_tiny_setup triangle with one packed RGB565 pixel: exactly the
 * pixels zl_tri_rows_flat writes for the same triangle. */
void zl_tiny_draw(const zl_tiny *tt, const zl_span_state *ss, uint8_t *color, int32_t color_stride, uint8_t *depth,
                  int32_t depth_stride, uint16_t pixel);
/* All rows of a flat triangle (frame mode, whole target): zl_tri_row's
 * pixels without its per-row record updates. */
void zl_tri_rows_flat(const zl_active *t, const zl_span_state *ss, uint8_t *color, int32_t color_stride,
                      uint8_t *depth, int32_t depth_stride);
/* Fill the span of row t->row into the given row buffers, then step t to the
 * next row. Returns 0 when the triangle has no rows left. */
int zl_tri_row(zl_active *t, zl_gouraud *g, const zl_span_state *ss, uint8_t *color_row,
               uint16_t *depth_row);
/* Span writer settings for a state and a target format (bpp 0 = no colour). */
void zl_span_state_init(zl_span_state *ss, const zl_state *st, int has_depth, int has_color,
                        zl_format format, uint16_t width);
/* Fill width pixels of a row with a colour, honouring the colour mask. */
void zl_fill_color_row(uint8_t *row, const zl_span_state *ss, zl_rgb c);
/* Fill n 16-bit values (depth rows, RGB565 rows). */
void zl_fill16(uint16_t *p, uint16_t v, uint32_t n);

/* Polygon offset of a triangle, Q20 depth steps: factor * max(|dz/dx|,
 * |dz/dy|) + units; 0 when both are 0. */
int64_t zl_tri_offset(const zl_wvert *a, const zl_wvert *b, const zl_wvert *c, const zl_style *sty);
/* zl_tri_offset from a depth plane's own gradients (a clipped piece with
 * the original triangle's plane). */
int64_t zl_tri_offset_plane(const zl_attr *z, const zl_style *sty);
/* Move a set-up triangle's depth plane by an offset (Q20 steps). */
void zl_tri_apply_offset(zl_active *t, int64_t offset);
/* Plot the current row of a line or point record into the row buffers and
 * step it; returns 0 when it has no rows left. */
int zl_prim_row(zl_active *t, const zl_span_state *ss, uint8_t *color_row, uint16_t *depth_row);

/* ---- stage 4, primitives: 4_primitives/zl_line.c */
/* Window-space endpoint of a line or point, with its clipping flag. */
typedef struct {
    int32_t x, y;   /* subpixels */
    uint32_t z;     /* Q16 of the stored depth scale, as zl_wvert */
} zl_lvert;

/* Segment of a zl_lines or polygon edge, ready for setup: both endpoints,
 * which end pixels to leave out (bit 0: a, bit 1: b) and the colour. */
typedef struct {
    zl_lvert a, b;
    unsigned skip;
    zl_rgb rgb;
} zl_segment;

/* Transform and clip the segment between vertices ia and ib of a source
 * (mesh positions) into window space; skip_a/skip_b ask to leave out an
 * end pixel when that end is not moved by clipping. 0 if nothing is left. */
int zl_segment_make(const zl_source *s, uint16_t ia, uint16_t ib, int skip_a, int skip_b, zl_segment *out);
/* Transform a vertex for a point; 0 when it is outside a clip plane. */
int zl_point_make(const zl_source *s, uint16_t idx, zl_lvert *out);
/* Set up a line record for the target size: 1 if it has pixels in view. */
int zl_line_setup(zl_active *t, const zl_segment *seg, unsigned algo, int64_t offset_q20,
                  uint16_t width, uint16_t height);
/* The same for an antialiased line (two pixels per major step). */
int zl_line_setup_aa(zl_active *t, const zl_segment *seg, int64_t offset_q20, uint16_t width, uint16_t height);
/* Set up a point record: 1 if it has pixels in view. */
int zl_point_setup(zl_active *t, const zl_lvert *p, zl_rgb rgb, unsigned size, int64_t offset_q20,
                   uint16_t width, uint16_t height);

/* Primitive `k` of a zl_lines: its record (line or point), 0 if it shows
 * nothing. Segments after the first of a strip or loop leave out their
 * first pixel. */
int zl_lines_record(const zl_source *s, const zl_lines *l, const zl_style *sty, const zl_state *st,
                    uint32_t k, zl_active *out);

/* Piece `k` of a triangle drawn by polygon mode (fill pieces are the fan
 * of its polygon; line pieces its 3 edges; point pieces its 3 vertices).
 * Returns the number of pieces in *count on k == 0 and sets up piece k into
 * t (and g): 1 if it has pixels. */
unsigned zl_tri_pieces(const zl_source *s, const zl_style *sty, uint32_t tri, const zl_poly *poly);
/* A set-up fan triangle (a, b, c) of the clipped polygon of triangle tri:
 * the depth, colour and (with tp, when the style needs them; then poly is
 * the p of a zl_tpoly) texture planes of the original triangle instead of
 * its own (zl_tri_orig_planes, zl_tri_orig_texplanes, zl_tri_set_planes). */
void zl_tri_orig_piece(const zl_source *s, const zl_style *sty, uint32_t tri, const zl_poly *poly, const zl_wvert *a,
                       const zl_wvert *b, const zl_wvert *c, zl_active *t, zl_gouraud *g, zl_texplanes *tp);
int zl_tri_piece(const zl_source *s, const zl_style *sty, uint32_t tri, const zl_poly *poly, unsigned k,
                 zl_active *t, zl_gouraud *g, zl_texplanes *tp);

/* ---- stage 4, primitives: 4_primitives/zl_outline.c */
/* Is edge e of the outline drawn (silhouette, crease or border)? */
int zl_outline_selected(const zl_source *s, const zl_mesh *mesh, const zl_outline *o, const zl_mesh_edge *e);
/* Line record of edge k of an outline of `mesh` (s->mesh may be a view with
 * its positions only); 0 when the edge is not drawn or not in view. */
int zl_outline_record(const zl_source *s, const zl_mesh *mesh, const zl_outline *o, const zl_style *sty,
                      uint32_t k, zl_active *out);
zl_status zl_check_outline(const zl_mesh *mesh, const zl_outline *o);

/* ---- stage 1, base: 1_base/zl_state.c, argument checks */
zl_status zl_check_mesh(const zl_mesh *m, int pixel_space);
/* ---- stage 2: 2_geometry/zl_matrix.c: zl_check_mesh, then the transform limits of zline.h
 * (LIMITS) when mvp is given; ZL_ERR_RANGE before anything is drawn. */
zl_status zl_check_geometry(const zl_mesh *m, const zl_mat4 *mvp);
/* The same limits for bare positions (lines and points). */
zl_status zl_check_positions(const zl_fixed *positions, uint32_t vertex_count, const zl_mat4 *mvp);
/* ---- stage 1, base: 1_base/zl_state.c */
zl_status zl_check_lines(const zl_lines *l);
/* ---- stage 4, primitives: 4_primitives/zl_line.c: a mesh view of lines */
void zl_lines_mesh(const zl_lines *l, zl_mesh *m);

#endif /* ZLINE_INTERNAL_H */

/*
 * zline internals shared by the immediate (frame) mode and the scanline/band
 * mode. Both modes run every triangle through the same three stages, which is
 * why their pixels are identical:
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
#define ZL_GRAD_LIMIT ((int64_t)1 << 43)     /* clamp of a per-pixel attribute gradient */

/* Window-space vertex, after projection and snapping. */
typedef struct {
    int32_t x, y;       /* subpixels */
    uint32_t z;         /* window depth * 65535 * 65536, i.e. Q16 of the stored scale */
    uint16_t r, g, b;   /* colour, Q8 (0 .. 255 * 256) */
} zl_wvert;

/* Clip-space vertex carried through clipping. */
typedef struct {
    int32_t x, y, z, w; /* Q16.16 */
    int32_t r, g, b;    /* colour, Q8 */
} zl_cvert;

/* Cached window vertex of scanline mode: 8 bytes. x == ZL_CACHE_COMPLEX marks a
 * vertex outside a clip plane or outside the int16 window range; triangles
 * using it take the clipping path, which recomputes it exactly. */
typedef struct {
    int16_t x, y;
    uint32_t z;
} zl_cached_vertex;
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
    unsigned n;
    zl_rgb flat;        /* lit flat colour */
} zl_poly;

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
    zl_attr c[3];       /* r, g, b, Q20 of 0..255 */
} zl_gouraud;

struct zl_active {
    zl_edge left, right;   /* edges bounding the current rows */
    zl_edge lower;         /* replaces the short edge from row `mid` on */
    zl_attr z;
    int32_t ax;            /* anchor column of the attribute planes */
    uint32_t zlo, zhi;     /* vertex depth range, Q16 (same scale as zl_wvert.z) */
    int16_t row, mid, end; /* next row, row where `lower` takes over, end row */
    uint8_t lower_is_left;
    uint8_t mesh;          /* index of the frame mesh (scanline mode) */
    uint8_t rgb[3];        /* flat colour */
    uint16_t id;           /* source triangle: the drawing order */
    uint16_t next;         /* active-list link (scanline mode) */
};

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

#define ZL_LIST_END 0xFFFFu

/* ---- zl_clip.c */
/* Transform vertex `idx` of the source's mesh to clip space (colour
 * included). Returns 0 if the transform leaves its range. */
int zl_vertex_clip(const zl_source *s, uint16_t idx, zl_cvert *out);
/* Bit mask of the clip planes the vertex is outside of (0 = inside all). */
unsigned zl_outcode(const zl_source *s, const zl_cvert *v);
/* Project and snap an inside vertex to window space. */
void zl_project(const zl_source *s, const zl_cvert *v, zl_wvert *out);
/* Project one mesh vertex into a cache entry (scanline mode). */
zl_cached_vertex zl_cache_vertex(const zl_source *s, uint16_t idx);
/* The window-space polygon of triangle t; 0 if nothing of it is left. */
int zl_tri_polygon(const zl_source *s, uint32_t t, zl_poly *out);

/* ---- zl_raster.c */
/* Cull and bound fan triangle (a, b, c). Returns 1 and the row range
 * [*first, *end) when it may cover pixels of the width x height target. */
int zl_tri_classify(const zl_wvert *a, const zl_wvert *b, const zl_wvert *c, const zl_state *st,
                    uint16_t width, uint16_t height, int32_t *first, int32_t *end);
/* Full setup of a classified triangle into *t (and *g for Gouraud). */
int zl_tri_setup(zl_active *t, zl_gouraud *g, const zl_wvert *a, const zl_wvert *b,
                 const zl_wvert *c, const zl_poly *poly, const zl_state *st, uint16_t width,
                 uint16_t height);
/* Fill the span of row t->row into the given row buffers, then step t to the
 * next row. Returns 0 when the triangle has no rows left. */
int zl_tri_row(zl_active *t, zl_gouraud *g, const zl_span_state *ss, uint8_t *color_row,
               uint16_t *depth_row);
/* Span writer settings for a state and a target format (bpp 0 = no colour). */
void zl_span_state_init(zl_span_state *ss, const zl_state *st, int has_depth, int has_color,
                        zl_format format, uint16_t width);
/* Fill width pixels of a row with a colour, honouring the colour mask. */
void zl_fill_color_row(uint8_t *row, const zl_span_state *ss, zl_rgb c);

/* ---- zl_draw.c */
zl_status zl_check_mesh(const zl_mesh *m, int pixel_space);
/* ---- zl_matrix.c: zl_check_mesh, then the transform limits of zline.h
 * (LIMITS) when mvp is given; ZL_ERR_RANGE before anything is drawn. */
zl_status zl_check_geometry(const zl_mesh *m, const zl_mat4 *mvp);

#endif /* ZLINE_INTERNAL_H */

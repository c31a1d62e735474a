/* SPDX-License-Identifier: MIT */
/*
 * Stage 2, geometry: what the vertex, lighting and clipping files share.
 * Internal to core/src/2_geometry; later stages use zl_internal.h only.
 */
#ifndef ZL_GEOMETRY_H
#define ZL_GEOMETRY_H

#include "../1_base/zl_internal.h"

/* The clip planes, in the order a triangle is clipped against them. */
enum {
    PLANE_W = 0,      /* w >= 1 raw: keeps every later division defined */
    PLANE_NEAR = 1,   /* z >= 0 */
    PLANE_FAR = 2,    /* z <= w */
    PLANE_LEFT = 3,   /* window x >= -ZL_GUARD_PX */
    PLANE_RIGHT = 4,  /* window x <= width + ZL_GUARD_PX */
    PLANE_TOP = 5,    /* window y >= -ZL_GUARD_PX */
    PLANE_BOTTOM = 6, /* window y <= height + ZL_GUARD_PX */
    PLANE_COUNT = 7
};

#define COORD_LIMIT ((uint32_t)1 << 30) /* zl_matrix.c's limit: +-16384.0 */

/* (k + 1) mod 3 for k in 0..2, without a division (a library call on
 * Cortex-M0): the cyclic index of a cross product's loop. */
#define NEXT3(k) ((k) == 2u ? 0u : (k) + 1u)

/* Vertex colour channel k in Q8 (0 without vertex colours). */
ZL_SHARED_STATIC int32_t color_q8(const zl_mesh *m, uint16_t idx, int k)
{
    return m->vertex_colors ? (int32_t)ZL_MESH_U8(m->vertex_colors, idx * 3u + (unsigned)k) * 256 : 0;
}

/* Texture coordinate (Q16.16 of the size) in 1/256 texel, within +-2^23. */
ZL_SHARED_STATIC int32_t texel_q8(zl_fixed c, uint16_t size)
{
    int64_t v = zl_floor_shift64((int64_t)c * size + 128, 8);
    const int64_t lim = (int64_t)1 << 23;
    return (int32_t)(v < -lim ? -lim : (v > lim ? lim : v));
}

/* Texture coordinates of vertex idx under the style (0 without a texture). */
ZL_SHARED_STATIC void tex_coords(const zl_style *sty, uint16_t idx, int32_t *u, int32_t *v)
{
    *u = 0;
    *v = 0;
    if (sty != NULL && sty->texture != NULL && sty->texcoords != NULL) {
        *u = texel_q8(sty->texcoords[idx * 2u], sty->texture->width);
        *v = texel_q8(sty->texcoords[idx * 2u + 1], sty->texture->height);
    }
}

/* |v| <= 2^30, the coordinate and matrix entry limit, in one compare. */
ZL_SHARED_STATIC int in_limit(zl_fixed v)
{
    return (uint32_t)v + COORD_LIMIT <= 2u * COORD_LIMIT;
}

/* Bit length of v (0 for 0): the 64-bit scaling of the geometry stage. */
ZL_SHARED_STATIC unsigned bit_length64(uint64_t v)
{
    unsigned n = 0;
    while (v != 0) {
        v >>= 1;
        n++;
    }
    return n;
}

ZL_SHARED_STATIC uint64_t mag64(int64_t v)
{
    return v < 0 ? 0u - (uint64_t)v : (uint64_t)v;
}

ZL_SHARED_STATIC uint32_t abs32(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/*
 * Signed distance of v to a plane, positive inside, in 64 bits. The x/y
 * planes come from window x = (x/w + 1) * W/2 >= -G, multiplied through by
 * 2w > 0: W x + (W + 2G) w >= 0; in pixel space window x is x itself.
 */
#if ZL_FAST_PATHS /* a switch: the compact form below costs BSP draws 3 % more Cortex-M4 instructions */
ZL_SHARED_STATIC int64_t plane_distance_of(const zl_source *s, unsigned plane, const zl_cvert *v)
{
    const int64_t g = ZL_GUARD_PX;
    const int64_t w = v->w, wd = s->width, ht = s->height;
    int pixel = s->mvp == NULL;
    switch (plane) {
    case PLANE_W:
        return w - 1;
    case PLANE_NEAR:
        return v->z;
    case PLANE_FAR:
        return w - v->z;
    case PLANE_LEFT:
        return pixel ? v->x + g * w : wd * v->x + (wd + 2 * g) * w;
    case PLANE_RIGHT:
        return pixel ? (wd + g) * w - v->x : -wd * v->x + (wd + 2 * g) * w;
    case PLANE_TOP:
        return pixel ? v->y + g * w : -ht * v->y + (ht + 2 * g) * w;
    default:
        return pixel ? (ht + g) * w - v->y : ht * v->y + (ht + 2 * g) * w;
    }
}
#else
/* The same distances in half the code: the one out-of-line copy (below). */
ZL_SHARED_STATIC int64_t plane_distance_of(const zl_source *s, unsigned plane, const zl_cvert *v)
{
    const int64_t g = ZL_GUARD_PX, w = v->w;
    int64_t c, d; /* the plane's coordinate (x or y) and the window's extent along it */
    if (plane == PLANE_W)
        return w - 1;
    if (plane == PLANE_NEAR)
        return v->z;
    if (plane == PLANE_FAR)
        return w - v->z;
    c = plane <= PLANE_RIGHT ? v->x : v->y;
    d = plane <= PLANE_RIGHT ? s->width : s->height;
    if (s->mvp == NULL) /* pixel space: x >= -G, x <= W + G, likewise y */
        return plane == PLANE_RIGHT || plane == PLANE_BOTTOM ? (d + g) * w - c : c + g * w;
    if (plane == PLANE_RIGHT || plane == PLANE_TOP) /* clip y grows up, window y down */
        c = -c;
    return d * c + (d + 2 * g) * w;
}
#endif

/* A copy of it in each file that clips, inlined in its loops; without the
 * fast paths (zl_config.h) one out-of-line copy (zl_vertex.c). */
#if ZL_FAST_PATHS
#define plane_distance plane_distance_of
#else
int64_t zl_plane_distance(const zl_source *s, unsigned plane, const zl_cvert *v);
#define plane_distance zl_plane_distance
#endif

/* Lights given in world (or eye) space (zl_light_point.c). The model
 * matrix's 3x3 A as A^-1 = inv / det 2^exp (det > 0; model NULL: the
 * identity); 0 when A is singular. */
int zl_light_inverse3(const zl_mat4 *model, int64_t inv[9], uint64_t *det, int *exp);
/* A point light's position into model space, M^-1 (position - t) with t the
 * model matrix's translation, in Q16.16 (int64, within +-2^46 raw); 0 when
 * the 3x3 is singular. */
int zl_light_point_to_model(const zl_mat4 *model, zl_vec3 position, int64_t out[3]);

#endif /* ZL_GEOMETRY_H */

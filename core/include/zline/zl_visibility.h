/* SPDX-License-Identifier: MIT */
/*
 * zline visibility without a per-pixel depth buffer (issue #6).
 *
 * Four hidden-surface methods that share the pipeline of zline.h (transform,
 * homogeneous clipping, projection, snapping, culling, the exact edge
 * steppers), so every pixel they cover is a pixel the z-buffer covers under
 * the RASTER CONTRACT; only the choice of which surface shows differs:
 *
 *   scan-line AET   rows with an active edge table; spans between edge
 *                   crossings are resolved from the triangles' depth planes
 *                   at the span ends, split where two planes cross. No depth
 *                   memory at all; output one row at a time.
 *   painter's       triangles sorted far to near (key: the farthest vertex),
 *                   drawn over each other into a full colour frame.
 *   BSP             a tree built offline (tools/bsp) from a mesh, walked back
 *                   to front (painter's order that is always right) or front
 *                   to back with a 1-bit coverage mask and early out.
 *   ray casting     the reference: for each pixel centre, the nearest
 *                   triangle along the view ray, decided with exact integer
 *                   coverage and a high-precision depth. Used as the oracle in
 *                   the tests; slow (every active triangle at every pixel).
 *
 * Semantics shared by all four: the nearest surface wins (the z-buffer's
 * LESS with depth writes); equal depth goes to the earlier triangle in
 * submission order. The state's depth_test, depth_func, depth_write,
 * color_mask and shading fields are ignored: every triangle is drawn flat in
 * its (lit) face colour, as the z-buffer draws it with ZL_SHADE_FLAT. Culling
 * and lighting follow the state. Every output pixel also gets the id of the
 * source triangle that shows there (its index counted over the meshes in
 * submission order), or ZL_VIS_NONE: comparing id images is how the tests
 * check visibility independently of colours.
 *
 * Memory: as zl_frame, every byte is in the caller's work buffer, whose exact
 * size zl_vis_bytes() gives; the painter's and BSP methods draw into a full
 * colour frame the caller owns (zl_vis_target).
 */
#ifndef ZLINE_VISIBILITY_H
#define ZLINE_VISIBILITY_H

#include <stddef.h>
#include <stdint.h>

#include "zline.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Id of a pixel no triangle covers. */
#define ZL_VIS_NONE 0xFFFFu

/*
 * ZL_BSP_MAX_DEPTH: longest root-to-leaf path a BSP tree may have; the
 * traversal keeps an explicit stack of this many uint16 node indices on the
 * C stack (no recursion): 512 bytes by default. Trees of scanned meshes are
 * deep (tools/bsp makes the benchmark bunny 136 levels deep, choosing
 * splitters for few splits rather than balance); tools/bsp refuses to write
 * a tree deeper than this.
 */
#ifndef ZL_BSP_MAX_DEPTH
#define ZL_BSP_MAX_DEPTH 256
#endif
#if ZL_BSP_MAX_DEPTH < 1 || ZL_BSP_MAX_DEPTH > 1024
#error "ZL_BSP_MAX_DEPTH must be in 1..1024"
#endif

typedef enum {
    ZL_VIS_AET = 1,     /* scan-line algorithm with an active edge table */
    ZL_VIS_PAINTER = 2, /* depth sort, back to front */
    ZL_VIS_RAYCAST = 3  /* reference ray caster */
} zl_vis_algo;

/*
 * Configuration of a zl_vis. Capacities as zl_frame_config:
 *   max_meshes     zl_vis_add_mesh calls
 *   max_vertices   sum of vertex_count over the meshes
 *   max_triangles  source triangles kept after culling and off-screen
 *                  rejection (the sum of triangle_count always suffices);
 *                  <= 65535
 *   max_active     AET and ray caster: triangle pieces crossing one row at
 *                  once (a clipped triangle counts once per fan piece, up to
 *                  7); ignored by the painter's method
 * A scene that needs more fails with ZL_ERR_CAPACITY before any output, and
 * zl_vis_needs() then tells what it needs.
 */
typedef struct {
    uint16_t width, height; /* 1 .. ZL_MAX_DIM */
    uint8_t algorithm;      /* zl_vis_algo */
    uint8_t format;         /* zl_format of the colour output */
    uint16_t max_meshes;    /* 1 .. 255 */
    uint32_t max_vertices;
    uint32_t max_triangles;
    uint32_t max_active;
} zl_vis_config;

typedef struct zl_vis_mesh zl_vis_mesh;

/* Private bookkeeping; the caller allocates it and never touches it. */
typedef struct {
    zl_vis_config cfg;
    uint16_t mesh_count;
    uint8_t planned;
    uint32_t vertex_count, triangle_total;
    zl_frame_needs_t needs;
    zl_vis_mesh *meshes;
    void *vcache;        /* cached window vertices */
    uint16_t *row_start; /* AET, ray caster: height + 1 bucket ends (edge table) */
    uint16_t *visible;   /* kept triangle ids: by first row, or in painter's order */
    uint32_t *keys;      /* painter's: sort keys */
    void *pool;          /* AET: zl_active records; ray caster: window triangles */
    void *edges;         /* AET: the active edge list */
    uint16_t *inset;     /* AET: triangles in the current span, nearest first */
    uint16_t *act;       /* AET: activated records */
    uint16_t *free_slots; /* AET: stack of free records */
    uint8_t *flags;      /* AET: per record, live / in the span */
    uint8_t *color_row;  /* one row of output colour */
    uint16_t *id_row;    /* one row of output ids */
    uint16_t *gap_row;   /* ray caster: depth gap to the next surface */
} zl_vis;

/* Exact work-buffer bytes of a configuration; 0 if it is invalid. */
size_t zl_vis_bytes(const zl_vis_config *cfg);
/* Start a scene in `work` (>= zl_vis_bytes(cfg) bytes, 8-byte aligned). */
zl_status zl_vis_begin(zl_vis *v, const zl_vis_config *cfg, void *work, size_t work_bytes);
/* Submit a mesh with its transform (NULL: pixel space) and state (copied). */
zl_status zl_vis_add_mesh(zl_vis *v, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state);
/* What the scene needs; valid after the first render call, even a failed one. */
zl_frame_needs_t zl_vis_needs(const zl_vis *v);

/*
 * One output row of the row-by-row methods (AET, ray caster).
 *   color  width pixels of cfg.format
 *   ids    width source-triangle ids, ZL_VIS_NONE for background
 *   gap    ray caster only (else NULL): at each covered pixel, how much
 *          farther the second-nearest surface through that pixel centre is
 *          than the nearest, in 1/256 of a depth step (1/65535 of the depth
 *          range), saturated at 65535, which also means "no second surface".
 *          gap <= 256 marks the pixels where depth-buffer methods may
 *          legitimately pick either surface.
 */
typedef struct {
    uint16_t y, width;
    const void *color;
    const uint16_t *ids;
    const uint16_t *gap;
} zl_vis_row;

/* Called for each row in order; a non-zero return stops the frame. */
typedef int (*zl_vis_row_fn)(void *user, const zl_vis_row *row);

/*
 * Render every row with the configured row method (ZL_VIS_AET or
 * ZL_VIS_RAYCAST) and hand each to fn. Returns 0 when every row is out, a
 * negative zl_status (ZL_ERR_ARG for the painter's configuration), or fn's
 * first non-zero value. A scene renders once; begin again for a new frame.
 */
int zl_vis_render_rows(zl_vis *v, zl_rgb clear, zl_vis_row_fn fn, void *user);

/* A full-frame output for the painter's and BSP methods. */
typedef struct {
    void *color;           /* width x height pixels of `format`, or NULL */
    int32_t color_stride;  /* bytes */
    uint16_t *ids;         /* width x height ids, or NULL */
    int32_t ids_stride;    /* bytes, even */
    uint16_t width, height;
    uint8_t format;        /* zl_format */
} zl_vis_target;

/*
 * Painter's algorithm (ZL_VIS_PAINTER): clear the target, sort the kept
 * triangles by their farthest vertex's window depth, far first (ties: the
 * later-submitted triangle first, so the earlier one ends on top as with
 * LESS), with an in-place heap sort (O(n log n), no extra memory), and draw
 * them in that order with no depth test. The target must match cfg's size
 * and format. Right whenever no pair of overlapping triangles is ordered
 * differently by the key than by depth at their common pixels: it fails on
 * cyclic overlap and on intersecting triangles (see docs/VISIBILITY.md).
 */
zl_status zl_painter_draw(zl_vis *v, const zl_vis_target *target, zl_rgb clear);

/*
 * The painter's order for transparent geometry (zline.h, BLENDING): the
 * triangles of mesh, transformed by mvp (NULL: pixel space), written to
 * out_indices (3 per triangle, each triangle's vertices in their order)
 * back to front by the key above: the farthest vertex's window depth, a
 * vertex's z / w clamped to the depth range (0 for one at or behind the
 * eye, as near clipping leaves it), far first; equal keys put the later
 * triangle first, so equal-depth triangles blend in the z-buffer's order.
 * keys and order are scratch of triangle_count entries each; out_indices
 * must not be mesh->indices. Draw the mesh with its indices replaced by
 * out_indices (and depth writes off). ZL_ERR_ARG for NULL arguments,
 * ZL_ERR_RANGE for an index out of range or a vertex the transform cannot
 * take (zl_transform_point).
 */
zl_status zl_painter_order(const zl_mesh *mesh, const zl_mat4 *mvp, uint16_t *out_indices, uint32_t *keys,
                           uint16_t *order);

/* ------------------------------------------------------------------ BSP */

#define ZL_BSP_LEAF 0xFFFFu /* child index of an empty subtree */

/*
 * A node: the plane n . p = d in model space (n as Q16.16, roughly unit
 * length; d in Q32.32, i.e. n . p computed with Q16.16 n and p), the
 * triangles lying in it (first .. first + count - 1 of the tree's triangle
 * arrays), and the subtrees in front (n . p > d) and behind.
 */
typedef struct {
    int32_t n[3];
    int64_t d;
    uint16_t first, count;
    uint16_t front, back;
} zl_bsp_node;

/* A tree as tools/bsp writes it: const arrays, flash-resident. */
typedef struct {
    const zl_fixed *positions;  /* 3 Q16.16 per vertex (model space) */
    const uint16_t *indices;    /* 3 per triangle, grouped by node */
    const uint16_t *source;     /* per triangle: the input triangle it came from */
    const uint8_t *face_colors; /* 3 per triangle, or NULL for the state's colour */
    const zl_bsp_node *nodes;
    uint16_t vertex_count, triangle_count, node_count, root;
    uint16_t depth;             /* longest root-to-leaf path, in nodes */
} zl_bsp;

typedef enum {
    ZL_BSP_BACK_TO_FRONT = 0, /* painter's order: no memory beyond the frame */
    ZL_BSP_FRONT_TO_BACK = 1  /* nearest first, each pixel written once; needs the mask */
} zl_bsp_order;

/* Bytes of the coverage mask of front-to-back drawing: one bit a pixel plus
 * a count of covered pixels per row (0 for an invalid size). */
size_t zl_bsp_mask_bytes(uint16_t width, uint16_t height);

/*
 * Draw a BSP tree seen from `eye` (the camera position in the tree's model
 * space) through mvp into target, without a depth buffer: clear, then walk
 * the tree iteratively with an explicit stack of ZL_BSP_MAX_DEPTH entries.
 * Back to front overwrites farther surfaces; front to back writes a pixel
 * only when its mask bit is clear, skips full rows, and stops the walk once
 * every row is full. mask: zl_bsp_mask_bytes() bytes, 4-byte aligned
 * (NULL for back to front). Ids are the tree's `source` entries. Checks the
 * tree (indices, child links, depth) before drawing: ZL_ERR_RANGE when it is
 * malformed, ZL_ERR_CAPACITY when it is deeper than ZL_BSP_MAX_DEPTH.
 */
zl_status zl_bsp_draw(const zl_bsp *bsp, const zl_mat4 *mvp, zl_vec3 eye, const zl_state *state,
                      const zl_vis_target *target, zl_rgb clear, zl_bsp_order order, void *mask,
                      size_t mask_bytes);

/* ------------------------------------------------------ back-face culling */

/*
 * The two culling tests of the lecture, for triangle t of a mesh:
 *   zl_cull_viewpoint  before projection: the plane equation of the
 *                      triangle in model space against the eye position
 *                      (model space): sign of n . (eye - p0), n = (p1 - p0)
 *                      x (p2 - p0), exact in 128-bit integer arithmetic.
 *   zl_cull_projected  after projection (view direction): the winding of the
 *                      snapped window-space triangle, which is what the
 *                      rasteriser culls by (the clipped polygon when the
 *                      triangle crosses the near plane).
 * Both return 1 when the triangle faces the viewer under front_face
 * (zl_front_face), 0 when it faces away, and -1 when undecided: on the plane
 * (edge-on), a degenerate triangle, nothing left after clipping, or bad
 * arguments. The tests agree when mvp is model-view-projection with a perspective
 * projection and eye is that camera's position in model space, except on
 * triangles so close to edge-on that snapping to 1/16 pixel flips or zeroes
 * their projected area (tests/test_visibility.c bounds this).
 */
int zl_cull_viewpoint(const zl_mesh *mesh, uint32_t t, zl_vec3 eye, uint8_t front_face);
int zl_cull_projected(const zl_mesh *mesh, uint32_t t, const zl_mat4 *mvp, uint16_t width,
                      uint16_t height, uint8_t front_face);

#ifdef __cplusplus
}
#endif

#endif /* ZLINE_VISIBILITY_H */

/* SPDX-License-Identifier: MIT */
/*
 * Offline BSP tree builder (host only; used by the zline-bsp tool, the
 * visibility benchmark and the tree's own test).
 *
 * Input: a triangle mesh with Q16.16 positions. Output: the arrays of a
 * zl_bsp (zl_visibility.h), heap-allocated. Method, per node:
 *   1. choose the splitting plane among up to `candidates` of the node's
 *      triangles (evenly spaced in its list) by the classic score
 *      8 * (triangles it would split) + |front - back|;
 *   2. classify every triangle by the side of each vertex (a vertex within
 *      `epsilon` model units of the plane is on it): all on it -> the node's
 *      own list; none behind -> front; none in front -> back; else split;
 *   3. split a crossing triangle one plane at a time (Sutherland-Hodgman on
 *      the triangle as a polygon): the part in front and the part behind,
 *      each fan-triangulated; new vertices are the edge's intersection with
 *      the plane rounded to Q16.16 and shared by both parts (and by a
 *      neighbour split along the same edge), so the pieces of one triangle
 *      meet without cracks among themselves;
 *   4. recurse into both sides.
 * Rounding the new vertices to Q16.16 moves them off the original edge by at
 * most half a unit (2^-17) per coordinate: that, and the snapping of the new
 * vertex to 1/16 pixel, is why a tree's image can differ from the mesh's
 * along the edges of split triangles (docs/VISIBILITY.md).
 */
#ifndef ZLINE_BSP_BUILD_H
#define ZLINE_BSP_BUILD_H

#include <stdint.h>
#include <stdio.h>

#include "zline/zl_visibility.h"

typedef struct {
    int candidates;   /* splitter candidates per node (default 24) */
    double epsilon;   /* on-plane tolerance, model units (default 2^-13) */
} bsp_options;

typedef struct {
    zl_fixed *positions;
    uint16_t *indices;
    uint16_t *source;
    zl_bsp_node *nodes;
    uint32_t vertex_count, triangle_count, node_count, depth;
    uint32_t splits;          /* triangles split (each counted once per cut) */
    uint8_t *split_source;    /* per input triangle: 1 when any cut touched it */
    uint32_t input_triangles;
} bsp_tree;

void bsp_options_default(bsp_options *o);
/* 0 on success; -1 with a message on stderr when the tree would exceed the
 * zl_bsp limits (65535 vertices/triangles/nodes, ZL_BSP_MAX_DEPTH). */
int bsp_build(bsp_tree *out, const zl_fixed *positions, uint32_t vertex_count, const uint16_t *indices,
              uint32_t triangle_count, const bsp_options *opt);
/* A zl_bsp viewing the tree's arrays. */
zl_bsp bsp_view(const bsp_tree *t);
void bsp_free(bsp_tree *t);
/* Write the tree as const C arrays named NAME_*, and `const zl_bsp NAME`, to f
 * (the caller opens and closes it: zline-bsp through the output rule of
 * port/host/zl_output.h). 0, or -1 when the stream saw a write error. */
int bsp_write_c(const bsp_tree *t, FILE *f, const char *name);

#endif

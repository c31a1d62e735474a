/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: the painter's order of a mesh's triangles as an
 * index array, for transparent geometry drawn with blending (zline.h,
 * BLENDING): the key of zl_painter.c (the farthest vertex's window depth,
 * far first; equal keys put the later triangle first), and the heap sort
 * both use (zl_sort_far_first), over caller memory.
 */
#include "zl_vis_internal.h"

/* Window depth of a clip-space vertex as Q16 (0 .. 65536): z / w clamped
 * to the depth range, which is what clipping against near and far leaves
 * of it; a vertex at or behind the eye (w <= 0) is clipped to the near
 * plane, depth 0. */
static uint32_t window_depth(const zl_vec4 *c)
{
    int64_t q;
    if (c->w <= 0 || c->z <= 0)
        return 0;
    if (c->z >= c->w)
        return 65536u;
    q = ((int64_t)c->z * 65536) / c->w; /* 0 <= z < w: the quotient is below 65536 */
    return (uint32_t)q;
}

/* Does entry i come before entry j (farther, or as far and later)? */
static int before(const uint32_t *keys, const uint16_t *order, uint32_t i, uint32_t j)
{
    return keys[i] > keys[j] || (keys[i] == keys[j] && order[i] > order[j]);
}

static void swap_entries(uint32_t *keys, uint16_t *order, uint32_t i, uint32_t j)
{
    uint32_t k = keys[i];
    uint16_t o = order[i];
    keys[i] = keys[j];
    order[i] = order[j];
    keys[j] = k;
    order[j] = o;
}

/* Restore the max-heap (by `before`: the root comes last) below `root`. */
static void sift_down(uint32_t *keys, uint16_t *order, uint32_t root, uint32_t n)
{
    for (;;) {
        uint32_t child = 2 * root + 1;
        if (child >= n)
            return;
        if (child + 1 < n && before(keys, order, child, child + 1))
            child++;
        if (!before(keys, order, root, child))
            return;
        swap_entries(keys, order, root, child);
        root = child;
    }
}

/* The painter's order in place: an in-place heap sort of the (key, id)
 * pairs, O(n log n) comparisons, no extra memory, no recursion. Heap sort is
 * not stable, so the id is part of the comparison: the order is total and
 * the result unique. The heap's root is the entry that comes last, moved to
 * the end each step, so ids[] ends in drawing order. zl_painter_draw sorts
 * its planned triangles with it too. */
void zl_sort_far_first(uint32_t *keys, uint16_t *ids, uint32_t n)
{
    uint32_t i;
    if (n < 2)
        return;
    for (i = n / 2; i-- > 0;)
        sift_down(keys, ids, i, n);
    for (i = n - 1; i > 0; i--) {
        swap_entries(keys, ids, 0, i);
        sift_down(keys, ids, 0, i);
    }
}

zl_status zl_painter_order(const zl_mesh *mesh, const zl_mat4 *mvp, uint16_t *out_indices, uint32_t *keys,
                           uint16_t *order)
{
    uint32_t t, n, i;
    zl_status st;
    if (mesh == NULL || out_indices == NULL || out_indices == mesh->indices ||
        (mesh->triangle_count > 0 && (keys == NULL || order == NULL)))
        return ZL_ERR_ARG;
    st = zl_check_mesh(mesh, mvp == NULL);
    if (st != ZL_OK)
        return st;
    n = mesh->triangle_count;
    for (t = 0; t < n; t++) {
        uint32_t key = 0;
        unsigned k;
        for (k = 0; k < 3; k++) {
            const zl_fixed *p = mesh->positions + (size_t)mesh->indices[t * 3 + k] * 3;
            uint32_t d;
            if (mvp != NULL) {
                zl_vec3 v;
                zl_vec4 c;
                v.x = p[0];
                v.y = p[1];
                v.z = p[2];
                st = zl_transform_point(mvp, v, &c);
                if (st != ZL_OK)
                    return st;
                d = window_depth(&c);
            } else { /* pixel space: z is the window depth */
                d = p[2] <= 0 ? 0u : (p[2] >= ZL_FX_ONE ? 65536u : (uint32_t)p[2]);
            }
            if (d > key)
                key = d;
        }
        keys[t] = key;
        order[t] = (uint16_t)t;
    }
    zl_sort_far_first(keys, order, n);
    for (i = 0; i < n; i++) {
        uint32_t src = (uint32_t)order[i] * 3u;
        out_indices[i * 3] = mesh->indices[src];
        out_indices[i * 3 + 1] = mesh->indices[src + 1];
        out_indices[i * 3 + 2] = mesh->indices[src + 2];
    }
    return ZL_OK;
}

/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: drawing a BSP tree without a depth buffer.
 *
 * The tree (built offline by tools/bsp, stored as const arrays) partitions
 * the mesh by planes: each node holds the triangles lying in its plane, a
 * subtree in front of it and one behind. Seen from the eye, everything on
 * the far side of a node's plane can be hidden by the node's triangles and
 * by the near side, never the other way round; so far subtree, node, near
 * subtree is a correct back-to-front order for any eye position, without
 * sorting and without per-pixel depth.
 *
 * The walk is the iterative in-order traversal: push nodes while going to the
 * far child, pop one, draw it, continue with its near child. The explicit
 * stack holds at most one entry per level, ZL_BSP_MAX_DEPTH uint16 entries
 * on the C stack; no recursion. Front to back is the same walk with near and
 * far exchanged: then a pixel is final once written, so a 1-bit coverage mask
 * decides which pixels a span may still write, a count of covered pixels per
 * row skips rows that are full, and the walk stops when every row is.
 *
 * Within a node, triangles are drawn in reverse order back to front and in
 * order front to back, so that of two coplanar overlapping triangles the
 * earlier one shows, as with the z-buffer's LESS.
 */
#include <string.h>

#include "zl_vis_internal.h"

size_t zl_bsp_mask_bytes(uint16_t width, uint16_t height)
{
    size_t words = ((size_t)width + 31u) / 32u;
    if (width < 1 || height < 1 || width > ZL_MAX_DIM || height > ZL_MAX_DIM)
        return 0;
    return (size_t)height * words * 4u + (((size_t)height * 2u + 3u) & ~(size_t)3u);
}

/* Is the eye on the front side of node n's plane (or on it)? */
static int eye_in_front(const zl_bsp_node *n, zl_vec3 eye)
{
    int64_t s = (int64_t)n->n[0] * eye.x + (int64_t)n->n[1] * eye.y + (int64_t)n->n[2] * eye.z - n->d;
    return s >= 0;
}

static uint16_t far_child(const zl_bsp_node *n, zl_vec3 eye, int front_to_back)
{
    int front = eye_in_front(n, eye);
    if (front_to_back)
        front = !front;
    return front ? n->back : n->front;
}

static uint16_t near_child(const zl_bsp_node *n, zl_vec3 eye, int front_to_back)
{
    int front = eye_in_front(n, eye);
    if (front_to_back)
        front = !front;
    return front ? n->front : n->back;
}

/* The tree's arrays and links; the walk itself checks the depth. */
static zl_status check_tree(const zl_bsp *b)
{
    uint32_t i;
    if (b->positions == NULL && b->vertex_count > 0)
        return ZL_ERR_ARG;
    if ((b->indices == NULL || b->source == NULL) && b->triangle_count > 0)
        return ZL_ERR_ARG;
    if (b->nodes == NULL && b->node_count > 0)
        return ZL_ERR_ARG;
    if (b->node_count > 0 && b->root >= b->node_count)
        return ZL_ERR_RANGE;
    for (i = 0; i < b->node_count; i++) {
        const zl_bsp_node *n = &b->nodes[i];
        int k;
        if ((uint32_t)n->first + n->count > b->triangle_count)
            return ZL_ERR_RANGE;
        if ((n->front != ZL_BSP_LEAF && n->front >= b->node_count) ||
            (n->back != ZL_BSP_LEAF && n->back >= b->node_count))
            return ZL_ERR_RANGE;
        for (k = 0; k < 3; k++)
            if (n->n[k] > 2 * ZL_FX_ONE || n->n[k] < -2 * ZL_FX_ONE)
                return ZL_ERR_RANGE; /* keeps the side test inside 64 bits */
    }
    if (b->depth > ZL_BSP_MAX_DEPTH)
        return ZL_ERR_CAPACITY;
    return ZL_OK;
}

typedef struct {
    const zl_vis_target *tg;
    uint32_t *bits;   /* front to back: coverage, one bit a pixel */
    uint16_t *count;  /* covered pixels per row */
    size_t words;     /* uint32 per mask row */
    uint32_t full;    /* rows with every pixel covered */
} cover;

static void draw_masked(cover *c, zl_active *t, const uint8_t *pix, uint16_t id)
{
    const zl_vis_target *tg = c->tg;
    unsigned bpp = zl_format_bytes((zl_format)tg->format);
    do {
        int32_t x0 = t->left.x < 0 ? 0 : t->left.x, x1 = t->right.x > tg->width ? tg->width : t->right.x, i;
        uint32_t *bits = c->bits + (size_t)t->row * c->words;
        uint8_t *crow;
        uint16_t *irow;
        if (x0 >= x1 || c->count[t->row] == tg->width)
            continue;
        crow = tg->color ? (uint8_t *)tg->color + (size_t)t->row * (size_t)tg->color_stride : NULL;
        irow = tg->ids ? (uint16_t *)(void *)((uint8_t *)tg->ids + (size_t)t->row * (size_t)tg->ids_stride) : NULL;
        for (i = x0; i < x1; i++) {
            uint32_t bit = UINT32_C(1) << ((unsigned)i & 31u);
            if (bits[i >> 5] & bit)
                continue;
            bits[i >> 5] |= bit;
            if (crow)
                zl_vis_fill(crow + (size_t)i * bpp, bpp, pix, 1);
            if (irow)
                irow[i] = id;
            c->count[t->row]++;
        }
        if (c->count[t->row] == tg->width)
            c->full++;
    } while (zl_vis_step(t, 0));
}

static void draw_node(const zl_bsp *b, const zl_bsp_node *n, const zl_source *src, cover *c, int front_to_back)
{
    uint32_t k;
    for (k = 0; k < n->count; k++) {
        uint32_t t = front_to_back ? (uint32_t)n->first + k : (uint32_t)n->first + n->count - 1u - k;
        zl_poly poly;
        uint8_t rgb[3], pix[3];
        unsigned p;
        if (c->full == c->tg->height)
            return;
        if (!zl_tri_polygon(src, t, &poly))
            continue;
        rgb[0] = poly.flat.r;
        rgb[1] = poly.flat.g;
        rgb[2] = poly.flat.b;
        zl_vis_pack((zl_format)c->tg->format, rgb, pix);
        for (p = 1; p + 1 < poly.n; p++) {
            zl_active a;
            if (!zl_tri_setup(&a, NULL, &poly.v[0], &poly.v[p], &poly.v[p + 1], &poly, src->state, c->tg->width,
                              c->tg->height))
                continue;
            if (front_to_back)
                draw_masked(c, &a, pix, b->source[t]);
            else
                zl_vis_draw_spans(&a, c->tg, pix, b->source[t]);
        }
    }
}

zl_status zl_bsp_draw(const zl_bsp *bsp, const zl_mat4 *mvp, zl_vec3 eye, const zl_state *state,
                      const zl_vis_target *target, zl_rgb clear, zl_bsp_order order, void *mask,
                      size_t mask_bytes)
{
    uint16_t stack[ZL_BSP_MAX_DEPTH];
    unsigned sp = 0;
    uint16_t node;
    zl_mesh mesh;
    zl_source src;
    zl_status st;
    cover c;
    int ftb = order == ZL_BSP_FRONT_TO_BACK;
    if (bsp == NULL || mvp == NULL || state == NULL || (order != ZL_BSP_BACK_TO_FRONT && !ftb))
        return ZL_ERR_ARG;
    st = zl_vis_check_target(target);
    if (st == ZL_OK)
        st = zl_state_check(state);
    if (st == ZL_OK)
        st = check_tree(bsp);
    if (st != ZL_OK)
        return st;
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = bsp->positions;
    mesh.indices = bsp->indices;
    mesh.face_colors = bsp->face_colors;
    mesh.vertex_count = bsp->vertex_count;
    mesh.triangle_count = bsp->triangle_count;
    st = zl_check_mesh(&mesh, 0);
    if (st != ZL_OK)
        return st;
    memset(&c, 0, sizeof c);
    c.tg = target;
    if (ftb) {
        size_t need = zl_bsp_mask_bytes(target->width, target->height);
        if (mask == NULL || ((uintptr_t)mask & 3u) != 0)
            return ZL_ERR_ARG;
        if (mask_bytes < need)
            return ZL_ERR_SIZE;
        c.words = ((size_t)target->width + 31u) / 32u;
        c.bits = mask;
        c.count = (uint16_t *)(void *)(c.bits + (size_t)target->height * c.words);
    }
    /* A dry walk first: a malformed tree (a cycle, a path deeper than the
     * stack) is an error before any pixel. */
    node = bsp->node_count > 0 ? bsp->root : ZL_BSP_LEAF;
    {
        uint32_t visits = 0;
        for (;;) {
            while (node != ZL_BSP_LEAF) {
                if (sp == ZL_BSP_MAX_DEPTH || ++visits > bsp->node_count)
                    return ZL_ERR_CAPACITY;
                stack[sp++] = node;
                node = far_child(&bsp->nodes[node], eye, ftb);
            }
            if (sp == 0)
                break;
            node = near_child(&bsp->nodes[stack[--sp]], eye, ftb);
        }
    }
    /* Only now, with the tree known good, is anything written: the mask
     * too (a failing call leaves every buffer as it was; fuzz_bsp). */
    if (ftb)
        memset(mask, 0, zl_bsp_mask_bytes(target->width, target->height));
    zl_vis_clear_target(target, clear);
    src.mesh = &mesh;
    src.mvp = mvp;
    src.state = state;
    src.cache = NULL;
    src.width = target->width;
    src.height = target->height;
    node = bsp->node_count > 0 ? bsp->root : ZL_BSP_LEAF;
    for (;;) {
        const zl_bsp_node *n;
        while (node != ZL_BSP_LEAF) {
            stack[sp++] = node;
            node = far_child(&bsp->nodes[node], eye, ftb);
        }
        if (sp == 0 || (ftb && c.full == target->height))
            break;
        n = &bsp->nodes[stack[--sp]];
        draw_node(bsp, n, &src, &c, ftb);
        node = near_child(n, eye, ftb);
    }
    return ZL_OK;
}

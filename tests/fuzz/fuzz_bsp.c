/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: zl_bsp_draw, the reader of BSP trees (zl_visibility.h).
 *
 * A tree is const data a firmware takes from flash, written by tools/bsp or
 * by anything else; zl_bsp_draw checks it (indices, child links, depth)
 * before drawing. Here every field of the tree is arbitrary: vertex and
 * triangle indices out of range, child links that point anywhere (cycles,
 * shared subtrees, the root itself), claimed depths that lie, planes of any
 * size, first/count beyond the triangle arrays. The target (colour and id
 * planes), the state, the matrix, the eye, the order and the mask (its size
 * and alignment too) are arbitrary as well. Every buffer is exactly as large
 * as promised, between guard zones; a failing call must write nothing.
 */
#include "fz_scene.h"
#include "zline/zl_visibility.h"

#define FZ_BSP_MAX_NODES 24u

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fz_mesh fm;
    static zl_bsp_node nodes[FZ_BSP_MAX_NODES];
    static uint16_t source[FZ_MAX_TRIANGLES];
    fz_in in = {data, size};
    zl_bsp bsp;
    zl_vis_target t;
    zl_state st;
    zl_mat4 m;
    const zl_mat4 *mvp;
    zl_vec3 eye;
    fz_buf color, ids, mask;
    uint8_t *snap;
    uint32_t flags = fz_u8(&in);
    unsigned w = 1 + fz_u8(&in) % 48, h = 1 + fz_u8(&in) % 48, bpp, nn, i;
    size_t mask_bytes, mask_alloc, csize, isize, misalign;
    zl_status s;
    int state_ok;

    fz_read_mesh(&in, &fm, w, h);
    for (i = 0; i < fm.mesh.triangle_count; i++)
        source[i] = (uint16_t)fz_u16(&in);
    nn = fz_u8(&in) % (FZ_BSP_MAX_NODES + 1);
    for (i = 0; i < nn; i++) {
        uint32_t link = fz_u8(&in);
        nodes[i].n[0] = fz_fixed(&in);
        nodes[i].n[1] = fz_fixed(&in);
        nodes[i].n[2] = fz_fixed(&in);
        nodes[i].d = (int64_t)(int32_t)fz_u32(&in) * ((int64_t)1 << (fz_u8(&in) % 32));
        nodes[i].first = (uint16_t)(fz_u8(&in) % (fm.mesh.triangle_count + 3u));
        nodes[i].count = (uint16_t)(fz_u8(&in) % 5u);
        /* mostly a child below this node (a proper tree), sometimes anywhere */
        nodes[i].front = (uint16_t)((link & 1u) ? ZL_BSP_LEAF
                                                : ((link & 2u) ? fz_u8(&in) % (nn + 1u)
                                                               : i + 1u + fz_u8(&in) % (nn - i)));
        nodes[i].back = (uint16_t)((link & 4u) ? ZL_BSP_LEAF
                                               : ((link & 8u) ? fz_u8(&in) % (nn + 1u)
                                                              : i + 1u + fz_u8(&in) % (nn - i)));
        if (nodes[i].front == nn)
            nodes[i].front = ZL_BSP_LEAF;
        if (nodes[i].back == nn)
            nodes[i].back = ZL_BSP_LEAF;
    }
    memset(&bsp, 0, sizeof bsp);
    bsp.positions = fm.mesh.positions;
    bsp.indices = fm.mesh.indices;
    bsp.source = (flags & 1u) ? NULL : source;
    bsp.face_colors = fm.mesh.face_colors;
    bsp.nodes = nn ? nodes : NULL;
    bsp.vertex_count = fm.mesh.vertex_count;
    bsp.triangle_count = fm.mesh.triangle_count;
    bsp.node_count = (uint16_t)nn;
    bsp.root = (uint16_t)((flags & 2u) ? ZL_BSP_LEAF : fz_u8(&in) % (nn + 1u));
    bsp.depth = (uint16_t)fz_u16(&in);

    fz_read_state(&in, &st, &state_ok);
    mvp = fz_read_matrix(&in, &m);
    eye.x = fz_fixed(&in);
    eye.y = fz_fixed(&in);
    eye.z = fz_fixed(&in);

    memset(&t, 0, sizeof t);
    t.format = fz_enum(&in, 3);
    bpp = zl_format_bytes((zl_format)t.format);
    if (bpp == 0)
        bpp = 2;
    t.width = (uint16_t)w;
    t.height = (uint16_t)h;
    t.color_stride = (int32_t)(w * bpp + fz_u8(&in) % 4 * bpp);
    t.ids_stride = (int32_t)(w * 2 + fz_u8(&in) % 3 * 2);
    if (flags & 4u)
        t.color_stride -= 1;
    if (flags & 8u)
        t.ids_stride -= 1;
    csize = t.color_stride > 0 ? (size_t)(h - 1) * (size_t)t.color_stride + (size_t)w * bpp : 1;
    isize = t.ids_stride > 0 ? (size_t)(h - 1) * (size_t)t.ids_stride + (size_t)w * 2 : 2;
    fz_buf_alloc(&color, csize);
    fz_buf_alloc(&ids, isize);
    t.color = (flags & 16u) ? NULL : (void *)color.data;
    t.ids = (flags & 32u) ? (uint16_t *)(void *)ids.data : NULL;

    mask_bytes = zl_bsp_mask_bytes((uint16_t)w, (uint16_t)h);
    mask_alloc = mask_bytes;
    misalign = 0;
    if (flags & 64u) { /* one byte short, or misaligned */
        if (fz_u8(&in) & 1u)
            mask_alloc = mask_bytes ? mask_bytes - 1 : 0;
        else
            misalign = 1 + fz_u8(&in) % 3;
    }
    fz_buf_alloc(&mask, mask_alloc + misalign);

    snap = (uint8_t *)malloc(csize + isize + mask.size + 1);
    if (snap == NULL)
        abort();
    memcpy(snap, color.data, csize);
    memcpy(snap + csize, ids.data, isize);
    memcpy(snap + csize + isize, mask.data, mask.size);
    s = zl_bsp_draw(&bsp, mvp, eye, &st, &t, (zl_rgb){1, 2, 3}, (zl_bsp_order)fz_enum(&in, 2),
                    (flags & 128u) ? NULL : (void *)(mask.data + misalign), mask_alloc);
    fz_buf_check(&color, "colour");
    fz_buf_check(&ids, "ids");
    fz_buf_check(&mask, "mask");
    if (s != ZL_OK) {
        FZ_REQUIRE(s == ZL_ERR_ARG || s == ZL_ERR_RANGE || s == ZL_ERR_SIZE || s == ZL_ERR_CAPACITY,
                   "unexpected status %d", s);
        FZ_REQUIRE(memcmp(snap, color.data, csize) == 0, "failing zl_bsp_draw wrote colour (%d)", s);
        FZ_REQUIRE(memcmp(snap + csize, ids.data, isize) == 0, "failing zl_bsp_draw wrote ids (%d)", s);
        FZ_REQUIRE(memcmp(snap + csize + isize, mask.data, mask.size) == 0, "failing zl_bsp_draw wrote the mask (%d)",
                   s);
    } else {
        FZ_REQUIRE(state_ok, "zl_bsp_draw accepted an invalid state");
    }
    free(snap);
    fz_buf_free(&color);
    fz_buf_free(&ids);
    fz_buf_free(&mask);
    return 0;
}

/*
 * Fuzz target: frame mode (zl_init, zl_clear, zl_draw_mesh) fed arbitrary
 * targets, meshes, matrices and render states.
 *
 * Every colour and depth buffer is allocated with exactly the size zline.h
 * promises ((height - 1) * stride + width * bpp) between guard zones, so
 * AddressSanitizer and the guard check catch any write outside it; the
 * padding bytes of each row (stride beyond width * bpp) must stay untouched.
 * The status of every call is checked against an oracle computed here from
 * the documented rules, and a call that fails must leave every byte as it
 * was. UndefinedBehaviorSanitizer catches overflowing arithmetic.
 */
#include "fz_scene.h"

typedef struct {
    fz_buf buf;
    uint8_t *snap;
    uint8_t *px;      /* first byte of row 0: buf.data + offset */
    size_t offset;
    size_t row_bytes; /* bytes of a row that belong to pixels */
    int32_t stride;
} fz_plane;

/* A plane of `rows` rows of row_bytes within `stride`, starting `offset`
 * bytes into its buffer (an odd address for offset 1); a stride below
 * row_bytes (invalid) still gets a buffer of rows * row_bytes. */
static void plane_make(fz_plane *p, unsigned rows, size_t row_bytes, int32_t stride, size_t offset)
{
    size_t size = stride >= (int32_t)row_bytes ? (size_t)(rows - 1) * (size_t)stride + row_bytes
                                               : (size_t)rows * row_bytes;
    size += offset;
    p->row_bytes = row_bytes;
    p->stride = stride;
    p->offset = offset;
    fz_buf_alloc(&p->buf, size);
    p->px = p->buf.data + offset;
    p->snap = (uint8_t *)malloc(size ? size : 1);
    if (p->snap == NULL)
        abort();
}

static void plane_snap(fz_plane *p)
{
    memcpy(p->snap, p->buf.data, p->buf.size);
}

/* After a successful call: guards and row padding unchanged. After a failed
 * one: nothing changed at all. */
static void plane_check(const fz_plane *p, int failed, const char *what)
{
    size_t i;
    fz_buf_check(&p->buf, what);
    if (failed) {
        FZ_REQUIRE(memcmp(p->snap, p->buf.data, p->buf.size) == 0, "%s written by a failing call", what);
        return;
    }
    for (i = 0; i < p->buf.size; i++) {
        size_t col = i < p->offset ? p->row_bytes : (p->stride > 0 ? (i - p->offset) % (size_t)p->stride : i);
        if (col >= p->row_bytes)
            FZ_REQUIRE(p->snap[i] == p->buf.data[i], "%s: row padding byte %zu written", what, i);
    }
}

static void plane_free(fz_plane *p)
{
    fz_buf_free(&p->buf);
    free(p->snap);
}

/* The oracle for positions and matrices: each within +-16384.0 and every
 * vertex's clip-space position inside Q16.16 (zl_transform_point). */
static int range_ok(const zl_mesh *m, const zl_mat4 *mvp)
{
    unsigned i;
    if (mvp == NULL)
        return 1;
    for (i = 0; i < 16; i++)
        if (!fz_in_range(mvp->m[i]))
            return 0;
    if (m->positions == NULL)
        return 1;
    for (i = 0; i < m->vertex_count; i++) {
        zl_vec3 v;
        zl_vec4 c;
        v.x = m->positions[i * 3];
        v.y = m->positions[i * 3 + 1];
        v.z = m->positions[i * 3 + 2];
        if (zl_transform_point(mvp, v, &c) != ZL_OK)
            return 0;
    }
    return 1;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    zl_target t;
    zl_context ctx;
    fz_plane color, depth;
    uint32_t flags = fz_u8(&in);
    unsigned w = 1 + fz_u8(&in) % 72, h = 1 + fz_u8(&in) % 72, bpp, draws, d;
    int fmt_ok, target_ok;
    zl_status st;
    zl_rgb clear_color;
    uint16_t clear_depth;

    memset(&t, 0, sizeof t);
    t.format = fz_enum(&in, 3);
    bpp = zl_format_bytes((zl_format)t.format);
    fmt_ok = bpp != 0;
    if (!fmt_ok)
        bpp = 2;
    t.width = (uint16_t)w;
    t.height = (uint16_t)h;
    t.color_stride = (int32_t)(w * bpp + (fz_u8(&in) % 8) * ((flags & 64u) ? 1u : bpp));
    t.depth_stride = (int32_t)(w * 2 + (fz_u8(&in) % 4) * 2);
    if (flags & 32u) { /* deliberately too small, odd or negative strides */
        uint32_t k = fz_u8(&in);
        if (k & 1u)
            t.color_stride -= (int32_t)(1 + k % 5);
        if (k & 2u)
            t.depth_stride -= (int32_t)(1 + (k >> 2) % 3);
        if (k & 4u)
            t.color_stride = -t.color_stride;
    }
    plane_make(&color, h, (size_t)w * bpp, t.color_stride, (flags & 16u) ? 1 : 0);
    plane_make(&depth, h, (size_t)w * 2, t.depth_stride, 0);
    t.color = (flags & 1u) ? (void *)color.px : NULL;
    t.depth = (flags & 2u) ? (uint16_t *)(void *)depth.px : NULL;
    if (flags & 128u) { /* width or height out of 1..ZL_MAX_DIM */
        if (fz_u8(&in) & 1u)
            t.width = (uint16_t)(fz_u8(&in) & 1u ? 0 : ZL_MAX_DIM + 1 + fz_u8(&in));
        else
            t.height = (uint16_t)(fz_u8(&in) & 1u ? 0 : ZL_MAX_DIM + 1 + fz_u8(&in));
    }
    /* native RGB565 needs an even colour address and stride (RGB565_BE is
     * bytes); depth needs even strides */
    target_ok = fmt_ok && t.width >= 1 && t.height >= 1 && t.width <= ZL_MAX_DIM && t.height <= ZL_MAX_DIM &&
                (t.color == NULL ||
                 (t.color_stride >= (int32_t)(w * bpp) &&
                  (t.format != ZL_FORMAT_RGB565 ||
                   (t.color_stride % 2 == 0 && ((uintptr_t)t.color & 1u) == 0)))) &&
                (t.depth == NULL || (t.depth_stride >= (int32_t)(w * 2) && t.depth_stride % 2 == 0));

    plane_snap(&color);
    plane_snap(&depth);
    st = zl_init(&ctx, &t);
    FZ_REQUIRE((st == ZL_OK) == (target_ok != 0), "zl_init returned %d, target_ok %d", st, target_ok);
    if (st != ZL_OK) {
        plane_check(&color, 1, "colour");
        plane_check(&depth, 1, "depth");
        goto done;
    }
    clear_color.r = (uint8_t)fz_u8(&in);
    clear_color.g = (uint8_t)fz_u8(&in);
    clear_color.b = (uint8_t)fz_u8(&in);
    clear_depth = (uint16_t)fz_u16(&in);
    st = zl_clear(&ctx, clear_color, clear_depth);
    FZ_REQUIRE(st == ZL_OK, "zl_clear returned %d", st);
    plane_check(&color, 0, "colour after zl_clear");
    plane_check(&depth, 0, "depth after zl_clear");

    draws = 1 + fz_u8(&in) % 3;
    for (d = 0; d < draws; d++) {
        static fz_mesh fm;
        zl_mat4 m;
        const zl_mat4 *mvp;
        int state_ok, ptrs_ok, expect_ok;
        fz_read_mesh(&in, &fm, w, h);
        fz_read_state(&in, &ctx.state, &state_ok);
        mvp = fz_read_matrix(&in, &m);
        ptrs_ok = (fm.mesh.vertex_count == 0 || fm.mesh.positions != NULL) &&
                  (fm.mesh.triangle_count == 0 || fm.mesh.indices != NULL);
        expect_ok = state_ok && ptrs_ok && fm.indices_ok && range_ok(&fm.mesh, mvp);
        plane_snap(&color);
        plane_snap(&depth);
        st = zl_draw_mesh(&ctx, &fm.mesh, mvp);
        FZ_REQUIRE((st == ZL_OK) == (expect_ok != 0), "zl_draw_mesh returned %d, expected %s", st,
                   expect_ok ? "ZL_OK" : "an error");
        FZ_REQUIRE(st == ZL_OK || st == ZL_ERR_ARG || st == ZL_ERR_RANGE, "unexpected status %d", st);
        plane_check(&color, st != ZL_OK, "colour after zl_draw_mesh");
        plane_check(&depth, st != ZL_OK, "depth after zl_draw_mesh");
    }
done:
    plane_free(&color);
    plane_free(&depth);
    return 0;
}

/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: frame mode (zl_init, zl_clear, zl_draw_mesh, zl_draw_lines)
 * fed arbitrary targets, meshes, lines, matrices, render states and styles
 * (polygon modes, offsets, textures, toon shading).
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

/* Style (zline.h: lines, polygon modes, offsets, textures, toon): every
 * field arbitrary. The arrays it points to are allocated with exactly the
 * size promised (texels: (height - 1) * stride + width, texcoords: 2 per
 * vertex, toon colours: toon_bands) and no guard zone, so that
 * AddressSanitizer catches a read past any of them. */
typedef struct {
    zl_style style;
    zl_texture tex;
    uint16_t *texels;
    zl_fixed *texcoords;
    zl_rgb *toon;
} fz_style;

static void read_style(fz_in *in, fz_style *fs, unsigned vertex_count)
{
    uint32_t f = fz_u8(in);
    memset(fs, 0, sizeof *fs);
    zl_style_default(&fs->style);
    if (!(f & 1u))
        return;
    fs->style.polygon_front = fz_enum(in, 3);
    fs->style.polygon_back = fz_enum(in, 3);
    fs->style.point_size = (uint8_t)fz_u8(in);
    fs->style.line_algo = fz_enum(in, 2);
    fs->style.offset_factor = fz_fixed(in);
    fs->style.offset_units = fz_fixed(in);
    fs->style.tex_mapping = fz_enum(in, 2);
    fs->style.tex_every = (uint8_t)fz_u8(in);
    fs->style.persp_gouraud = fz_enum(in, 2);
    fs->style.line_aa = fz_enum(in, 2);
    if (f & 2u) {
        unsigned i, n;
        fs->tex.width = (uint16_t)(1u << (fz_u8(in) % 6));
        fs->tex.height = (uint16_t)(1u << (fz_u8(in) % 6));
        if (f & 4u) /* not a power of two, or a short stride */
            fs->tex.width = (uint16_t)(fs->tex.width + 1u);
        fs->tex.stride = (uint16_t)(fs->tex.width + fz_u8(in) % 3 - ((f & 8u) ? 1 : 0));
        fs->tex.wrap_s = fz_enum(in, 2);
        fs->tex.wrap_t = fz_enum(in, 2);
        n = (unsigned)(fs->tex.height - 1u) * fs->tex.stride + fs->tex.width;
        fs->texels = (uint16_t *)malloc(n * sizeof(uint16_t));
        if (fs->texels == NULL)
            abort();
        for (i = 0; i < n; i++)
            fs->texels[i] = (uint16_t)(i * 2654435761u >> 16);
        fs->tex.texels = fs->texels;
        fs->style.texture = &fs->tex;
        if (vertex_count > 0) {
            fs->texcoords = (zl_fixed *)malloc(vertex_count * 2 * sizeof(zl_fixed));
            if (fs->texcoords == NULL)
                abort();
            for (i = 0; i < vertex_count * 2; i++)
                fs->texcoords[i] = fz_fixed(in);
        }
        fs->style.texcoords = fs->texcoords;
    }
    if (f & 16u) {
        unsigned i;
        fs->style.toon_bands = (uint8_t)(1 + fz_u8(in) % 8);
        fs->toon = (zl_rgb *)malloc(fs->style.toon_bands * sizeof(zl_rgb));
        if (fs->toon == NULL)
            abort();
        for (i = 0; i < fs->style.toon_bands; i++) {
            fs->toon[i].r = (uint8_t)fz_u8(in);
            fs->toon[i].g = (uint8_t)fz_u8(in);
            fs->toon[i].b = (uint8_t)fz_u8(in);
        }
        fs->style.toon_colors = fs->toon;
    }
    if (f & 32u) { /* issue 15: blending, constant alpha, filtering, texel format */
        fs->style.blend = fz_enum(in, 3);
        fs->style.alpha = (uint8_t)fz_u8(in);
        fs->style.tex_filter = fz_enum(in, 2);
        fs->tex.format = fz_enum(in, 2);
    }
}

static void free_style(fz_style *fs)
{
    free(fs->texels);
    free(fs->texcoords);
    free(fs->toon);
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
        fz_style fs;
        zl_mat4 m;
        const zl_mat4 *mvp;
        int state_ok, ptrs_ok, expect_ok, lines = (fz_u8(&in) & 7u) == 0;
        fz_read_mesh(&in, &fm, w, h);
        fz_read_state(&in, &ctx.state, &state_ok);
        mvp = fz_read_matrix(&in, &m);
        read_style(&in, &fs, fm.mesh.vertex_count);
        ctx.style = fs.style;
        plane_snap(&color);
        plane_snap(&depth);
        if (lines) {
            /* the mesh's positions and indices as lines or points */
            zl_lines l;
            unsigned i;
            memset(&l, 0, sizeof l);
            l.positions = fm.mesh.positions;
            l.indices = (fz_u8(&in) & 1u) ? fm.mesh.indices : NULL;
            l.colors = fm.mesh.face_colors;
            l.vertex_count = fm.mesh.vertex_count;
            l.count = (uint16_t)(fz_u8(&in) % (fm.mesh.triangle_count * 3u + 1u));
            if (l.colors != NULL && l.count > fm.mesh.triangle_count)
                l.count = fm.mesh.triangle_count; /* colours: one per primitive, at most count */
            l.prim = fz_enum(&in, 4);
            ptrs_ok = l.count == 0 || l.positions != NULL;
            expect_ok = state_ok && ptrs_ok && l.prim <= ZL_PRIM_POINTS;
            for (i = 0; i < l.count && expect_ok; i++)
                if ((l.indices ? l.indices[i] : i) >= l.vertex_count)
                    expect_ok = 0;
            {
                zl_mesh pm = fm.mesh;
                pm.indices = NULL;
                pm.triangle_count = 0;
                pm.positions = l.positions;
                expect_ok = expect_ok && range_ok(&pm, mvp);
            }
            st = zl_draw_lines(&ctx, &l, mvp);
        } else {
            ptrs_ok = (fm.mesh.vertex_count == 0 || fm.mesh.positions != NULL) &&
                      (fm.mesh.triangle_count == 0 || fm.mesh.indices != NULL);
            expect_ok = state_ok && ptrs_ok && fm.indices_ok && range_ok(&fm.mesh, mvp);
            st = zl_draw_mesh(&ctx, &fm.mesh, mvp);
        }
        /* the style is checked by zl_style_check; any other refusal is a bug */
        if (zl_style_check(&fs.style) != ZL_OK)
            FZ_REQUIRE(st != ZL_OK, "a draw accepted a style zl_style_check refuses");
        else
            FZ_REQUIRE((st == ZL_OK) == (expect_ok != 0), "%s returned %d, expected %s",
                       lines ? "zl_draw_lines" : "zl_draw_mesh", st, expect_ok ? "ZL_OK" : "an error");
        FZ_REQUIRE(st == ZL_OK || st == ZL_ERR_ARG || st == ZL_ERR_RANGE || st == ZL_ERR_SIZE,
                   "unexpected status %d", st);
        plane_check(&color, st != ZL_OK, "colour after a draw");
        plane_check(&depth, st != ZL_OK, "depth after a draw");
        free_style(&fs);
    }
done:
    plane_free(&color);
    plane_free(&depth);
    return 0;
}

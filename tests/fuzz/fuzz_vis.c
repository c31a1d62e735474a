/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: the visibility methods without a depth buffer
 * (zl_visibility.h: AET, ray caster, painter's) with arbitrary
 * configurations, work-buffer sizes and alignments, and scenes.
 *
 *   - the work buffer is exactly as large as the fuzzer says (often
 *     zl_vis_bytes() give or take a little) between guard zones checked after
 *     every call; a failing zl_vis_begin writes nothing;
 *   - rows come out in order, each inside the work buffer, and a capacity
 *     error comes before the first row;
 *   - the painter's method draws into a guarded full target of exactly the
 *     promised size, and writes nothing when it fails.
 */
#include "fz_scene.h"
#include "zline/zl_visibility.h"

#define FZ_VIS_MESHES 3

typedef struct {
    const fz_buf *work;
    unsigned next_y, width;
    int bad;
} row_check;

static int check_row(void *user, const zl_vis_row *row)
{
    row_check *c = (row_check *)user;
    const uint8_t *lo = c->work->data, *hi = c->work->data + c->work->size;
    FZ_REQUIRE(row->y == c->next_y && row->width == c->width, "row %u (width %u), expected %u", row->y,
               row->width, c->next_y);
    FZ_REQUIRE(row->color != NULL && (const uint8_t *)row->color >= lo && (const uint8_t *)row->color < hi,
               "row colour outside the work buffer");
    FZ_REQUIRE(row->ids == NULL || ((const uint8_t *)row->ids >= lo && (const uint8_t *)(row->ids + row->width) <= hi),
               "row ids outside the work buffer");
    fz_buf_check(c->work, "work during zl_vis_render_rows");
    c->next_y++;
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static fz_mesh meshes[FZ_VIS_MESHES];
    zl_mat4 mats[FZ_VIS_MESHES];
    const zl_mat4 *mvps[FZ_VIS_MESHES];
    zl_state states[FZ_VIS_MESHES];
    fz_in in = {data, size};
    zl_vis_config cfg;
    zl_vis v;
    fz_buf work;
    uint8_t *snap;
    uint32_t flags = fz_u8(&in), sum_v = 0, sum_t = 0;
    unsigned n, i;
    size_t bytes, work_bytes, misalign = 0;
    zl_status st;
    zl_rgb clear;

    memset(&cfg, 0, sizeof cfg);
    cfg.width = (uint16_t)(1 + fz_u8(&in) % 48);
    cfg.height = (uint16_t)(1 + fz_u8(&in) % 48);
    cfg.algorithm = (uint8_t)(fz_u8(&in) % 5); /* 0 and 4: invalid */
    cfg.format = fz_enum(&in, 3);
    clear.r = (uint8_t)fz_u8(&in);
    clear.g = (uint8_t)fz_u8(&in);
    clear.b = (uint8_t)fz_u8(&in);
    n = 1 + fz_u8(&in) % FZ_VIS_MESHES;
    for (i = 0; i < n; i++) {
        int ok;
        fz_read_mesh(&in, &meshes[i], cfg.width, cfg.height);
        fz_read_state(&in, &states[i], &ok);
        mvps[i] = fz_read_matrix(&in, &mats[i]);
        sum_v += meshes[i].mesh.vertex_count;
        sum_t += meshes[i].mesh.triangle_count;
    }
    cfg.max_meshes = (uint16_t)((flags & 1u) ? fz_u8(&in) % 5 : n);
    cfg.max_vertices = (flags & 2u) ? fz_u8(&in) % 100 : sum_v;
    cfg.max_triangles = (flags & 4u) ? fz_u8(&in) % 100 : sum_t;
    cfg.max_active = (flags & 8u) ? fz_u8(&in) % 100 : 7 * (sum_t ? sum_t : 1);
    bytes = zl_vis_bytes(&cfg);
    work_bytes = bytes;
    if (flags & 16u)
        work_bytes = (fz_u8(&in) & 1u) ? (bytes > 0 ? bytes - 1 - fz_u8(&in) % (bytes < 64 ? bytes : 64) : 0)
                                       : bytes + fz_u8(&in);
    if (flags & 32u)
        misalign = 1 + fz_u8(&in) % 7;
    if (work_bytes == 0)
        work_bytes = fz_u8(&in);

    fz_buf_alloc(&work, work_bytes + misalign);
    snap = (uint8_t *)malloc(work.size + 1);
    if (snap == NULL)
        abort();
    memcpy(snap, work.data, work.size);
    st = zl_vis_begin(&v, &cfg, work.data + misalign, work_bytes);
    fz_buf_check(&work, "work after zl_vis_begin");
    if (bytes == 0 || misalign != 0 || work_bytes < bytes)
        FZ_REQUIRE(st != ZL_OK, "zl_vis_begin accepted bytes %zu work %zu misalign %zu", bytes, work_bytes,
                   misalign);
    else
        FZ_REQUIRE(st == ZL_OK, "zl_vis_begin refused a valid work buffer: %d", st);
    if (st != ZL_OK) {
        FZ_REQUIRE(memcmp(snap, work.data, work.size) == 0, "failing zl_vis_begin wrote to the work buffer");
        goto out;
    }
    for (i = 0; i < n; i++) {
        zl_status a = zl_vis_add_mesh(&v, &meshes[i].mesh, mvps[i], &states[i]);
        FZ_REQUIRE(a == ZL_OK || a == ZL_ERR_ARG || a == ZL_ERR_RANGE || a == ZL_ERR_CAPACITY,
                   "zl_vis_add_mesh: %d", a);
        fz_buf_check(&work, "work after zl_vis_add_mesh");
    }
    if (cfg.algorithm == ZL_VIS_PAINTER) {
        zl_vis_target t;
        fz_buf color, ids;
        unsigned bpp = zl_format_bytes((zl_format)cfg.format);
        uint8_t *csnap;
        memset(&t, 0, sizeof t);
        t.width = cfg.width;
        t.height = cfg.height;
        t.format = cfg.format;
        t.color_stride = (int32_t)(cfg.width * bpp);
        t.ids_stride = (int32_t)cfg.width * 2;
        fz_buf_alloc(&color, (size_t)cfg.width * cfg.height * bpp);
        fz_buf_alloc(&ids, (size_t)cfg.width * cfg.height * 2);
        t.color = color.data;
        t.ids = (flags & 64u) ? (uint16_t *)(void *)ids.data : NULL;
        csnap = (uint8_t *)malloc(color.size + 1);
        if (csnap == NULL)
            abort();
        memcpy(csnap, color.data, color.size);
        st = zl_painter_draw(&v, &t, clear);
        fz_buf_check(&color, "painter colour");
        fz_buf_check(&ids, "painter ids");
        fz_buf_check(&work, "work after zl_painter_draw");
        if (st != ZL_OK) {
            FZ_REQUIRE(st == ZL_ERR_CAPACITY || st == ZL_ERR_ARG || st == ZL_ERR_SIZE, "zl_painter_draw: %d", st);
            FZ_REQUIRE(memcmp(csnap, color.data, color.size) == 0, "failing zl_painter_draw wrote colour");
        }
        free(csnap);
        fz_buf_free(&color);
        fz_buf_free(&ids);
    } else {
        row_check c;
        int r;
        c.work = &work;
        c.next_y = 0;
        c.width = cfg.width;
        c.bad = 0;
        r = zl_vis_render_rows(&v, clear, check_row, &c);
        fz_buf_check(&work, "work after zl_vis_render_rows");
        if (r == 0)
            FZ_REQUIRE(c.next_y == cfg.height, "%u of %u rows", c.next_y, cfg.height);
        else
            FZ_REQUIRE((r == ZL_ERR_CAPACITY || r == ZL_ERR_ARG) && c.next_y == 0,
                       "zl_vis_render_rows: %d after %u rows", r, c.next_y);
    }
out:
    free(snap);
    fz_buf_free(&work);
    return 0;
}

/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: scanline and band mode (zl_frame_*) with arbitrary
 * configurations, work-buffer sizes and alignments, and scenes.
 *
 *   - the work buffer has exactly the size the fuzzer asks for (often
 *     zl_frame_bytes() give or take a few bytes), between guard zones that
 *     are checked after every call; a call that fails writes nothing;
 *   - every band lies inside the work buffer and rows come out in order;
 *   - with two colour buffers, the band returned last stays untouched while
 *     the next one is rendered (the DMA promise of zl_frame_next_band);
 *   - ZL_ERR_CAPACITY comes before any band, and the capacities
 *     zl_frame_needs() then reports are enough for the same scene;
 *   - the finished frame is byte-identical, colour and depth, to frame mode
 *     (zl_draw_mesh) drawing the same meshes into a full target.
 */
#include "fz_scene.h"

#define FZ_MAX_MESHES 3

typedef struct {
    fz_mesh m[FZ_MAX_MESHES];
    zl_mat4 mat[FZ_MAX_MESHES];
    const zl_mat4 *mvp[FZ_MAX_MESHES];
    zl_state state[FZ_MAX_MESHES];
    int added[FZ_MAX_MESHES];
    unsigned count;
} fz_scene;

static fz_scene scene;

/* Render the scene into a frame of config cfg; the whole image lands in
 * color/depth (width * height pixels, tightly packed). Returns the status
 * of the first failing call, ZL_OK when every band came out. */
static zl_status render_frame(const zl_frame_config *cfg, size_t work_bytes, size_t misalign, zl_rgb cc,
                              uint16_t cd, uint8_t *color, uint16_t *depth, int check_adds,
                              zl_frame_needs_t *needs)
{
    fz_buf work;
    uint8_t *snap, *prev = NULL, *prev_copy = NULL;
    size_t bytes = zl_frame_bytes(cfg), prev_size = 0;
    unsigned bpp = zl_format_bytes((zl_format)cfg->format);
    zl_frame f;
    zl_band band;
    zl_status st;
    unsigned i, next_row = 0;

    fz_buf_alloc(&work, work_bytes + misalign);
    snap = (uint8_t *)malloc(work.size ? work.size : 1);
    if (snap == NULL)
        abort();
    memcpy(snap, work.data, work.size);
    st = zl_frame_begin(&f, cfg, work.data + misalign, work_bytes, cc, cd);
    fz_buf_check(&work, "work after zl_frame_begin");
    if (bytes == 0 || misalign != 0 || work_bytes < bytes) {
        FZ_REQUIRE(st != ZL_OK, "zl_frame_begin accepted bytes %zu work %zu misalign %zu", bytes, work_bytes,
                   misalign);
    } else {
        FZ_REQUIRE(st == ZL_OK, "zl_frame_begin refused a valid work buffer: %d", st);
    }
    if (st != ZL_OK) {
        FZ_REQUIRE(memcmp(snap, work.data, work.size) == 0, "failing zl_frame_begin wrote to the work buffer");
        goto out;
    }
    for (i = 0; i < scene.count; i++) {
        zl_status a = zl_frame_add_mesh(&f, &scene.m[i].mesh, scene.mvp[i], &scene.state[i]);
        fz_buf_check(&work, "work after zl_frame_add_mesh");
        if (check_adds)
            scene.added[i] = a == ZL_OK;
        else
            FZ_REQUIRE((a == ZL_OK) == scene.added[i], "zl_frame_add_mesh changed its mind: %d", a);
    }
    for (;;) {
        st = zl_frame_next_band(&f, &band);
        fz_buf_check(&work, "work after zl_frame_next_band");
        if (prev != NULL) /* the previous band of a double-buffered frame */
            FZ_REQUIRE(memcmp(prev, prev_copy, prev_size) == 0, "the previous band changed");
        if (st == ZL_DONE) {
            FZ_REQUIRE(next_row == cfg->height, "ZL_DONE after %u of %u rows", next_row, cfg->height);
            st = ZL_OK;
            break;
        }
        if (st != ZL_OK) {
            FZ_REQUIRE(st == ZL_ERR_CAPACITY && next_row == 0, "zl_frame_next_band: %d at row %u", st, next_row);
            break;
        }
        FZ_REQUIRE(band.first_row == next_row && band.rows >= 1 && band.rows <= cfg->band_rows &&
                       band.first_row + band.rows <= cfg->height && band.width == cfg->width &&
                       band.format == cfg->format,
                   "bad band %u+%u", band.first_row, band.rows);
        FZ_REQUIRE((const uint8_t *)band.color >= work.data &&
                       (const uint8_t *)band.color + (size_t)band.color_stride * band.rows <= work.data + work.size &&
                       (const uint8_t *)band.depth >= work.data &&
                       (const uint8_t *)band.depth + (size_t)band.depth_stride * band.rows <= work.data + work.size,
                   "band outside the work buffer");
        for (i = 0; i < band.rows; i++) {
            memcpy(color + (size_t)(band.first_row + i) * cfg->width * bpp,
                   (const uint8_t *)band.color + (size_t)i * (size_t)band.color_stride, (size_t)cfg->width * bpp);
            memcpy(depth + (size_t)(band.first_row + i) * cfg->width,
                   (const uint8_t *)band.depth + (size_t)i * (size_t)band.depth_stride, (size_t)cfg->width * 2);
        }
        next_row += band.rows;
        free(prev_copy);
        prev = NULL;
        prev_copy = NULL;
        if (cfg->color_buffers == 2) {
            prev_size = (size_t)band.color_stride * band.rows;
            prev = (uint8_t *)(uintptr_t)band.color;
            prev_copy = (uint8_t *)malloc(prev_size);
            if (prev_copy == NULL)
                abort();
            memcpy(prev_copy, prev, prev_size);
        }
    }
    *needs = zl_frame_needs(&f);
out:
    free(prev_copy);
    free(snap);
    fz_buf_free(&work);
    return st;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    zl_frame_config cfg;
    uint32_t flags = fz_u8(&in), sum_v = 0, sum_t = 0;
    size_t bytes, work_bytes, misalign = 0, px;
    unsigned i, bpp;
    zl_rgb cc;
    uint16_t cd;
    uint8_t *color = NULL, *ref_color = NULL;
    uint16_t *depth = NULL, *ref_depth = NULL;
    zl_frame_needs_t needs;
    zl_status st;

    memset(&cfg, 0, sizeof cfg);
    cfg.width = (uint16_t)(1 + fz_u8(&in) % 64);
    cfg.height = (uint16_t)(1 + fz_u8(&in) % 64);
    cfg.band_rows = (uint16_t)(1 + fz_u8(&in) % cfg.height);
    cfg.format = fz_enum(&in, 3);
    cfg.color_buffers = (uint8_t)(1 + (fz_u8(&in) & 1u));
    cfg.gouraud = (uint8_t)(fz_u8(&in) & 1u);
    cc.r = (uint8_t)fz_u8(&in);
    cc.g = (uint8_t)fz_u8(&in);
    cc.b = (uint8_t)fz_u8(&in);
    cd = (uint16_t)fz_u16(&in);

    scene.count = 1 + fz_u8(&in) % FZ_MAX_MESHES;
    for (i = 0; i < scene.count; i++) {
        int ok;
        fz_read_mesh(&in, &scene.m[i], cfg.width, cfg.height);
        fz_read_state(&in, &scene.state[i], &ok);
        scene.mvp[i] = fz_read_matrix(&in, &scene.mat[i]);
        sum_v += scene.m[i].mesh.vertex_count;
        sum_t += scene.m[i].mesh.triangle_count;
    }
    /* capacities: the documented sufficient values, or fuzzed ones */
    cfg.max_meshes = (uint16_t)((flags & 1u) ? fz_u8(&in) % 5 : scene.count);
    cfg.max_vertices = (flags & 2u) ? fz_u8(&in) % 100 : sum_v;
    cfg.max_triangles = (flags & 4u) ? fz_u8(&in) % 100 : sum_t;
    cfg.max_active = (flags & 8u) ? fz_u8(&in) % 100 : (sum_t ? sum_t : 1);
    if (flags & 16u) { /* a config field out of range */
        switch (fz_u8(&in) % 6) {
        case 0: cfg.width = (uint16_t)(fz_u8(&in) & 1u ? 0 : ZL_MAX_DIM + 1); break;
        case 1: cfg.band_rows = (uint16_t)(fz_u8(&in) & 1u ? 0 : cfg.height + 1); break;
        case 2: cfg.color_buffers = (uint8_t)(fz_u8(&in) & 1u ? 0 : 3); break;
        case 3: cfg.max_triangles = 65536; break;
        case 4: cfg.max_active = 0; break;
        default: cfg.max_meshes = 256; break;
        }
    }
    bytes = zl_frame_bytes(&cfg);
    work_bytes = bytes;
    if (flags & 32u) /* too small, or larger */
        work_bytes = (fz_u8(&in) & 1u) ? (bytes > 0 ? bytes - 1 - fz_u8(&in) % (bytes < 64 ? bytes : 64) : 0)
                                       : bytes + fz_u8(&in);
    if (flags & 64u)
        misalign = 1 + fz_u8(&in) % 7;
    if (bytes == 0 && work_bytes == 0)
        work_bytes = fz_u8(&in); /* invalid config: any buffer is refused */

    bpp = zl_format_bytes((zl_format)cfg.format);
    px = (size_t)cfg.width * cfg.height;
    if (bpp != 0 && px != 0 && cfg.width <= ZL_MAX_DIM) {
        color = (uint8_t *)calloc(px, bpp);
        depth = (uint16_t *)calloc(px, 2);
        if (color == NULL || depth == NULL)
            abort();
    }
    if (color == NULL) { /* an invalid format or size: begin must refuse */
        uint16_t d1;
        uint8_t c1[3];
        FZ_REQUIRE(bytes == 0, "zl_frame_bytes %zu for an invalid config", bytes);
        st = render_frame(&cfg, work_bytes, misalign, cc, cd, c1, &d1, 1, &needs);
        FZ_REQUIRE(st != ZL_OK, "invalid config accepted");
        goto out;
    }
    st = render_frame(&cfg, work_bytes, misalign, cc, cd, color, depth, 1, &needs);
    if (st == ZL_ERR_CAPACITY) {
        /* what zl_frame_needs reports must be enough */
        FZ_REQUIRE(needs.triangles > cfg.max_triangles || needs.active > cfg.max_active,
                   "ZL_ERR_CAPACITY but needs %u/%u fit %u/%u", needs.triangles, needs.active, cfg.max_triangles,
                   cfg.max_active);
        if (needs.triangles > 65535 || needs.active > 65534)
            goto out;
        cfg.max_triangles = needs.triangles;
        cfg.max_active = needs.active ? needs.active : 1;
        bytes = zl_frame_bytes(&cfg);
        FZ_REQUIRE(bytes != 0, "the needed capacities give an invalid config");
        st = render_frame(&cfg, bytes, 0, cc, cd, color, depth, 0, &needs);
        FZ_REQUIRE(st == ZL_OK, "the capacities zl_frame_needs reported were not enough: %d", st);
    }
    if (st != ZL_OK)
        goto out;

    /* The same scene in frame mode. */
    {
        zl_target t;
        zl_context ctx;
        ref_color = (uint8_t *)calloc(px, bpp);
        ref_depth = (uint16_t *)calloc(px, 2);
        if (ref_color == NULL || ref_depth == NULL)
            abort();
        t.color = ref_color;
        t.color_stride = (int32_t)(cfg.width * bpp);
        t.depth = ref_depth;
        t.depth_stride = (int32_t)cfg.width * 2;
        t.width = cfg.width;
        t.height = cfg.height;
        t.format = cfg.format;
        FZ_REQUIRE(zl_init(&ctx, &t) == ZL_OK, "zl_init of the reference");
        FZ_REQUIRE(zl_clear(&ctx, cc, cd) == ZL_OK, "zl_clear of the reference");
        for (i = 0; i < scene.count; i++) {
            if (!scene.added[i])
                continue;
            ctx.state = scene.state[i];
            st = zl_draw_mesh(&ctx, &scene.m[i].mesh, scene.mvp[i]);
            FZ_REQUIRE(st == ZL_OK, "zl_draw_mesh refused a mesh zl_frame_add_mesh took: %d", st);
        }
        for (i = 0; i < px; i++) {
            FZ_REQUIRE(memcmp(color + i * bpp, ref_color + i * bpp, bpp) == 0,
                       "colour differs from frame mode at pixel (%zu, %zu)", (size_t)i % cfg.width,
                       (size_t)i / cfg.width);
            FZ_REQUIRE(depth[i] == ref_depth[i], "depth differs from frame mode at pixel (%zu, %zu): %u vs %u",
                       (size_t)i % cfg.width, (size_t)i / cfg.width, depth[i], ref_depth[i]);
        }
    }
out:
    free(color);
    free(depth);
    free(ref_color);
    free(ref_depth);
    return 0;
}

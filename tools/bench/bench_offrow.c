/* SPDX-License-Identifier: MIT */
/*
 * zline-bench-offrow: the per-row cost of scanline mode does not grow with
 * triangles that are not on the row.
 *
 *   zline-bench-offrow base|crowded
 *
 * base: 1000 small triangles in rows 0..119 of a 320x240 frame.
 * crowded: the same 1000 plus 10000 more in rows 130..239.
 * The frame is rendered in scanline mode; the measured function
 * render_top_rows produces rows 1..119 (row 0 is produced first, outside it,
 * because the first call also plans the whole frame, which is linear in all
 * triangles by design). Count it with
 *   valgrind --tool=callgrind --toggle-collect=render_top_rows zline-bench-offrow base
 * tools/bench/measure.sh runs both and prints the ratio.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zline/zline.h"

/* Measured functions must stay real calls for callgrind --toggle-collect. */
#ifdef __GNUC__
#define BENCH_NOINLINE __attribute__((noinline))
#else
#define BENCH_NOINLINE
#endif

enum { W = 320, H = 240, BASE = 1000, EXTRA = 10000, TOTAL = BASE + EXTRA };

static zl_fixed positions[TOTAL * 9];
static uint16_t indices[TOTAL * 3];

static uint32_t rng = 2463534242u;
static int32_t rand_below(int32_t n)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return (int32_t)(rng % (uint32_t)n);
}

/* A small triangle with its top-left corner in [x0, x0+w) x [y0, y0+h). */
static void small_triangle(int i, int y0, int h)
{
    zl_fixed x = ZL_FX_INT(rand_below(W - 8)), y = ZL_FX_INT(y0 + rand_below(h));
    zl_fixed z = rand_below(ZL_FX_ONE);
    zl_fixed tri[9] = {x, y, z, x + ZL_FX_INT(6), y + ZL_FX_INT(2), z, x + ZL_FX_INT(2), y + ZL_FX_INT(7), z};
    memcpy(&positions[i * 9], tri, sizeof tri);
    indices[i * 3] = (uint16_t)(i * 3);
    indices[i * 3 + 1] = (uint16_t)(i * 3 + 1);
    indices[i * 3 + 2] = (uint16_t)(i * 3 + 2);
}

static long rows_out;
static int count_rows(void *user, const zl_band *b)
{
    (void)user;
    rows_out += b->rows;
    return 0;
}

void render_top_rows(zl_frame *f);
BENCH_NOINLINE void render_top_rows(zl_frame *f)
{
    zl_band b;
    int y;
    for (y = 1; y < 120; y++)
        if (zl_frame_next_band(f, &b) != ZL_OK || count_rows(NULL, &b) != 0)
            exit(3);
}

int main(int argc, char **argv)
{
    int crowded, i, count;
    zl_mesh mesh;
    zl_state st;
    zl_frame_config cfg;
    zl_frame f;
    zl_band b;
    void *work;
    size_t bytes;
    if (argc != 2 || (strcmp(argv[1], "base") != 0 && strcmp(argv[1], "crowded") != 0)) {
        fprintf(stderr, "usage: %s base|crowded\n", argv[0]);
        return 2;
    }
    crowded = strcmp(argv[1], "crowded") == 0;
    count = crowded ? TOTAL : BASE;
    for (i = 0; i < BASE; i++)
        small_triangle(i, 0, 112);
    for (i = BASE; i < count; i++)
        small_triangle(i, 130, 100);
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.vertex_count = (uint16_t)(count * 3);
    mesh.triangle_count = (uint16_t)count;
    zl_state_default(&st);
    memset(&cfg, 0, sizeof cfg);
    cfg.width = W;
    cfg.height = H;
    cfg.band_rows = 1;
    cfg.format = ZL_FORMAT_RGB565;
    cfg.color_buffers = 1;
    cfg.max_meshes = 1;
    cfg.max_vertices = mesh.vertex_count;
    cfg.max_triangles = mesh.triangle_count;
    cfg.max_active = mesh.triangle_count;
    bytes = zl_frame_bytes(&cfg);
    work = malloc(bytes) /* malloc aligns for any type */;
    if (work == NULL || zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){0, 0, 0}, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &mesh, NULL, &st) != ZL_OK)
        return 2;
    if (zl_frame_next_band(&f, &b) != ZL_OK) /* row 0, and planning */
        return 3;
    render_top_rows(&f);
    while (zl_frame_next_band(&f, &b) == ZL_OK)
        rows_out++;
    printf("%s: %d triangles, %ld rows after row 0\n", argv[1], count, rows_out);
    free(work);
    return rows_out == H - 1 ? 0 : 1;
}

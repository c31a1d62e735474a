/* SPDX-License-Identifier: MIT */
/*
 * Two cores, one frame on QEMU mps2-an521 (SSE-200: two Cortex-M33; issue
 * 27). Core 0 starts as every port/cortex-m program does; core 1 is held by
 * the SSE-200 system control element's CPUWAIT register until core 0 points
 * INITSVTOR1 at core1_vectors and clears CPUWAIT bit 1. Then, for the
 * benchmark bunny and the triangle-rate scene (scenes.c), core 0 submits
 * the frame (cfg.parts = 2) and splits it (zl_frame_split), publishes it
 * through a flag; each core transforms its half of the vertices
 * (zl_frame_prepare), both meet at the barrier, then core 0 renders the
 * rows above the split while core 1 renders the rows below into the same
 * whole-frame image (disjoint rows), and core 0 waits for core 1's "done"
 * flag. The image (colour then depth, golden.c's layout) is written
 * through semihosting as an521-SCENE-scanline.bin; CTest dual_an521
 * (compare-dual.cmake) requires it to equal the host's single-core
 * scanline rendering (zline-golden-host's host-SCENE-scanline.bin) byte for
 * byte.
 *
 * QEMU's AN521 cores have no FPU: built soft-float (ZLINE_FLOAT_ABI=soft).
 *
 * Per-core counts: mark() (tools/qemu-vcpu-count, measure-an521.sh) on
 * core 0 before and after a single-core frame (m0, m1), before and after
 * the submission and split (m2, m3), after its prepare (m4), after the
 * barrier (m5) and after its bands (m6); on core 1 after `go` (n0), after
 * its prepare (n1), after the barrier (n2) and after its bands (n3).
 *
 * The flag protocol is zline.h's (two cores, one frame): a DMB before each
 * flag store, a DMB after each flag is seen. `go` and `done` count frames,
 * so no flag is ever reset.
 */
#include <stdio.h>
#include <string.h>

#include "scenes.h"

#define W SCENE_W
#define H SCENE_H

/* SSE-200 system control element, Secure (QEMU hw/misc/iotkit-sysctl.c,
 * Arm's SSE-200 TRM): INITSVTOR1 is core 1's initial Secure VTOR, CPUWAIT
 * bit n holds core n at reset. */
#define SSE200_SYSCTL 0x50021000u
#define INITSVTOR1 (*(volatile uint32_t *)(SSE200_SYSCTL + 0x114u))
#define CPUWAIT (*(volatile uint32_t *)(SSE200_SYSCTL + 0x118u))

#define dmb() __asm__ volatile("dmb" ::: "memory")

/* The hook of the per-core instruction count (tools/qemu-vcpu-count: each
 * vCPU's count at every entry of mark(); measure-an521.sh reads them). */
void mark(void) __attribute__((noinline, used));
void mark(void)
{
    __asm__ volatile("" ::: "memory");
}

static uint16_t image[2 * W * H];
static uint64_t work[160 * 1024 / 8];
static uint64_t work1[96 * 1024 / 8]; /* core 1's part (zl_frame_part_bytes) */

/* What core 0 hands core 1 for a frame, and the flags (frame numbers). */
static zl_frame second;
static volatile uint32_t go, prepared[2], done;
static volatile int32_t core1_result;

/* zline.h's barrier after zl_frame_prepare: this core's flag, then the
 * other's awaited; DMB on both sides. */
static void barrier(unsigned core, uint32_t frame_no)
{
    dmb();
    prepared[core] = frame_no;
    while (prepared[core ^ 1u] != frame_no)
        ;
    dmb();
}

/* ---------------------------------------------------------------- core 1 */

static int copy_band(void *user, const zl_band *b)
{
    uint16_t r;
    (void)user;
    for (r = 0; r < b->rows; r++) {
        memcpy(image + (size_t)(b->first_row + r) * W, (const uint8_t *)b->color + (size_t)r * (size_t)b->color_stride,
               W * 2);
        memcpy(image + W * H + (size_t)(b->first_row + r) * W,
               (const uint8_t *)b->depth + (size_t)r * (size_t)b->depth_stride, W * 2);
    }
    return 0;
}

static void core1_main(void) __attribute__((noreturn));
static void core1_main(void)
{
    uint32_t seen = 0;
    for (;;) {
        int r;
        while (go == seen)
            ;
        seen = go;
        dmb(); /* the frame core 0 published before `go` */
        mark(); /* core 1: n0 */
        r = zl_frame_prepare(&second);
        mark(); /* n1 */
        barrier(1, seen);
        mark(); /* n2 */
        if (r == 0)
            r = zl_frame_render(&second, copy_band, NULL);
        mark(); /* n3 */
        core1_result = r;
        dmb(); /* its rows and result before `done` */
        done = seen;
    }
}

static uint32_t core1_stack[1024] __attribute__((aligned(8)));

/* Core 1's vector table: initial MSP and reset; a fault on core 1 reads
 * entry 3 and spins there (core 0 then times out and fails). */
static void core1_fault(void)
{
    for (;;)
        ;
}

typedef struct {
    void *sp;
    void (*handlers[15])(void);
} vector_table;

static const vector_table core1_vectors __attribute__((aligned(128))) = {
    core1_stack + sizeof core1_stack / sizeof core1_stack[0],
    {core1_main, core1_fault, core1_fault, core1_fault, core1_fault, core1_fault, core1_fault, core1_fault,
     core1_fault, core1_fault, core1_fault, core1_fault, core1_fault, core1_fault, core1_fault}};

/* ---------------------------------------------------------------- core 0 */

/* The scene's exact capacities: one planning with generous ones (as
 * golden.c's config_for). */
static int config_for(const scene *s, zl_frame_config *cfg)
{
    zl_frame f;
    zl_band b;
    zl_rgb bg = {0, 0, 0};
    zl_frame_needs_t needs;
    zl_status st;
    memset(cfg, 0, sizeof *cfg);
    cfg->width = W;
    cfg->height = H;
    cfg->band_rows = 1;
    cfg->format = ZL_FORMAT_RGB565;
    cfg->color_buffers = 1;
    cfg->gouraud = s->gouraud;
    cfg->max_meshes = 1;
    cfg->max_vertices = s->mesh.vertex_count;
    cfg->max_triangles = s->mesh.triangle_count;
    cfg->max_active = 512;
    if (zl_frame_bytes(cfg) > sizeof work || zl_frame_begin(&f, cfg, work, sizeof work, bg, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &s->mesh, &s->mvp, &s->state) != ZL_OK)
        return 1;
    st = zl_frame_next_band(&f, &b);
    if (st != ZL_OK && st != ZL_DONE)
        return 1;
    needs = zl_frame_needs(&f);
    cfg->max_triangles = needs.triangles > 0 ? needs.triangles : 1;
    cfg->max_active = needs.active > 0 ? needs.active : 1;
    cfg->parts = 2; /* the vertex transform shared by both cores */
    return zl_frame_part_bytes(cfg) > sizeof work1;
}

static int save(const char *scene_name)
{
    char path[96];
    FILE *f;
    int ok;
    snprintf(path, sizeof path, "an521-%s-scanline.bin", scene_name);
    f = fopen(path, "wb");
    if (f == NULL) {
        printf("dual: cannot write %s\n", path);
        return 1;
    }
    ok = fwrite(image, 1, sizeof image, f) == sizeof image;
    ok = (fclose(f) == 0) && ok;
    printf("dual: %s written\n", path);
    return !ok;
}

/* The same frame on core 0 alone (cfg.parts = 0): the reference count of
 * the per-core table, between marks m0 and m1. */
static int render_single(const scene *s, zl_frame_config cfg)
{
    zl_frame f;
    zl_rgb bg = {20, 24, 32};
    int r;
    cfg.parts = 0;
    mark(); /* core 0: m0 */
    if (zl_frame_begin(&f, &cfg, work, zl_frame_bytes(&cfg), bg, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &s->mesh, &s->mvp, &s->state) != ZL_OK)
        return 1;
    r = zl_frame_render(&f, copy_band, NULL);
    mark(); /* m1 */
    return r != 0;
}

static int render_split(const scene *s, uint32_t frame_no)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_rgb bg = {20, 24, 32};
    uint32_t spins = 0;
    int r;
    if (config_for(s, &cfg) != 0) {
        printf("dual: %s: cannot plan the frame\n", s->name);
        return 1;
    }
    if (render_single(s, cfg) != 0)
        return 1;
    memset(image, 0, sizeof image);
    mark(); /* m2 */
    if (zl_frame_begin(&f, &cfg, work, zl_frame_bytes(&cfg), bg, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &s->mesh, &s->mvp, &s->state) != ZL_OK ||
        zl_frame_split(&f, &second, work1, sizeof work1, 0) != ZL_OK)
        return 1;
    mark(); /* m3 */
    dmb(); /* the frame and `second` before `go` */
    go = frame_no;
    r = zl_frame_prepare(&f);
    mark(); /* m4 */
    barrier(0, frame_no);
    mark(); /* m5 */
    if (r == 0)
        r = zl_frame_render(&f, copy_band, NULL);
    mark(); /* m6 */
    while (done != frame_no)
        if (++spins == 0x40000000u) {
            printf("dual: %s: core 1 did not finish\n", s->name);
            return 1;
        }
    dmb(); /* core 1's rows after `done` */
    printf("dual: %s split at row %u\n", s->name, (unsigned)f.end_row);
    if (r != 0 || core1_result != 0) {
        printf("dual: %s: rendering failed (%d, %d)\n", s->name, r, (int)core1_result);
        return 1;
    }
    return 0;
}

int main(void)
{
    static const int which[] = {SCENE_BUNNY, SCENE_TRIS};
    unsigned k;
    int failed = 0;
    INITSVTOR1 = (uint32_t)(uintptr_t)&core1_vectors;
    dmb();
    CPUWAIT = CPUWAIT & ~2u; /* release core 1 */
    for (k = 0; k < sizeof which / sizeof which[0]; k++) {
        scene s;
        if (scene_make(&s, which[k]) != 0) {
            printf("dual: scene %d: cannot build the camera\n", which[k]);
            failed++;
            continue;
        }
        memset(image, 0, sizeof image);
        if (render_split(&s, k + 1u) || save(s.name))
            failed++;
    }
    printf("dual: %d failure(s)\n", failed);
    return failed;
}

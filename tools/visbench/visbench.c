/* SPDX-License-Identifier: MIT */
/*
 * zline-visbench: the visibility methods side by side on the same scenes.
 *
 *   zline-visbench MODEL_DIR                   the table (markdown): RAM,
 *                                              flash of the BSP tree, and
 *                                              agreement with the ray caster
 *   zline-visbench MODEL_DIR --only SCENE METHOD
 *                                              render once, for an instruction
 *                                              count of vb_measured() with
 *                                              valgrind --tool=callgrind
 *                                              --toggle-collect=vb_measured
 *
 * Scenes (320x240, RGB565, camera at (0, 0, 3.5) looking at the origin, 60
 * degree field of view, near 0.1, far 100, lit flat colours):
 *   bunny      the benchmark scene (bunny.obj normalised, back faces culled)
 *   spider     spider.obj, the same way
 *   intersect  64 random triangles in the unit cube, all crossing each other
 *              (no culling)
 *   layers     32 overlapping squares parallel to the screen, submitted in
 *              random depth order: depth complexity up to 32 (no culling)
 * Methods: zbuffer (zl_draw_mesh into a full frame), scanline (zl_frame,
 * band of 1 row), band16 (zl_frame, 16 rows), aet, painter, bsp-b2f, bsp-f2b
 * (tree built here by tools/bsp's builder; it would be const data in flash),
 * raycast (the reference).
 *
 * Correctness: every method also renders the scene's id image (which input
 * triangle shows at each pixel: the vis methods report ids; the z-buffer
 * modes draw id-encoded face colours without lighting into RGB888) and it is
 * compared with the ray caster's: "differ" pixels, and of those the "near
 * ties", where the ray caster's two nearest surfaces are within one depth
 * step.
 *
 * RAM counts every byte the method needs besides the scene's own const data:
 * the work buffer from the library's size function with capacities set to
 * what the scene needs, plus the caller-owned frame buffers (colour 2 bytes
 * and depth 2 bytes a pixel where used), plus the BSP coverage mask. The BSP
 * walk's stack (ZL_BSP_MAX_DEPTH uint16, 512 bytes) is on the C stack and not
 * counted, like every method's other locals.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bsp_build.h"
#include "zl_obj.h"
#include "zline/zl_visibility.h"
#include "zline/zline.h"

#ifdef __GNUC__
#define VB_NOINLINE __attribute__((noinline))
#else
#define VB_NOINLINE
#endif

#define W 320
#define H 240
#define TIE 257

typedef struct {
    const char *name;
    zl_obj obj;
    zl_fixed *pos;
    uint16_t *idx;
    uint8_t *fcol, *idcol;
    zl_mesh mesh, idmesh;
    zl_mat4 mvp;
    zl_state state, idstate;
    zl_vec3 eye;
    bsp_tree tree;
    uint8_t *tree_fcol, *tree_idcol;
} scene;

/* zl_draw_mesh's draw cache (zl_context.draw_cache) at the library's size:
 * the default call's cached path, as zl_context held it before issue 23. */
static uint64_t draw_cache_buf[ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) / 8 + 1];

static const char *methods[] = {"zbuffer", "scanline", "band16", "aet", "painter", "bsp-b2f", "bsp-f2b", "raycast"};
#define NMETHODS 8

static uint16_t color[W * H], depth[W * H];
static uint8_t color888[W * H * 3];
static uint16_t ids[W * H], rc_ids[W * H], rc_gap[W * H];

static uint32_t rng = 2463534242u;
static double frand(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return (rng & 0xFFFFFF) / 16777216.0;
}

static zl_fixed fx(double v)
{
    return (zl_fixed)floor(v * 65536.0 + 0.5);
}

static void camera(scene *s)
{
    zl_mat4 proj, view;
    zl_vec3 target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    s->eye.x = 0;
    s->eye.y = 0;
    s->eye.z = ZL_FX_ONE * 7 / 2;
    if (zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(W) / H, ZL_FX_ONE / 10,
                            ZL_FX_INT(100)) != ZL_OK ||
        zl_mat4_look_at(&view, s->eye, target, up) != ZL_OK)
        exit(2);
    zl_mat4_mul(&s->mvp, &proj, &view);
    zl_state_default(&s->state);
    s->state.light_on = 1;
    s->state.ambient = 40;
    s->state.color.r = 230;
    s->state.color.g = 200;
    s->state.color.b = 160;
    s->state.light_dir.x = 24576;
    s->state.light_dir.y = 32768;
    s->state.light_dir.z = 49152;
}

static int load_scene(scene *s, const char *dir, const char *name)
{
    uint32_t t, nt;
    memset(s, 0, sizeof *s);
    s->name = name;
    camera(s);
    if (strcmp(name, "bunny") == 0 || strcmp(name, "spider") == 0) {
        char path[1024], msg[512];
        zl_obj_options o;
        zl_obj_options_default(&o);
        o.normalize = 1;
        snprintf(path, sizeof path, "%s/%s.obj", dir, name);
        if (zl_obj_load_file(&s->obj, path, &o, msg, sizeof msg) != ZL_OBJ_OK) {
            fprintf(stderr, "%s\n", msg);
            return 1;
        }
        s->mesh = zl_obj_mesh(&s->obj);
        s->state.cull = ZL_CULL_BACK;
    } else if (strcmp(name, "intersect") == 0) {
        nt = 64;
        s->pos = malloc(nt * 9 * sizeof(zl_fixed));
        s->idx = malloc(nt * 3 * sizeof(uint16_t));
        for (t = 0; t < nt * 9; t++)
            s->pos[t] = fx(frand() * 2 - 1);
        for (t = 0; t < nt * 3; t++)
            s->idx[t] = (uint16_t)t;
        s->mesh.positions = s->pos;
        s->mesh.indices = s->idx;
        s->mesh.vertex_count = (uint16_t)(nt * 3);
        s->mesh.triangle_count = (uint16_t)nt;
    } else if (strcmp(name, "layers") == 0) {
        uint32_t order[32], i;
        nt = 64;
        s->pos = malloc(32 * 4 * 3 * sizeof(zl_fixed));
        s->idx = malloc(nt * 3 * sizeof(uint16_t));
        for (i = 0; i < 32; i++)
            order[i] = i;
        for (i = 31; i > 0; i--) { /* random submission order */
            uint32_t j = (uint32_t)(frand() * (i + 1)), k = order[i];
            order[i] = order[j];
            order[j] = k;
        }
        for (i = 0; i < 32; i++) {
            double z = -1 + 2.0 * order[i] / 31, cx = frand() * 0.6 - 0.3, cy = frand() * 0.6 - 0.3, r = 1.0;
            double c[4][2] = {{cx - r, cy - r}, {cx + r, cy - r}, {cx + r, cy + r}, {cx - r, cy + r}};
            int k;
            for (k = 0; k < 4; k++) {
                s->pos[(i * 4 + (uint32_t)k) * 3] = fx(c[k][0]);
                s->pos[(i * 4 + (uint32_t)k) * 3 + 1] = fx(c[k][1]);
                s->pos[(i * 4 + (uint32_t)k) * 3 + 2] = fx(z);
            }
            s->idx[i * 6] = (uint16_t)(i * 4);
            s->idx[i * 6 + 1] = (uint16_t)(i * 4 + 1);
            s->idx[i * 6 + 2] = (uint16_t)(i * 4 + 2);
            s->idx[i * 6 + 3] = (uint16_t)(i * 4);
            s->idx[i * 6 + 4] = (uint16_t)(i * 4 + 2);
            s->idx[i * 6 + 5] = (uint16_t)(i * 4 + 3);
        }
        s->mesh.positions = s->pos;
        s->mesh.indices = s->idx;
        s->mesh.vertex_count = 128;
        s->mesh.triangle_count = (uint16_t)nt;
    } else {
        fprintf(stderr, "unknown scene %s\n", name);
        return 1;
    }
    nt = s->mesh.triangle_count;
    /* per-triangle colours for the measured renders, id colours for the check */
    s->fcol = malloc(nt * 3);
    s->idcol = malloc(nt * 3);
    for (t = 0; t < nt; t++) {
        s->fcol[t * 3] = (uint8_t)(120 + (t * 37) % 136);
        s->fcol[t * 3 + 1] = (uint8_t)(120 + (t * 91) % 136);
        s->fcol[t * 3 + 2] = (uint8_t)(120 + (t * 53) % 136);
        s->idcol[t * 3] = (uint8_t)(t >> 8);
        s->idcol[t * 3 + 1] = (uint8_t)(t & 0xFF);
        s->idcol[t * 3 + 2] = 0x80;
    }
    if (s->obj.positions == NULL)
        s->mesh.face_colors = s->fcol; /* the models keep the state's colour, lit */
    s->idmesh = s->mesh;
    s->idmesh.face_colors = s->idcol;
    s->idstate = s->state;
    s->idstate.light_on = 0;
    if (bsp_build(&s->tree, s->mesh.positions, s->mesh.vertex_count, s->mesh.indices, nt, NULL) != 0)
        return 1;
    s->tree_fcol = malloc(s->tree.triangle_count * 3 + 3);
    s->tree_idcol = malloc(s->tree.triangle_count * 3 + 3);
    for (t = 0; t < s->tree.triangle_count; t++) {
        memcpy(&s->tree_fcol[t * 3], &s->fcol[s->tree.source[t] * 3], 3);
        memcpy(&s->tree_idcol[t * 3], &s->idcol[s->tree.source[t] * 3], 3);
    }
    return 0;
}

static void free_scene(scene *s)
{
    zl_obj_free(&s->obj);
    free(s->pos);
    free(s->idx);
    free(s->fcol);
    free(s->idcol);
    free(s->tree_fcol);
    free(s->tree_idcol);
    bsp_free(&s->tree);
}

static size_t tree_flash(const bsp_tree *t)
{
    return (size_t)t->vertex_count * 12 + (size_t)t->triangle_count * 8 + (size_t)t->node_count * sizeof(zl_bsp_node);
}

/* ------------------------------------------------------------- methods */

typedef struct {
    int check;          /* 1: id image into ids[] (RGB888, id colours, no lighting) */
    size_t ram;
    zl_frame_needs_t needs;
} run_info;

static int frame_rows_888;

static int band_sink(void *user, const zl_band *b)
{
    uint16_t r;
    (void)user;
    if (!frame_rows_888)
        return 0;
    for (r = 0; r < b->rows; r++)
        memcpy(color888 + ((size_t)b->first_row + r) * W * 3,
               (const uint8_t *)b->color + (size_t)r * (size_t)b->color_stride, W * 3);
    return 0;
}

static int row_sink(void *user, const zl_vis_row *row)
{
    int check = *(int *)user;
    if (check) {
        memcpy(ids + (size_t)row->y * W, row->ids, W * 2);
        if (row->gap)
            memcpy(rc_gap + (size_t)row->y * W, row->gap, W * 2);
    }
    return 0;
}

static zl_frame_needs_t frame_needs(const scene *s, const zl_mesh *m, const zl_state *st)
{
    zl_frame_config c;
    zl_frame f;
    zl_band b;
    void *work;
    zl_frame_needs_t n;
    memset(&c, 0, sizeof c);
    c.width = W;
    c.height = H;
    c.band_rows = 1;
    c.format = ZL_FORMAT_RGB565;
    c.color_buffers = 1;
    c.max_meshes = 1;
    c.max_vertices = m->vertex_count;
    c.max_triangles = m->triangle_count;
    c.max_active = (uint32_t)m->triangle_count * 7u;
    work = malloc(zl_frame_bytes(&c));
    if (zl_frame_begin(&f, &c, work, zl_frame_bytes(&c), (zl_rgb){0, 0, 0}, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, m, &s->mvp, st) != ZL_OK || zl_frame_next_band(&f, &b) != ZL_OK)
        exit(3);
    n = zl_frame_needs(&f);
    free(work);
    return n;
}

static zl_frame_needs_t vis_needs(const scene *s, int algo, const zl_mesh *m, const zl_state *st)
{
    zl_vis_config c;
    zl_vis v;
    void *work;
    zl_frame_needs_t n;
    int dummy = 0;
    memset(&c, 0, sizeof c);
    c.width = W;
    c.height = H;
    c.algorithm = (uint8_t)algo;
    c.format = ZL_FORMAT_RGB565;
    c.max_meshes = 1;
    c.max_vertices = m->vertex_count;
    c.max_triangles = m->triangle_count;
    c.max_active = (uint32_t)m->triangle_count * 7u;
    work = malloc(zl_vis_bytes(&c));
    if (zl_vis_begin(&v, &c, work, zl_vis_bytes(&c)) != ZL_OK || zl_vis_add_mesh(&v, m, &s->mvp, st) != ZL_OK)
        exit(3);
    if (algo == ZL_VIS_PAINTER) {
        zl_vis_target t;
        memset(&t, 0, sizeof t);
        t.width = W;
        t.height = H;
        t.format = ZL_FORMAT_RGB565;
        zl_painter_draw(&v, &t, (zl_rgb){0, 0, 0});
    } else {
        zl_vis_render_rows(&v, (zl_rgb){0, 0, 0}, row_sink, &dummy);
    }
    n = zl_vis_needs(&v);
    free(work);
    return n;
}

/* The measured region: one frame of method m (allocation is the caller's). */
void vb_measured(int m, const scene *s, const zl_mesh *mesh, const zl_state *st, const zl_bsp *bsp, void *work,
                 size_t work_bytes, int check, run_info *ri);
VB_NOINLINE void vb_measured(int m, const scene *s, const zl_mesh *mesh, const zl_state *st, const zl_bsp *bsp,
                             void *work, size_t work_bytes, int check, run_info *ri)
{
    zl_rgb bg = {20, 24, 32};
    zl_format fmt = check ? ZL_FORMAT_RGB888 : ZL_FORMAT_RGB565;
    if (m == 0) {
        zl_target t;
        zl_context ctx;
        memset(&t, 0, sizeof t);
        t.color = check ? (void *)color888 : (void *)color;
        t.color_stride = W * (check ? 3 : 2);
        t.depth = depth;
        t.depth_stride = W * 2;
        t.width = W;
        t.height = H;
        t.format = (uint8_t)fmt;
        if (zl_init(&ctx, &t) != ZL_OK || zl_clear(&ctx, bg, 65535) != ZL_OK)
            exit(3);
        ctx.state = *st;
        ctx.draw_cache = draw_cache_buf;
        ctx.draw_cache_bytes = sizeof draw_cache_buf;
        if (zl_draw_mesh(&ctx, mesh, &s->mvp) != ZL_OK)
            exit(3);
    } else if (m == 1 || m == 2) {
        zl_frame_config c;
        zl_frame f;
        memset(&c, 0, sizeof c);
        c.width = W;
        c.height = H;
        c.band_rows = m == 1 ? 1 : 16;
        c.format = (uint8_t)fmt;
        c.color_buffers = 1;
        c.max_meshes = 1;
        c.max_vertices = mesh->vertex_count;
        c.max_triangles = ri->needs.triangles;
        c.max_active = ri->needs.active;
        frame_rows_888 = check;
        if (zl_frame_begin(&f, &c, work, work_bytes, bg, 65535) != ZL_OK || zl_frame_add_mesh(&f, mesh, &s->mvp, st) != ZL_OK ||
            zl_frame_render(&f, band_sink, NULL) != 0)
            exit(3);
    } else if (m == 3 || m == 4 || m == 7) {
        zl_vis_config c;
        zl_vis v;
        memset(&c, 0, sizeof c);
        c.width = W;
        c.height = H;
        c.algorithm = (uint8_t)(m == 3 ? ZL_VIS_AET : m == 4 ? ZL_VIS_PAINTER : ZL_VIS_RAYCAST);
        c.format = (uint8_t)fmt;
        c.max_meshes = 1;
        c.max_vertices = mesh->vertex_count;
        c.max_triangles = ri->needs.triangles;
        c.max_active = ri->needs.active ? ri->needs.active : 1;
        if (zl_vis_begin(&v, &c, work, work_bytes) != ZL_OK || zl_vis_add_mesh(&v, mesh, &s->mvp, st) != ZL_OK)
            exit(3);
        if (m == 4) {
            zl_vis_target t;
            memset(&t, 0, sizeof t);
            t.color = check ? (void *)color888 : (void *)color;
            t.color_stride = W * (check ? 3 : 2);
            t.ids = check ? ids : NULL;
            t.ids_stride = W * 2;
            t.width = W;
            t.height = H;
            t.format = (uint8_t)fmt;
            if (zl_painter_draw(&v, &t, bg) != ZL_OK)
                exit(3);
        } else if (zl_vis_render_rows(&v, bg, row_sink, &check) != 0) {
            exit(3);
        }
    } else {
        zl_vis_target t;
        memset(&t, 0, sizeof t);
        t.color = check ? (void *)color888 : (void *)color;
        t.color_stride = W * (check ? 3 : 2);
        t.ids = check ? ids : NULL;
        t.ids_stride = W * 2;
        t.width = W;
        t.height = H;
        t.format = (uint8_t)fmt;
        if (zl_bsp_draw(bsp, &s->mvp, s->eye, st, &t, bg, m == 5 ? ZL_BSP_BACK_TO_FRONT : ZL_BSP_FRONT_TO_BACK, work,
                        work_bytes) != ZL_OK)
            exit(3);
    }
}

/* Run method m on scene s; with check, leave the id image in ids[]. */
static void run(int m, scene *s, int check, run_info *ri)
{
    const zl_mesh *mesh = check ? &s->idmesh : &s->mesh;
    const zl_state *st = check ? &s->idstate : &s->state;
    zl_bsp bsp = bsp_view(&s->tree);
    size_t bytes = 0, frame = (size_t)W * H * 2;
    void *work = NULL;
    bsp.face_colors = check ? s->tree_idcol : s->tree_fcol;
    memset(ri, 0, sizeof *ri);
    ri->check = check;
    if (m == 0) {
        ri->ram = 2 * frame;
    } else if (m == 1 || m == 2) {
        zl_frame_config c;
        ri->needs = frame_needs(s, mesh, st);
        memset(&c, 0, sizeof c);
        c.width = W;
        c.height = H;
        c.band_rows = m == 1 ? 1 : 16;
        c.format = (uint8_t)(check ? ZL_FORMAT_RGB888 : ZL_FORMAT_RGB565);
        c.color_buffers = 1;
        c.max_meshes = 1;
        c.max_vertices = mesh->vertex_count;
        c.max_triangles = ri->needs.triangles;
        c.max_active = ri->needs.active;
        bytes = zl_frame_bytes(&c);
        ri->ram = bytes;
    } else if (m == 3 || m == 4 || m == 7) {
        zl_vis_config c;
        int algo = m == 3 ? ZL_VIS_AET : m == 4 ? ZL_VIS_PAINTER : ZL_VIS_RAYCAST;
        ri->needs = vis_needs(s, algo, mesh, st);
        memset(&c, 0, sizeof c);
        c.width = W;
        c.height = H;
        c.algorithm = (uint8_t)algo;
        c.format = (uint8_t)(check ? ZL_FORMAT_RGB888 : ZL_FORMAT_RGB565);
        c.max_meshes = 1;
        c.max_vertices = mesh->vertex_count;
        c.max_triangles = ri->needs.triangles;
        c.max_active = ri->needs.active ? ri->needs.active : 1;
        bytes = zl_vis_bytes(&c);
        ri->ram = bytes + (m == 4 ? frame : 0);
    } else {
        bytes = m == 6 ? zl_bsp_mask_bytes(W, H) : 0;
        ri->ram = frame + bytes;
    }
    if (bytes)
        work = malloc(bytes);
    vb_measured(m, s, mesh, st, &bsp, work, bytes, check, ri);
    free(work);
    if (check && m <= 2) {
        size_t i;
        for (i = 0; i < (size_t)W * H; i++) {
            const uint8_t *p = &color888[i * 3];
            ids[i] = p[2] == 0x80 ? (uint16_t)(p[0] << 8 | p[1]) : (uint16_t)ZL_VIS_NONE;
        }
    }
}

int main(int argc, char **argv)
{
    static const char *scenes[] = {"bunny", "spider", "intersect", "layers"};
    unsigned si, m;
    if (argc == 5 && strcmp(argv[2], "--only") == 0) {
        scene s;
        run_info ri;
        for (m = 0; m < NMETHODS; m++)
            if (strcmp(argv[4], methods[m]) == 0)
                break;
        if (m == NMETHODS || load_scene(&s, argv[1], argv[3]) != 0) {
            fprintf(stderr, "unknown method or scene\n");
            return 2;
        }
        run((int)m, &s, 0, &ri);
        free_scene(&s);
        return 0;
    }
    if (argc != 2) {
        fprintf(stderr, "usage: %s MODEL_DIR [--only SCENE METHOD]\n", argv[0]);
        return 2;
    }
    static char trees[4][256];
    printf("| scene | method | RAM bytes | covered px | differ from ray caster | of which near ties |\n");
    printf("|---|---|---:|---:|---:|---:|\n");
    for (si = 0; si < sizeof scenes / sizeof scenes[0]; si++) {
        scene s;
        run_info ri;
        long covered = 0;
        size_t i;
        if (load_scene(&s, argv[1], scenes[si]) != 0)
            return 1;
        run(7, &s, 1, &ri); /* the oracle */
        memcpy(rc_ids, ids, sizeof ids);
        for (i = 0; i < (size_t)W * H; i++)
            covered += rc_ids[i] != ZL_VIS_NONE;
        for (m = 0; m < NMETHODS; m++) {
            long differ = 0, ties = 0;
            run((int)m, &s, 1, &ri);
            for (i = 0; i < (size_t)W * H; i++) {
                if (ids[i] == rc_ids[i])
                    continue;
                differ++;
                ties += ids[i] != ZL_VIS_NONE && rc_ids[i] != ZL_VIS_NONE && rc_gap[i] <= TIE;
            }
            run((int)m, &s, 0, &ri); /* RAM of the measured (RGB565) configuration */
            printf("| %s | %s | %zu | %ld | %ld | %ld |\n", s.name, methods[m], ri.ram, covered, differ, ties);
        }
        snprintf(trees[si], sizeof trees[si], "| %s | %u | %u | %u | %u | %u | %zu |", s.name,
                 (unsigned)s.mesh.triangle_count, s.tree.triangle_count, s.tree.splits, s.tree.node_count,
                 s.tree.depth, tree_flash(&s.tree));
        free_scene(&s);
    }
    printf("\nBSP trees (tools/bsp builder, default options), const data in flash:\n\n");
    printf("| scene | input triangles | tree triangles | splits | nodes | depth | flash bytes |\n");
    printf("|---|---:|---:|---:|---:|---:|---:|\n");
    for (si = 0; si < sizeof scenes / sizeof scenes[0]; si++)
        printf("%s\n", trees[si]);
    return 0;
}

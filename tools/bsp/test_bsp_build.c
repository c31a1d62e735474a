/* SPDX-License-Identifier: MIT */
/*
 * The BSP builder and the core's tree walk, on real meshes.
 *
 * Invariants of the tree (independent of drawing): every triangle of a node
 * lies in the node's plane, every triangle of its front subtree is in front
 * of it and every one of its back subtree behind (within the builder's
 * epsilon plus the Q16.16 rounding of new vertices), every input triangle
 * with an area is still represented, and the stated depth is the real one.
 *
 * Images: the tree drawn by zl_bsp_draw, back to front and front to back,
 * against the ray caster on the original mesh (ids of input triangles). A
 * pixel may differ only
 *   - at a near tie (the oracle's two nearest surfaces within a depth step),
 *   - or along the edges of split triangles: its centre within 1/8 pixel of
 *     an edge of an input triangle the builder cut (the new vertex is
 *     rounded to Q16.16 and then snapped to 1/16 pixel, which moves the
 *     outline there by up to about 1/32 pixel; 1/8 leaves room for the
 *     projection of the rounding).
 * Every other pixel must agree. The counts are printed for the record.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bsp_build.h"
#include "unity.h"
#include "zl_obj.h"
#include "zline/zl_visibility.h"

void setUp(void) {}
void tearDown(void) {}

#define W 320
#define H 240
#define TIE 257

static uint16_t rc_ids[W * H], rc_gap[W * H], bsp_ids[W * H];
static uint32_t mask[(W + 31) / 32 * H + H];

static int load(const char *file, zl_obj *obj)
{
    char path[1024], msg[512];
    zl_obj_options o;
    FILE *f;
    snprintf(path, sizeof path, "%s/models/%s", ZLINE_SHARED_DIR, file);
    f = fopen(path, "rb");
    if (f == NULL)
        return 0;
    fclose(f);
    zl_obj_options_default(&o);
    o.normalize = 1;
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, zl_obj_load_file(obj, path, &o, msg, sizeof msg), msg);
    return 1;
}

static double side(const zl_bsp_node *n, const zl_fixed *p)
{
    return ((double)n->n[0] * p[0] + (double)n->n[1] * p[1] + (double)n->n[2] * p[2] - (double)n->d) / 4294967296.0;
}

/* Check subtree `node` against the planes on the path (sign +1 front, -1 back). */
static uint32_t check_subtree(const bsp_tree *t, uint16_t node, const uint16_t *path, const int *sgn, int depth,
                              uint32_t *max_depth)
{
    const double tol = 1.0 / 8192 + 3.0 / 65536; /* epsilon + rounding of new vertices */
    uint16_t p2[ZL_BSP_MAX_DEPTH + 1];
    int s2[ZL_BSP_MAX_DEPTH + 1];
    const zl_bsp_node *n;
    uint32_t k, count;
    int d, v;
    if (node == ZL_BSP_LEAF)
        return 0;
    TEST_ASSERT_TRUE(node < t->node_count);
    TEST_ASSERT_TRUE(depth < ZL_BSP_MAX_DEPTH);
    if ((uint32_t)depth + 1 > *max_depth)
        *max_depth = (uint32_t)depth + 1;
    n = &t->nodes[node];
    count = n->count;
    for (k = n->first; k < (uint32_t)n->first + n->count; k++)
        for (v = 0; v < 3; v++) {
            const zl_fixed *p = &t->positions[t->indices[k * 3 + (uint32_t)v] * 3];
            TEST_ASSERT_TRUE(fabs(side(n, p)) <= tol);
            for (d = 0; d < depth; d++)
                TEST_ASSERT_TRUE(sgn[d] * side(&t->nodes[path[d]], p) >= -tol);
        }
    if (depth > 0) {
        memcpy(p2, path, sizeof(uint16_t) * (size_t)depth);
        memcpy(s2, sgn, sizeof(int) * (size_t)depth);
    }
    p2[depth] = node;
    s2[depth] = 1;
    count += check_subtree(t, n->front, p2, s2, depth + 1, max_depth);
    s2[depth] = -1;
    count += check_subtree(t, n->back, p2, s2, depth + 1, max_depth);
    return count;
}

static void check_invariants(const bsp_tree *t, const zl_obj *obj)
{
    uint32_t max_depth = 0, k;
    uint8_t *seen = calloc(obj->triangle_count, 1);
    TEST_ASSERT_EQUAL_UINT32(t->triangle_count, check_subtree(t, 0, NULL, NULL, 0, &max_depth));
    TEST_ASSERT_EQUAL_UINT32(t->depth, max_depth);
    for (k = 0; k < t->triangle_count; k++)
        seen[t->source[k]] = 1;
    for (k = 0; k < obj->triangle_count; k++) {
        const uint16_t *i = &obj->indices[k * 3];
        const zl_fixed *a = &obj->positions[i[0] * 3], *b = &obj->positions[i[1] * 3], *c = &obj->positions[i[2] * 3];
        double e1[3], e2[3], n[3];
        int m;
        for (m = 0; m < 3; m++) {
            e1[m] = b[m] - a[m];
            e2[m] = c[m] - a[m];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        if (n[0] != 0 || n[1] != 0 || n[2] != 0)
            TEST_ASSERT_TRUE_MESSAGE(seen[k], "an input triangle is missing from the tree");
    }
    free(seen);
}

typedef struct {
    uint16_t *ids, *gap;
} sink;

static int collect(void *user, const zl_vis_row *row)
{
    sink *s = user;
    memcpy(s->ids + (size_t)row->y * W, row->ids, W * 2);
    memcpy(s->gap + (size_t)row->y * W, row->gap, W * 2);
    return 0;
}

static void raycast(const zl_mesh *m, const zl_mat4 *mvp, const zl_state *st)
{
    zl_vis_config c;
    zl_vis v;
    sink s = {rc_ids, rc_gap};
    void *work;
    memset(&c, 0, sizeof c);
    c.width = W;
    c.height = H;
    c.algorithm = ZL_VIS_RAYCAST;
    c.format = ZL_FORMAT_RGB565;
    c.max_meshes = 1;
    c.max_vertices = m->vertex_count;
    c.max_triangles = m->triangle_count;
    c.max_active = (uint32_t)m->triangle_count * 7u;
    work = malloc(zl_vis_bytes(&c));
    TEST_ASSERT_NOT_NULL(work);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_begin(&v, &c, work, zl_vis_bytes(&c)));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_add_mesh(&v, m, mvp, st));
    TEST_ASSERT_EQUAL_INT(0, zl_vis_render_rows(&v, (zl_rgb){0, 0, 0}, collect, &s));
    free(work);
}

static void project(const zl_mat4 *m, const zl_fixed *p, double *wx, double *wy, double *ww)
{
    double c[4];
    int r;
    for (r = 0; r < 4; r++)
        c[r] = ((double)m->m[r * 4] * p[0] + (double)m->m[r * 4 + 1] * p[1] + (double)m->m[r * 4 + 2] * p[2] +
                (double)m->m[r * 4 + 3] * 65536.0) / 4294967296.0;
    *ww = c[3];
    *wx = (c[0] / c[3] + 1) * W / 2;
    *wy = (1 - c[1] / c[3]) * H / 2;
}

/* Window positions of the tree's vertices for one view (w <= 0: behind). */
static double *win_x, *win_y, *win_w;

static void project_tree(const bsp_tree *t, const zl_mat4 *mvp)
{
    uint32_t v;
    win_x = realloc(win_x, t->vertex_count * sizeof(double));
    win_y = realloc(win_y, t->vertex_count * sizeof(double));
    win_w = realloc(win_w, t->vertex_count * sizeof(double));
    for (v = 0; v < t->vertex_count; v++)
        project(mvp, &t->positions[v * 3], &win_x[v], &win_y[v], &win_w[v]);
}

/* Is pixel i's centre within 1/8 pixel of an edge of a piece of a split
 * triangle? Those are the cut lines and the outline segments through new
 * vertices: where T-junctions between pieces in different subtrees leave
 * cracks (or overlaps) after rounding and snapping. */
static int near_split_edge(const bsp_tree *t, int i)
{
    double px = i % W + 0.5, py = i / W + 0.5;
    uint32_t k;
    for (k = 0; k < t->triangle_count; k++) {
        const uint16_t *v = &t->indices[k * 3];
        int e;
        if (!t->split_source[t->source[k]])
            continue;
        if (win_w[v[0]] <= 0 || win_w[v[1]] <= 0 || win_w[v[2]] <= 0)
            return 1; /* crosses the eye plane: no simple outline to measure */
        for (e = 0; e < 3; e++) {
            double ax = win_x[v[e]], ay = win_y[v[e]], dx = win_x[v[(e + 1) % 3]] - ax, dy = win_y[v[(e + 1) % 3]] - ay;
            double len2 = dx * dx + dy * dy, u = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0, qx, qy;
            u = u < 0 ? 0 : (u > 1 ? 1 : u);
            qx = ax + u * dx - px;
            qy = ay + u * dy - py;
            if (qx * qx + qy * qy <= 1.0 / 64)
                return 1;
        }
    }
    return 0;
}

static void check_model(const char *file, int views)
{
    zl_obj obj;
    bsp_tree t;
    zl_mesh mesh;
    zl_bsp bsp;
    zl_state st;
    zl_mat4 proj;
    int view, order;
    long ties = 0, edges = 0, covered = 0;
    char line[256];
    if (!load(file, &obj)) {
        TEST_IGNORE_MESSAGE("test model not found (ZLINE_SHARED_DIR/models)");
        return;
    }
    TEST_ASSERT_EQUAL_INT(0, bsp_build(&t, obj.positions, obj.vertex_count, obj.indices, obj.triangle_count, NULL));
    check_invariants(&t, &obj);
    mesh = zl_obj_mesh(&obj);
    bsp = bsp_view(&t);
    zl_state_default(&st);
    st.cull = ZL_CULL_BACK;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(W) / H,
                                                     ZL_FX_ONE / 10, ZL_FX_INT(100)));
    for (view = 0; view < views; view++) {
        /* the benchmark camera, then around the model and from above/below */
        zl_angle a = (zl_angle)(view * 65536 / views);
        zl_vec3 eye = {zl_fx_mul(ZL_FX_INT(7) / 2, zl_sin(a)), (view % 3 - 1) * ZL_FX_ONE,
                       zl_fx_mul(ZL_FX_INT(7) / 2, zl_cos(a))};
        zl_vec3 target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
        zl_mat4 vw, mvp;
        if (view == 0)
            eye.y = 0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&vw, eye, target, up));
        zl_mat4_mul(&mvp, &proj, &vw);
        raycast(&mesh, &mvp, &st);
        project_tree(&t, &mvp);
        for (order = 0; order < 2; order++) {
            zl_vis_target tg;
            int i;
            memset(&tg, 0, sizeof tg);
            tg.ids = bsp_ids;
            tg.ids_stride = W * 2;
            tg.width = W;
            tg.height = H;
            tg.format = ZL_FORMAT_RGB565;
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_bsp_draw(&bsp, &mvp, eye, &st, &tg, (zl_rgb){0, 0, 0}, (zl_bsp_order)order,
                                                     mask, sizeof mask));
            for (i = 0; i < W * H; i++) {
                covered += rc_ids[i] != ZL_VIS_NONE;
                if (bsp_ids[i] == rc_ids[i])
                    continue;
                if (bsp_ids[i] != ZL_VIS_NONE && rc_ids[i] != ZL_VIS_NONE && rc_gap[i] <= TIE) {
                    ties++;
                } else if (near_split_edge(&t, i)) {
                    edges++;
                } else {
                    snprintf(line, sizeof line, "%s view %d order %d pixel (%d, %d): bsp %u, ray caster %u, gap %u",
                             file, view, order, i % W, i / W, bsp_ids[i], rc_ids[i], rc_gap[i]);
                    TEST_FAIL_MESSAGE(line);
                }
            }
        }
    }
    snprintf(line, sizeof line, "%s: %u -> %u triangles, %u splits, %u nodes, depth %u; over %d views x 2 orders: "
             "%ld covered pixels, %ld near ties, %ld along split edges",
             file, obj.triangle_count, t.triangle_count, t.splits, t.node_count, t.depth, views, covered, ties, edges);
    TEST_MESSAGE(line);
    TEST_ASSERT_GREATER_THAN(views * 2L * 2000, covered);
    TEST_ASSERT_LESS_THAN(covered / 100, ties + edges); /* under 1% of covered pixels */
    bsp_free(&t);
    zl_obj_free(&obj);
}

static void test_bunny(void)
{
    check_model("bunny.obj", 6);
}

static void test_spider(void)
{
    check_model("spider.obj", 4);
}

static void test_writer_output_round_trips(void)
{
    /* Two crossing quads: the tree written as C, read back as numbers. */
    static const zl_fixed pos[] = {0, -65536, -65536, 0, 65536, -65536, 0, 65536, 65536, 0, -65536, 65536,
                                   -65536, -65536, 0, 65536, -65536, 0, 65536, 65536, 0, -65536, 65536, 0};
    static const uint16_t idx[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    bsp_tree t;
    char path[] = "test_bsp_build_out.c";
    FILE *f;
    char text[200000];
    size_t n;
    TEST_ASSERT_EQUAL_INT(0, bsp_build(&t, pos, 8, idx, 4, NULL));
    TEST_ASSERT_EQUAL_UINT32(2, t.splits); /* the second quad's two triangles are cut by the first's plane */
    TEST_ASSERT_EQUAL_UINT32(8, t.triangle_count); /* A, and each cut triangle in three (a triangle and a quad) */
    f = fopen(path, "wb");
    TEST_ASSERT_NOT_NULL(f);
    TEST_ASSERT_EQUAL_INT(0, bsp_write_c(&t, f, "crossing"));
    TEST_ASSERT_EQUAL_INT(0, fclose(f));
    f = fopen(path, "rb");
    TEST_ASSERT_NOT_NULL(f);
    n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    remove(path);
    text[n] = 0;
    TEST_ASSERT_NOT_NULL(strstr(text, "const zl_bsp crossing = {crossing_positions, crossing_indices, crossing_source, NULL, crossing_nodes"));
    TEST_ASSERT_NOT_NULL(strstr(text, "static const zl_bsp_node crossing_nodes["));
    bsp_free(&t);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_writer_output_round_trips);
    RUN_TEST(test_bunny);
    RUN_TEST(test_spider);
    return UNITY_END();
}

/* SPDX-License-Identifier: MIT */
/*
 * Stage 4, primitives: outlines: the edge list of a mesh (adjacency), and the silhouette, crease
 * and border edges of it drawn as depth-tested lines (the LINE RULE).
 *
 * Facing comes from the homogeneous orientation of the triangle's clip-space
 * vertices, sign(det[x y w]): for vertices in front of the eye it is the
 * winding the rasteriser culls by (the y flip of the viewport included), and
 * it stays defined for triangles reaching behind the eye, which have no
 * window-space winding. So a silhouette is decided for every edge, seen or
 * not; the line itself is clipped like any segment.
 */
#include "../1_base/zl_internal.h"

/* ---------------------------------------------------------- edge list */

static int edge_less(const zl_mesh_edge *a, const zl_mesh_edge *b)
{
    if (a->v0 != b->v0)
        return a->v0 < b->v0;
    if (a->v1 != b->v1)
        return a->v1 < b->v1;
    return a->t0 < b->t0;
}

static void sift_down(zl_mesh_edge *e, uint32_t root, uint32_t n)
{
    for (;;) {
        uint32_t child = 2 * root + 1;
        zl_mesh_edge t;
        if (child >= n)
            return;
        if (child + 1 < n && edge_less(&e[child], &e[child + 1]))
            child++;
        if (!edge_less(&e[root], &e[child]))
            return;
        t = e[root];
        e[root] = e[child];
        e[child] = t;
        root = child;
    }
}

uint32_t zl_mesh_edges(const zl_mesh *m, zl_mesh_edge *edges, uint32_t capacity)
{
    if (!ZL_FEATURE_OUTLINES) /* compiled out (zl_config.h) */
        return 0;
    uint32_t n, i, out, t;
    if (m == NULL || edges == NULL || zl_check_mesh(m, 0) != ZL_OK)
        return 0;
    n = (uint32_t)m->triangle_count * 3u;
    if (capacity < n)
        return 0;
    for (t = 0; t < m->triangle_count; t++)
        for (i = 0; i < 3; i++) {
            uint16_t a = m->indices[t * 3 + i], b = m->indices[t * 3 + (i + 1) % 3];
            zl_mesh_edge *e = &edges[t * 3 + i];
            e->v0 = a < b ? a : b;
            e->v1 = a < b ? b : a;
            e->t0 = (uint16_t)t;
            e->t1 = ZL_NO_TRIANGLE;
        }
    /* Heap sort by (v0, v1, t0): no memory beyond the list itself. */
    for (i = n / 2; i-- > 0;)
        sift_down(edges, i, n);
    for (i = n; i-- > 1;) {
        zl_mesh_edge tmp = edges[0];
        edges[0] = edges[i];
        edges[i] = tmp;
        sift_down(edges, 0, i);
    }
    /* Pair equal edges: each pair becomes one entry with both triangles
     * (a third triangle on the same edge starts a new entry). Degenerate
     * edges (v0 == v1) are dropped. */
    for (i = 0, out = 0; i < n; i++) {
        zl_mesh_edge e = edges[i];
        if (e.v0 == e.v1)
            continue;
        if (i + 1 < n && edges[i + 1].v0 == e.v0 && edges[i + 1].v1 == e.v1) {
            e.t1 = edges[i + 1].t0;
            i++;
        }
        edges[out++] = e;
    }
    return out;
}

/* ---------------------------------------------------------- selection */

static int64_t abs64(int64_t v)
{
    return v < 0 ? -v : v;
}

/* +1 front, 0 back, -1 undecided (edge-on, or the transform left its range). */
static int facing(const zl_source *s, const zl_mesh *mesh, uint16_t t)
{
    zl_cvert c[3];
    int64_t x[3], y[3], w[3], big = 0, det;
    unsigned k, shift = 0;
    for (k = 0; k < 3; k++) {
        if (!zl_vertex_clip(s, mesh->indices[t * 3u + k], &c[k]))
            return -1;
        x[k] = c[k].x;
        y[k] = c[k].y;
        w[k] = c[k].w;
        if (abs64(x[k]) > big)
            big = abs64(x[k]);
        if (abs64(y[k]) > big)
            big = abs64(y[k]);
        if (abs64(w[k]) > big)
            big = abs64(w[k]);
    }
    /* Below 2^19 each, so the 3x3 determinant fits 64 bits. */
    while ((big >> shift) >= ((int64_t)1 << 19))
        shift++;
    for (k = 0; k < 3; k++) {
        x[k] = zl_floor_shift64(x[k], shift);
        y[k] = zl_floor_shift64(y[k], shift);
        w[k] = zl_floor_shift64(w[k], shift);
    }
    det = x[0] * (y[1] * w[2] - y[2] * w[1]) - y[0] * (x[1] * w[2] - x[2] * w[1]) + w[0] * (x[1] * y[2] - x[2] * y[1]);
    if (det == 0)
        return -1;
    if (s->mvp == NULL)
        det = -det; /* pixel space: y already points down */
    /* det > 0 is counter-clockwise as the viewer sees it (window y points
     * down, clip y up) when every w > 0. */
    return (det > 0) == (s->state->front_face == ZL_FRONT_CCW);
}

/* Unit normal (Q16) of triangle t in model space; 0 for a degenerate one. */
static int unit_normal(const zl_mesh *mesh, uint16_t t, int64_t *n)
{
    const zl_fixed *p = mesh->positions;
    const uint16_t *idx = &mesh->indices[t * 3u];
    int64_t e1[3], e2[3], big = 0;
    uint64_t len;
    unsigned k, shift = 0;
    for (k = 0; k < 3; k++) {
        e1[k] = (int64_t)p[idx[1] * 3u + k] - p[idx[0] * 3u + k];
        e2[k] = (int64_t)p[idx[2] * 3u + k] - p[idx[0] * 3u + k];
        if (abs64(e1[k]) > big)
            big = abs64(e1[k]);
        if (abs64(e2[k]) > big)
            big = abs64(e2[k]);
    }
    while ((big >> shift) >= ((int64_t)1 << 20))
        shift++;
    for (k = 0; k < 3; k++) {
        e1[k] = zl_floor_shift64(e1[k], shift);
        e2[k] = zl_floor_shift64(e2[k], shift);
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    /* |n| < 2^41: shift below 2^30 so the squared length fits */
    big = abs64(n[0]) > abs64(n[1]) ? abs64(n[0]) : abs64(n[1]);
    big = big > abs64(n[2]) ? big : abs64(n[2]);
    shift = 0;
    while ((big >> shift) >= ((int64_t)1 << 30))
        shift++;
    for (k = 0; k < 3; k++)
        n[k] = zl_floor_shift64(n[k], shift);
    len = zl_isqrt64((uint64_t)(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
    if (len == 0)
        return 0;
    for (k = 0; k < 3; k++)
        n[k] = n[k] * 65536 / (int64_t)len;
    return 1;
}

int zl_outline_selected(const zl_source *s, const zl_mesh *mesh, const zl_outline *o, const zl_mesh_edge *e)
{
    int f0, f1;
    if (e->t1 == ZL_NO_TRIANGLE || e->t1 >= mesh->triangle_count)
        return o->borders != 0;
    f0 = facing(s, mesh, e->t0);
    f1 = facing(s, mesh, e->t1);
    if (o->silhouettes && f0 >= 0 && f1 >= 0 && f0 != f1)
        return 1;
    if (o->creases && (f0 == 1 || f1 == 1)) {
        int64_t n0[3], n1[3];
        if (unit_normal(mesh, e->t0, n0) && unit_normal(mesh, e->t1, n1) &&
            zl_floor_shift64(n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2], 16) < o->crease_cos)
            return 1;
    }
    return 0;
}

int zl_outline_record(const zl_source *s, const zl_mesh *mesh, const zl_outline *o, const zl_style *sty,
                      uint32_t k, zl_active *out)
{
    if (!ZL_FEATURE_OUTLINES) /* compiled out (zl_config.h) */
        return 0;
    const zl_mesh_edge *e = &o->edges[k];
    zl_segment seg;
    if (!zl_outline_selected(s, mesh, o, e))
        return 0;
    if (!zl_segment_make(s, e->v0, e->v1, 0, 0, &seg))
        return 0;
    seg.rgb = o->color;
    if (sty->line_aa)
        return zl_line_setup_aa(out, &seg, (int64_t)sty->offset_units * (1 << (ZL_ATTR_FRAC - 16)), s->width,
                                s->height);
    return zl_line_setup(out, &seg, sty->line_algo, (int64_t)sty->offset_units * (1 << (ZL_ATTR_FRAC - 16)),
                         s->width, s->height);
}

zl_status zl_check_outline(const zl_mesh *mesh, const zl_outline *o)
{
    if (!ZL_FEATURE_OUTLINES) /* compiled out (zl_config.h) */
        return ZL_ERR_UNSUPPORTED;
    uint32_t i;
    if (o == NULL || (o->edge_count > 0 && o->edges == NULL))
        return ZL_ERR_ARG;
    for (i = 0; i < o->edge_count; i++) {
        const zl_mesh_edge *e = &o->edges[i];
        if (e->v0 >= mesh->vertex_count || e->v1 >= mesh->vertex_count || e->t0 >= mesh->triangle_count ||
            (e->t1 != ZL_NO_TRIANGLE && e->t1 >= mesh->triangle_count))
            return ZL_ERR_RANGE;
    }
    return ZL_OK;
}

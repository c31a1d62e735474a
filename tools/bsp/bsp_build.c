/* SPDX-License-Identifier: MIT */
/* Offline BSP builder: see bsp_build.h. Host code: doubles for geometry,
 * Q16.16 integers for every vertex it stores. */
#include "bsp_build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    uint32_t v[3];
    uint32_t src;
} tri;

typedef struct {
    tri *t;
    size_t n, cap;
} tri_list;

typedef struct {
    const bsp_options *opt;
    /* vertices (Q16.16) and a hash from position to index, for sharing */
    int32_t *pos;
    size_t nv, cap_v;
    uint32_t *hash;
    size_t hash_cap;
    tri_list out;          /* output triangles, grouped by node */
    zl_bsp_node *nodes;
    size_t nn, cap_n;
    uint32_t depth, splits;
    uint8_t *split_source;
    int failed;
} builder;

static void *grow(void *p, size_t *cap, size_t need, size_t elem)
{
    if (need <= *cap)
        return p;
    while (*cap < need)
        *cap = *cap ? *cap * 2 : 64;
    p = realloc(p, *cap * elem);
    if (p == NULL) {
        fprintf(stderr, "bsp: out of memory\n");
        exit(1);
    }
    return p;
}

static void push_tri(tri_list *l, tri t)
{
    l->t = grow(l->t, &l->cap, l->n + 1, sizeof(tri));
    l->t[l->n++] = t;
}

static uint32_t hash3(const int32_t *p)
{
    uint32_t h = (uint32_t)p[0] * 73856093u ^ (uint32_t)p[1] * 19349663u ^ (uint32_t)p[2] * 83492791u;
    return h ^ (h >> 15);
}

static void rehash(builder *b)
{
    size_t i;
    free(b->hash);
    b->hash_cap = 1024;
    while (b->hash_cap < b->nv * 2 + 16)
        b->hash_cap *= 2;
    b->hash = malloc(b->hash_cap * sizeof(uint32_t));
    if (b->hash == NULL)
        exit(1);
    for (i = 0; i < b->hash_cap; i++)
        b->hash[i] = UINT32_MAX;
    for (i = 0; i < b->nv; i++) {
        size_t h = hash3(&b->pos[i * 3]) & (b->hash_cap - 1);
        while (b->hash[h] != UINT32_MAX) {
            const int32_t *q = &b->pos[b->hash[h] * 3];
            if (memcmp(q, &b->pos[i * 3], 3 * sizeof(int32_t)) == 0)
                break; /* duplicate input vertex: keep the first */
            h = (h + 1) & (b->hash_cap - 1);
        }
        if (b->hash[h] == UINT32_MAX)
            b->hash[h] = (uint32_t)i;
    }
}

/* Index of the vertex at p, added when new. */
static uint32_t vertex_at(builder *b, const int32_t *p)
{
    size_t h;
    if (b->nv * 2 + 2 > b->hash_cap)
        rehash(b);
    h = hash3(p) & (b->hash_cap - 1);
    while (b->hash[h] != UINT32_MAX) {
        if (memcmp(&b->pos[b->hash[h] * 3], p, 3 * sizeof(int32_t)) == 0)
            return b->hash[h];
        h = (h + 1) & (b->hash_cap - 1);
    }
    b->pos = grow(b->pos, &b->cap_v, (b->nv + 1) * 3, sizeof(int32_t));
    memcpy(&b->pos[b->nv * 3], p, 3 * sizeof(int32_t));
    b->hash[h] = (uint32_t)b->nv;
    return (uint32_t)b->nv++;
}

typedef struct {
    double n[3], d;   /* unit normal, model units */
    int32_t nq[3];    /* normal as Q16.16 */
    int64_t dq;       /* nq . p0 with p0 Q16.16: Q32.32 */
} plane;

static double coord(const builder *b, uint32_t v, int k)
{
    return b->pos[v * 3 + (uint32_t)k] / 65536.0;
}

static int plane_of(const builder *b, const tri *t, plane *p)
{
    double e1[3], e2[3], len;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = coord(b, t->v[1], k) - coord(b, t->v[0], k);
        e2[k] = coord(b, t->v[2], k) - coord(b, t->v[0], k);
    }
    p->n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    p->n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    p->n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    len = sqrt(p->n[0] * p->n[0] + p->n[1] * p->n[1] + p->n[2] * p->n[2]);
    if (len == 0)
        return 0;
    p->dq = 0;
    for (k = 0; k < 3; k++) {
        p->n[k] /= len;
        p->nq[k] = (int32_t)lround(p->n[k] * 65536.0);
        p->dq += (int64_t)p->nq[k] * b->pos[t->v[0] * 3 + (uint32_t)k];
    }
    p->d = p->n[0] * coord(b, t->v[0], 0) + p->n[1] * coord(b, t->v[0], 1) + p->n[2] * coord(b, t->v[0], 2);
    return 1;
}

static double dist(const builder *b, const plane *p, uint32_t v)
{
    return p->n[0] * coord(b, v, 0) + p->n[1] * coord(b, v, 1) + p->n[2] * coord(b, v, 2) - p->d;
}

/* -1 behind, 0 on, 1 in front, per vertex; returns the triangle's class:
 * 0 coplanar, 1 front, 2 back, 3 spanning. */
static int classify(const builder *b, const plane *p, const tri *t, double *s, int *c)
{
    int k, front = 0, back = 0;
    for (k = 0; k < 3; k++) {
        s[k] = dist(b, p, t->v[k]);
        c[k] = s[k] > b->opt->epsilon ? 1 : (s[k] < -b->opt->epsilon ? -1 : 0);
        front |= c[k] > 0;
        back |= c[k] < 0;
    }
    return front && back ? 3 : (back ? 2 : (front ? 1 : 0));
}

static void add_fan(tri_list *l, const uint32_t *poly, int n, uint32_t src)
{
    int k;
    for (k = 1; k + 1 < n; k++) {
        tri t;
        t.v[0] = poly[0];
        t.v[1] = poly[k];
        t.v[2] = poly[k + 1];
        t.src = src;
        if (t.v[0] != t.v[1] && t.v[1] != t.v[2] && t.v[0] != t.v[2])
            push_tri(l, t);
    }
}

static void split(builder *b, const plane *p, const tri *t, const double *s, const int *c, tri_list *front,
                  tri_list *back)
{
    uint32_t fp[4], bp[4];
    int nf = 0, nb = 0, i;
    for (i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        if (c[i] >= 0)
            fp[nf++] = t->v[i];
        if (c[i] <= 0)
            bp[nb++] = t->v[i];
        if (c[i] * c[j] < 0) {
            double u = s[i] / (s[i] - s[j]);
            int32_t q[3];
            uint32_t nv;
            int k;
            for (k = 0; k < 3; k++) {
                double a = b->pos[t->v[i] * 3 + (uint32_t)k], e = b->pos[t->v[j] * 3 + (uint32_t)k];
                q[k] = (int32_t)floor(a + u * (e - a) + 0.5);
            }
            nv = vertex_at(b, q);
            fp[nf++] = nv;
            bp[nb++] = nv;
        }
    }
    (void)p;
    add_fan(front, fp, nf, t->src);
    add_fan(back, bp, nb, t->src);
    b->splits++;
    b->split_source[t->src] = 1;
}

static uint16_t build(builder *b, tri_list *in, uint32_t level)
{
    size_t i, best = 0, step;
    long best_score = -1;
    plane pl;
    tri_list front = {0}, back = {0};
    uint16_t node;
    uint32_t first;
    if (in->n == 0)
        return ZL_BSP_LEAF;
    if (level > b->depth)
        b->depth = level;
    /* choose the splitter */
    step = in->n / (size_t)b->opt->candidates + 1;
    for (i = 0; i < in->n; i += step) {
        plane cand;
        size_t j;
        long nf = 0, nbk = 0, ns = 0, score;
        if (!plane_of(b, &in->t[i], &cand))
            continue;
        for (j = 0; j < in->n; j++) {
            double s[3];
            int c[3], cls = classify(b, &cand, &in->t[j], s, c);
            nf += cls == 1;
            nbk += cls == 2;
            ns += cls == 3;
        }
        score = 8 * ns + labs(nf - nbk);
        if (best_score < 0 || score < best_score) {
            best_score = score;
            best = i;
        }
    }
    if (best_score < 0) {
        /* only degenerate triangles left: they draw nothing; drop them */
        free(in->t);
        in->t = NULL;
        in->n = 0;
        return ZL_BSP_LEAF;
    }
    plane_of(b, &in->t[best], &pl);
    b->nodes = grow(b->nodes, &b->cap_n, b->nn + 1, sizeof(zl_bsp_node));
    node = (uint16_t)b->nn++;
    if (b->nn > 65535)
        b->failed = 1;
    first = (uint32_t)b->out.n;
    for (i = 0; i < in->n; i++) {
        double s[3];
        int c[3], cls = classify(b, &pl, &in->t[i], s, c);
        if (cls == 0)
            push_tri(&b->out, in->t[i]);
        else if (cls == 1)
            push_tri(&front, in->t[i]);
        else if (cls == 2)
            push_tri(&back, in->t[i]);
        else
            split(b, &pl, &in->t[i], s, c, &front, &back);
    }
    free(in->t);
    in->t = NULL;
    in->n = 0;
    {
        zl_bsp_node *n = &b->nodes[node];
        memcpy(n->n, pl.nq, sizeof n->n);
        n->d = pl.dq;
        n->first = (uint16_t)first;
        n->count = (uint16_t)(b->out.n - first);
        if (b->out.n > 65535)
            b->failed = 1;
    }
    {
        uint16_t f = build(b, &front, level + 1);
        uint16_t k = build(b, &back, level + 1);
        b->nodes[node].front = f;
        b->nodes[node].back = k;
    }
    return node;
}

void bsp_options_default(bsp_options *o)
{
    o->candidates = 24;
    o->epsilon = 1.0 / 8192.0;
}

int bsp_build(bsp_tree *out, const zl_fixed *positions, uint32_t vertex_count, const uint16_t *indices,
              uint32_t triangle_count, const bsp_options *opt)
{
    builder b;
    tri_list in = {0};
    bsp_options def;
    uint32_t i;
    uint16_t root;
    memset(out, 0, sizeof *out);
    memset(&b, 0, sizeof b);
    if (opt == NULL) {
        bsp_options_default(&def);
        opt = &def;
    }
    b.opt = opt;
    b.pos = malloc((size_t)vertex_count * 3 * sizeof(int32_t) + 12);
    b.cap_v = (size_t)vertex_count * 3 + 3;
    memcpy(b.pos, positions, (size_t)vertex_count * 3 * sizeof(int32_t));
    b.nv = vertex_count;
    rehash(&b);
    b.split_source = calloc(triangle_count + 1u, 1);
    for (i = 0; i < triangle_count; i++) {
        tri t;
        int k;
        for (k = 0; k < 3; k++)
            t.v[k] = indices[i * 3 + (uint32_t)k];
        t.src = i;
        push_tri(&in, t);
    }
    root = build(&b, &in, 1);
    free(b.hash);
    if (b.failed || b.nv > 65535 || b.out.n > 65535 || b.depth > ZL_BSP_MAX_DEPTH) {
        fprintf(stderr, "bsp: tree too large: %zu vertices, %zu triangles, %zu nodes, depth %u (limits 65535 and %d)\n",
                b.nv, b.out.n, b.nn, b.depth, ZL_BSP_MAX_DEPTH);
        free(b.pos);
        free(b.out.t);
        free(b.nodes);
        free(b.split_source);
        return -1;
    }
    out->positions = (zl_fixed *)b.pos;
    out->vertex_count = (uint32_t)b.nv;
    out->triangle_count = (uint32_t)b.out.n;
    out->indices = malloc(b.out.n * 3 * sizeof(uint16_t) + 2);
    out->source = malloc(b.out.n * sizeof(uint16_t) + 2);
    for (i = 0; i < b.out.n; i++) {
        int k;
        for (k = 0; k < 3; k++)
            out->indices[i * 3 + (uint32_t)k] = (uint16_t)b.out.t[i].v[k];
        out->source[i] = (uint16_t)b.out.t[i].src;
    }
    free(b.out.t);
    out->nodes = b.nodes;
    out->node_count = (uint32_t)b.nn;
    out->depth = b.depth;
    out->splits = b.splits;
    out->split_source = b.split_source;
    out->input_triangles = triangle_count;
    (void)root; /* pre-order: the root is node 0 */
    return 0;
}

zl_bsp bsp_view(const bsp_tree *t)
{
    zl_bsp v;
    memset(&v, 0, sizeof v);
    v.positions = t->positions;
    v.indices = t->indices;
    v.source = t->source;
    v.nodes = t->nodes;
    v.vertex_count = (uint16_t)t->vertex_count;
    v.triangle_count = (uint16_t)t->triangle_count;
    v.node_count = (uint16_t)t->node_count;
    v.root = 0;
    v.depth = (uint16_t)t->depth;
    return v;
}

void bsp_free(bsp_tree *t)
{
    free(t->positions);
    free(t->indices);
    free(t->source);
    free(t->nodes);
    free(t->split_source);
    memset(t, 0, sizeof *t);
}

int bsp_write_c(const bsp_tree *t, FILE *f, const char *name)
{
    uint32_t i;
    fprintf(f, "/* Generated by zline-bsp: %u input triangles -> %u triangles (%u splits), %u vertices,\n"
               " * %u nodes, depth %u. Do not edit. */\n#include \"zline/zl_visibility.h\"\n\n",
            t->input_triangles, t->triangle_count, t->splits, t->vertex_count, t->node_count, t->depth);
    fprintf(f, "static const zl_fixed %s_positions[%u] = {\n", name, t->vertex_count * 3);
    for (i = 0; i < t->vertex_count; i++)
        fprintf(f, "    %ld, %ld, %ld,\n", (long)t->positions[i * 3], (long)t->positions[i * 3 + 1],
                (long)t->positions[i * 3 + 2]);
    fprintf(f, "};\n\nstatic const uint16_t %s_indices[%u] = {\n", name, t->triangle_count * 3);
    for (i = 0; i < t->triangle_count; i++)
        fprintf(f, "    %u, %u, %u,\n", t->indices[i * 3], t->indices[i * 3 + 1], t->indices[i * 3 + 2]);
    fprintf(f, "};\n\n/* the input triangle each one came from */\nstatic const uint16_t %s_source[%u] = {\n", name,
            t->triangle_count);
    for (i = 0; i < t->triangle_count; i++)
        fprintf(f, "    %u,\n", t->source[i]);
    fprintf(f, "};\n\n/* {normal (Q16.16), d (Q32.32), first, count, front, back} */\n"
               "static const zl_bsp_node %s_nodes[%u] = {\n", name, t->node_count);
    for (i = 0; i < t->node_count; i++) {
        const zl_bsp_node *n = &t->nodes[i];
        fprintf(f, "    {{%ld, %ld, %ld}, INT64_C(%lld), %u, %u, %u, %u},\n", (long)n->n[0], (long)n->n[1],
                (long)n->n[2], (long long)n->d, n->first, n->count, n->front, n->back);
    }
    fprintf(f, "};\n\nconst zl_bsp %s = {%s_positions, %s_indices, %s_source, NULL, %s_nodes, %u, %u, %u, 0, %u};\n",
            name, name, name, name, name, t->vertex_count, t->triangle_count, t->node_count, t->depth);
    return ferror(f) ? -1 : 0;
}

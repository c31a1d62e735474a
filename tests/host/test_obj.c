/* SPDX-License-Identifier: MIT */
/* The host OBJ loader: formats, triangulation, every error with its line. */
#if !defined(_WIN32) && !defined(_POSIX_C_SOURCE)
#define _POSIX_C_SOURCE 200809L /* opendir: every model of the shared folder */
#endif
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "zl_obj.h"

#ifndef _WIN32
#include <dirent.h>
#endif

static zl_obj obj;
static char msg[512];

void setUp(void)
{
    memset(&obj, 0, sizeof obj);
    msg[0] = '\0';
}

void tearDown(void)
{
    zl_obj_free(&obj);
}

static zl_obj_status load_text(const char *text, int normalize)
{
    zl_obj_options opt;
    zl_obj_options_default(&opt);
    opt.normalize = normalize;
    return zl_obj_load_mem(&obj, text, strlen(text), "t.obj", &opt, msg, sizeof msg);
}

static void load_ok(const char *text)
{
    zl_obj_status st = load_text(text, 0);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, st, msg);
}

/* The load fails with status st and "t.obj:LINE: ...what...". */
static void check_error(zl_obj_status got, zl_obj_status st, unsigned long line, const char *what)
{
    char prefix[64];
    TEST_ASSERT_EQUAL_INT_MESSAGE(st, got, msg);
    snprintf(prefix, sizeof prefix, "t.obj:%lu: ", line);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(prefix, msg, strlen(prefix), msg);
    TEST_ASSERT_NOT_NULL(strstr(msg, what));
    /* A failed load leaves nothing behind. */
    TEST_ASSERT_NULL(obj.positions);
    TEST_ASSERT_NULL(obj.indices);
    TEST_ASSERT_NULL(obj.vertex_colors);
    TEST_ASSERT_EQUAL_UINT(0, obj.vertex_count);
}

static void expect_error_mem(const char *data, size_t size, unsigned long line, const char *what)
{
    zl_obj_status st = zl_obj_load_mem(&obj, data, size, "t.obj", NULL, msg, sizeof msg);
    check_error(st, ZL_OBJ_ERR_PARSE, line, what);
}

static void expect_error(const char *text, unsigned long line, const char *what)
{
    expect_error_mem(text, strlen(text), line, what);
}

static void assert_tri(uint32_t t, unsigned a, unsigned b, unsigned c)
{
    TEST_ASSERT_TRUE(t < obj.triangle_count);
    TEST_ASSERT_EQUAL_UINT(a, obj.indices[3 * t]);
    TEST_ASSERT_EQUAL_UINT(b, obj.indices[3 * t + 1]);
    TEST_ASSERT_EQUAL_UINT(c, obj.indices[3 * t + 2]);
}

/* ------------------------------------------------- polygon coverage checks */

/* Project vertex i onto the plane dropping axis k (cyclic order kept). */
static void proj2(unsigned i, int k, int64_t *x, int64_t *y)
{
    *x = obj.positions[3 * i + (k + 1) % 3];
    *y = obj.positions[3 * i + (k + 2) % 3];
}

static int64_t area2(unsigned a, unsigned b, unsigned c, int k)
{
    int64_t ax, ay, bx, by, cx, cy;
    proj2(a, k, &ax, &ay);
    proj2(b, k, &bx, &by);
    proj2(c, k, &cx, &cy);
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

/* Even-odd test of point (px, py) / 3 against the polygon, all coordinates x3. */
static int inside3(const unsigned *poly, size_t n, int k, int64_t px, int64_t py)
{
    size_t i;
    int in = 0;
    for (i = 0; i < n; i++) {
        int64_t x0, y0, x1, y1;
        proj2(poly[i], k, &x0, &y0);
        proj2(poly[(i + 1) % n], k, &x1, &y1);
        x0 *= 3;
        y0 *= 3;
        x1 *= 3;
        y1 *= 3;
        if ((y0 > py) != (y1 > py)) {
            /* x of the edge at py, compared without division */
            double xc = (double)x0 + (double)(py - y0) * (double)(x1 - x0) / (double)(y1 - y0);
            if ((double)px < xc)
                in = !in;
        }
    }
    return in;
}

/*
 * The triangles first_tri .. first_tri + n - 3 triangulate the polygon
 * poly[0..n-1]: n - 2 of them, every one wound like the polygon, their
 * areas summing exactly to the polygon's, every centroid inside it. Since
 * their signed areas add up to the polygon's and none is negative, they
 * cannot overlap or stick out.
 */
static void check_triangulation(const unsigned *poly, size_t n, uint32_t first_tri, int k)
{
    int64_t poly2 = 0, sum = 0;
    size_t i;
    for (i = 1; i + 1 < n; i++)
        poly2 += area2(poly[0], poly[i], poly[i + 1], k);
    TEST_ASSERT_TRUE_MESSAGE(poly2 != 0, "test polygon has no area in its projection");
    TEST_ASSERT_TRUE(first_tri + n - 2 <= obj.triangle_count);
    for (i = 0; i + 2 < n; i++) {
        const uint16_t *t = obj.indices + 3 * (first_tri + i);
        int64_t a = area2(t[0], t[1], t[2], k);
        int64_t cx = 0, cy = 0;
        unsigned j;
        if (poly2 < 0)
            a = -a;
        TEST_ASSERT_TRUE_MESSAGE(a >= 0, "a triangle is wound against its polygon");
        sum += a;
        if (a == 0)
            continue;
        for (j = 0; j < 3; j++) {
            int64_t x, y;
            proj2(t[j], k, &x, &y);
            cx += x;
            cy += y;
        }
        TEST_ASSERT_TRUE_MESSAGE(inside3(poly, n, k, cx, cy),
                                 "a triangle lies outside its polygon");
    }
    TEST_ASSERT_TRUE_MESSAGE(sum == (poly2 < 0 ? -poly2 : poly2),
                             "triangle areas do not add up to the polygon's");
}

/* ------------------------------------------------------------------ tests */

static void test_face_entry_formats(void)
{
    uint32_t t;
    load_ok("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
            "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
            "f 1 2 3\n"
            "f 1/1 2/2 3/3\n"
            "f 1//1 2//1 3//1\n"
            "f 1/1/1 2/2/1 3/3/1\n"
            "f 2/1/1 3/2/1 4/3/1\n");
    TEST_ASSERT_EQUAL_UINT(4, obj.vertex_count);
    TEST_ASSERT_EQUAL_UINT(5, obj.triangle_count);
    TEST_ASSERT_EQUAL_UINT(5, obj.face_count);
    for (t = 0; t < 4; t++)
        assert_tri(t, 0, 1, 2);
    assert_tri(4, 1, 2, 3);
    TEST_ASSERT_NULL(obj.vertex_colors);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE, obj.positions[3]);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE, obj.positions[7]);
}

/* Issue 26: a face's corners all have a vt or none has, the same for vn
 * (the OBJ form of a face is one of v, v/vt, v//vn, v/vt/vn throughout). */
static void test_face_mixing_forms_is_an_error(void)
{
    static const char head[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n";
    char text[256];
    snprintf(text, sizeof text, "%sf 1 2 3\nf 2/1/1 3//1 4/3\n", head);
    expect_error(text, 10, "a face mixes corners with and without a texture coordinate (vt): 2 of 3 have one");
    snprintf(text, sizeof text, "%sf 1/1 2/2 3\n", head);
    expect_error(text, 9, "(vt): 2 of 3 have one");
    snprintf(text, sizeof text, "%sf 1//1 2 3//1 4//1\n", head);
    expect_error(text, 9, "a face mixes corners with and without a normal (vn): 3 of 4 have one");
}

static void test_negative_indices(void)
{
    load_ok("v 0 0 0\nv 1 0 0\nv 1 1 0\n"
            "vt 0 0\nvt 1 1\nvn 0 0 1\n"
            "f -3 -2 -1\n"
            "v 0 1 0\n"
            "f -4/-2/-1 -2/-1/-1 -1/-2/-1\n" /* relative to the 4 vertices so far */
            "f 1 -3 -1\n");
    TEST_ASSERT_EQUAL_UINT(3, obj.triangle_count);
    assert_tri(0, 0, 1, 2);
    assert_tri(1, 0, 2, 3);
    assert_tri(2, 0, 1, 3);
}

static void test_forward_reference(void)
{
    /* Positive indices may name vertices defined further down. */
    load_ok("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    TEST_ASSERT_EQUAL_UINT(1, obj.triangle_count);
    assert_tri(0, 0, 1, 2);
}

static void test_crlf_comments_and_ignored_statements(void)
{
    load_ok("\xEF\xBB\xBF# exported\r\n"
            "mtllib a.mtl\r\n"
            "o thing\r\n"
            "\r\n"
            "g group one\r\n"
            "\tv  0.5 -0.25  2e-1 # a comment after data\r\n"
            "v 1 0 0\r\n"
            "v 0 1 0\r\n"
            "   \r\n"
            "s off\r\n"
            "usemtl red\r\n"
            "vt 0.5\r\n"
            "vn 0 0 1\r\n"
            "l 1 2\r\n"
            "p 1\r\n"
            "f 1 2 3"); /* no final newline */
    TEST_ASSERT_EQUAL_UINT(3, obj.vertex_count);
    TEST_ASSERT_EQUAL_UINT(1, obj.triangle_count);
    TEST_ASSERT_EQUAL_INT32(32768, obj.positions[0]);
    TEST_ASSERT_EQUAL_INT32(-16384, obj.positions[1]);
    TEST_ASSERT_EQUAL_INT32(13107, obj.positions[2]); /* 0.2 * 65536 = 13107.2 */
}

static void test_rounding_to_q16(void)
{
    /* round to nearest, ties up: 1.5/65536 -> 2, -1.5/65536 -> -1 */
    load_ok("v 0.000022888183593750 -0.000022888183593750 0.0000076293945\nv 1 0 0\nv 0 1 0\n"
            "f 1 2 3\n");
    TEST_ASSERT_EQUAL_INT32(2, obj.positions[0]);
    TEST_ASSERT_EQUAL_INT32(-1, obj.positions[1]);
    TEST_ASSERT_EQUAL_INT32(0, obj.positions[2]); /* 0.49999 of a unit */
}

static void test_quad(void)
{
    static const unsigned quad[4] = {0, 1, 2, 3};
    load_ok("v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nf 1 2 3 4\n");
    TEST_ASSERT_EQUAL_UINT(2, obj.triangle_count);
    check_triangulation(quad, 4, 0, 2);
}

static void test_concave_polygons_by_hand(void)
{
    /* An arrow head (a fan from the face's first vertex covers the notch),
     * an L, and a star in the xz plane, each checked in its plane. */
    static const unsigned ell[6] = {4, 5, 6, 7, 8, 9};
    static const unsigned star[10] = {10, 11, 12, 13, 14, 15, 16, 17, 18, 19};
    load_ok("v 0 0 0\nv 2 1 0\nv 4 0 0\nv 2 4 0\n"
            "f 3 4 1 2\n"
            "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 3 0\nv 0 3 0\n"
            "f 5 6 7 8 9 10\n"
            "v 0 0 5\nv 1 0 2\nv 4 0 2\nv 1.5 0 0\nv 2.5 0 -3\n"
            "v 0 0 -1\nv -2.5 0 -3\nv -1.5 0 0\nv -4 0 2\nv -1 0 2\n"
            "f 11 12 13 14 15 16 17 18 19 20\n");
    TEST_ASSERT_EQUAL_UINT(2 + 4 + 8, obj.triangle_count);
    {
        /* the arrow's face starts at vertex 3 */
        static const unsigned arrow_face[4] = {2, 3, 0, 1};
        check_triangulation(arrow_face, 4, 0, 2);
    }
    check_triangulation(ell, 6, 2, 2);
    check_triangulation(star, 10, 6, 1);
}

static void test_polygon_winding_kept_in_every_plane(void)
{
    /* The same concave pentagon in the xy, yz and zx planes, in both
     * windings: triangles keep the face's winding (normal direction). */
    static const char *const faces[] = {
        "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 2 1 0\nv 0 4 0\nf 1 2 3 4 5\n",
        "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 2 1 0\nv 0 4 0\nf 5 4 3 2 1\n",
        "v 0 0 0\nv 0 4 0\nv 0 4 4\nv 0 2 1\nv 0 0 4\nf 1 2 3 4 5\n",
        "v 0 0 0\nv 0 4 0\nv 0 4 4\nv 0 2 1\nv 0 0 4\nf 5 4 3 2 1\n",
        "v 0 0 0\nv 0 0 4\nv 4 0 4\nv 1 0 2\nv 4 0 0\nf 1 2 3 4 5\n",
        "v 0 0 0\nv 0 0 4\nv 4 0 4\nv 1 0 2\nv 4 0 0\nf 5 4 3 2 1\n",
    };
    static const int axis[] = {2, 2, 0, 0, 1, 1};
    size_t i;
    for (i = 0; i < sizeof faces / sizeof faces[0]; i++) {
        unsigned fwd[5] = {0, 1, 2, 3, 4}, rev[5] = {4, 3, 2, 1, 0};
        load_ok(faces[i]);
        TEST_ASSERT_EQUAL_UINT(3, obj.triangle_count);
        check_triangulation(i % 2 ? rev : fwd, 5, 0, axis[i]);
        zl_obj_free(&obj);
    }
}

static void test_concave_polygon_model(void)
{
    char path[1024];
    FILE *f;
    char line[4096];
    unsigned poly[128];
    size_t n = 0;
    snprintf(path, sizeof path, "%s/models/concave_polygon.obj", ZLINE_SHARED_DIR);
    f = fopen(path, "rb");
    if (f == NULL) {
        TEST_IGNORE_MESSAGE("shared/models/concave_polygon.obj not found");
        return;
    }
    /* The test reads the face itself: 66 entries (a seam to the hole repeats
     * two vertices). */
    while (fgets(line, sizeof line, f) != NULL) {
        if (line[0] == 'f' && line[1] == ' ') {
            char *p = line + 2;
            for (;;) {
                char *end;
                long v = strtol(p, &end, 10);
                if (end == p)
                    break;
                poly[n++] = (unsigned)(v - 1);
                while (*end != '\0' && *end != ' ')
                    end++;
                p = end;
                if (n == sizeof poly / sizeof poly[0])
                    break;
            }
        }
    }
    fclose(f);
    TEST_ASSERT_EQUAL_UINT(66, n);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, zl_obj_load_file(&obj, path, NULL, msg, sizeof msg),
                                  msg);
    TEST_ASSERT_EQUAL_UINT(64, obj.vertex_count);
    TEST_ASSERT_EQUAL_UINT(64, obj.triangle_count);
    check_triangulation(poly, n, 0, 0); /* the polygon lies in the plane x = -1.146 */
    zl_obj_free(&obj);
    /* Normalised, the same holds. */
    {
        zl_obj_options opt;
        opt.normalize = 1;
        TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK,
                                      zl_obj_load_file(&obj, path, &opt, msg, sizeof msg), msg);
        check_triangulation(poly, n, 0, 0);
    }
}

static void test_polygon_with_hole_by_seam(void)
{
    /* A 10x10 square with a 4x4 hole, joined by a seam: the outline repeats
     * two vertices. Area 84, 8 triangles. */
    static const unsigned poly[10] = {0, 1, 2, 3, 0, 4, 5, 6, 7, 4};
    load_ok("v 0 0 0\nv 10 0 0\nv 10 10 0\nv 0 10 0\n"
            "v 3 3 0\nv 3 7 0\nv 7 7 0\nv 7 3 0\n"
            "f 1 2 3 4 1 5 6 7 8 5\n");
    TEST_ASSERT_EQUAL_UINT(8, obj.triangle_count);
    check_triangulation(poly, 10, 0, 2);
}

static void test_comb(void)
{
    /* 100 teeth: 400 vertices, 199 of them reflex. */
    enum { T = 100 };
    unsigned poly[4 * T];
    char *text = (char *)malloc(64 * 4 * T + 4096);
    size_t len = 0, n = 0, i;
    double xs[4 * T], ys[4 * T];
    TEST_ASSERT_TRUE(text != NULL);
    xs[n] = 0;
    ys[n++] = 0;
    xs[n] = 2 * T - 1;
    ys[n++] = 0;
    for (i = T; i-- > 0;) {
        xs[n] = 2.0 * (double)i + 1;
        ys[n++] = 4;
        xs[n] = 2.0 * (double)i;
        ys[n++] = 4;
        if (i > 0) {
            xs[n] = 2.0 * (double)i;
            ys[n++] = 1;
            xs[n] = 2.0 * (double)i - 1;
            ys[n++] = 1;
        }
    }
    TEST_ASSERT_EQUAL_UINT(4 * T, n);
    for (i = 0; i < n; i++)
        len += (size_t)sprintf(text + len, "v %g %g 0\n", xs[i], ys[i]);
    len += (size_t)sprintf(text + len, "f");
    for (i = 0; i < n; i++) {
        len += (size_t)sprintf(text + len, " %lu", (unsigned long)(i + 1));
        poly[i] = (unsigned)i;
    }
    len += (size_t)sprintf(text + len, "\n");
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        ZL_OBJ_OK, zl_obj_load_mem(&obj, text, len, "t.obj", NULL, msg, sizeof msg), msg);
    free(text);
    TEST_ASSERT_EQUAL_UINT(4 * T - 2, obj.triangle_count);
    check_triangulation(poly, n, 0, 2);
}

/* A small deterministic generator for the random polygons. */
static uint32_t lcg_state = 12345u;
static uint32_t lcg(void)
{
    lcg_state = lcg_state * 1664525u + 1013904223u;
    return lcg_state >> 8;
}

static void test_random_star_polygons(void)
{
    /* Star-shaped outlines (angles increasing, random radii) are simple but
     * often very concave. Integer coordinates are exact in Q16.16, so the
     * check sees exactly what the triangulator saw. */
    int round;
    for (round = 0; round < 300; round++) {
        /* up to 130 vertices: both the small and the z-order ear search */
        unsigned n = 4 + lcg() % 127, i, poly[130];
        char *text = (char *)malloc(64 * 130 + 1024);
        size_t len = 0;
        int flip = (int)(lcg() % 2);
        TEST_ASSERT_TRUE(text != NULL);
        for (i = 0; i < n; i++) {
            double a = 6.283185307179586 * ((double)i + 0.8 * (double)(lcg() % 1000) / 1000.0) / n;
            double r = 100.0 + (double)(lcg() % 900);
            long x = (long)floor(r * cos(a) + 0.5), y = (long)floor(r * sin(a) + 0.5);
            len += (size_t)sprintf(text + len, "v %ld %ld %ld\n", x, flip ? 0L : y, flip ? y : 0L);
        }
        len += (size_t)sprintf(text + len, "f");
        for (i = 0; i < n; i++) {
            unsigned k = flip ? n - 1 - i : i; /* both windings */
            len += (size_t)sprintf(text + len, " %u", k + 1);
            poly[i] = k;
        }
        len += (size_t)sprintf(text + len, "\n");
        TEST_ASSERT_EQUAL_INT_MESSAGE(
            ZL_OBJ_OK, zl_obj_load_mem(&obj, text, len, "t.obj", NULL, msg, sizeof msg), msg);
        free(text);
        TEST_ASSERT_EQUAL_UINT(n - 2, obj.triangle_count);
        check_triangulation(poly, n, 0, flip ? 1 : 2);
        zl_obj_free(&obj);
    }
}

static void test_degenerate_faces_end(void)
{
    /* Collinear, all one point, a bow tie, a spike: n - 2 triangles each,
     * every index from the face, and the loop ends. */
    uint32_t t;
    load_ok("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 1 1 0\nv 0 1 0\nv 1 -1 0\n"
            "f 1 2 3 4 3 2\n"   /* a line folded back */
            "f 1 1 1 1 1\n"     /* one point */
            "f 1 2 5 6 2 7\n"   /* self-touching */
            "f 1 3 5 2 6\n"     /* bow tie: crosses itself */
            "f 6 1 2 3 4 5 5\n" /* repeated vertex */
            "f 1 2 3\n");
    TEST_ASSERT_EQUAL_UINT(4 + 3 + 4 + 3 + 5 + 1, obj.triangle_count);
    for (t = 0; t < 3 * obj.triangle_count; t++)
        TEST_ASSERT_TRUE(obj.indices[t] < 7);
}

static void test_large_degenerate_face_is_fast(void)
{
    /* 20000 points on a line and 20000 around a zigzag: the fallbacks must
     * not take quadratic turns per vertex. */
    size_t n = 20000, i, len = 0, cap = n * 64 + 64;
    char *text = (char *)malloc(cap);
    TEST_ASSERT_TRUE(text != NULL);
    for (i = 0; i < n; i++)
        len += (size_t)snprintf(text + len, cap - len, "v %lu %lu 0\n", (unsigned long)i,
                                (unsigned long)(i % 2));
    len += (size_t)snprintf(text + len, cap - len, "f");
    for (i = 0; i < n; i++)
        len += (size_t)snprintf(text + len, cap - len, " %lu", (unsigned long)(i + 1));
    len += (size_t)snprintf(text + len, cap - len, "\n");
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        ZL_OBJ_OK, zl_obj_load_mem(&obj, text, len, "t.obj", NULL, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(n - 2, obj.triangle_count);
    free(text);
}

static void test_vertex_colors(void)
{
    load_ok("v 0 0 0 1 0 0.5\nv 1 0 0 0 1 0.2\nv 0 1 0 -0.5 2 0.998\nf 1 2 3\n");
    TEST_ASSERT_NOT_NULL(obj.vertex_colors);
    TEST_ASSERT_EQUAL_UINT8(255, obj.vertex_colors[0]);
    TEST_ASSERT_EQUAL_UINT8(0, obj.vertex_colors[1]);
    TEST_ASSERT_EQUAL_UINT8(128, obj.vertex_colors[2]); /* 127.5 rounds up */
    TEST_ASSERT_EQUAL_UINT8(51, obj.vertex_colors[5]);
    TEST_ASSERT_EQUAL_UINT8(0, obj.vertex_colors[6]);   /* clamped */
    TEST_ASSERT_EQUAL_UINT8(255, obj.vertex_colors[7]); /* clamped */
    TEST_ASSERT_EQUAL_UINT8(254, obj.vertex_colors[8]);
    {
        zl_mesh m = zl_obj_mesh(&obj);
        TEST_ASSERT_TRUE(m.vertex_colors == obj.vertex_colors);
        TEST_ASSERT_EQUAL_UINT(3, m.vertex_count);
        TEST_ASSERT_EQUAL_UINT(1, m.triangle_count);
        TEST_ASSERT_NULL(m.face_colors);
    }
    zl_obj_free(&obj);
    /* Colours on some vertices only: none kept. */
    load_ok("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 1 1 1\nf 1 2 3\n");
    TEST_ASSERT_NULL(obj.vertex_colors);
    zl_obj_free(&obj);
    /* x y z w: the weight is read and ignored. */
    load_ok("v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 0.5\nf 1 2 3\n");
    TEST_ASSERT_NULL(obj.vertex_colors);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE, obj.positions[7]);
}

static void test_normalize(void)
{
    uint32_t i;
    load_text("v -1 10 100\nv 3 11 100.5\nv 1 12 101\nf 1 2 3\n", 1);
    TEST_ASSERT_EQUAL_STRING("", msg);
    /* extent x = 4 is the largest: scale 0.5, centre (1, 11, 100.5) */
    TEST_ASSERT_EQUAL_INT32(-ZL_FX_ONE, obj.positions[0]);
    TEST_ASSERT_EQUAL_INT32(-ZL_FX_ONE / 2, obj.positions[1]);
    TEST_ASSERT_EQUAL_INT32(-ZL_FX_ONE / 4, obj.positions[2]);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE, obj.positions[3]);
    TEST_ASSERT_EQUAL_INT32(0, obj.positions[4]);
    TEST_ASSERT_EQUAL_INT32(0, obj.positions[5]);
    TEST_ASSERT_EQUAL_INT32(0, obj.positions[6]);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE / 2, obj.positions[7]);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE / 4, obj.positions[8]);
    TEST_ASSERT_TRUE(obj.scale == 0.5);
    for (i = 0; i < 9; i++)
        TEST_ASSERT_TRUE(obj.positions[i] >= -ZL_FX_ONE && obj.positions[i] <= ZL_FX_ONE);
    zl_obj_free(&obj);
    /* Coordinates beyond Q16.16 load when normalised, fail when not. */
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, load_text("v 0 0 0\nv 1e6 0 0\nv 0 1e6 0\nf 1 2 3\n", 1));
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE, obj.positions[3]);
    zl_obj_free(&obj);
    check_error(load_text("v 0 0 0\nv 1e6 0 0\nv 0 1e6 0\nf 1 2 3\n", 0), ZL_OBJ_ERR_PARSE, 2,
                "Q16.16");
    /* One point only: it stays a point, at the origin. */
    zl_obj_free(&obj);
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, load_text("v 5 5 5\nf 1 1 1\n", 1));
    TEST_ASSERT_EQUAL_INT32(0, obj.positions[0]);
}

static void test_errors_statements_and_numbers(void)
{
    expect_error("v 0 0 0\nv 1 0 0\nfoo 1 2\n", 3, "unknown statement 'foo'");
    expect_error("v 0 0 0\nv 1 0 0\nV 1 2 3\n", 3, "unknown statement 'V'");
    expect_error("v 1 abc 3\n", 1, "'abc' is not a number");
    expect_error("v 1 2\nv 1 2 3\n", 1, "needs x y z");
    expect_error("# c\nv 1 2 3 foo\n", 2, "unexpected 'foo' after the vertex coordinates");
    expect_error("v 1 2 3,\n", 1, "'3,' is not a number");
    expect_error("v 1 2 3 4 5\n", 1, "this one has 5 numbers");
    expect_error("v 1 2 3 4 5 6 7\n", 1, "this one has 7 numbers");
    expect_error("v 1.2.3 0 0\n", 1, "not a number");
    expect_error("v 0x10 0 0\n", 1, "not a number");
    expect_error("v 1e 0 0\n", 1, "not a number");
    expect_error("\n\nv nan 0 0\n", 3, "'nan' is not a finite number");
    expect_error("v 0 -inf 0\n", 1, "'-inf' is not a finite number");
    expect_error("v 0 0 Infinity\n", 1, "not a finite number");
    expect_error("v 1e999 0 0\n", 1, "out of the range");
    expect_error("v 0 0 0 1 nan 0\n", 1, "not a finite number");
    expect_error("vt 0 0 0 0\n", 1, "vt");
    expect_error("vt\n", 1, "vt");
    expect_error("vn 0 1\n", 1, "normal (vn) has 3 numbers");
    expect_error("vn 0 x 1\n", 1, "'x' is not a number");
}

static void test_errors_faces(void)
{
    const char *v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    char text[256];
#define WITH(face) (snprintf(text, sizeof text, "%s%s", v3, face), text)
    expect_error(WITH("f 1 2 0\n"), 4, "index 0");
    expect_error(WITH("f 1 2 4\n"), 4,
                 "vertex index 4 in '4' is out of range: the file has 3 vertices");
    expect_error(WITH("f 1 2 99999999999999999999999\n"), 4, "out of range");
    expect_error(WITH("f -1 -2 -4\n"), 4, "relative vertex index -4");
    expect_error(WITH("f 1 2\n"), 4, "at least 3 vertices; this one has 2");
    expect_error(WITH("f\n"), 4, "this one has 0");
    expect_error(WITH("f 1 2 3 # 4\nf 1 2\n"), 5, "at least 3");
    expect_error(WITH("f 1 2 x\n"), 4, "'x' is not a face vertex");
    expect_error(WITH("f 1 2 3/\n"), 4, "'3/' is not a face vertex");
    expect_error(WITH("f 1 2 3//\n"), 4, "'3//' is not a face vertex");
    expect_error(WITH("f 1 2 /3\n"), 4, "'/3' is not a face vertex");
    expect_error(WITH("f 1 2 3/1/1/1\n"), 4, "not a face vertex");
    expect_error(WITH("f 1 2 3.0\n"), 4, "not a face vertex");
    expect_error(WITH("f 1/1 2/1 3/1\n"), 4, "texture coordinate index 1 in '1/1' is out of range");
    expect_error(WITH("vn 0 0 1\nf 1//1 2//2 3//1\n"), 5, "normal index 2");
    expect_error(WITH("vt 0 0\nf 1/-2 2/1 3/1\n"), 5, "relative texture coordinate index -2");
    expect_error(WITH("f 1 2 3\nf 1 2 5\n"), 5, "out of range");
#undef WITH
    /* Relative indices count only the vertices above the line. */
    expect_error("v 0 0 0\nf -1 -2 -3\nv 1 0 0\nv 0 1 0\n", 2, "1 vertex defined before");
}

static void test_errors_line_numbers_with_crlf(void)
{
    expect_error("v 0 0 0\r\nv 1 0 0\r\n\r\nv 0 1 0\r\nf 1 2 3\r\nf 1 2\r\n", 6, "at least 3");
    expect_error("# a\r\n# b\r\nv 0 0 0 junk", 3, "unexpected 'junk'");
}

static void test_errors_empty_and_no_faces(void)
{
    expect_error("", 1, "empty");
    expect_error("  \n\t\r\n\n", 1, "empty");
    expect_error("# only a comment\n# and another\n", 2, "no faces");
    expect_error("v 0 0 0\nv 1 0 0\nv 0 1 0", 3, "no faces");
    expect_error("\xEF\xBB\xBF", 1, "empty");
}

static void test_errors_encoding(void)
{
    static const char utf16le[] = "\xFF\xFEv\0 \0";
    static const char utf16be[] = "\xFE\xFF\0v\0 ";
    static const char nul[] = "v 0 0 0\nv 1 0 0\nv 0 \0 1 0\nf 1 2 3\n";
    expect_error_mem(utf16le, sizeof utf16le - 1, 1, "UTF-16");
    expect_error_mem(utf16be, sizeof utf16be - 1, 1, "UTF-16");
    expect_error_mem(nul, sizeof nul - 1, 3, "NUL byte");
    /* The statements the loader reads are ASCII; the byte and its line are named. */
    expect_error("v 0 0 0\nv caf\xE9 0 0\nf 1 1 1\n", 2, "byte 0xE9");
    expect_error("v 0 0 0\n\n\nf 1 1 1\xC3\n", 4, "must be ASCII");
    expect_error("v 0 0 0\n\xC3\xA9 1 2 3\n", 2, "byte 0xC3");
    /* Valid UTF-8 in comments and names is fine. */
    load_ok("# café ☕ 𝄞\ng grüße\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
}

/*
 * OBJ lexical rules (zl_obj.h): comments and the names of ignored statements
 * may hold any bytes but NUL (Latin-1 material names, as assimp's
 * regr01.obj); a backslash before a line end continues the line; a line may
 * end in LF, CR LF or a lone CR, and errors count lines by those ends.
 */
static void test_latin1_in_names_and_comments_is_ignored(void)
{
    load_ok("mtllib r\xE9gr.mtl\nusemtl Mat\xE9riau_\xC0\xFF\ng gr\xFC\xDF" "e\no \xA0\n# caf\xE9 \xC0\xAF \xED\xA0\x80\n"
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 # \xE9t\xE9\n");
    TEST_ASSERT_EQUAL_UINT32(3, obj.vertex_count);
    TEST_ASSERT_EQUAL_UINT32(1, obj.triangle_count);
}

static void test_backslash_continues_a_line(void)
{
    load_ok("v 0 0 \\\n0\nv 1 \\\r\n 0 0\nv 0 1 0\nf 1 \\\n 2 \\\n 3\n");
    TEST_ASSERT_EQUAL_UINT32(3, obj.vertex_count);
    TEST_ASSERT_EQUAL_UINT32(1, obj.triangle_count);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE, obj.positions[3]);
    assert_tri(0, 0, 1, 2);
    zl_obj_free(&obj);
    /* an error names the physical line where the statement starts, and
     * lines after a continuation keep their numbers */
    expect_error("v 0 0 0\nv 1 \\\n 0 0\nv 0 1 0 junk\nf 1 2 3\n", 4, "unexpected 'junk'");
    expect_error("v 0 0 \\\n 0 \\\n junk\n", 1, "unexpected 'junk'");
    /* a backslash inside a comment does not continue it */
    load_ok("# see C:\\\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    TEST_ASSERT_EQUAL_UINT32(3, obj.vertex_count);
}

static void test_cr_only_line_ends(void)
{
    load_ok("# classic Mac\rv 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 3\r");
    TEST_ASSERT_EQUAL_UINT32(3, obj.vertex_count);
    TEST_ASSERT_EQUAL_UINT32(1, obj.triangle_count);
    zl_obj_free(&obj);
    expect_error("v 0 0 0\rv 1 0 0\r\rv 0 1 0\rf 1 2 3\rf 1 2\r", 6, "at least 3");
    {
        static const char nul[] = "v 0 0 0\rv 1 0 0\n\r\nv 0 \0 1 0\r";
        expect_error_mem(nul, sizeof nul - 1, 4, "NUL byte");
    }
}

/*
 * Normalising extreme but valid boxes: a box below 1e-308 (denormal extents,
 * where 2 / extent is infinite) and coordinates near 1.7e308 (where
 * min + max overflows). Every position must be finite and in -1 .. 1 (the
 * Q16.16 of the exact answer, up to rounding); no float-to-integer
 * conversion may see NaN or infinity (clang's UBSan checks that in the
 * sanitize build).
 */
static void test_normalize_extreme_boxes(void)
{
    static const char *const files[] = {
        "v 1e-310 0 0\nv 3e-310 0 0\nv 2e-310 1e-310 0\nf 1 2 3\n",
        "v 4.9e-324 0 0\nv 1e-323 0 0\nv 0 4.9e-324 0\nf 1 2 3\n",
        "v 1.7e308 0 0\nv 1.6e308 1e307 0\nv 1.65e308 0 1e307\nf 1 2 3\n",
        "v -1.7e308 1.7e308 0\nv 1.7e308 -1.7e308 0\nv 0 0 1.7e308\nf 1 2 3\n",
        ("v 1.7976931348623157e308 1.7976931348623157e308 1.7976931348623157e308\n"
         "v -1.7976931348623157e308 -1.7976931348623157e308 -1.7976931348623157e308\nv 0 0 0\nf 1 2 3\n"),
    };
    unsigned f, i;
    for (f = 0; f < sizeof files / sizeof files[0]; f++) {
        TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, load_text(files[f], 1), msg);
        for (i = 0; i < 9; i++)
            TEST_ASSERT_TRUE(obj.positions[i] >= -ZL_FX_ONE && obj.positions[i] <= ZL_FX_ONE);
        TEST_ASSERT_TRUE(isfinite(obj.center[0]) && isfinite(obj.center[1]) && isfinite(obj.center[2]));
        zl_obj_free(&obj);
    }
    /* the denormal triangle keeps its shape: x -1, 1, 0 and y -1, -1, 1 */
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, load_text(files[0], 1));
    TEST_ASSERT_EQUAL_INT32(-ZL_FX_ONE, obj.positions[0]);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE, obj.positions[3]);
    TEST_ASSERT_EQUAL_INT32(0, obj.positions[6]);
    TEST_ASSERT_EQUAL_INT32(-ZL_FX_ONE / 2, obj.positions[1]);
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE / 2, obj.positions[7]);
    zl_obj_free(&obj);
    /* the box spanning the whole double range: the corners are -1 and 1, the origin 0 */
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, load_text(files[4], 1));
    TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE, obj.positions[0]);
    TEST_ASSERT_EQUAL_INT32(-ZL_FX_ONE, obj.positions[3]);
    TEST_ASSERT_EQUAL_INT32(0, obj.positions[6]);
}

/* n statements "prefix" after three vertices, as one text. */
static char *repeat_lines(const char *head, const char *line, size_t n, size_t *len)
{
    size_t hl = strlen(head), ll = strlen(line), i;
    char *text = (char *)malloc(hl + n * ll + 1);
    TEST_ASSERT_TRUE(text != NULL);
    memcpy(text, head, hl);
    for (i = 0; i < n; i++)
        memcpy(text + hl + i * ll, line, ll);
    *len = hl + n * ll;
    text[*len] = '\0';
    return text;
}

static void test_errors_limits(void)
{
    size_t len;
    char *text;
    zl_obj_status st;
    /* 65535 vertices load; the 65536th is an error on its own line. */
    text = repeat_lines("f 1 2 3\n", "v 1 2 3\n", 65535, &len);
    st = zl_obj_load_mem(&obj, text, len, "t.obj", NULL, msg, sizeof msg);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, st, msg);
    TEST_ASSERT_EQUAL_UINT(65535, obj.vertex_count);
    zl_obj_free(&obj);
    free(text);
    text = repeat_lines("f 1 2 3\n", "v 1 2 3\n", 65536, &len);
    st = zl_obj_load_mem(&obj, text, len, "t.obj", NULL, msg, sizeof msg);
    check_error(st, ZL_OBJ_ERR_LIMIT, 65537, "more than 65535 vertices");
    free(text);
    /* Triangles: 65535 load, one more fails on its face's line. */
    text = repeat_lines("v 0 0 0\nv 1 0 0\nv 0 1 0\n", "f 1 2 3\n", 65535, &len);
    st = zl_obj_load_mem(&obj, text, len, "t.obj", NULL, msg, sizeof msg);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, st, msg);
    TEST_ASSERT_EQUAL_UINT(65535, obj.triangle_count);
    {
        zl_mesh m = zl_obj_mesh(&obj);
        TEST_ASSERT_EQUAL_UINT(65535, m.triangle_count);
    }
    zl_obj_free(&obj);
    free(text);
    text = repeat_lines("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n", "f 1 2 3 4\n", 32768, &len);
    st = zl_obj_load_mem(&obj, text, len, "t.obj", NULL, msg, sizeof msg);
    check_error(st, ZL_OBJ_ERR_LIMIT, 4 + 32768, "more than 65535 triangles");
    free(text);
}

static void test_file_errors(void)
{
    zl_obj_status st = zl_obj_load_file(&obj, "/nonexistent/dir/x.obj", NULL, msg, sizeof msg);
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_IO, st);
    TEST_ASSERT_NOT_NULL(strstr(msg, "/nonexistent/dir/x.obj"));
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_ARG, zl_obj_load_file(NULL, "x", NULL, msg, sizeof msg));
    /* A tiny message buffer is still terminated. */
    {
        char small[8];
        TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_PARSE,
                              zl_obj_load_mem(&obj, "f 1", 3, "t.obj", NULL, small, sizeof small));
        TEST_ASSERT_EQUAL_UINT(7, strlen(small));
    }
    /* No message buffer at all. */
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_PARSE,
                          zl_obj_load_mem(&obj, "f 1", 3, "t.obj", NULL, NULL, 0));
}

/* ------------------------------------------------------- the real models */

typedef struct {
    const char *file;
    uint32_t vertices, triangles;
    int colors;
} model_info;

static void load_model(const char *dir, const model_info *m, int normalize)
{
    char path[1024];
    zl_obj_options opt;
    uint32_t i;
    opt.normalize = normalize;
    snprintf(path, sizeof path, "%s/%s", dir, m->file);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, zl_obj_load_file(&obj, path, &opt, msg, sizeof msg),
                                  msg);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(m->vertices, obj.vertex_count, m->file);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(m->triangles, obj.triangle_count, m->file);
    TEST_ASSERT_TRUE_MESSAGE((obj.vertex_colors != NULL) == m->colors, m->file);
    for (i = 0; i < 3 * obj.triangle_count; i++)
        TEST_ASSERT_TRUE(obj.indices[i] < obj.vertex_count);
    if (normalize) {
        /* largest extent 2, centred */
        zl_fixed lo[3] = {ZL_FX_MAX, ZL_FX_MAX, ZL_FX_MAX},
                 hi[3] = {ZL_FX_MIN, ZL_FX_MIN, ZL_FX_MIN};
        zl_fixed ext = 0;
        int j;
        for (i = 0; i < obj.vertex_count; i++)
            for (j = 0; j < 3; j++) {
                zl_fixed c = obj.positions[3 * i + j];
                lo[j] = c < lo[j] ? c : lo[j];
                hi[j] = c > hi[j] ? c : hi[j];
            }
        for (j = 0; j < 3; j++) {
            TEST_ASSERT_INT_WITHIN(1, 0, lo[j] + hi[j]);
            if (hi[j] - lo[j] > ext)
                ext = hi[j] - lo[j];
        }
        TEST_ASSERT_INT_WITHIN(1, 2 * ZL_FX_ONE, ext);
    }
    zl_obj_free(&obj);
}

static const model_info shared_models[] = {
    {"bunny.obj", 1839, 3674, 0},
    {"spider.obj", 762, 1368, 0},
    {"box.obj", 8, 12, 0},
    {"cube_with_vertexcolors.obj", 8, 12, 1},
    {"concave_polygon.obj", 64, 64, 0},
};

static void test_shared_models_load(void)
{
    char dir[1024];
    FILE *probe;
    size_t i;
    snprintf(dir, sizeof dir, "%s/models", ZLINE_SHARED_DIR);
    {
        char readme[1100];
        snprintf(readme, sizeof readme, "%s/README.md", dir);
        probe = fopen(readme, "rb");
    }
    if (probe == NULL) {
        TEST_IGNORE_MESSAGE("the shared models folder (ZLINE_SHARED_DIR/models) is absent");
        return;
    }
    fclose(probe);
    for (i = 0; i < sizeof shared_models / sizeof shared_models[0]; i++) {
        load_model(dir, &shared_models[i], 0);
        load_model(dir, &shared_models[i], 1);
    }
#ifndef _WIN32
    {
        /* Every .obj there, including any added later, loads normalised. */
        DIR *d = opendir(dir);
        struct dirent *e;
        unsigned count = 0;
        TEST_ASSERT_TRUE(d != NULL);
        while ((e = readdir(d)) != NULL) {
            size_t n = strlen(e->d_name);
            char file[1400];
            zl_obj_options opt;
            if (n < 5 || strcmp(e->d_name + n - 4, ".obj") != 0)
                continue;
            snprintf(file, sizeof file, "%s/%s", dir, e->d_name);
            opt.normalize = 1;
            if (zl_obj_load_file(&obj, file, &opt, msg, sizeof msg) != ZL_OBJ_OK) {
                closedir(d);
                TEST_FAIL_MESSAGE(msg);
            }
            TEST_ASSERT_TRUE_MESSAGE(obj.triangle_count > 0, e->d_name);
            zl_obj_free(&obj);
            count++;
        }
        closedir(d);
        TEST_ASSERT_TRUE(count >= sizeof shared_models / sizeof shared_models[0]);
    }
#endif
}

static void test_cube_vertex_colors_values(void)
{
    char path[1024];
    FILE *probe;
    snprintf(path, sizeof path, "%s/models/cube_with_vertexcolors.obj", ZLINE_SHARED_DIR);
    probe = fopen(path, "rb");
    if (probe == NULL) {
        TEST_IGNORE_MESSAGE("shared/models/cube_with_vertexcolors.obj not found");
        return;
    }
    fclose(probe);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, zl_obj_load_file(&obj, path, NULL, msg, sizeof msg),
                                  msg);
    TEST_ASSERT_NOT_NULL(obj.vertex_colors);
    /* v 0 0 0 0.48627 0.43137 0.47059 -> 124 110 120 */
    TEST_ASSERT_EQUAL_UINT8(124, obj.vertex_colors[0]);
    TEST_ASSERT_EQUAL_UINT8(110, obj.vertex_colors[1]);
    TEST_ASSERT_EQUAL_UINT8(120, obj.vertex_colors[2]);
    /* v 1 1 1 0.09020 0 0.78431 -> 23 0 200 */
    TEST_ASSERT_EQUAL_UINT8(23, obj.vertex_colors[21]);
    TEST_ASSERT_EQUAL_UINT8(0, obj.vertex_colors[22]);
    TEST_ASSERT_EQUAL_UINT8(200, obj.vertex_colors[23]);
}

static void test_bundled_bunny(void)
{
    /* The copy shipped with the port is always there. */
    static const model_info bunny = {"bunny.obj", 1839, 3674, 0};
    load_model(ZLINE_SOURCE_DIR "/port/host/models", &bunny, 1);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_face_entry_formats);
    RUN_TEST(test_face_mixing_forms_is_an_error);
    RUN_TEST(test_negative_indices);
    RUN_TEST(test_forward_reference);
    RUN_TEST(test_crlf_comments_and_ignored_statements);
    RUN_TEST(test_rounding_to_q16);
    RUN_TEST(test_quad);
    RUN_TEST(test_concave_polygons_by_hand);
    RUN_TEST(test_polygon_winding_kept_in_every_plane);
    RUN_TEST(test_concave_polygon_model);
    RUN_TEST(test_polygon_with_hole_by_seam);
    RUN_TEST(test_comb);
    RUN_TEST(test_random_star_polygons);
    RUN_TEST(test_degenerate_faces_end);
    RUN_TEST(test_large_degenerate_face_is_fast);
    RUN_TEST(test_vertex_colors);
    RUN_TEST(test_normalize);
    RUN_TEST(test_errors_statements_and_numbers);
    RUN_TEST(test_errors_faces);
    RUN_TEST(test_errors_line_numbers_with_crlf);
    RUN_TEST(test_errors_empty_and_no_faces);
    RUN_TEST(test_errors_encoding);
    RUN_TEST(test_latin1_in_names_and_comments_is_ignored);
    RUN_TEST(test_backslash_continues_a_line);
    RUN_TEST(test_cr_only_line_ends);
    RUN_TEST(test_normalize_extreme_boxes);
    RUN_TEST(test_errors_limits);
    RUN_TEST(test_file_errors);
    RUN_TEST(test_shared_models_load);
    RUN_TEST(test_cube_vertex_colors_values);
    RUN_TEST(test_bundled_bunny);
    return UNITY_END();
}

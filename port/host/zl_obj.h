/* SPDX-License-Identifier: MIT */
/*
 * Wavefront OBJ loader for the host port: reads a text OBJ file into heap
 * arrays that a core zl_mesh can point at.
 *
 * Accepted statements:
 *   v x y z [w]          a vertex (w, a rational weight, is read and ignored)
 *   v x y z r g b        a vertex with a colour, each channel 0..1 (clamped),
 *                        stored as round(c * 255); the colours are kept only
 *                        when every vertex of the file has one
 *   f a b c ...          a face of 3 or more vertices, each written as v,
 *                        v/vt, v//vn or v/vt/vn; negative indices count back
 *                        from the last vertex defined before the line;
 *                        positive ones may refer to vertices defined later
 *   vt u [v [w]]         a texture coordinate; with the *_tex loaders kept
 *                        when faces refer to it: the model then gets
 *                        texcoords (s = u, t = 1 - v,
 *                        Q16.16, 2 per vertex), and a vertex used with
 *                        different vt is split into one vertex per pair
 *   vn                   a normal (3 finite numbers); when faces refer to
 *                        normals (v//vn, v/vt/vn) the model gets normals:
 *                        per vertex, the normalised sum of the unit vn of
 *                        its face corners, Q14 (16384 = 1.0); vertices are
 *                        not split by vn (a hard edge is smoothed), and a
 *                        vertex no corner gives a vn gets (0, 0, 0)
 *   g o s usemtl mtllib l p and the free-form geometry statements
 *                        ignored
 *   # ...                a comment, at the start of a line or after data
 *
 * Lexical rules (issue 16):
 *   line ends    LF, CR LF or a lone CR (classic Mac OS files); the last line
 *                needs no line end; error line numbers count these ends
 *   continuation a backslash right before a line end joins the next line
 *                (the OBJ specification's rule), except inside a comment;
 *                an error names the line the statement starts on
 *   encoding     a UTF-8 byte order mark is skipped; a UTF-16 byte order
 *                mark or a NUL byte is an error. Comments and the arguments
 *                of ignored statements (names in g, o, usemtl, mtllib, ...)
 *                may hold any other bytes: the loader never reads them, so
 *                Latin-1 names (assimp's regr01.obj) load. The statements it
 *                reads (v, vt, vn, f, and a statement's keyword) must be
 *                ASCII: another byte is an error naming it and its line.
 *
 * Faces of more than three vertices are triangulated by ear clipping in the
 * plane of the polygon's dominant normal axis (Newell normal), which is
 * correct for concave polygons, including polygons whose outline touches
 * itself (a hole joined to the outside by a seam). Each face of n vertices
 * gives exactly n - 2 triangles, wound like the face. A face on which no ear
 * can be found (self-intersecting, collinear or repeated points) is finished
 * by a bounded fallback that still gives n - 2 triangles, some of them
 * possibly zero-area (the rasteriser draws nothing for those).
 *
 * Every malformed input is an error with a message "FILE:LINE: what is
 * wrong": a statement that is not OBJ, a number that is not one, a NaN or
 * infinite value, an index of 0 or one that refers to no vertex (or texture
 * coordinate or normal), a face of fewer than three vertices, anything
 * after the numbers of a v line, more than 65535 vertices or triangles (the
 * limit of zl_mesh), a file with no faces, and a file that is not text (a
 * UTF-16 byte order mark, NUL bytes) or has a non-ASCII byte in a statement
 * the loader reads.
 *
 * Floating point is used here, on the host, only to parse the file: positions
 * become Q16.16 (rounded to nearest, ties up) before they leave the loader.
 */
#ifndef ZL_OBJ_H
#define ZL_OBJ_H

#include <stddef.h>
#include <stdint.h>

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The most vertices and triangles a zl_mesh can hold (uint16 counts). */
#define ZL_OBJ_MAX_VERTICES 65535u
#define ZL_OBJ_MAX_TRIANGLES 65535u

typedef enum {
    ZL_OBJ_OK = 0,
    ZL_OBJ_ERR_IO = -1,     /* the file cannot be opened or read */
    ZL_OBJ_ERR_PARSE = -2,  /* malformed input; the message says FILE:LINE: what */
    ZL_OBJ_ERR_LIMIT = -3,  /* more vertices or triangles than a zl_mesh holds */
    ZL_OBJ_ERR_MEMORY = -4, /* out of memory */
    ZL_OBJ_ERR_ARG = -5     /* a NULL argument */
} zl_obj_status;

typedef struct {
    /*
     * Non-zero: centre the bounding box of all vertices on the origin and
     * scale uniformly so that its largest extent is 2.0 (the benchmark
     * scene's convention). Done in double before the conversion to Q16.16,
     * and finite for every valid file: boxes below 1e-308 (denormal) and
     * coordinates near DBL_MAX (whose sum overflows) give positions in
     * -1 .. 1 like any other (tests/host/test_obj.c,
     * test_normalize_extreme_boxes).
     * Zero: coordinates are taken as they are and must lie in the Q16.16
     * range -32768 .. 32767.99998 (else a FILE:LINE error).
     */
    int normalize;
} zl_obj_options;

/* A loaded model. Arrays are heap-allocated and owned by the struct. */
typedef struct {
    zl_fixed *positions;     /* 3 per vertex, Q16.16 */
    uint16_t *indices;       /* 3 per triangle */
    uint8_t *vertex_colors;  /* 3 per vertex (r, g, b), or NULL */
    zl_fixed *texcoords;     /* 2 per vertex (s, t), Q16.16, or NULL when no face uses vt */
    int16_t *normals;        /* 3 per vertex, Q14 unit vectors, or NULL when no face uses vn
                                (zl_obj_compute_normals makes them); for zl_light_vertices */
    uint32_t vertex_count;   /* <= ZL_OBJ_MAX_VERTICES */
    uint32_t triangle_count; /* <= ZL_OBJ_MAX_TRIANGLES */
    uint32_t face_count;     /* f lines */
    /* Bounding box of the vertices as written in the file, and the map
     * applied to them: stored = (file - center) * scale (identity when not
     * normalising). */
    double bbox_min[3], bbox_max[3];
    double center[3];
    double scale;
} zl_obj;

/* Fill *opt with the defaults: no normalisation. */
void zl_obj_options_default(zl_obj_options *opt);

/*
 * Load the OBJ file at path. On success *obj owns its arrays (release them
 * with zl_obj_free). On failure *obj is left empty (nothing to free) and, when
 * msg is not NULL, msg receives a NUL-terminated message of at most msg_size
 * bytes: "path:line: what is wrong" for malformed input. opt may be NULL
 * (the defaults).
 */
zl_obj_status zl_obj_load_file(zl_obj *obj, const char *path, const zl_obj_options *opt, char *msg,
                               size_t msg_size);

/* The same for OBJ text already in memory (size bytes, need not end in NUL);
 * name stands for the file name in messages. */
zl_obj_status zl_obj_load_mem(zl_obj *obj, const char *data, size_t size, const char *name,
                              const zl_obj_options *opt, char *msg, size_t msg_size);

/* The same two loaders keeping texture coordinates: texcoords gets 2 per
 * vertex when faces use vt, and a vertex used with different vt is split into
 * one vertex per (position, vt) pair (positions and colours copied; the
 * corners of a face without vt get (0, 0)). Every corner of a face has a vt or
 * none has, the same for vn (ZL_OBJ_ERR_PARSE otherwise), and u and 1 - v of
 * every vt must fit Q16.16 (ZL_OBJ_ERR_LIMIT). The plain loaders never split
 * vertices. */
zl_obj_status zl_obj_load_file_tex(zl_obj *obj, const char *path, const zl_obj_options *opt, char *msg,
                                   size_t msg_size);
zl_obj_status zl_obj_load_mem_tex(zl_obj *obj, const char *data, size_t size, const char *name,
                                  const zl_obj_options *opt, char *msg, size_t msg_size);

/*
 * Compute per-vertex normals from the triangles (replacing any from vn):
 * each triangle adds its normal to its three vertices, weighted by its area
 * (ZL_OBJ_NORMALS_AREA: the plain cross product) or by the angle of the
 * triangle at that vertex (ZL_OBJ_NORMALS_ANGLE: the unit normal times the
 * angle, Thurmer and Wuthrich 1998, which does not depend on how a face was
 * triangulated). Vertices at the same position share the sum (no seam where
 * a vertex was split by vt). The sum is normalised to Q14; a vertex of
 * zero-area triangles only gets (0, 0, 0). ZL_OBJ_ERR_ARG or
 * ZL_OBJ_ERR_MEMORY on failure (obj unchanged).
 */
typedef enum { ZL_OBJ_NORMALS_AREA = 0, ZL_OBJ_NORMALS_ANGLE = 1 } zl_obj_normal_weight;
zl_obj_status zl_obj_compute_normals(zl_obj *obj, zl_obj_normal_weight weight);

/* Release the arrays and empty *obj. Safe on an empty or failed zl_obj. */
void zl_obj_free(zl_obj *obj);

/* A zl_mesh viewing the arrays of obj (no copy; valid while obj lives).
 * face_colors is NULL. */
zl_mesh zl_obj_mesh(const zl_obj *obj);

/* A short English name of a status, for messages. */
const char *zl_obj_status_name(zl_obj_status s);

#ifdef __cplusplus
}
#endif

#endif /* ZL_OBJ_H */

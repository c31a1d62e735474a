/* SPDX-License-Identifier: MIT */
/*
 * zline-obj2c: turn a Wavefront OBJ into a C source of const arrays for
 * firmware, plus its header. The model is read by the host port's loader
 * (port/host/zl_obj.h), so the arrays are exactly what zl_obj_load_file gives:
 *
 *   const zl_fixed NAME_positions[3 * NAME_VERTEX_COUNT];    Q16.16, x y z
 *   const uint16_t NAME_indices[3 * NAME_TRIANGLE_COUNT];
 *   const uint8_t  NAME_vertex_colors[3 * NAME_VERTEX_COUNT]; only when the OBJ
 *                  has a colour on every vertex (v x y z r g b) and
 *                  --no-colors is not given; NAME_HAS_VERTEX_COLORS says which
 *   const int16_t  NAME_normals[3 * NAME_VERTEX_COUNT];       only with --normals:
 *                  unit vectors, Q14 (16384 = 1.0), for zl_light_vertices;
 *                  NAME_HAS_NORMALS says whether they are there
 *   const zl_fixed NAME_texcoords[2 * NAME_VERTEX_COUNT];    only when faces use
 *                  vt and --no-texcoords is not given: s, t per vertex,
 *                  Q16.16 (s = u, t = 1 - v), for zl_style.texcoords; a
 *                  vertex used with different vt is split (zl_obj_load_file_tex);
 *                  NAME_HAS_TEXCOORDS says which
 *   const zl_mesh  NAME_mesh;                                 views the arrays
 *
 * All const, so on a microcontroller they stay in flash.
 *
 *   zline-obj2c [--normalize] [--no-colors] [--no-texcoords] [--normals MODE] [--name NAME] IN.obj OUT.c OUT.h
 *
 * --normalize  centre the bounding box on the origin and scale it to a
 *              largest extent of 2.0 (the benchmark scene's convention)
 * --normals MODE  emit per-vertex normals: "file" the OBJ's vn (an error
 *              when no face has one), "area" or "angle" computed from the
 *              triangles, weighted by area or by corner angle
 *              (zl_obj_compute_normals), "auto" the OBJ's vn when it has
 *              them, else area-weighted; the C file's comment says which
 * --name NAME  prefix of the symbols, a C identifier (default: the OBJ's
 *              file name without extension, non-identifier characters as _)
 * Exit status 0 on success, 1 on a bad model or output error, 2 on usage.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "c_symbol.h"
#include "zl_output.h"
#include "zl_obj.h"

static void usage(void)
{
    fprintf(stderr, "usage: zline-obj2c [--normalize] [--no-colors] [--no-texcoords] [--normals file|area|angle|auto] "
                    "[--name NAME] IN.obj OUT.c OUT.h\n");
    exit(2);
}

/* A Q16.16 value as a C constant expression of type int32_t (INT32_MIN has
 * no literal: 2147483648 does not fit an int). */
static void put_fixed(FILE *f, zl_fixed v)
{
    if (v == INT32_MIN)
        fputs("(-2147483647 - 1)", f);
    else
        fprintf(f, "%ld", (long)v);
}

int main(int argc, char **argv)
{
    zl_obj_options opt;
    zl_obj obj;
    char msg[512], guard[160];
    zt_symbol sym;
    const char *name, *upper;
    const char *in, *out_c, *out_h, *given_name = NULL;
    int colors_wanted = 1, has_colors, tex_wanted = 1, has_tex, i;
    const char *normals_mode = NULL, *normals_from = NULL;
    uint32_t k, n;
    FILE *fc, *fh;
    zl_output out[2]; /* the header, the source */

    zl_obj_options_default(&opt);
    for (i = 1; i < argc && argv[i][0] == '-' && argv[i][1] == '-'; i++) {
        if (strcmp(argv[i], "--normalize") == 0)
            opt.normalize = 1;
        else if (strcmp(argv[i], "--no-colors") == 0)
            colors_wanted = 0;
        else if (strcmp(argv[i], "--normals") == 0 && i + 1 < argc && normals_mode == NULL)
            normals_mode = argv[++i];
        else if (strcmp(argv[i], "--no-texcoords") == 0)
            tex_wanted = 0;
        else if (strcmp(argv[i], "--name") == 0 && i + 1 < argc)
            given_name = argv[++i];
        else
            usage();
    }
    if (argc - i != 3)
        usage();
    if (normals_mode != NULL && strcmp(normals_mode, "file") != 0 && strcmp(normals_mode, "area") != 0 &&
        strcmp(normals_mode, "angle") != 0 && strcmp(normals_mode, "auto") != 0)
        usage();
    in = argv[i];
    out_c = argv[i + 1];
    out_h = argv[i + 2];
    {
        const char *outs[2], *ins[2] = {in, NULL};
        outs[0] = out_c;
        outs[1] = out_h;
        if (zl_output_check(outs, 2, ins, 2, msg, sizeof msg) != 0) {
            fprintf(stderr, "zline-obj2c: %s\n", msg);
            return 2;
        }
    }
    if (zt_symbol_make(&sym, given_name, in, 'm') != 0) {
            fprintf(stderr, "zline-obj2c: --name '%s' is not a C identifier (or too long)\n", given_name);
        return 2;
    }
    name = sym.name;
    upper = sym.upper;
    sprintf(guard, "%s_MESH_H", upper);

    if ((tex_wanted ? zl_obj_load_file_tex(&obj, in, &opt, msg, sizeof msg)
                    : zl_obj_load_file(&obj, in, &opt, msg, sizeof msg)) != ZL_OBJ_OK) {
        fprintf(stderr, "zline-obj2c: %s\n", msg);
        return 1;
    }
    has_colors = colors_wanted && obj.vertex_colors != NULL;
    if (normals_mode != NULL) {
        int want_file = strcmp(normals_mode, "file") == 0;
        if (want_file && obj.normals == NULL) {
            fprintf(stderr, "zline-obj2c: %s: --normals file, but no face refers to a normal (vn)\n", in);
            zl_obj_free(&obj);
            return 1;
        }
        if (want_file || (strcmp(normals_mode, "auto") == 0 && obj.normals != NULL)) {
            normals_from = "the OBJ's vn (normalised sum per vertex)";
        } else {
            int angle = strcmp(normals_mode, "angle") == 0;
            if (zl_obj_compute_normals(&obj, angle ? ZL_OBJ_NORMALS_ANGLE : ZL_OBJ_NORMALS_AREA) != ZL_OBJ_OK) {
                fprintf(stderr, "zline-obj2c: out of memory computing normals\n");
                zl_obj_free(&obj);
                return 1;
            }
            normals_from = angle ? "computed, angle-weighted" : "computed, area-weighted";
        }
    }
    has_tex = tex_wanted && obj.texcoords != NULL;

    memset(out, 0, sizeof out);
    /* Both outputs go to temporary files renamed only when both are
     * complete; a failure leaves the previous files as they were. */
    if (zl_output_open(&out[0], out_h, 0, msg, sizeof msg) != 0 ||
        zl_output_open(&out[1], out_c, 0, msg, sizeof msg) != 0) {
        fprintf(stderr, "zline-obj2c: %s\n", msg);
        zl_output_discard(&out[0]);
        zl_obj_free(&obj);
        return 1;
    }
    fh = out[0].file;
    fc = out[1].file;

    fprintf(fh, "/* Generated by zline-obj2c from %s: do not edit. */\n", zt_base_name(in));
    fprintf(fh, "#ifndef %s\n#define %s\n\n#include <stdint.h>\n\n#include \"zline/zline.h\"\n\n", guard, guard);
    fprintf(fh, "#define %s_VERTEX_COUNT %luu\n", upper, (unsigned long)obj.vertex_count);
    fprintf(fh, "#define %s_TRIANGLE_COUNT %luu\n", upper, (unsigned long)obj.triangle_count);
    fprintf(fh, "#define %s_HAS_VERTEX_COLORS %d\n", upper, has_colors);
    if (normals_from != NULL)
        fprintf(fh, "#define %s_HAS_NORMALS 1\n", upper);
    fprintf(fh, "#define %s_HAS_TEXCOORDS %d\n\n", upper, has_tex);
    fprintf(fh, "/* x, y, z per vertex, Q16.16%s */\n", opt.normalize ?
            " (bounding box centred on the origin, largest extent 2.0)" : "");
    fprintf(fh, "extern const zl_fixed %s_positions[3 * %s_VERTEX_COUNT];\n", name, upper);
    fprintf(fh, "/* 3 vertex indices per triangle, wound as in the OBJ */\n");
    fprintf(fh, "extern const uint16_t %s_indices[3 * %s_TRIANGLE_COUNT];\n", name, upper);
    if (has_colors) {
        fprintf(fh, "/* r, g, b per vertex, 0..255 */\n");
        fprintf(fh, "extern const uint8_t %s_vertex_colors[3 * %s_VERTEX_COUNT];\n", name, upper);
    }
    if (normals_from != NULL) {
        fprintf(fh, "/* normal x, y, z per vertex, Q14 unit vectors (16384 = 1.0), %s */\n", normals_from);
        fprintf(fh, "extern const int16_t %s_normals[3 * %s_VERTEX_COUNT];\n", name, upper);
    }
    if (has_tex) {
        fprintf(fh, "/* s, t per vertex, Q16.16 (1.0 = the texture's size), for zl_style.texcoords */\n");
        fprintf(fh, "extern const zl_fixed %s_texcoords[2 * %s_VERTEX_COUNT];\n", name, upper);
    }
    fprintf(fh, "/* A mesh viewing the arrays (no face colours). */\n");
    fprintf(fh, "extern const zl_mesh %s_mesh;\n\n#endif\n", name);

    fprintf(fc, "/* Generated by zline-obj2c from %s: %lu vertices, %lu triangles. Do not edit. */\n",
            zt_base_name(in), (unsigned long)obj.vertex_count, (unsigned long)obj.triangle_count);
    fprintf(fc, "#include \"%s\"\n\n", zt_base_name(out_h));
    fprintf(fc, "const zl_fixed %s_positions[3 * %s_VERTEX_COUNT] = {\n", name, upper);
    for (k = 0; k < obj.vertex_count; k++) {
        fputs("    ", fc);
        put_fixed(fc, obj.positions[3 * k]);
        fputs(", ", fc);
        put_fixed(fc, obj.positions[3 * k + 1]);
        fputs(", ", fc);
        put_fixed(fc, obj.positions[3 * k + 2]);
        fputs(",\n", fc);
    }
    fprintf(fc, "};\n\nconst uint16_t %s_indices[3 * %s_TRIANGLE_COUNT] = {\n", name, upper);
    n = 3 * obj.triangle_count;
    for (k = 0; k < n; k += 3)
        fprintf(fc, "    %u, %u, %u,\n", obj.indices[k], obj.indices[k + 1], obj.indices[k + 2]);
    fputs("};\n", fc);
    if (has_colors) {
        fprintf(fc, "\nconst uint8_t %s_vertex_colors[3 * %s_VERTEX_COUNT] = {\n", name, upper);
        for (k = 0; k < obj.vertex_count; k++)
            fprintf(fc, "    %u, %u, %u,\n", obj.vertex_colors[3 * k], obj.vertex_colors[3 * k + 1],
                    obj.vertex_colors[3 * k + 2]);
        fputs("};\n", fc);
    }
    if (normals_from != NULL) {
        fprintf(fc, "\n/* normals: %s */\n", normals_from);
        fprintf(fc, "const int16_t %s_normals[3 * %s_VERTEX_COUNT] = {\n", name, upper);
        for (k = 0; k < obj.vertex_count; k++)
            fprintf(fc, "    %d, %d, %d,\n", obj.normals[3 * k], obj.normals[3 * k + 1], obj.normals[3 * k + 2]);
        fputs("};\n", fc);
    }
    if (has_tex) {
        fprintf(fc, "\nconst zl_fixed %s_texcoords[2 * %s_VERTEX_COUNT] = {\n", name, upper);
        for (k = 0; k < obj.vertex_count; k++) {
            fputs("    ", fc);
            put_fixed(fc, obj.texcoords[2 * k]);
            fputs(", ", fc);
            put_fixed(fc, obj.texcoords[2 * k + 1]);
            fputs(",\n", fc);
        }
        fputs("};\n", fc);
    }
    fprintf(fc, "\nconst zl_mesh %s_mesh = {\n    .positions = %s_positions,\n    .indices = %s_indices,\n",
            name, name, name);
    if (has_colors)
        fprintf(fc, "    .vertex_colors = %s_vertex_colors,\n", name);
    fprintf(fc, "    .vertex_count = %s_VERTEX_COUNT,\n    .triangle_count = %s_TRIANGLE_COUNT,\n};\n", upper, upper);
    zl_obj_free(&obj);
    if (zl_output_commit_all(out, 2, msg, sizeof msg) != 0) {
        fprintf(stderr, "zline-obj2c: %s\n", msg);
        return 1;
    }
    return 0;
}

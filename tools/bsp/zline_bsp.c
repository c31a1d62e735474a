/* SPDX-License-Identifier: MIT */
/*
 * zline-bsp: build a BSP tree from an OBJ file offline and write it as const
 * C arrays for firmware (a `const zl_bsp NAME` to pass to zl_bsp_draw).
 *
 *   zline-bsp [--normalize] [--candidates N] MODEL.obj OUT.c NAME
 *
 * --normalize centres the model and scales its largest extent to 2.0 (the
 * benchmark scene's convention, as zl_obj's option). Prints the tree's
 * statistics. See bsp_build.h for the method.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bsp_build.h"
#include "zl_obj.h"
#include "zl_output.h"

/* The tree to path through a temporary file (the output rule, zl_output.h). */
static int write_tree(const bsp_tree *t, const char *path, const char *name)
{
    zl_output out;
    char msg[512];
    if (zl_output_open(&out, path, 0, msg, sizeof msg) != 0 || bsp_write_c(t, out.file, name) != 0 ||
        zl_output_commit(&out, msg, sizeof msg) != 0) {
        if (out.file != NULL)
            snprintf(msg, sizeof msg, "%s: write error", path);
        zl_output_discard(&out);
        fprintf(stderr, "zline-bsp: %s\n", msg);
        return -1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    zl_obj_options oo;
    bsp_options bo;
    zl_obj obj;
    bsp_tree t;
    char msg[512];
    int i = 1;
    zl_obj_options_default(&oo);
    bsp_options_default(&bo);
    for (; i < argc && strncmp(argv[i], "--", 2) == 0; i++) {
        if (strcmp(argv[i], "--normalize") == 0)
            oo.normalize = 1;
        else if (strcmp(argv[i], "--candidates") == 0 && i + 1 < argc)
            bo.candidates = atoi(argv[++i]);
        else
            break;
    }
    if (argc - i != 3 || bo.candidates < 1) {
        fprintf(stderr, "usage: %s [--normalize] [--candidates N] MODEL.obj OUT.c NAME\n", argv[0]);
        return 2;
    }
    {
        const char *outs[1], *ins[1];
        outs[0] = argv[i + 1];
        ins[0] = argv[i];
        if (zl_output_check(outs, 1, ins, 1, msg, sizeof msg) != 0) {
            fprintf(stderr, "zline-bsp: %s\n", msg);
            return 2;
        }
    }
    if (zl_obj_load_file(&obj, argv[i], &oo, msg, sizeof msg) != ZL_OBJ_OK) {
        fprintf(stderr, "%s\n", msg);
        return 1;
    }
    if (bsp_build(&t, obj.positions, obj.vertex_count, obj.indices, obj.triangle_count, &bo) != 0) {
        zl_obj_free(&obj);
        return 1;
    }
    printf("%s: %u triangles -> %u (%u splits), %u vertices, %u nodes, depth %u\n", argv[i],
           (unsigned)obj.triangle_count, t.triangle_count, t.splits, t.vertex_count, t.node_count, t.depth);
    printf("flash: %zu bytes (positions %zu, indices %zu, source ids %zu, nodes %zu)\n",
           (size_t)t.vertex_count * 12 + (size_t)t.triangle_count * 8 + (size_t)t.node_count * sizeof(zl_bsp_node),
           (size_t)t.vertex_count * 12, (size_t)t.triangle_count * 6, (size_t)t.triangle_count * 2,
           (size_t)t.node_count * sizeof(zl_bsp_node));
    if (write_tree(&t, argv[i + 1], argv[i + 2]) != 0) {
        bsp_free(&t);
        zl_obj_free(&obj);
        return 1;
    }
    bsp_free(&t);
    zl_obj_free(&obj);
    return 0;
}

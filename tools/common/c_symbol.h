/* SPDX-License-Identifier: MIT */
/*
 * The C names the generators (zline-obj2c, zline-img2c) give what they
 * write: a prefix for the arrays (from --name, or from the input file's
 * name) and its upper-case form for the macros.
 */
#ifndef ZLINE_TOOLS_C_SYMBOL_H
#define ZLINE_TOOLS_C_SYMBOL_H

#include <stddef.h>

/* Longest prefix: leaves room in the 128-byte buffers for the suffixes the
 * generators append ("_texels", "_MESH_H", ...). */
#define ZT_SYMBOL_MAX 95

typedef struct {
    char name[ZT_SYMBOL_MAX + 1];
    char upper[ZT_SYMBOL_MAX + 1];
} zt_symbol;

/* The file name of a path, after its last '/' or '\'. */
const char *zt_base_name(const char *path);

/* The symbol `given` (NULL: made from in_path's base name up to its first
 * '.', other characters than letters, digits and '_' as '_', led by `lead`
 * when it does not start with a letter or '_'). Returns 0, or -1 when
 * `given` is not a C identifier of at most ZT_SYMBOL_MAX characters. */
int zt_symbol_make(zt_symbol *s, const char *given, const char *in_path, char lead);

#endif

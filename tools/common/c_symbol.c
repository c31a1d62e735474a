/* SPDX-License-Identifier: MIT */
/* C symbol names for the generators (c_symbol.h). */
#include "c_symbol.h"

#include <ctype.h>
#include <string.h>

const char *zt_base_name(const char *path)
{
    const char *s = strrchr(path, '/');
    const char *b = strrchr(path, '\\');
    if (b != NULL && (s == NULL || b > s))
        s = b;
    return s ? s + 1 : path;
}

static int is_identifier(const char *s)
{
    if (!isalpha((unsigned char)*s) && *s != '_')
        return 0;
    for (; *s != '\0'; s++)
        if (!isalnum((unsigned char)*s) && *s != '_')
            return 0;
    return 1;
}

static void name_from_path(const char *path, char lead, char *out, size_t size)
{
    const char *b = zt_base_name(path);
    size_t i = 0;
    if (!isalpha((unsigned char)*b) && *b != '_' && i + 1 < size)
        out[i++] = lead;
    for (; *b != '\0' && *b != '.' && i + 1 < size; b++)
        out[i++] = (isalnum((unsigned char)*b) || *b == '_') ? *b : '_';
    out[i] = '\0';
}

int zt_symbol_make(zt_symbol *s, const char *given, const char *in_path, char lead)
{
    size_t k;
    if (given != NULL) {
        if (strlen(given) > ZT_SYMBOL_MAX || !is_identifier(given))
            return -1;
        strcpy(s->name, given);
    } else {
        name_from_path(in_path, lead, s->name, sizeof s->name);
    }
    for (k = 0; s->name[k] != '\0'; k++)
        s->upper[k] = (char)toupper((unsigned char)s->name[k]);
    s->upper[k] = '\0';
    return 0;
}

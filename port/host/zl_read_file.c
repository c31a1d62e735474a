/* SPDX-License-Identifier: MIT */
/* Whole-file reading for the host loaders (zl_read_file.h). */
#include "zl_read_file.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static zl_read_status fail(zl_read_status st, FILE *f, char *buf, char *msg, size_t msg_size, const char *path)
{
    const char *why = st == ZL_READ_ERR_MEMORY ? "out of memory reading the file" : strerror(errno);
    free(buf);
    if (f != NULL)
        fclose(f);
    if (msg != NULL && msg_size > 0)
        snprintf(msg, msg_size, "%s: %s%s", path, st == ZL_READ_ERR_MEMORY ? "" : "read error: ", why);
    return st;
}

zl_read_status zl_read_file(const char *path, char **data, size_t *size, char *msg, size_t msg_size)
{
    FILE *f = fopen(path, "rb");
    char *buf = NULL;
    size_t n = 0, cap = 0;
    *data = NULL;
    *size = 0;
    if (f == NULL) {
        if (msg != NULL && msg_size > 0)
            snprintf(msg, msg_size, "%s: cannot open: %s", path, strerror(errno));
        return ZL_READ_ERR_OPEN;
    }
    for (;;) {
        size_t got;
        if (n == cap) { /* doubling from 64 KB: linear time for any size */
            size_t grown = cap != 0 ? cap * 2 : 65536;
            char *nb = grown > cap ? (char *)realloc(buf, grown) : NULL;
            if (nb == NULL)
                return fail(ZL_READ_ERR_MEMORY, f, buf, msg, msg_size, path);
            buf = nb;
            cap = grown;
        }
        got = fread(buf + n, 1, cap - n, f);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(f))
        return fail(ZL_READ_ERR_IO, f, buf, msg, msg_size, path);
    fclose(f);
    *data = buf;
    *size = n;
    return ZL_READ_OK;
}

/* SPDX-License-Identifier: MIT */
/*
 * Reading a whole file into memory, shared by the host loaders (zl_obj.c,
 * zl_pnm.c). Private to the host port: not installed.
 */
#ifndef ZLINE_HOST_READ_FILE_H
#define ZLINE_HOST_READ_FILE_H

#include <stddef.h>

typedef enum {
    ZL_READ_OK = 0,
    ZL_READ_ERR_OPEN,   /* "PATH: cannot open: REASON" */
    ZL_READ_ERR_MEMORY, /* "PATH: out of memory reading the file" */
    ZL_READ_ERR_IO      /* "PATH: read error" */
} zl_read_status;

/* The whole of `path` in a malloc'ed buffer (*data, to free; *size bytes).
 * On an error nothing is left allocated, *data is NULL and msg (when not
 * NULL) holds the message above. */
zl_read_status zl_read_file(const char *path, char **data, size_t *size, char *msg, size_t msg_size);

#endif

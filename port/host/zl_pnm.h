/* SPDX-License-Identifier: MIT */
/*
 * Netpbm image files for the host port.
 *
 * Writing:
 *   PPM P6, 8-bit RGB, from rows of ZL_FORMAT_RGB888, RGB565 (native byte
 *     order) or RGB565_BE pixels. 5- and 6-bit channels widen to 8 bits by
 *     bit replication (r8 = r5 << 3 | r5 >> 2), so 0 -> 0 and 31 -> 255.
 *   PGM P5, 16-bit grey (maxval 65535, big-endian samples as Netpbm
 *     specifies), from rows of uint16 values: a depth buffer as it is.
 * A writer streams one row at a time, so a caller that renders by bands never
 * holds a frame. Output goes to a temporary file beside the destination
 * (same directory, so the rename is atomic on POSIX); only a successful
 * close renames it to the final name. A failed or abandoned write leaves no
 * output file (and an existing file of that name untouched).
 *
 * Reading (for tests and image comparison): P6 and P5 with maxval 1..65535,
 * with comments in the header.
 *
 * Every function returns a zl_pnm_status and, on error, writes a
 * NUL-terminated message into the caller's buffer (may be NULL).
 */
#ifndef ZL_PNM_H
#define ZL_PNM_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "zl_output.h"

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    ZL_PNM_OK = 0,
    ZL_PNM_ERR_IO = -1,     /* cannot create, write, rename or read a file */
    ZL_PNM_ERR_ARG = -2,    /* bad size, format or call order (e.g. wrong number of rows) */
    ZL_PNM_ERR_FORMAT = -3, /* reading: not a P5/P6 file this reader takes, or truncated */
    ZL_PNM_ERR_MEMORY = -4
} zl_pnm_status;

typedef enum {
    ZL_PNM_PPM = 6,  /* P6, 8-bit RGB */
    ZL_PNM_PGM16 = 5 /* P5, 16-bit grey */
} zl_pnm_kind;

/* A row-streaming writer. The caller owns the struct; treat it as opaque. */
typedef struct {
    zl_output out;  /* the temporary file the rows go to until zl_pnm_commit */
    char *path;     /* destination */
    uint8_t *row;   /* one converted row */
    uint32_t width, height, rows;
    int kind;
    int state; /* 0 closed, 1 writing, 2 finished (temporary file complete), 3 failed */
    char *msg;
    size_t msg_size;
} zl_pnm_writer;

/*
 * Create the temporary file and write the header. width, height: 1 ..
 * 1000000. msg, msg_size: the buffer for this and every later error of the
 * writer. On failure nothing is left open or on disk.
 */
zl_pnm_status zl_pnm_open(zl_pnm_writer *w, const char *path, zl_pnm_kind kind, uint32_t width,
                          uint32_t height, char *msg, size_t msg_size);

/* Append one row of width pixels of `format` to a PPM writer. */
zl_pnm_status zl_pnm_write_row_rgb(zl_pnm_writer *w, const void *pixels, zl_format format);

/* Append one row of width values to a 16-bit PGM writer. */
zl_pnm_status zl_pnm_write_row_gray16(zl_pnm_writer *w, const uint16_t *values);

/*
 * Check that exactly height rows were written, flush and close the
 * temporary file. On any error (including earlier failed writes) the
 * temporary file is removed and the writer released.
 */
zl_pnm_status zl_pnm_finish(zl_pnm_writer *w);

/* Rename a finished temporary file to its destination and release the
 * writer. Two-phase (finish everything, then commit everything) lets a
 * caller writing several files keep all or none. */
zl_pnm_status zl_pnm_commit(zl_pnm_writer *w);

/* zl_pnm_finish, then zl_pnm_commit. */
zl_pnm_status zl_pnm_close(zl_pnm_writer *w);

/* Abandon the writer: remove its temporary file, release it. Safe in any
 * state (a no-op after commit or on a zeroed writer). */
void zl_pnm_abort(zl_pnm_writer *w);

/* Whole images. stride: bytes from one row to the next. */
zl_pnm_status zl_pnm_write_ppm(const char *path, const void *pixels, int32_t stride,
                               zl_format format, uint32_t width, uint32_t height, char *msg,
                               size_t msg_size);
zl_pnm_status zl_pnm_write_pgm16(const char *path, const uint16_t *values, int32_t stride,
                                 uint32_t width, uint32_t height, char *msg, size_t msg_size);

/* Convert one row of width pixels of `format` to RGB888 (3 bytes a pixel). */
void zl_pnm_row_to_rgb888(uint8_t *rgb, const void *pixels, zl_format format, uint32_t width);

/* An image read back. */
typedef struct {
    uint32_t width, height;
    uint32_t channels; /* 3 for P6, 1 for P5 */
    uint32_t maxval;   /* 1 .. 65535 */
    uint16_t *samples; /* width * height * channels, row by row, top row first */
} zl_pnm_image;

zl_pnm_status zl_pnm_read(zl_pnm_image *img, const char *path, char *msg, size_t msg_size);
void zl_pnm_image_free(zl_pnm_image *img);

#ifdef __cplusplus
}
#endif

#endif /* ZL_PNM_H */

/* SPDX-License-Identifier: MIT */
/* Netpbm P6/P5 writing and reading (host port). See zl_pnm.h. */
#include "zl_pnm.h"
#include "zl_read_file.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>


/* Sizes above this are surely a mistake (and keep every product in size_t). */
#define PNM_MAX_DIM 1000000u

enum { W_CLOSED = 0, W_WRITING = 1, W_FINISHED = 2, W_FAILED = 3 };

static void vmsg(char *msg, size_t msg_size, const char *fmt, va_list ap)
{
    if (msg != NULL && msg_size > 0)
        vsnprintf(msg, msg_size, fmt, ap);
}

static void set_msg(char *msg, size_t msg_size, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg(msg, msg_size, fmt, ap);
    va_end(ap);
}

/* Release everything of w; remove the temporary file unless it was renamed. */
static void writer_release(zl_pnm_writer *w)
{
    zl_output_discard(&w->out);
    free(w->path);
    free(w->row);
    w->path = NULL;
    w->row = NULL;
    w->state = W_CLOSED;
}

/* Fail the writer: message, clean up, the status. */
static zl_pnm_status writer_fail(zl_pnm_writer *w, zl_pnm_status st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vmsg(w->msg, w->msg_size, fmt, ap);
    va_end(ap);
    writer_release(w);
    w->state = W_FAILED;
    return st;
}

static char *dup_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = (char *)malloc(n);
    if (d != NULL)
        memcpy(d, s, n);
    return d;
}

zl_pnm_status zl_pnm_open(zl_pnm_writer *w, const char *path, zl_pnm_kind kind, uint32_t width,
                          uint32_t height, char *msg, size_t msg_size)
{
    size_t row_bytes;
    if (msg != NULL && msg_size > 0)
        msg[0] = '\0';
    if (w == NULL || path == NULL) {
        set_msg(msg, msg_size, "zl_pnm_open: NULL argument");
        return ZL_PNM_ERR_ARG;
    }
    memset(w, 0, sizeof *w);
    w->msg = msg;
    w->msg_size = msg_size;
    if (kind != ZL_PNM_PPM && kind != ZL_PNM_PGM16) {
        set_msg(msg, msg_size, "%s: unknown PNM kind %d", path, (int)kind);
        return ZL_PNM_ERR_ARG;
    }
    if (width < 1 || height < 1 || width > PNM_MAX_DIM || height > PNM_MAX_DIM) {
        set_msg(msg, msg_size, "%s: image size %lux%lu out of range 1..%u", path,
                (unsigned long)width, (unsigned long)height, PNM_MAX_DIM);
        return ZL_PNM_ERR_ARG;
    }
    w->kind = (int)kind;
    w->width = width;
    w->height = height;
    row_bytes = (size_t)width * (kind == ZL_PNM_PPM ? 3u : 2u);
    w->path = dup_string(path);
    w->row = (uint8_t *)malloc(row_bytes);
    if (w->path == NULL || w->row == NULL)
        return writer_fail(w, ZL_PNM_ERR_MEMORY, "%s: out of memory", path);
    if (zl_output_open(&w->out, path, 1, msg, msg_size) != 0) {
        writer_release(w);
        w->state = W_FAILED;
        return ZL_PNM_ERR_IO; /* zl_output_open's message stands */
    }
    w->state = W_WRITING;
    if (fprintf(w->out.file, "P%d\n%lu %lu\n%u\n", w->kind, (unsigned long)width, (unsigned long)height,
                kind == ZL_PNM_PPM ? 255u : 65535u) < 0)
        return writer_fail(w, ZL_PNM_ERR_IO, "%s: write error: %s", path, strerror(errno));
    return ZL_PNM_OK;
}

static int expand5(unsigned v)
{
    return (int)((v << 3) | (v >> 2));
}

static int expand6(unsigned v)
{
    return (int)((v << 2) | (v >> 4));
}

void zl_pnm_row_to_rgb888(uint8_t *rgb, const void *pixels, zl_format format, uint32_t width)
{
    const uint8_t *src = (const uint8_t *)pixels;
    uint32_t x;
    switch (format) {
    case ZL_FORMAT_RGB888:
        memcpy(rgb, src, (size_t)width * 3);
        break;
    case ZL_FORMAT_RGB565:
    case ZL_FORMAT_RGB565_BE:
        for (x = 0; x < width; x++) {
            unsigned v;
            if (format == ZL_FORMAT_RGB565) {
                uint16_t n;
                memcpy(&n, src + 2 * (size_t)x, 2); /* native order, any alignment */
                v = n;
            } else {
                v = (unsigned)src[2 * (size_t)x] << 8 | src[2 * (size_t)x + 1];
            }
            rgb[3 * (size_t)x + 0] = (uint8_t)expand5((v >> 11) & 31u);
            rgb[3 * (size_t)x + 1] = (uint8_t)expand6((v >> 5) & 63u);
            rgb[3 * (size_t)x + 2] = (uint8_t)expand5(v & 31u);
        }
        break;
    }
}

/* Common checks of a row write. */
static zl_pnm_status row_check(zl_pnm_writer *w, int kind)
{
    if (w == NULL)
        return ZL_PNM_ERR_ARG;
    if (w->state != W_WRITING) {
        if (w->state != W_FAILED)
            set_msg(w->msg, w->msg_size, "PNM writer: row written to a writer that is not open");
        return ZL_PNM_ERR_ARG;
    }
    if (w->kind != kind)
        return writer_fail(w, ZL_PNM_ERR_ARG, "%s: %s row written to a %s writer", w->path,
                           kind == ZL_PNM_PPM ? "an RGB" : "a grey",
                           w->kind == ZL_PNM_PPM ? "PPM" : "PGM");
    if (w->rows >= w->height)
        return writer_fail(w, ZL_PNM_ERR_ARG, "%s: row %lu written to an image of %lu rows",
                           w->path, (unsigned long)w->rows + 1, (unsigned long)w->height);
    return ZL_PNM_OK;
}

static zl_pnm_status row_put(zl_pnm_writer *w, size_t bytes)
{
    if (fwrite(w->row, 1, bytes, w->out.file) != bytes)
        return writer_fail(w, ZL_PNM_ERR_IO, "%s: write error: %s", w->path, strerror(errno));
    w->rows++;
    return ZL_PNM_OK;
}

zl_pnm_status zl_pnm_write_row_rgb(zl_pnm_writer *w, const void *pixels, zl_format format)
{
    zl_pnm_status st = row_check(w, ZL_PNM_PPM);
    if (st != ZL_PNM_OK)
        return st;
    if (pixels == NULL)
        return writer_fail(w, ZL_PNM_ERR_ARG, "%s: NULL row", w->path);
    if (format != ZL_FORMAT_RGB888 && format != ZL_FORMAT_RGB565 && format != ZL_FORMAT_RGB565_BE)
        return writer_fail(w, ZL_PNM_ERR_ARG, "%s: unknown pixel format %d", w->path, (int)format);
    zl_pnm_row_to_rgb888(w->row, pixels, format, w->width);
    return row_put(w, (size_t)w->width * 3);
}

zl_pnm_status zl_pnm_write_row_gray16(zl_pnm_writer *w, const uint16_t *values)
{
    uint32_t x;
    zl_pnm_status st = row_check(w, ZL_PNM_PGM16);
    if (st != ZL_PNM_OK)
        return st;
    if (values == NULL)
        return writer_fail(w, ZL_PNM_ERR_ARG, "%s: NULL row", w->path);
    for (x = 0; x < w->width; x++) {
        w->row[2 * (size_t)x] = (uint8_t)(values[x] >> 8); /* Netpbm: most significant first */
        w->row[2 * (size_t)x + 1] = (uint8_t)(values[x] & 0xFFu);
    }
    return row_put(w, (size_t)w->width * 2);
}

zl_pnm_status zl_pnm_finish(zl_pnm_writer *w)
{
    int bad;
    if (w == NULL)
        return ZL_PNM_ERR_ARG;
    if (w->state == W_FAILED)
        return ZL_PNM_ERR_IO; /* the message is already there */
    if (w->state != W_WRITING) {
        set_msg(w->msg, w->msg_size, "PNM writer: finish without an open writer");
        return ZL_PNM_ERR_ARG;
    }
    if (w->rows != w->height)
        return writer_fail(w, ZL_PNM_ERR_ARG, "%s: %lu of %lu rows written", w->path,
                           (unsigned long)w->rows, (unsigned long)w->height);
    bad = fflush(w->out.file) != 0 || ferror(w->out.file);
    if (fclose(w->out.file) != 0)
        bad = 1;
    w->out.file = NULL;
    if (bad)
        return writer_fail(w, ZL_PNM_ERR_IO, "%s: write error: %s", w->path, strerror(errno));
    w->state = W_FINISHED;
    return ZL_PNM_OK;
}

zl_pnm_status zl_pnm_commit(zl_pnm_writer *w)
{
    if (w == NULL)
        return ZL_PNM_ERR_ARG;
    if (w->state != W_FINISHED) {
        if (w->state != W_FAILED)
            set_msg(w->msg, w->msg_size, "PNM writer: commit before finish");
        return ZL_PNM_ERR_ARG;
    }
    if (zl_output_commit(&w->out, w->msg, w->msg_size) != 0) {
        writer_release(w);
        w->state = W_FAILED;
        return ZL_PNM_ERR_IO;
    }
    writer_release(w);
    return ZL_PNM_OK;
}

zl_pnm_status zl_pnm_close(zl_pnm_writer *w)
{
    zl_pnm_status st = zl_pnm_finish(w);
    if (st != ZL_PNM_OK)
        return st;
    return zl_pnm_commit(w);
}

void zl_pnm_abort(zl_pnm_writer *w)
{
    if (w == NULL)
        return;
    if (w->state == W_WRITING || w->state == W_FINISHED)
        writer_release(w);
}

zl_pnm_status zl_pnm_write_ppm(const char *path, const void *pixels, int32_t stride,
                               zl_format format, uint32_t width, uint32_t height, char *msg,
                               size_t msg_size)
{
    zl_pnm_writer w;
    zl_pnm_status st;
    uint32_t y;
    memset(&w, 0, sizeof w);
    if (pixels == NULL || stride <= 0) {
        set_msg(msg, msg_size, "%s: NULL pixels or non-positive stride",
                path != NULL ? path : "(null)");
        return ZL_PNM_ERR_ARG;
    }
    st = zl_pnm_open(&w, path, ZL_PNM_PPM, width, height, msg, msg_size);
    for (y = 0; st == ZL_PNM_OK && y < height; y++)
        st = zl_pnm_write_row_rgb(&w, (const uint8_t *)pixels + (size_t)y * (size_t)stride, format);
    if (st == ZL_PNM_OK)
        st = zl_pnm_close(&w);
    zl_pnm_abort(&w);
    return st;
}

zl_pnm_status zl_pnm_write_pgm16(const char *path, const uint16_t *values, int32_t stride,
                                 uint32_t width, uint32_t height, char *msg, size_t msg_size)
{
    zl_pnm_writer w;
    zl_pnm_status st;
    uint32_t y;
    memset(&w, 0, sizeof w);
    if (values == NULL || stride <= 0 || stride % 2 != 0) {
        set_msg(msg, msg_size, "%s: NULL values or a stride that is not positive and even",
                path != NULL ? path : "(null)");
        return ZL_PNM_ERR_ARG;
    }
    st = zl_pnm_open(&w, path, ZL_PNM_PGM16, width, height, msg, msg_size);
    for (y = 0; st == ZL_PNM_OK && y < height; y++)
        st = zl_pnm_write_row_gray16(
            &w,
            (const uint16_t *)(const void *)((const uint8_t *)values + (size_t)y * (size_t)stride));
    if (st == ZL_PNM_OK)
        st = zl_pnm_close(&w);
    zl_pnm_abort(&w);
    return st;
}

/* ---------------------------------------------------------------- reading */

/* Skip white space and # comments; 0 at the end of the data. */
static int skip_header_space(const uint8_t *b, size_t n, size_t *i)
{
    while (*i < n) {
        if (b[*i] == '#') {
            while (*i < n && b[*i] != '\n')
                (*i)++;
        } else if (b[*i] == ' ' || b[*i] == '\t' || b[*i] == '\n' || b[*i] == '\r' ||
                   b[*i] == '\v' || b[*i] == '\f') {
            (*i)++;
        } else {
            return 1;
        }
    }
    return 0;
}

static int header_number(const uint8_t *b, size_t n, size_t *i, uint32_t *out)
{
    uint32_t v = 0;
    size_t digits = 0;
    if (!skip_header_space(b, n, i))
        return 0;
    while (*i < n && b[*i] >= '0' && b[*i] <= '9') {
        if (v > PNM_MAX_DIM)
            return 0;
        v = v * 10 + (uint32_t)(b[*i] - '0');
        (*i)++;
        digits++;
    }
    if (digits == 0)
        return 0;
    *out = v;
    return 1;
}

zl_pnm_status zl_pnm_read(zl_pnm_image *img, const char *path, char *msg, size_t msg_size)
{
    char *data;
    uint8_t *buf;
    zl_read_status rs;
    size_t size, i = 2, count, bytes, k;
    uint32_t width, height, maxval, channels, sample_bytes;
    if (msg != NULL && msg_size > 0)
        msg[0] = '\0';
    if (img == NULL || path == NULL) {
        set_msg(msg, msg_size, "zl_pnm_read: NULL argument");
        return ZL_PNM_ERR_ARG;
    }
    memset(img, 0, sizeof *img);
    rs = zl_read_file(path, &data, &size, msg, msg_size);
    if (rs != ZL_READ_OK)
        return rs == ZL_READ_ERR_MEMORY ? ZL_PNM_ERR_MEMORY : ZL_PNM_ERR_IO;
    buf = (uint8_t *)data;

    if (size < 2 || buf[0] != 'P' || (buf[1] != '6' && buf[1] != '5')) {
        free(buf);
        set_msg(msg, msg_size, "%s: not a P6 or P5 file", path);
        return ZL_PNM_ERR_FORMAT;
    }
    channels = buf[1] == '6' ? 3u : 1u;
    if (!header_number(buf, size, &i, &width) || !header_number(buf, size, &i, &height) ||
        !header_number(buf, size, &i, &maxval) || width < 1 || height < 1 || width > PNM_MAX_DIM ||
        height > PNM_MAX_DIM || maxval < 1 || maxval > 65535 || i >= size ||
        !(buf[i] == ' ' || buf[i] == '\t' || buf[i] == '\n' || buf[i] == '\r')) {
        set_msg(msg, msg_size, "%s: bad P%c header", path, channels == 3 ? '6' : '5');
        free(buf);
        return ZL_PNM_ERR_FORMAT;
    }
    i++; /* the single white space character before the raster */
    sample_bytes = maxval > 255 ? 2u : 1u;
    count = (size_t)width * height * channels;
    bytes = count * sample_bytes;
    if (size - i < bytes) {
        free(buf);
        set_msg(msg, msg_size, "%s: truncated: %lu raster bytes of %lu", path,
                (unsigned long)(size - i), (unsigned long)bytes);
        return ZL_PNM_ERR_FORMAT;
    }
    img->samples = (uint16_t *)malloc(count * sizeof(uint16_t));
    if (img->samples == NULL) {
        free(buf);
        set_msg(msg, msg_size, "%s: out of memory", path);
        return ZL_PNM_ERR_MEMORY;
    }
    for (k = 0; k < count; k++) {
        img->samples[k] = sample_bytes == 2
                              ? (uint16_t)((unsigned)buf[i + 2 * k] << 8 | buf[i + 2 * k + 1])
                              : buf[i + k];
        if (img->samples[k] > maxval) { /* Netpbm: no sample exceeds maxval */
            size_t pixel = k / channels;
            set_msg(msg, msg_size, "%s: sample %u at pixel (%lu, %lu) is above the maxval %lu", path,
                    (unsigned)img->samples[k], (unsigned long)(pixel % width), (unsigned long)(pixel / width),
                    (unsigned long)maxval);
            free(buf);
            zl_pnm_image_free(img);
            return ZL_PNM_ERR_FORMAT;
        }
    }
    free(buf);
    img->width = width;
    img->height = height;
    img->channels = channels;
    img->maxval = maxval;
    return ZL_PNM_OK;
}

void zl_pnm_image_free(zl_pnm_image *img)
{
    if (img == NULL)
        return;
    free(img->samples);
    memset(img, 0, sizeof *img);
}

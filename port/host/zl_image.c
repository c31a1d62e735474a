/* SPDX-License-Identifier: MIT */
/* Images as textures for the host port (see zl_image.h). */
#include "zl_image.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zl_pnm.h"

#ifdef ZL_HAVE_PNG
#include <png.h>
#endif

static void set_msg(char *msg, size_t msg_size, const char *fmt, ...)
{
    va_list ap;
    if (msg == NULL || msg_size == 0)
        return;
    va_start(ap, fmt);
    vsnprintf(msg, msg_size, fmt, ap);
    va_end(ap);
}

int zl_image_png_supported(void)
{
#ifdef ZL_HAVE_PNG
    return 1;
#else
    return 0;
#endif
}

void zl_image_free(zl_image *img)
{
    if (img == NULL)
        return;
    free(img->rgba);
    memset(img, 0, sizeof *img);
}

static unsigned scale8(uint32_t s, uint32_t maxval)
{
    return (unsigned)((s * 255u + maxval / 2u) / maxval);
}

/* A P6 or P5 file into img (alpha 255). */
static int load_pnm(zl_image *img, const char *path, char *msg, size_t msg_size)
{
    zl_pnm_image p;
    size_t i, n;
    if (zl_pnm_read(&p, path, msg, msg_size) != ZL_PNM_OK)
        return -1;
    if (p.width > ZL_IMAGE_MAX_DIM || p.height > ZL_IMAGE_MAX_DIM) {
        set_msg(msg, msg_size, "%s: %lux%lu is larger than a texture (at most %ux%u)", path,
                (unsigned long)p.width, (unsigned long)p.height, ZL_IMAGE_MAX_DIM, ZL_IMAGE_MAX_DIM);
        zl_pnm_image_free(&p);
        return -1;
    }
    n = (size_t)p.width * p.height;
    img->rgba = (uint8_t *)malloc(n * 4u);
    if (img->rgba == NULL) {
        set_msg(msg, msg_size, "%s: out of memory", path);
        zl_pnm_image_free(&p);
        return -1;
    }
    for (i = 0; i < n; i++) {
        unsigned k;
        for (k = 0; k < 3; k++)
            img->rgba[i * 4 + k] = (uint8_t)scale8(p.samples[i * p.channels + (p.channels == 3 ? k : 0)], p.maxval);
        img->rgba[i * 4 + 3] = 255;
    }
    img->width = p.width;
    img->height = p.height;
    zl_pnm_image_free(&p);
    return 0;
}

static int load_png(zl_image *img, const char *path, char *msg, size_t msg_size)
{
#ifdef ZL_HAVE_PNG
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&pi, path)) {
        set_msg(msg, msg_size, "%s: bad PNG: %s", path, pi.message);
        return -1;
    }
    if (pi.width < 1 || pi.height < 1 || pi.width > ZL_IMAGE_MAX_DIM || pi.height > ZL_IMAGE_MAX_DIM) {
        set_msg(msg, msg_size, "%s: %lux%lu is not a texture size (1 .. %u on each side)", path,
                (unsigned long)pi.width, (unsigned long)pi.height, ZL_IMAGE_MAX_DIM);
        png_image_free(&pi);
        return -1;
    }
    pi.format = PNG_FORMAT_RGBA;
    img->rgba = (uint8_t *)malloc(PNG_IMAGE_SIZE(pi));
    if (img->rgba == NULL) {
        set_msg(msg, msg_size, "%s: out of memory", path);
        png_image_free(&pi);
        return -1;
    }
    if (!png_image_finish_read(&pi, NULL, img->rgba, 0, NULL)) {
        set_msg(msg, msg_size, "%s: bad PNG: %s", path, pi.message);
        free(img->rgba);
        img->rgba = NULL;
        return -1;
    }
    img->width = pi.width;
    img->height = pi.height;
    return 0;
#else
    (void)img;
    set_msg(msg, msg_size,
            "%s: a PNG, and this build has no libpng: convert it with netpbm, pngtopnm %s > image.ppm "
            "(and pngtopnm -alpha %s > alpha.pgm for its alpha)",
            path, path, path);
    return -1;
#endif
}

int zl_image_load(zl_image *img, const char *path, const char *alpha_path, char *msg, size_t msg_size)
{
    unsigned char magic[8] = {0};
    size_t got;
    FILE *f;
    int st;
    if (msg != NULL && msg_size > 0)
        msg[0] = '\0';
    if (img == NULL || path == NULL) {
        set_msg(msg, msg_size, "zl_image_load: NULL argument");
        return -1;
    }
    memset(img, 0, sizeof *img);
    f = fopen(path, "rb");
    if (f == NULL) {
        set_msg(msg, msg_size, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    got = fread(magic, 1, sizeof magic, f);
    if (ferror(f)) { /* a folder opens, and fails here with EISDIR */
        set_msg(msg, msg_size, "%s: cannot read: %s", path, strerror(errno));
        fclose(f);
        return -1;
    }
    fclose(f);
    if (got == 8 && memcmp(magic, "\x89PNG\r\n\x1a\n", 8) == 0)
        st = load_png(img, path, msg, msg_size);
    else if (got >= 2 && magic[0] == 'P' && (magic[1] == '6' || magic[1] == '5'))
        st = load_pnm(img, path, msg, msg_size);
    else {
        set_msg(msg, msg_size, "%s: not a PPM (P6), PGM (P5) or PNG image", path);
        return -1;
    }
    if (st != 0) {
        zl_image_free(img);
        return -1;
    }
    if (alpha_path != NULL) {
        zl_pnm_image a;
        size_t i, n = (size_t)img->width * img->height;
        if (zl_pnm_read(&a, alpha_path, msg, msg_size) != ZL_PNM_OK) {
            zl_image_free(img);
            return -1;
        }
        if (a.channels != 1 || a.width != img->width || a.height != img->height) {
            set_msg(msg, msg_size, "%s: an alpha mask must be a PGM (P5) of the image's size %lux%lu", alpha_path,
                    (unsigned long)img->width, (unsigned long)img->height);
            zl_pnm_image_free(&a);
            zl_image_free(img);
            return -1;
        }
        for (i = 0; i < n; i++)
            img->rgba[i * 4 + 3] = (uint8_t)scale8(a.samples[i], a.maxval);
        zl_pnm_image_free(&a);
    }
    {
        size_t i, n = (size_t)img->width * img->height;
        for (i = 0; i < n; i++)
            if (img->rgba[i * 4 + 3] != 255)
                img->has_alpha = 1;
    }
    return 0;
}

uint16_t zl_image_texel(unsigned r, unsigned g, unsigned b, unsigned a, zl_texel_format format)
{
    if (format == ZL_TEXEL_RGBA4444)
        return (uint16_t)((((r * 15u + 127u) / 255u) << 12) | (((g * 15u + 127u) / 255u) << 8) |
                          (((b * 15u + 127u) / 255u) << 4) | ((a * 15u + 127u) / 255u));
    return (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}

void zl_image_texels(const zl_image *img, zl_texel_format format, uint16_t *out)
{
    size_t i, n = (size_t)img->width * img->height;
    for (i = 0; i < n; i++)
        out[i] = zl_image_texel(img->rgba[i * 4], img->rgba[i * 4 + 1], img->rgba[i * 4 + 2], img->rgba[i * 4 + 3],
                                format);
}

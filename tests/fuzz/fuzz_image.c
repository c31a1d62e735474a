/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: the image readers of port/host (zl_image_load: PPM, PGM and,
 * with libpng, PNG; zl_pnm_read) and zline-img2c's conversion
 * (zl_image_texels) in both texel formats.
 *
 * The readers take a path, so the input is written to a temporary file of
 * this process (created once, rewritten for every input). The first byte
 * picks the texel format (bit 0), a separate alpha mask (bit 1: the next
 * byte says how many of the remaining bytes are the image, the rest is the
 * mask's file) and the size of the guarded message buffer (bits 2..7). Checked:
 *   - success: 1 .. 4096 on each side, has_alpha exactly when some alpha
 *     is below 255, alpha 255 everywhere for a PNM without a mask; for a
 *     PNM every channel is round(s * 255 / maxval) of what zl_pnm_read
 *     reads from the same file (computed here, the rule of zl_image.h);
 *   - every texel is the rule of zl_image.h, computed here (RGB565: the top
 *     5, 6, 5 bits; RGBA4444: round(c * 15 / 255) per channel), written
 *     into a guarded buffer of exactly width * height texels;
 *   - zl_pnm_read: channels 1 or 3, maxval 1 .. 65535, every sample
 *     <= maxval; on failure a known status and nothing kept;
 *   - failure: -1, *img empty, the message NUL-terminated in its buffer.
 */
#define _POSIX_C_SOURCE 200809L
#include <unistd.h>

#include "fz_common.h"
#include "zl_image.h"
#include "zl_pnm.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* This process's two temporary files (image, alpha mask). */
static char image_path[64], alpha_path[64];

static void make_temp(char *path, size_t n, const char *tag)
{
    int fd;
    snprintf(path, n, "/tmp/zl-fuzz-%s-XXXXXX", tag);
    fd = mkstemp(path);
    if (fd < 0)
        abort();
    close(fd);
}

static void remove_temps(void)
{
    remove(image_path);
    remove(alpha_path);
}

static void write_file(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL || (size > 0 && fwrite(data, 1, size, f) != size) || fclose(f) != 0)
        abort();
}

static unsigned expect_scale8(unsigned s, unsigned maxval)
{
    return (unsigned)(((uint64_t)s * 255u * 2u + maxval) / (2u * (uint64_t)maxval));
}

static uint16_t expect_texel(const uint8_t *c, zl_texel_format format)
{
    if (format == ZL_TEXEL_RGB565)
        return (uint16_t)((c[0] >> 3) << 11 | (c[1] >> 2) << 5 | (c[2] >> 3));
    {
        uint16_t v = 0;
        unsigned k;
        for (k = 0; k < 4; k++) { /* round(c * 15 / 255): nearest of 0..15, ties up */
            unsigned q = (c[k] * 30u + 255u) / 510u;
            v = (uint16_t)(v << 4 | q);
        }
        return v;
    }
}

/* zl_pnm_read on the image file: checked on its own, and its samples are
 * what a PNM's pixels must be made of. */
static void check_pnm(const zl_image *img, int loaded, int has_mask)
{
    zl_pnm_image p;
    char msg[80];
    size_t i, n;
    zl_pnm_status st = zl_pnm_read(&p, image_path, msg, sizeof msg);
    if (st != ZL_PNM_OK) {
        FZ_REQUIRE(st == ZL_PNM_ERR_FORMAT || st == ZL_PNM_ERR_IO || st == ZL_PNM_ERR_MEMORY, "status %d", (int)st);
        FZ_REQUIRE(!loaded, "zl_image_load took a PNM that zl_pnm_read refuses: %s", msg);
        return;
    }
    FZ_REQUIRE(p.channels == 1 || p.channels == 3, "channels %u", p.channels);
    FZ_REQUIRE(p.maxval >= 1 && p.maxval <= 65535, "maxval %u", p.maxval);
    n = (size_t)p.width * p.height * p.channels;
    for (i = 0; i < n; i++)
        FZ_REQUIRE(p.samples[i] <= p.maxval, "sample %zu = %u above maxval %u", i, p.samples[i], p.maxval);
    if (loaded) {
        FZ_REQUIRE(img->width == p.width && img->height == p.height, "size %ux%u vs %ux%u", img->width,
                   img->height, p.width, p.height);
        for (i = 0; i < (size_t)p.width * p.height; i++) {
            unsigned k;
            for (k = 0; k < 3; k++) {
                unsigned s = p.samples[i * p.channels + (p.channels == 3 ? k : 0)];
                FZ_REQUIRE(img->rgba[i * 4 + k] == expect_scale8(s, p.maxval),
                           "pixel %zu channel %u: %u from sample %u of maxval %u", i, k, img->rgba[i * 4 + k], s,
                           p.maxval);
            }
            if (!has_mask)
                FZ_REQUIRE(img->rgba[i * 4 + 3] == 255, "alpha %u in a PNM", img->rgba[i * 4 + 3]);
        }
    }
    zl_pnm_image_free(&p);
}

static void check_texels(const zl_image *img, zl_texel_format format)
{
    size_t i, n = (size_t)img->width * img->height;
    fz_buf out;
    int any_alpha = 0;
    fz_buf_alloc(&out, n * sizeof(uint16_t));
    zl_image_texels(img, format, (uint16_t *)(void *)out.data);
    fz_buf_check(&out, "texels");
    for (i = 0; i < n; i++) {
        uint16_t got;
        memcpy(&got, out.data + i * 2, 2);
        FZ_REQUIRE(got == expect_texel(img->rgba + i * 4, format), "texel %zu: %04x for %u,%u,%u,%u (format %d)", i,
                   got, img->rgba[i * 4], img->rgba[i * 4 + 1], img->rgba[i * 4 + 2], img->rgba[i * 4 + 3],
                   (int)format);
        any_alpha |= img->rgba[i * 4 + 3] != 255;
    }
    FZ_REQUIRE(img->has_alpha == any_alpha, "has_alpha %d, alpha below 255: %d", img->has_alpha, any_alpha);
    fz_buf_free(&out);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    zl_image img;
    fz_buf msg;
    size_t msg_size, image_size = size;
    uint32_t sel = size > 0 ? data[0] : 0;
    zl_texel_format format = (sel & 1u) ? ZL_TEXEL_RGBA4444 : ZL_TEXEL_RGB565;
    int has_mask = (sel & 2u) != 0, st;
    if (image_path[0] == '\0') {
        make_temp(image_path, sizeof image_path, "image");
        make_temp(alpha_path, sizeof alpha_path, "alpha");
        atexit(remove_temps);
    }
    if (size > 0) {
        data++;
        size--;
    }
    image_size = size;
    if (has_mask && size > 0) {
        image_size = (size_t)data[0] * (size - 1) / 255u;
        data++;
        size--;
        write_file(alpha_path, data + image_size, size - image_size);
    }
    write_file(image_path, data, image_size);
    msg_size = (sel >> 2) % 63;
    fz_buf_alloc(&msg, msg_size);
    st = zl_image_load(&img, image_path, has_mask ? alpha_path : NULL, msg_size ? (char *)msg.data : NULL, msg_size);
    fz_buf_check(&msg, "message");
    if (msg_size > 0)
        FZ_REQUIRE(memchr(msg.data, '\0', msg_size) != NULL, "message not NUL-terminated in %zu bytes", msg_size);
    if (st == 0) {
        FZ_REQUIRE(img.width >= 1 && img.width <= ZL_IMAGE_MAX_DIM && img.height >= 1 &&
                       img.height <= ZL_IMAGE_MAX_DIM && img.rgba != NULL,
                   "size %ux%u", img.width, img.height);
        FZ_REQUIRE(msg_size == 0 || msg.data[0] == '\0', "message on success: %s", (char *)msg.data);
        check_texels(&img, format);
    } else {
        FZ_REQUIRE(st == -1, "status %d", st);
        FZ_REQUIRE(img.rgba == NULL && img.width == 0 && img.height == 0, "a failed load left data in *img");
    }
    if (image_size >= 2 && data[0] == 'P')
        check_pnm(&img, st == 0, has_mask);
    if (st == 0)
        zl_image_free(&img);
    fz_buf_free(&msg);
    return 0;
}

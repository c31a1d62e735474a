/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: texture sampling and blending state through zl_draw_mesh
 * with a zl_style: textures of any size 1 .. 300 (not only powers of two),
 * strides above the width, both texel formats, wrap and filter modes,
 * affine and perspective mapping, the three blend modes and any constant
 * alpha, drawn as two triangles in pixel space (NULL matrix, with w = 1,
 * and through a matrix with a perspective w) into a target of any
 * format and stride. The texels and texture coordinates are allocated with
 * exactly the size promised (AddressSanitizer catches a read past them), the
 * colour and depth planes are guarded. Checked, from zline.h:
 *   - the status is that of zl_style_check for a bad style (and nothing is
 *     written), else ZL_OK in pixel space;
 *   - in pixel space no pixel outside the triangles' bounding box changes;
 *   - ZL_BLEND_ALPHA with alpha 0 discards every fragment: neither colour
 *     nor depth changes;
 *   - ZL_BLEND_ADD never makes a channel darker (new = min(255, old + ..)).
 */
#include "fz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { W = 23, H = 17 };

typedef struct {
    zl_texture tex;
    uint16_t *texels;
    zl_fixed texcoords[4 * 2];
    zl_style style;
} fz_tex_style;

static void read_texture(fz_in *in, fz_tex_style *t)
{
    unsigned i, n;
    uint32_t f = fz_u8(in);
    t->tex.width = (uint16_t)((f & 1u) ? 1u + fz_u16(in) % 300u : 1u << (fz_u8(in) % 9));
    t->tex.height = (uint16_t)((f & 2u) ? 1u + fz_u16(in) % 300u : 1u << (fz_u8(in) % 9));
    t->tex.stride = (uint16_t)(t->tex.width + fz_u8(in) % 4u - ((f & 4u) ? 1u : 0u)); /* short: an error */
    t->tex.wrap_s = (uint8_t)(fz_u8(in) % 3u); /* 2: unknown */
    t->tex.wrap_t = (uint8_t)(fz_u8(in) % 3u);
    t->tex.format = (uint8_t)(fz_u8(in) % 3u);
    n = t->tex.stride >= t->tex.width ? (unsigned)(t->tex.height - 1u) * t->tex.stride + t->tex.width : 1u;
    t->texels = (uint16_t *)malloc(n * sizeof(uint16_t));
    if (t->texels == NULL)
        abort();
    for (i = 0; i < n; i++) /* every alpha 0 .. 15 occurs, with colours that vary */
        t->texels[i] = (uint16_t)((i * 2654435761u) >> 16 ^ fz_u8(in));
    t->tex.texels = t->texels;
}

static void read_style(fz_in *in, fz_tex_style *t)
{
    unsigned i;
    zl_style_default(&t->style);
    read_texture(in, t);
    t->style.texture = (fz_u8(in) % 8u) ? &t->tex : NULL;
    for (i = 0; i < 8; i++)
        t->texcoords[i] = fz_fixed(in);
    t->style.texcoords = t->texcoords;
    t->style.tex_mapping = (uint8_t)(fz_u8(in) % 3u);
    t->style.tex_every = (uint8_t)(1u << (fz_u8(in) % 8u));
    t->style.tex_filter = (uint8_t)(fz_u8(in) % 3u);
    t->style.blend = (uint8_t)(fz_u8(in) % 4u);
    t->style.alpha = (uint8_t)((fz_u8(in) & 1u) ? fz_u8(in) : 0u);
    t->style.persp_gouraud = (uint8_t)(fz_u8(in) % 2u);
}

/* The 8-bit channels of pixel (x, y) as stored (RGB565 fields unwidened). */
static void pixel_channels(const zl_target *t, unsigned x, unsigned y, unsigned c[3])
{
    const uint8_t *p = (const uint8_t *)t->color + (size_t)y * (size_t)t->color_stride;
    if (t->format == ZL_FORMAT_RGB888) {
        c[0] = p[x * 3];
        c[1] = p[x * 3 + 1];
        c[2] = p[x * 3 + 2];
    } else {
        unsigned v;
        if (t->format == ZL_FORMAT_RGB565) {
            uint16_t u;
            memcpy(&u, p + x * 2, 2);
            v = u;
        } else {
            v = (unsigned)p[x * 2] << 8 | p[x * 2 + 1];
        }
        c[0] = v >> 11;
        c[1] = (v >> 5) & 63u;
        c[2] = v & 31u;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    fz_tex_style ts;
    zl_target t;
    zl_context ctx;
    fz_buf color, depth;
    uint8_t *color_before, *depth_before;
    zl_fixed pos[4 * 3];
    static const uint16_t quad[6] = {0, 1, 2, 0, 2, 3};
    uint8_t vcol[4 * 3];
    zl_mesh mesh;
    zl_mat4 proj;
    const zl_mat4 *mvp = NULL;
    zl_status st, check;
    unsigned i, x, y, bpp;
    int32_t xmin = W, xmax = -1, ymin = H, ymax = -1;
    uint32_t f = fz_u8(&in);
    memset(&ts, 0, sizeof ts);
    t.format = (uint8_t)(fz_u8(&in) % 3u);
    bpp = zl_format_bytes((zl_format)t.format);
    t.width = W;
    t.height = H;
    t.color_stride = (int32_t)(W * bpp + (fz_u8(&in) % 3u) * 2u);
    t.depth_stride = W * 2;
    fz_buf_alloc(&color, (size_t)t.color_stride * (H - 1) + W * bpp);
    fz_buf_alloc(&depth, (size_t)W * H * 2);
    t.color = color.data;
    t.depth = (uint16_t *)(void *)depth.data;
    read_style(&in, &ts);
    for (i = 0; i < 4; i++) {
        /* pixel positions -8 .. W + 8 with a fraction, depth 0 .. 1 */
        pos[i * 3] = (zl_fixed)((int32_t)(fz_u16(&in) % ((W + 16) * 256)) * 256 - 8 * 65536);
        pos[i * 3 + 1] = (zl_fixed)((int32_t)(fz_u16(&in) % ((H + 16) * 256)) * 256 - 8 * 65536);
        pos[i * 3 + 2] = (zl_fixed)(fz_u16(&in));
        xmin = pos[i * 3] >> 16 < xmin ? pos[i * 3] >> 16 : xmin;
        xmax = (pos[i * 3] >> 16) + 1 > xmax ? (pos[i * 3] >> 16) + 1 : xmax;
        ymin = pos[i * 3 + 1] >> 16 < ymin ? pos[i * 3 + 1] >> 16 : ymin;
        ymax = (pos[i * 3 + 1] >> 16) + 1 > ymax ? (pos[i * 3 + 1] >> 16) + 1 : ymax;
    }
    for (i = 0; i < sizeof vcol; i++)
        vcol[i] = (uint8_t)fz_u8(&in);
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = pos;
    mesh.indices = quad;
    mesh.vertex_count = 4;
    mesh.triangle_count = 2;
    FZ_REQUIRE(zl_init(&ctx, &t) == ZL_OK, "zl_init");
    ctx.state.shading = (uint8_t)(f & 1u);
    ctx.state.depth_func = (uint8_t)(fz_u8(&in) % 8u);
    ctx.state.depth_write = (uint8_t)(fz_u8(&in) % 2u);
    if (f & 2u)
        mesh.vertex_colors = vcol;
    if (f & 4u) { /* through a perspective camera: w varies across the quad */
        FZ_REQUIRE(zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_ONE, ZL_FX_ONE / 4,
                                       ZL_FX_INT(64)) == ZL_OK,
                   "perspective");
        for (i = 0; i < 4; i++) { /* x, y -4 .. 4, z -0.5 .. -8.5 */
            pos[i * 3] = (pos[i * 3] >> 2) - ZL_FX_INT(4);
            pos[i * 3 + 1] = (pos[i * 3 + 1] >> 2) - ZL_FX_INT(4);
            pos[i * 3 + 2] = -(ZL_FX_ONE / 2 + pos[i * 3 + 2] * 8);
        }
        mvp = &proj;
    }
    FZ_REQUIRE(zl_clear(&ctx, (zl_rgb){(uint8_t)f, 90, 200}, (uint16_t)(40000u + fz_u8(&in))) == ZL_OK, "zl_clear");
    ctx.style = ts.style;
    color_before = (uint8_t *)malloc(color.size);
    depth_before = (uint8_t *)malloc(depth.size);
    if (color_before == NULL || depth_before == NULL)
        abort();
    memcpy(color_before, color.data, color.size);
    memcpy(depth_before, depth.data, depth.size);
    check = zl_style_check(&ts.style);
    st = zl_draw_mesh(&ctx, &mesh, mvp);
    fz_buf_check(&color, "colour");
    fz_buf_check(&depth, "depth");
    if (check != ZL_OK) {
        FZ_REQUIRE(st == check, "draw %d, style check %d", (int)st, (int)check);
    } else if (mvp == NULL) {
        FZ_REQUIRE(st == ZL_OK, "draw %d with a valid style in pixel space", (int)st);
    } else {
        FZ_REQUIRE(st == ZL_OK || st == ZL_ERR_RANGE, "draw %d", (int)st);
    }
    if (st != ZL_OK || (ts.style.blend == ZL_BLEND_ALPHA && ts.style.alpha == 0)) {
        FZ_REQUIRE(memcmp(color.data, color_before, color.size) == 0, "colour written (status %d, blend %u alpha %u)",
                   (int)st, ts.style.blend, ts.style.alpha);
        FZ_REQUIRE(memcmp(depth.data, depth_before, depth.size) == 0, "depth written (status %d, blend %u alpha %u)",
                   (int)st, ts.style.blend, ts.style.alpha);
    }
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            unsigned now[3], old[3], k;
            zl_target before = t;
            int inside = (int32_t)x >= xmin && (int32_t)x <= xmax && (int32_t)y >= ymin && (int32_t)y <= ymax;
            before.color = color_before;
            pixel_channels(&t, x, y, now);
            pixel_channels(&before, x, y, old);
            for (k = 0; k < 3; k++) {
                if (mvp == NULL && !inside)
                    FZ_REQUIRE(now[k] == old[k], "pixel %u,%u outside the quad's box changed", x, y);
                if (ts.style.blend == ZL_BLEND_ADD)
                    FZ_REQUIRE(now[k] >= old[k], "pixel %u,%u channel %u darker under ADD: %u < %u", x, y, k, now[k],
                               old[k]);
            }
        }
    }
    free(color_before);
    free(depth_before);
    fz_buf_free(&color);
    fz_buf_free(&depth);
    free(ts.texels);
    return 0;
}

/* SPDX-License-Identifier: MIT */
/*
 * Blending and texel formats (zline.h: TEXEL FORMATS AND SIZES, BLENDING)
 * against an exact per-pixel reference written here:
 *   - which pixels a triangle covers and the colour it would write there are
 *     taken from the same triangle drawn unblended into an RGB888 target (8
 *     bits per channel: the source colour before any packing), and the
 *     RGBA4444 texel alpha from the same draw of an "alpha as grey" copy of
 *     the texture;
 *   - the blend equations, the RGB565 widening and packing, the alpha-0
 *     discard and the depth writes are then computed here, per pixel, with
 *     plain divisions, and must match the library's output bit for bit in
 *     RGB565, RGB565_BE and RGB888.
 * Also: repeat and clamp of textures of any size (not a power of two) by
 * hand, and scanline / band mode byte-identical to frame mode with blended
 * meshes in every format.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zl_visibility.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 40, H = 30, TW = 5, TH = 3 };

static uint32_t rng = 12345;

static unsigned next_rand(void)
{
    return zt_rand(&rng);
}

/* ------------------------------------------------------------ targets */

static uint8_t color[W * H * 3];
static uint16_t depth[W * H];
static uint8_t src888[W * H * 3], alpha888[W * H * 3];
static uint16_t srcdepth[W * H], alphadepth[W * H];
static uint8_t bg[W * H * 3];

static void init_ctx(zl_context *c, void *col, uint16_t *dep, zl_format fmt)
{
    zl_target t;
    zt_target_packed(&t, col, dep, W, H, fmt);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(c, &t));
}

/* The 8-bit channels of pixel i of a buffer in format fmt (RGB565 widened
 * by bit replication). */
static void read_pixel(const uint8_t *buf, zl_format fmt, int i, unsigned out[3])
{
    unsigned v;
    if (fmt == ZL_FORMAT_RGB888) {
        out[0] = buf[i * 3];
        out[1] = buf[i * 3 + 1];
        out[2] = buf[i * 3 + 2];
        return;
    }
    if (fmt == ZL_FORMAT_RGB565_BE) {
        v = ((unsigned)buf[i * 2] << 8) | buf[i * 2 + 1];
    } else {
        uint16_t s;
        memcpy(&s, buf + i * 2, 2);
        v = s;
    }
    out[0] = ((v >> 11) << 3) | ((v >> 11) >> 2);
    out[1] = (((v >> 5) & 63u) << 2) | (((v >> 5) & 63u) >> 4);
    out[2] = ((v & 31u) << 3) | ((v & 31u) >> 2);
}

static void write_pixel(uint8_t *buf, zl_format fmt, int i, const unsigned c[3])
{
    if (fmt == ZL_FORMAT_RGB888) {
        buf[i * 3] = (uint8_t)c[0];
        buf[i * 3 + 1] = (uint8_t)c[1];
        buf[i * 3 + 2] = (uint8_t)c[2];
    } else {
        uint16_t v = (uint16_t)(((c[0] >> 3) << 11) | ((c[1] >> 2) << 5) | (c[2] >> 3));
        if (fmt == ZL_FORMAT_RGB565_BE) {
            buf[i * 2] = (uint8_t)(v >> 8);
            buf[i * 2 + 1] = (uint8_t)v;
        } else {
            memcpy(buf + i * 2, &v, 2);
        }
    }
}

/* --------------------------------------------------------------- scene */

/* RGBA4444 texels with every alpha 0..15 and random colours, and the same
 * texture with the alpha as grey (r = g = b = alpha, opaque). */
static uint16_t tex4444[TW * TH], texgrey[TW * TH];
static zl_texture tex, texg;
/* the same for an 8 x 4 texture: a power of two, the blended fast loop's */
static uint16_t p4444[8 * 4], pgrey[8 * 4];
static zl_texture ptex, ptexg;

static void make_textures(void)
{
    int i;
    for (i = 0; i < TW * TH; i++) {
        unsigned a = (unsigned)i % 16u, c = next_rand() & 0xFFFu;
        tex4444[i] = (uint16_t)((c << 4) | a);
        texgrey[i] = (uint16_t)((a << 12) | (a << 8) | (a << 4) | 15u);
    }
    memset(&tex, 0, sizeof tex);
    tex.texels = tex4444;
    tex.width = TW;
    tex.height = TH;
    tex.stride = TW;
    tex.format = ZL_TEXEL_RGBA4444;
    texg = tex;
    texg.texels = texgrey;
    for (i = 0; i < 8 * 4; i++) {
        unsigned a = (unsigned)(i * 7) % 16u, c = next_rand() & 0xFFFu;
        p4444[i] = (uint16_t)((c << 4) | a);
        pgrey[i] = (uint16_t)((a << 12) | (a << 8) | (a << 4) | 15u);
    }
    ptex = tex;
    ptex.texels = p4444;
    ptex.width = 8;
    ptex.height = 4;
    ptex.stride = 8;
    ptexg = ptex;
    ptexg.texels = pgrey;
}

static zl_fixed pos[9];
static zl_fixed uv[6];
static uint8_t vcol[9];
static const uint16_t idx[3] = {0, 1, 2};

static void random_triangle(void)
{
    int k;
    for (k = 0; k < 3; k++) {
        pos[k * 3] = (zl_fixed)(next_rand() % ((W + 20) * 65536u)) - 10 * 65536;
        pos[k * 3 + 1] = (zl_fixed)(next_rand() % ((H + 20) * 65536u)) - 10 * 65536;
        pos[k * 3 + 2] = (zl_fixed)(next_rand() % 65536u);
    }
    for (k = 0; k < 6; k++)
        uv[k] = (zl_fixed)(next_rand() % (6u * 65536u)) - 3 * 65536;
    for (k = 0; k < 9; k++)
        vcol[k] = (uint8_t)next_rand();
}

/* The style of case n: texture (RGBA4444, RGB565 view of it, none), blend
 * mode, shading. */
typedef struct {
    int textured; /* 0 none, 1 RGBA4444, 2 the same texels read as RGB565 */
    unsigned blend, alpha, gouraud, persp, depth_write, mask, pow2, filter;
} blend_case;

static void apply(zl_context *c, const blend_case *bc, const zl_texture *t, unsigned blend)
{
    static zl_texture t565;
    zl_style_default(&c->style);
    zl_state_default(&c->state);
    c->state.shading = (uint8_t)(bc->gouraud ? ZL_SHADE_GOURAUD : ZL_SHADE_FLAT);
    c->state.color.r = 200;
    c->state.color.g = 90;
    c->state.color.b = 17;
    c->state.depth_write = (uint8_t)bc->depth_write;
    c->state.color_mask = (uint8_t)bc->mask;
    if (bc->textured) {
        t565 = *t;
        if (bc->textured == 2)
            t565.format = ZL_TEXEL_RGB565;
        c->style.texture = &t565;
        c->style.texcoords = uv;
        c->style.tex_mapping = (uint8_t)bc->persp;
    }
    c->style.blend = (uint8_t)blend;
    c->style.alpha = (uint8_t)bc->alpha;
    c->style.tex_filter = (uint8_t)bc->filter;
}

/* Unblended untextured Gouraud into RGB565 (either byte order) is lane
 * colour (zl_span.h; zline.h's Gouraud bound): within one RGB565 step of
 * the RGB888 capture's packing, not equal to it. The bound itself is
 * checked against the exact mix in test_paths_match_reference.c and
 * test_gouraud_bound.c; here the blending is the subject. */
static int lane_case(const blend_case *bc, zl_format fmt)
{
    return bc->gouraud && !bc->textured && bc->blend == ZL_BLEND_OFF && fmt != ZL_FORMAT_RGB888;
}

static unsigned value565(const uint8_t *p, zl_format fmt)
{
    uint16_t v;
    if (fmt == ZL_FORMAT_RGB565_BE)
        return (unsigned)((p[0] << 8) | p[1]);
    memcpy(&v, p, 2);
    return v;
}

/* Every channel of the RGB565 pixels a and b within one step. */
static int within_one_step(const uint8_t *a, const uint8_t *b, zl_format fmt)
{
    static const unsigned shift[3] = {11, 5, 0}, mask[3] = {31, 63, 31};
    unsigned va = value565(a, fmt), vb = value565(b, fmt), k;
    for (k = 0; k < 3; k++) {
        int ca = (int)((va >> shift[k]) & mask[k]), cb = (int)((vb >> shift[k]) & mask[k]);
        if (ca - cb > 1 || cb - ca > 1)
            return 0;
    }
    return 1;
}

/* One case in one format: background, unblended captures, blended draw, and
 * the reference compared pixel by pixel. Returns the number of pixels the
 * blend changed (to check the test is not vacuous). */
static int run_case(const blend_case *bc, zl_format fmt)
{
    static zl_mat4 mvp; /* a perspective camera over the pixel-space-like triangle */
    zl_context c, cs;
    zl_mesh m = {pos, idx, vcol, NULL, 3, 1};
    zl_rgb black = {0, 0, 0};
    int i, changed = 0;
    const zl_mat4 *mp = NULL;
    (void)mvp;
    /* captures: unblended colour, and the texel alpha as grey */
    init_ctx(&cs, src888, srcdepth, ZL_FORMAT_RGB888);
    apply(&cs, bc, bc->pow2 ? &ptex : &tex, ZL_BLEND_OFF);
    cs.state.depth_write = 1;
    cs.state.color_mask = ZL_MASK_RGB;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&cs, black, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&cs, &m, mp));
    init_ctx(&cs, alpha888, alphadepth, ZL_FORMAT_RGB888);
    apply(&cs, bc, bc->pow2 ? &ptexg : &texg, ZL_BLEND_OFF);
    cs.state.depth_write = 1;
    cs.state.color_mask = ZL_MASK_RGB;
    cs.state.shading = ZL_SHADE_FLAT;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&cs, black, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&cs, &m, mp));
    /* the background: random bytes, depth 65535 (so every covered pixel passes LESS) */
    for (i = 0; i < W * H * 3; i++)
        bg[i] = (uint8_t)next_rand();
    memcpy(color, bg, sizeof color);
    for (i = 0; i < W * H; i++)
        depth[i] = 65535;
    init_ctx(&c, color, depth, fmt);
    apply(&c, bc, bc->pow2 ? &ptex : &tex, bc->blend);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c, &m, mp));
    for (i = 0; i < W * H; i++) {
        unsigned old[3], src[3], ref[3], a = bc->alpha, k;
        uint8_t expect[3];
        uint16_t zexp = 65535;
        size_t bpp = zl_format_bytes(fmt);
        read_pixel(bg, fmt, i, old);
        memcpy(ref, old, sizeof ref);
        if (srcdepth[i] != 65535) { /* covered */
            src[0] = src888[i * 3];
            src[1] = src888[i * 3 + 1];
            src[2] = src888[i * 3 + 2];
            if (bc->textured == 1) /* alpha888 holds 17 * texel alpha in every channel */
                a = (bc->alpha * alpha888[i * 3] + 127) / 255;
            if (bc->blend == ZL_BLEND_OFF || a != 0) {
                for (k = 0; k < 3; k++) {
                    unsigned v;
                    if (!(bc->mask & (1u << k)))
                        continue;
                    if (bc->blend == ZL_BLEND_OFF)
                        v = src[k];
                    else if (bc->blend == ZL_BLEND_ALPHA)
                        v = (src[k] * a + old[k] * (255 - a) + 127) / 255;
                    else
                        v = old[k] + (src[k] * a + 127) / 255 > 255 ? 255 : old[k] + (src[k] * a + 127) / 255;
                    ref[k] = v;
                }
                if (bc->depth_write)
                    zexp = srcdepth[i];
            }
        }
        /* masked channels keep their old bits exactly, so pack the masked
         * reference the way a write would and take the untouched bits from
         * the background */
        memcpy(expect, bg + (size_t)i * bpp, bpp);
        if (srcdepth[i] != 65535 && (bc->blend == ZL_BLEND_OFF || a != 0)) {
            uint8_t packed[3];
            unsigned keepbits[3] = {0, 0, 0};
            write_pixel(packed, fmt, 0, ref);
            if (fmt == ZL_FORMAT_RGB888) {
                for (k = 0; k < 3; k++)
                    if (bc->mask & (1u << k))
                        expect[k] = packed[k];
            } else {
                uint16_t pv, ov, keep = 0;
                if (!(bc->mask & 1u))
                    keep |= 0xF800u;
                if (!(bc->mask & 2u))
                    keep |= 0x07E0u;
                if (!(bc->mask & 4u))
                    keep |= 0x001Fu;
                (void)keepbits;
                if (fmt == ZL_FORMAT_RGB565_BE) {
                    pv = (uint16_t)((packed[0] << 8) | packed[1]);
                    ov = (uint16_t)((expect[0] << 8) | expect[1]);
                    pv = (uint16_t)((ov & keep) | (pv & (uint16_t)~keep));
                    expect[0] = (uint8_t)(pv >> 8);
                    expect[1] = (uint8_t)pv;
                } else {
                    memcpy(&pv, packed, 2);
                    memcpy(&ov, expect, 2);
                    pv = (uint16_t)((ov & keep) | (pv & (uint16_t)~keep));
                    memcpy(expect, &pv, 2);
                }
            }
        }
        if ((memcmp(expect, color + (size_t)i * bpp, bpp) != 0 &&
             !(lane_case(bc, fmt) && within_one_step(expect, color + (size_t)i * bpp, fmt))) ||
            zexp != depth[i]) {
            char msg[160];
            snprintf(msg, sizeof msg, "pixel %d (%d, %d) format %d blend %u tex %d: expected %02x%02x%02x z %u, got %02x%02x%02x z %u",
                    i, i % W, i / W, (int)fmt, bc->blend, bc->textured, expect[0], expect[1],
                    bpp == 3 ? expect[2] : 0, zexp, color[i * bpp], color[i * bpp + 1], bpp == 3 ? color[i * bpp + 2] : 0,
                    depth[i]);
            TEST_FAIL_MESSAGE(msg);
        }
        changed += memcmp(bg + (size_t)i * bpp, color + (size_t)i * bpp, bpp) != 0;
    }
    return changed;
}

static void test_blend_matches_reference_in_every_format(void)
{
    int n, changed = 0, f;
    make_textures();
    for (n = 0; n < 400; n++) {
        blend_case bc;
        random_triangle();
        bc.textured = (int)(next_rand() % 3u);
        bc.blend = next_rand() % 3u;
        bc.alpha = n % 7 == 0 ? 0u : (n % 5 == 0 ? 255u : next_rand() % 256u);
        bc.gouraud = next_rand() % 2u;
        bc.persp = next_rand() % 2u;
        bc.depth_write = n % 4 != 0;
        bc.mask = n % 6 == 0 ? (1u + next_rand() % 7u) : ZL_MASK_RGB;
        bc.pow2 = next_rand() % 2u;
        bc.filter = next_rand() % 2u;
        for (f = 0; f < 3; f++)
            changed += run_case(&bc, (zl_format)f);
    }
    TEST_ASSERT_GREATER_THAN(W * H, changed);
}

/* Repeat and clamp with a 5 x 3 texture: a quad of 1 pixel per texel whose
 * coordinates run from -1 to +2 texture sizes, so every pixel centre is a
 * texel centre and the index is known exactly. */
static void test_any_size_repeat_and_clamp(void)
{
    static const zl_fixed quad[] = {0, 0, 0, ZL_FX_INT(15), 0, 0, ZL_FX_INT(15), ZL_FX_INT(9), 0, 0, ZL_FX_INT(9), 0};
    static const zl_fixed quv[] = {-ZL_FX_ONE, -ZL_FX_ONE, ZL_FX_INT(2), -ZL_FX_ONE,
                                   ZL_FX_INT(2), ZL_FX_INT(2), -ZL_FX_ONE, ZL_FX_INT(2)};
    static const uint16_t qidx[] = {0, 1, 2, 0, 2, 3};
    static uint16_t tx565[TW * TH];
    zl_mesh m = {quad, qidx, NULL, NULL, 4, 2};
    zl_context c;
    zl_texture t;
    zl_rgb black = {0, 0, 0};
    int ws, wt, x, y, fmt4444;
    for (x = 0; x < TW * TH; x++)
        tx565[x] = (uint16_t)(((x + 1) << 11) | ((x * 3) << 5) | 7);
    for (fmt4444 = 0; fmt4444 < 2; fmt4444++)
        for (ws = 0; ws < 2; ws++)
            for (wt = 0; wt < 2; wt++) {
                memset(&t, 0, sizeof t);
                t.texels = tx565;
                t.width = TW;
                t.height = TH;
                t.stride = TW;
                t.wrap_s = (uint8_t)ws;
                t.wrap_t = (uint8_t)wt;
                t.format = (uint8_t)fmt4444;
                init_ctx(&c, color, depth, ZL_FORMAT_RGB888);
                c.style.texture = &t;
                c.style.texcoords = quv;
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&c, black, 65535));
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c, &m, NULL));
                for (y = 0; y < 9; y++)
                    for (x = 0; x < 15; x++) {
                        int ci = x - TW, cj = y - TH, k;
                        unsigned tv, e[3];
                        if (ws == ZL_WRAP_CLAMP)
                            ci = ci < 0 ? 0 : (ci >= TW ? TW - 1 : ci);
                        else
                            ci = (ci + 2 * TW) % TW;
                        if (wt == ZL_WRAP_CLAMP)
                            cj = cj < 0 ? 0 : (cj >= TH ? TH - 1 : cj);
                        else
                            cj = (cj + 2 * TH) % TH;
                        tv = tx565[cj * TW + ci];
                        if (fmt4444) {
                            e[0] = (tv >> 12) * 17u;
                            e[1] = ((tv >> 8) & 15u) * 17u;
                            e[2] = ((tv >> 4) & 15u) * 17u;
                        } else {
                            e[0] = ((tv >> 11) << 3) | ((tv >> 11) >> 2);
                            e[1] = (((tv >> 5) & 63u) << 2) | (((tv >> 5) & 63u) >> 4);
                            e[2] = ((tv & 31u) << 3) | ((tv & 31u) >> 2);
                        }
                        for (k = 0; k < 3; k++)
                            TEST_ASSERT_EQUAL_UINT8(e[k], color[(y * W + x) * 3 + k]);
                    }
            }
}

/* Bilinear filtering against the rule of zline.h (TEXTURE FILTERING)
 * computed here in double: a pixel-space quad 16 x 8 pixels whose texture
 * coordinates run from -1/2 to 3/2 of the texture on each axis, so the
 * coordinate at every pixel centre is an exact multiple of 1/256 texel;
 * repeat and clamp, a power-of-two (8 x 4) and a 5 x 3 RGBA4444 texture.
 * Colour unblended, and alpha through an ALPHA blend over black. */
static double tex_channel(const zl_texture *t, int i, int j, int ch)
{
    unsigned v;
    if (t->wrap_s == ZL_WRAP_CLAMP)
        i = i < 0 ? 0 : (i >= t->width ? t->width - 1 : i);
    else
        i = ((i % t->width) + t->width) % t->width;
    if (t->wrap_t == ZL_WRAP_CLAMP)
        j = j < 0 ? 0 : (j >= t->height ? t->height - 1 : j);
    else
        j = ((j % t->height) + t->height) % t->height;
    v = t->texels[j * t->stride + i];
    if (t->format == ZL_TEXEL_RGB565) {
        unsigned c = ch == 0 ? v >> 11 : (ch == 1 ? (v >> 5) & 63u : v & 31u);
        return (double)(ch == 1 ? (c << 2) | (c >> 4) : (c << 3) | (c >> 2));
    }
    return (double)(((v >> (12 - 4 * ch)) & 15u) * 17u);
}

static double floor_dd(double x)
{
    double f = (double)(long long)x;
    return f > x ? f - 1 : f;
}

static void test_bilinear_matches_rule(void)
{
    static const zl_fixed quad[] = {0, 0, 0, ZL_FX_INT(16), 0, 0, ZL_FX_INT(16), ZL_FX_INT(8), 0, 0, ZL_FX_INT(8), 0};
    static const zl_fixed quv[] = {-ZL_FX_HALF, -ZL_FX_HALF, ZL_FX_INT(3) / 2, -ZL_FX_HALF,
                                   ZL_FX_INT(3) / 2, ZL_FX_INT(3) / 2, -ZL_FX_HALF, ZL_FX_INT(3) / 2};
    static const uint16_t qidx[] = {0, 1, 2, 0, 2, 3};
    zl_mesh m = {quad, qidx, NULL, NULL, 4, 2};
    zl_context c;
    zl_rgb black = {0, 0, 0};
    int which, wrap, pass, x, y, k, mixed = 0;
    make_textures();
    /* which: 0 the 5x3 RGBA4444 texture, 1 the 8x4 one, 2 the 8x4 texels
     * read as RGB565 into an RGB565 target (the bilinear fast loop) */
    for (which = 0; which < 3; which++)
        for (wrap = 0; wrap < 4; wrap++)
            for (pass = 0; pass < 2 - (which == 2); pass++) {
                zl_texture t = which ? ptex : tex;
                zl_format fmt = which == 2 ? ZL_FORMAT_RGB565 : ZL_FORMAT_RGB888;
                t.wrap_s = (uint8_t)(wrap & 1);
                t.wrap_t = (uint8_t)(wrap >> 1);
                if (which == 2)
                    t.format = ZL_TEXEL_RGB565;
                init_ctx(&c, color, depth, fmt);
                c.style.texture = &t;
                c.style.texcoords = quv;
                c.style.tex_filter = ZL_FILTER_BILINEAR;
                c.style.blend = (uint8_t)(pass ? ZL_BLEND_ALPHA : ZL_BLEND_OFF);
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&c, black, 65535));
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c, &m, NULL));
                for (y = 0; y < 8; y++)
                    for (x = 0; x < 16; x++) {
                        /* texel coordinate at the centre: -size/2 + (x + 1/2) * 2 size / 16 */
                        double cu = -t.width / 2.0 + (x + 0.5) * t.width / 8.0;
                        double cv = -t.height / 2.0 + (y + 0.5) * t.height / 4.0;
                        double pu = cu - 0.5, pv = cv - 0.5, iu = floor_dd(pu), iv = floor_dd(pv);
                        double fu = pu - iu, fv = pv - iv, val[4];
                        for (k = 0; k < 4; k++) {
                            double top = tex_channel(&t, (int)iu, (int)iv, k) * (1 - fu) +
                                         tex_channel(&t, (int)iu + 1, (int)iv, k) * fu;
                            double bottom = tex_channel(&t, (int)iu, (int)iv + 1, k) * (1 - fu) +
                                            tex_channel(&t, (int)iu + 1, (int)iv + 1, k) * fu;
                            val[k] = floor_dd(top * (1 - fv) + bottom * fv + 0.5);
                        }
                        mixed += fu != 0 && fv != 0;
                        if (fmt == ZL_FORMAT_RGB565) {
                            uint16_t got, e = (uint16_t)((((unsigned)val[0] >> 3) << 11) |
                                                         (((unsigned)val[1] >> 2) << 5) | ((unsigned)val[2] >> 3));
                            memcpy(&got, color + (y * W + x) * 2, 2);
                            TEST_ASSERT_EQUAL_HEX16(e, got);
                            continue;
                        }
                        for (k = 0; k < 3; k++) {
                            unsigned e = (unsigned)val[k];
                            if (pass) /* over black: round(src a / 255), or untouched when a = 0 */
                                e = ((unsigned)val[k] * (unsigned)val[3] + 127u) / 255u;
                            TEST_ASSERT_EQUAL_UINT8(e, color[(y * W + x) * 3 + k]);
                        }
                    }
            }
    TEST_ASSERT_GREATER_THAN(100, mixed);
}

/* ------------------------------------------ scanline and band mode */

enum { NM = 6 };
static zl_fixed spos[NM][9], suv[NM][6];
static uint8_t scol[NM][9];
static zl_state sstate[NM];
static zl_style sstyle[NM];
static uint8_t frame_color[W * H * 3];
static uint16_t frame_depth[W * H];
static uint64_t work[(64 * 1024) / 8];

typedef struct {
    size_t bpp;
    int mismatches, rows;
} cmp_ctx;

static int compare_band(void *user, const zl_band *b)
{
    cmp_ctx *cc = user;
    uint16_t r;
    for (r = 0; r < b->rows; r++) {
        size_t y = (size_t)b->first_row + r;
        const uint8_t *col = (const uint8_t *)b->color + (size_t)r * (size_t)b->color_stride;
        const uint8_t *dep = (const uint8_t *)b->depth + (size_t)r * (size_t)b->depth_stride;
        if (memcmp(col, frame_color + y * W * cc->bpp, W * cc->bpp) != 0 || memcmp(dep, frame_depth + y * W, W * 2) != 0)
            cc->mismatches++;
        cc->rows++;
    }
    return 0;
}

static void test_scanline_and_bands_identical_to_frame(void)
{
    static const uint16_t bands[] = {1, 3, H};
    static const uint16_t sidx[3] = {0, 1, 2};
    zl_rgb clear = {30, 60, 90};
    int scene_no, i, k, f, b;
    make_textures();
    for (scene_no = 0; scene_no < 40; scene_no++) {
        for (i = 0; i < NM; i++) {
            for (k = 0; k < 3; k++) {
                spos[i][k * 3] = (zl_fixed)(next_rand() % ((W + 10) * 65536u)) - 5 * 65536;
                spos[i][k * 3 + 1] = (zl_fixed)(next_rand() % ((H + 10) * 65536u)) - 5 * 65536;
                spos[i][k * 3 + 2] = (zl_fixed)(next_rand() % 65536u);
            }
            for (k = 0; k < 6; k++)
                suv[i][k] = (zl_fixed)(next_rand() % (4u * 65536u)) - 2 * 65536;
            for (k = 0; k < 9; k++)
                scol[i][k] = (uint8_t)next_rand();
            zl_state_default(&sstate[i]);
            zl_style_default(&sstyle[i]);
            sstate[i].shading = (uint8_t)(next_rand() % 2u);
            sstate[i].color.r = (uint8_t)next_rand();
            sstate[i].depth_write = (uint8_t)(i == 0 || next_rand() % 2u);
            if (i > 0) {
                sstyle[i].blend = (uint8_t)(next_rand() % 3u);
                sstyle[i].alpha = (uint8_t)next_rand();
                if (next_rand() % 2u) {
                    sstyle[i].texture = &tex;
                    sstyle[i].texcoords = suv[i];
                    sstyle[i].tex_mapping = (uint8_t)(next_rand() % 2u);
                }
            }
        }
        for (f = 0; f < 3; f++) {
            zl_context c;
            size_t bpp = zl_format_bytes((zl_format)f);
            init_ctx(&c, frame_color, frame_depth, (zl_format)f);
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&c, clear, 65535));
            for (i = 0; i < NM; i++) {
                zl_mesh m = {spos[i], sidx, scol[i], NULL, 3, 1};
                c.state = sstate[i];
                c.style = sstyle[i];
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c, &m, NULL));
            }
            for (b = 0; b < 3; b++) {
                zl_frame_config cfg;
                zl_frame fr;
                cmp_ctx cc;
                size_t bytes;
                zt_frame_config_of(&cfg, W, H, bands[b], (zl_format)f);
                zt_frame_capacity(&cfg, NM, 3 * NM, NM, 8 * NM);
                cfg.gouraud = 1;
                cfg.styled = 1;
                cfg.textured = 1;
                bytes = zl_frame_bytes(&cfg);
                TEST_ASSERT_TRUE(bytes > 0 && bytes <= sizeof work);
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&fr, &cfg, work, bytes, clear, 65535));
                for (i = 0; i < NM; i++) {
                    zl_mesh m = {spos[i], sidx, scol[i], NULL, 3, 1};
                    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_styled(&fr, &m, NULL, &sstate[i], &sstyle[i]));
                }
                cc.bpp = bpp;
                cc.mismatches = 0;
                cc.rows = 0;
                TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&fr, compare_band, &cc));
                TEST_ASSERT_EQUAL_INT(H, cc.rows);
                TEST_ASSERT_EQUAL_INT(0, cc.mismatches);
            }
        }
    }
}

static void test_blend_state_checked(void)
{
    zl_style s;
    zl_frame_config cfg;
    zl_frame fr;
    zl_state st;
    zl_mesh m = {spos[0], idx, NULL, NULL, 3, 1};
    zl_rgb clear = {0, 0, 0};
    zl_style_default(&s);
    TEST_ASSERT_EQUAL_UINT8(ZL_BLEND_OFF, s.blend);
    TEST_ASSERT_EQUAL_UINT8(255, s.alpha);
    s.blend = 3;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_style_check(&s));
    s.blend = ZL_BLEND_ADD;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_style_check(&s));
    make_textures();
    s.texture = &tex;
    s.texcoords = uv;
    tex.format = 2;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_style_check(&s));
    tex.format = ZL_TEXEL_RGBA4444;
    s.tex_filter = 2;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_style_check(&s));
    s.tex_filter = ZL_FILTER_BILINEAR;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_style_check(&s));
    tex.format = ZL_TEXEL_RGBA4444;
    tex.width = 0;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_style_check(&s));
    tex.width = 4097;
    tex.stride = 4097;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_style_check(&s));
    make_textures();
    /* scanline mode: blending needs the styled rows */
    memset(&cfg, 0, sizeof cfg);
    cfg.width = W;
    cfg.height = H;
    cfg.band_rows = 1;
    cfg.color_buffers = 1;
    cfg.max_meshes = 1;
    cfg.max_vertices = 3;
    cfg.max_triangles = 1;
    cfg.max_active = 8;
    cfg.styled = 1;
    zl_state_default(&st);
    zl_style_default(&s);
    s.blend = ZL_BLEND_ALPHA;
    TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&fr, &cfg, work, zl_frame_bytes(&cfg), clear, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_frame_add_mesh_styled(&fr, &m, NULL, &st, &s));
    cfg.styled = 0;
    cfg.textured = 1;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&fr, &cfg, work, zl_frame_bytes(&cfg), clear, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_frame_add_mesh_styled(&fr, &m, NULL, &st, &s));
}

/* zl_painter_order: random triangles around a perspective camera, some
 * behind the eye or beyond the far plane; the output must be a permutation
 * of the triangles (each with its vertices in order) whose keys, computed
 * here in double from the matrix (farthest vertex's z / w clamped to 0..1,
 * 0 behind the eye), never increase, and equal keys keep the later
 * triangle first. */
static void test_painter_order(void)
{
    enum { NT = 60, NV = 3 * NT };
    static zl_fixed p[NV * 3];
    static uint16_t in[NT * 3], out[NT * 3], order[NT];
    static uint32_t keys[NT];
    static double key[NT];
    static int used[NT];
    zl_mat4 proj, view, mvp;
    zl_vec3 eye = {0, 0, ZL_FX_INT(3)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_mesh m;
    int i, k, round;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_ONE, ZL_FX_ONE / 2,
                                                     ZL_FX_INT(20)));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
    zl_mat4_mul(&mvp, &proj, &view);
    for (round = 0; round < 20; round++) {
        for (i = 0; i < NV * 3; i++)
            p[i] = (zl_fixed)(next_rand() % (60u * 65536u)) - 30 * 65536;
        for (i = 0; i < NT * 3; i++)
            in[i] = (uint16_t)(round % 2 ? (unsigned)i : next_rand() % NV); /* shared vertices: equal keys */
        memset(&m, 0, sizeof m);
        m.positions = p;
        m.indices = in;
        m.vertex_count = NV;
        m.triangle_count = NT;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_painter_order(&m, &mvp, out, keys, order));
        for (i = 0; i < NT; i++) {
            double best = 0;
            for (k = 0; k < 3; k++) {
                const zl_fixed *v = p + in[i * 3 + k] * 3;
                double z = 0, w = 0, d;
                int c;
                for (c = 0; c < 3; c++) {
                    z += mvp.m[8 + c] / 65536.0 * (v[c] / 65536.0);
                    w += mvp.m[12 + c] / 65536.0 * (v[c] / 65536.0);
                }
                z += mvp.m[11] / 65536.0;
                w += mvp.m[15] / 65536.0;
                d = w <= 0 || z <= 0 ? 0 : (z >= w ? 1 : z / w);
                if (d > best)
                    best = d;
            }
            key[i] = best;
            used[i] = 0;
        }
        for (i = 0; i < NT; i++) {
            int src = -1, j;
            /* the input triangle this output triangle is (the first unused match) */
            for (j = 0; j < NT && src < 0; j++)
                if (!used[j] && in[j * 3] == out[i * 3] && in[j * 3 + 1] == out[i * 3 + 1] &&
                    in[j * 3 + 2] == out[i * 3 + 2])
                    src = j;
            TEST_ASSERT_TRUE_MESSAGE(src >= 0, "not a permutation of the triangles");
            used[src] = 1;
            order[i] = (uint16_t)src;
        }
        for (i = 0; i + 1 < NT; i++) {
            double a = key[order[i]], b = key[order[i + 1]];
            if (!(a >= b - 2.0 / 65536)) {
                char msg[120];
                snprintf(msg, sizeof msg, "round %d position %d: key %.6f before %.6f", round, i, a, b);
                TEST_FAIL_MESSAGE(msg);
            }
            if (a == b && round % 2) /* exactly equal (distinct vertices): the later one first */
                TEST_ASSERT_TRUE(order[i] > order[i + 1]);
        }
    }
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_painter_order(&m, &mvp, in, keys, order));
    in[0] = NV;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_painter_order(&m, &mvp, out, keys, order));
}

/*
 * Long flat blended spans into native RGB565 (zl_span_tex.c builds per-span
 * channel tables from 64 pixels on; shorter spans take the lane loop): a
 * triangle whose rows run from 200 pixels down to a few, depth varying
 * along x, over random RGB565 pixels and stored depths that pass, tie or
 * fail, in both modes, LESS and LEQUAL, with and without depth writes. The
 * fragment depths come from an unblended capture; the colour is computed
 * here with plain divisions.
 */
enum { LW = 208, LH = 10 };
/* colour and depth 4-byte aligned (the rows then allow the pair loop) */
static union {
    uint32_t align;
    uint16_t px[LW * LH];
} long_col_u, long_dep_u;
#define long_col long_col_u.px
#define long_dep long_dep_u.px
static uint16_t long_bg[LW * LH], long_zbg[LW * LH], long_zsrc[LW * LH];

static unsigned widen565(unsigned v, unsigned k)
{
    unsigned c = k == 0 ? v >> 11 : (k == 1 ? (v >> 5) & 63u : v & 31u);
    return k == 1 ? (c << 2) | (c >> 4) : (c << 3) | (c >> 2);
}

static void long_ctx(zl_context *c, uint16_t *col, uint16_t *dep)
{
    zl_target t;
    zt_target_packed(&t, col, dep, LW, LH, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(c, &t));
}

static void test_long_flat_spans_match_reference(void)
{
    static const zl_fixed lpos[9] = {ZL_FX_INT(1) / 3, 0, ZL_FX_INT(1) / 5, ZL_FX_INT(205), ZL_FX_INT(1) / 2, ZL_FX_INT(4) / 5,
                                     0, ZL_FX_INT(LH), ZL_FX_INT(1) / 2};
    zl_mesh m = {lpos, idx, NULL, NULL, 3, 1};
    zl_rgb black = {0, 0, 0};
    int n, i, changed = 0, long_rows = 0;
    for (n = 0; n < 48; n++) {
        zl_context c;
        unsigned blend = n % 2 ? ZL_BLEND_ADD : ZL_BLEND_ALPHA, func = (n / 2) % 2 ? ZL_LEQUAL : ZL_LESS;
        unsigned zwrite = (n / 4) % 2 == 0, a = n % 12 == 0 ? 255u : 1u + next_rand() % 255u, srcc[3], k;
        long_ctx(&c, long_col, long_zsrc); /* the capture: fragment depths */
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&c, black, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c, &m, NULL));
        for (i = 0; i < LW * LH; i++) {
            unsigned r = next_rand() % 4u, d = long_zsrc[i];
            long_bg[i] = (uint16_t)next_rand();
            long_zbg[i] = (uint16_t)(d == 65535 || r == 0 ? 65535u : (r == 1 ? d : (r == 2 && d > 0 ? d - 1u : 65535u)));
        }
        memcpy(long_col, long_bg, sizeof long_col);
        memcpy(long_dep, long_zbg, sizeof long_dep);
        long_ctx(&c, long_col, long_dep);
        c.state.color.r = (uint8_t)next_rand();
        c.state.color.g = (uint8_t)next_rand();
        c.state.color.b = (uint8_t)next_rand();
        c.state.depth_func = (uint8_t)func;
        c.state.depth_write = (uint8_t)zwrite;
        c.style.blend = (uint8_t)blend;
        c.style.alpha = (uint8_t)a;
        srcc[0] = c.state.color.r;
        srcc[1] = c.state.color.g;
        srcc[2] = c.state.color.b;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c, &m, NULL));
        for (i = 0; i < LW * LH; i++) {
            unsigned d = long_zsrc[i], old = long_bg[i], out[3];
            uint16_t expect = long_bg[i], zexp = long_zbg[i];
            if (d != 65535 && (func == ZL_LESS ? d < long_zbg[i] : d <= long_zbg[i])) {
                for (k = 0; k < 3; k++) {
                    unsigned o = widen565(old, k), add = (srcc[k] * a + 127u) / 255u;
                    out[k] = blend == ZL_BLEND_ALPHA ? (srcc[k] * a + o * (255u - a) + 127u) / 255u
                                                     : (o + add > 255u ? 255u : o + add);
                }
                expect = (uint16_t)(((out[0] >> 3) << 11) | ((out[1] >> 2) << 5) | (out[2] >> 3));
                if (zwrite)
                    zexp = (uint16_t)d;
            }
            if (expect != long_col[i] || zexp != long_dep[i]) {
                char msg[120];
                snprintf(msg, sizeof msg, "case %d pixel (%d, %d): expected %04x z %u, got %04x z %u", n, i % LW, i / LW,
                         expect, zexp, long_col[i], long_dep[i]);
                TEST_FAIL_MESSAGE(msg);
            }
            changed += expect != long_bg[i];
        }
    }
    for (i = 0; i < LH; i++) { /* rows of 64 pixels and more, and shorter ones */
        int x, len = 0;
        for (x = 0; x < LW; x++)
            len += long_zsrc[i * LW + x] != 65535;
        long_rows += len >= 64;
    }
    TEST_ASSERT_TRUE(long_rows >= 3 && long_rows < LH);
    TEST_ASSERT_TRUE(changed > 48 * 500);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_blend_matches_reference_in_every_format);
    RUN_TEST(test_any_size_repeat_and_clamp);
    RUN_TEST(test_bilinear_matches_rule);
    RUN_TEST(test_scanline_and_bands_identical_to_frame);
    RUN_TEST(test_blend_state_checked);
    RUN_TEST(test_painter_order);
    RUN_TEST(test_long_flat_spans_match_reference);
    return UNITY_END();
}

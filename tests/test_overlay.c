/* SPDX-License-Identifier: MIT */
/*
 * 2D overlays (zl_overlay.h) against a naive full-frame painter written
 * here: every primitive decides each pixel of the frame on its own from the
 * contract (rectangles by inclusion, lines by the closed form of pixel i,
 * glyphs by their bits, images by the blend formula), in every zl_format.
 * Then the same overlay over a 3D scene is drawn into a full frame, and
 * into every band of scanline and band modes: the bytes must be identical.
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 53, H = 41, MAX_OPS = 24, TEX_W = 9, TEX_H = 7 };

static uint32_t rng = 2024u;

typedef enum { OP_FILL, OP_RECT, OP_LINE, OP_TEXT, OP_IMAGE } op_kind;
typedef struct {
    op_kind kind;
    int16_t x0, y0, x1, y1; /* line ends; x0, y0 the position of the rest */
    uint16_t w, h;
    zl_rgb color;
    uint8_t scale;
    char text[16];
    zl_texture image;
} overlay_op;

static overlay_op ops[MAX_OPS];
static int op_count;
static uint16_t texels[2][TEX_H * TEX_W];

/* ------------------------------------------------- the reference painter */

static unsigned bpp_of(zl_format f)
{
    return f == ZL_FORMAT_RGB888 ? 3u : 2u;
}

/* The colour rule of zline.h: RGB565 keeps the top bits of each channel. */
static void ref_store(uint8_t *frame, zl_format f, int x, int y, unsigned r, unsigned g, unsigned b)
{
    uint8_t *p = frame + ((size_t)y * W + (size_t)x) * bpp_of(f);
    unsigned v = ((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3);
    if (f == ZL_FORMAT_RGB888) {
        p[0] = (uint8_t)r;
        p[1] = (uint8_t)g;
        p[2] = (uint8_t)b;
    } else if (f == ZL_FORMAT_RGB565_BE) {
        p[0] = (uint8_t)(v >> 8);
        p[1] = (uint8_t)v;
    } else {
        uint16_t n = (uint16_t)v;
        memcpy(p, &n, 2);
    }
}

static void ref_load(const uint8_t *frame, zl_format f, int x, int y, unsigned rgb[3])
{
    unsigned ch[3], bits[3], k;
    zt_read_channels(frame, f, (unsigned)(y * W + x), ch, bits);
    for (k = 0; k < 3; k++) /* widen by bit replication */
        rgb[k] = bits[k] == 8 ? ch[k] : (ch[k] << (8 - bits[k])) | (ch[k] >> (2 * bits[k] - 8));
}

static void ref_plot(uint8_t *frame, zl_format f, long x, long y, zl_rgb c)
{
    if (x >= 0 && x < W && y >= 0 && y < H)
        ref_store(frame, f, (int)x, (int)y, c.r, c.g, c.b);
}

static void ref_fill(uint8_t *frame, zl_format f, const overlay_op *op)
{
    int x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            if (x >= op->x0 && x < op->x0 + op->w && y >= op->y0 && y < op->y0 + op->h)
                ref_store(frame, f, x, y, op->color.r, op->color.g, op->color.b);
}

static void ref_rect(uint8_t *frame, zl_format f, const overlay_op *op)
{
    int x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int inside = x >= op->x0 && x < op->x0 + op->w && y >= op->y0 && y < op->y0 + op->h;
            int border = x == op->x0 || x == op->x0 + op->w - 1 || y == op->y0 || y == op->y0 + op->h - 1;
            if (inside && border)
                ref_store(frame, f, x, y, op->color.r, op->color.g, op->color.b);
        }
}

/* Pixel i: i along the major axis, round(i d / m) (halves up) along the minor. */
static void ref_line(uint8_t *frame, zl_format f, const overlay_op *op)
{
    long dx = (long)op->x1 - op->x0, dy = (long)op->y1 - op->y0;
    long adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    long m = adx > ady ? adx : ady, d = adx > ady ? ady : adx, i;
    long sx = dx < 0 ? -1 : 1, sy = dy < 0 ? -1 : 1;
    for (i = 0; i <= m; i++) {
        long q = m == 0 ? 0 : (long)((2 * (int64_t)i * d + m) / (2 * (int64_t)m));
        long x = op->x0 + sx * (adx >= ady ? i : q), y = op->y0 + sy * (adx >= ady ? q : i);
        ref_plot(frame, f, x, y, op->color);
    }
}

static void ref_text(uint8_t *frame, zl_format f, const overlay_op *op)
{
    long cx = op->x0, cy = op->y0, s = op->scale;
    const char *t;
    for (t = op->text; *t != '\0'; t++) {
        unsigned col, row;
        long px, py;
        if (*t == '\n') {
            cx = op->x0;
            cy += 8 * s;
            continue;
        }
        for (col = 0; col < 5; col++)
            for (row = 0; row < 7; row++)
                if (zl_font_column(*t, col) >> row & 1u)
                    for (py = 0; py < s; py++)
                        for (px = 0; px < s; px++)
                            ref_plot(frame, f, cx + (long)col * s + px, cy + (long)row * s + py, op->color);
        cx += 6 * s;
    }
}

static void ref_image(uint8_t *frame, zl_format f, const overlay_op *op)
{
    const zl_texture *im = &op->image;
    int x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            long u = (long)x - op->x0, v = (long)y - op->y0;
            uint16_t t;
            unsigned src[3], old[3], a, k;
            if (u < 0 || v < 0 || u >= im->width || v >= im->height)
                continue;
            t = im->texels[v * im->stride + u];
            if (im->format == ZL_TEXEL_RGBA4444) {
                src[0] = (t >> 12) * 17u;
                src[1] = (t >> 8 & 15u) * 17u;
                src[2] = (t >> 4 & 15u) * 17u;
                a = (t & 15u) * 17u;
            } else {
                src[0] = ((unsigned)(t >> 11) << 3) | (unsigned)(t >> 13);
                src[1] = ((unsigned)(t >> 5 & 63u) << 2) | (unsigned)(t >> 9 & 3u);
                src[2] = ((unsigned)(t & 31u) << 3) | (unsigned)(t >> 2 & 7u);
                a = 255;
            }
            if (a == 0)
                continue;
            ref_load(frame, f, x, y, old);
            for (k = 0; k < 3; k++) {
                unsigned long num = (unsigned long)src[k] * a + (unsigned long)old[k] * (255u - a);
                src[k] = (unsigned)((2 * num + 255) / 510); /* nearest; no exact halves over 255 */
            }
            ref_store(frame, f, x, y, src[0], src[1], src[2]);
        }
}

static void ref_apply(uint8_t *frame, zl_format f)
{
    int i;
    for (i = 0; i < op_count; i++) {
        const overlay_op *op = &ops[i];
        switch (op->kind) {
        case OP_FILL: ref_fill(frame, f, op); break;
        case OP_RECT: ref_rect(frame, f, op); break;
        case OP_LINE: ref_line(frame, f, op); break;
        case OP_TEXT: ref_text(frame, f, op); break;
        case OP_IMAGE: ref_image(frame, f, op); break;
        }
    }
}

/* ---------------------------------------------------- the library's side */

static void lib_apply(const zl_canvas *c)
{
    int i;
    for (i = 0; i < op_count; i++) {
        const overlay_op *op = &ops[i];
        zl_status s = ZL_ERR_ARG;
        switch (op->kind) {
        case OP_FILL: s = zl_canvas_fill_rect(c, op->x0, op->y0, op->w, op->h, op->color); break;
        case OP_RECT: s = zl_canvas_rect(c, op->x0, op->y0, op->w, op->h, op->color); break;
        case OP_LINE: s = zl_canvas_line(c, op->x0, op->y0, op->x1, op->y1, op->color); break;
        case OP_TEXT: s = zl_canvas_text(c, op->x0, op->y0, op->text, op->scale, op->color); break;
        case OP_IMAGE: s = zl_canvas_image(c, op->x0, op->y0, &op->image); break;
        }
        TEST_ASSERT_EQUAL_INT(ZL_OK, s);
    }
}

static int16_t rand_coord(int32_t extent)
{
    return (int16_t)zt_rand_range(&rng, -extent / 2 - 8, extent + extent / 2);
}

static zl_rgb rand_rgb(void)
{
    zl_rgb c;
    c.r = (uint8_t)zt_rand(&rng);
    c.g = (uint8_t)zt_rand(&rng);
    c.b = (uint8_t)zt_rand(&rng);
    return c;
}

static void random_text(char *text, size_t size)
{
    static const char extra[] = {'\n', '\t', (char)0x80, (char)0xff, '~', ' '};
    size_t n = (size_t)zt_rand_range(&rng, 0, (int32_t)size - 1), i;
    for (i = 0; i < n; i++)
        text[i] = zt_rand_range(&rng, 0, 7) == 0 ? extra[zt_rand(&rng) % sizeof extra]
                                                 : (char)zt_rand_range(&rng, 32, 126);
    text[n] = '\0';
}

static void random_ops(void)
{
    int i, t, k;
    for (t = 0; t < 2; t++)
        for (k = 0; k < TEX_W * TEX_H; k++)
            texels[t][k] = (uint16_t)zt_rand(&rng);
    op_count = zt_rand_range(&rng, 1, MAX_OPS);
    for (i = 0; i < op_count; i++) {
        overlay_op *op = &ops[i];
        memset(op, 0, sizeof *op);
        op->kind = (op_kind)zt_rand_range(&rng, OP_FILL, OP_IMAGE);
        op->x0 = rand_coord(W);
        op->y0 = rand_coord(H);
        op->x1 = zt_rand_range(&rng, 0, 9) == 0 ? (int16_t)zt_rand_range(&rng, -16384, 16383) : rand_coord(W);
        op->y1 = zt_rand_range(&rng, 0, 4) == 0 ? op->y0 : rand_coord(H);
        op->w = (uint16_t)zt_rand_range(&rng, 0, W);
        op->h = (uint16_t)zt_rand_range(&rng, 0, H);
        op->color = rand_rgb();
        op->scale = (uint8_t)zt_rand_range(&rng, 1, 3);
        random_text(op->text, sizeof op->text);
        t = (int)zt_rand_range(&rng, 0, 1);
        op->image.texels = texels[t];
        op->image.format = (uint8_t)t; /* RGB565 or RGBA4444 */
        op->image.stride = TEX_W;
        op->image.width = (uint16_t)zt_rand_range(&rng, 1, TEX_W);
        op->image.height = (uint16_t)zt_rand_range(&rng, 1, TEX_H);
    }
}

/* ------------------------------------------------------------- 3D scene */

enum { NV = 12, NT = 4 };
static zl_fixed positions[NV * 3];
static uint16_t indices[NT * 3];
static uint8_t face_colors[NT * 3];
static zl_mesh mesh;

/* Pixel-space triangles, so the overlay draws over real 3D output. */
static void random_scene(void)
{
    int i;
    for (i = 0; i < NV; i++) {
        positions[i * 3] = zt_rand_range(&rng, -10, W + 10) * ZL_FX_ONE;
        positions[i * 3 + 1] = zt_rand_range(&rng, -10, H + 10) * ZL_FX_ONE;
        positions[i * 3 + 2] = zt_rand_range(&rng, 0, ZL_FX_ONE - 1);
    }
    for (i = 0; i < NT * 3; i++) {
        indices[i] = (uint16_t)i;
        face_colors[i] = (uint8_t)zt_rand(&rng);
    }
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.face_colors = face_colors;
    mesh.vertex_count = NV;
    mesh.triangle_count = NT;
}

static uint8_t frame3d[W * H * 3], expected[W * H * 3], got[W * H * 3];
static uint16_t depth[W * H];
static zl_context ctx;
static uint64_t work[40 * 1024 / 8];

static void render_frame_mode(zl_format f)
{
    zl_target t;
    zl_rgb bg = {20, 30, 40};
    zt_target_packed(&t, frame3d, depth, W, H, f);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, NULL));
}

static int overlay_then_copy(void *user, const zl_band *b)
{
    zl_canvas c;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_canvas_of_band(&c, b));
    lib_apply(&c);
    zt_band_copy((const zt_frame_copy *)user, b);
    return 0;
}

static void render_bands(zl_format f, uint16_t band_rows)
{
    zl_frame_config cfg;
    zl_frame frame;
    zl_state st;
    zl_rgb bg = {20, 30, 40};
    zt_frame_copy dst;
    dst.color = got;
    dst.depth = NULL;
    zt_frame_config_of(&cfg, W, H, band_rows, f);
    zt_frame_capacity(&cfg, 1, NV, NT, 8 * NT);
    TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
    zl_state_default(&st);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&frame, &cfg, work, sizeof work, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&frame, &mesh, NULL, &st));
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&frame, overlay_then_copy, &dst));
}

static void test_overlay_matches_reference_in_every_mode(void)
{
    static const zl_format formats[3] = {ZL_FORMAT_RGB565, ZL_FORMAT_RGB565_BE, ZL_FORMAT_RGB888};
    static const uint16_t band_rows[4] = {1, 7, 8, H};
    int round, fi, b;
    for (round = 0; round < 60; round++) {
        random_scene();
        random_ops();
        for (fi = 0; fi < 3; fi++) {
            zl_format f = formats[fi];
            size_t bytes = (size_t)W * H * bpp_of(f);
            zl_target t;
            zl_canvas c;
            render_frame_mode(f);
            memcpy(expected, frame3d, bytes);
            ref_apply(expected, f);
            zt_target_packed(&t, frame3d, depth, W, H, f);
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_canvas_of_target(&c, &t));
            lib_apply(&c);
            TEST_ASSERT_EQUAL_MEMORY(expected, frame3d, bytes);
            for (b = 0; b < 4; b++) {
                memset(got, 0xA5, sizeof got);
                render_bands(f, band_rows[b]);
                TEST_ASSERT_EQUAL_MEMORY(expected, got, bytes);
            }
        }
    }
}

/* The font table against glyphs drawn here by hand: column order, bit
 * order and the character mapping. */
static void test_font_glyphs(void)
{
    static const char *const a[7] = {".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"};
    static const char *const seven[7] = {"#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."};
    static const char *const question[7] = {".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."};
    unsigned col, row;
    for (row = 0; row < 7; row++)
        for (col = 0; col < 5; col++) {
            TEST_ASSERT_EQUAL_INT(a[row][col] == '#', zl_font_column('A', col) >> row & 1u);
            TEST_ASSERT_EQUAL_INT(seven[row][col] == '#', zl_font_column('7', col) >> row & 1u);
            TEST_ASSERT_EQUAL_INT(question[row][col] == '#', zl_font_column('?', col) >> row & 1u);
            TEST_ASSERT_EQUAL_INT(question[row][col] == '#', zl_font_column((char)0x7f, col) >> row & 1u);
            TEST_ASSERT_EQUAL_INT(0, zl_font_column(' ', col));
        }
    for (col = 32; col < 127; col++) { /* every printable glyph but space draws something */
        unsigned k, any = 0;
        for (k = 0; k < 5; k++)
            any |= zl_font_column((char)col, k);
        TEST_ASSERT_TRUE(col == ' ' || any != 0);
        TEST_ASSERT_EQUAL_INT(0, any & 0x80u);
    }
    TEST_ASSERT_EQUAL_UINT32(0, zl_text_width("", 1));
    TEST_ASSERT_EQUAL_UINT32(0, zl_text_width(NULL, 1));
    TEST_ASSERT_EQUAL_UINT32(18, zl_text_width("abc", 1));
    TEST_ASSERT_EQUAL_UINT32(48, zl_text_width("ab\nabcd", 2));
}

static void test_bad_arguments(void)
{
    zl_target t;
    zl_canvas c;
    zl_band band;
    zl_texture im;
    zl_rgb white = {255, 255, 255};
    zt_target_packed(&t, frame3d, NULL, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_canvas_of_target(&c, &t));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_of_target(NULL, &t));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_of_target(&c, NULL));
    t.format = 9;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_of_target(&c, &t));
    t.format = ZL_FORMAT_RGB888; /* stride of RGB565 rows: too small */
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_of_target(&c, &t));
    memset(&band, 0, sizeof band);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_of_band(&c, &band));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_of_band(&c, NULL));
    t.format = ZL_FORMAT_RGB565;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_canvas_of_target(&c, &t));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_fill_rect(NULL, 0, 0, 1, 1, white));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_text(&c, 0, 0, NULL, 1, white));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_canvas_text(&c, 0, 0, "x", 0, white));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_canvas_text(&c, 0, 0, "x", 17, white));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_canvas_line(&c, 0, 0, 16384, 0, white));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_canvas_line(&c, -16385, 0, 0, 0, white));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_canvas_line(&c, -16384, -16384, 16383, 16383, white));
    memset(&im, 0, sizeof im);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_image(&c, 0, 0, &im));
    im.texels = texels[0];
    im.width = 4;
    im.height = 1;
    im.stride = 3;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_image(&c, 0, 0, &im));
    im.stride = 4;
    im.format = 2;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_image(&c, 0, 0, &im));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_canvas_image(&c, 0, 0, NULL));
}

/* A writable band colour pointer: no cast between a band and a canvas. */
static void test_band_colour_is_writable(void)
{
    zl_band b;
    memset(&b, 0, sizeof b);
    b.color = got;
    ((uint8_t *)b.color)[0] = 7;
    TEST_ASSERT_EQUAL_UINT8(7, got[0]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_font_glyphs);
    RUN_TEST(test_bad_arguments);
    RUN_TEST(test_band_colour_is_writable);
    RUN_TEST(test_overlay_matches_reference_in_every_mode);
    return UNITY_END();
}

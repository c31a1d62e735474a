/* SPDX-License-Identifier: MIT */
/*
 * The asset consumer tests' firmware: a mesh and a texture converted at
 * build time by zline_add_mesh / zline_add_texture (cube_mesh.h,
 * crate_texture.h), drawn in scanline mode and sent through the panel
 * driver (zline::panel) to an ST7789 whose "bus" is this program: every byte
 * on the wire is recorded.
 *
 *   left   the cube, textured with crate.png (RGB565, perspective mapping)
 *   right  the cube lit per vertex from its generated normals (NORMALS area)
 *
 * Output: the wire's pixel bytes as hex, one line per row ("assets: row ..."),
 * and a summary line. The host build's output is the reference of the
 * Cortex-M builds' (run.sh compares the lines byte for byte). The program
 * itself fails when the frame is not plausible (what it can know alone):
 * the pixel count on the wire, the clear colour left where nothing is drawn,
 * the texture's colours on the textured cube.
 */
#include <stdio.h>
#include <string.h>

#include "cube_mesh.h"
#include "crate_texture.h"
#include "zl_spi_panel.h"
#include "zline/zline.h"

#define W 64u
#define H 40u

/* The fake bus: pixel bytes after RAMWR go to `pixels`. */
typedef struct {
    int dc, selected, after_ramwr;
    uint8_t last_command;
    uint32_t pixel_bytes, command_count;
    uint8_t pixels[W * H * 2u];
} wire;

static void bus_select(void *user, int selected)
{
    ((wire *)user)->selected = selected;
}

static void bus_set_dc(void *user, int data)
{
    ((wire *)user)->dc = data;
}

static void bus_write(void *user, const uint8_t *bytes, size_t count)
{
    wire *w = (wire *)user;
    size_t k;
    for (k = 0; k < count; k++) {
        if (!w->dc) {
            w->last_command = bytes[k];
            w->command_count++;
        } else if (w->last_command == 0x2Cu) { /* RAMWR: pixel data */
            if (w->pixel_bytes < sizeof w->pixels)
                w->pixels[w->pixel_bytes] = bytes[k];
            w->pixel_bytes++;
        }
    }
}

static void bus_delay(void *user, uint32_t ms)
{
    (void)user;
    (void)ms;
}

static zl_status cube_matrix(zl_mat4 *mvp, zl_fixed x)
{
    zl_mat4 proj, view, rx, ry, t, m, vm;
    zl_vec3 eye = {0, 0, ZL_FX_INT(5)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0}, at = {x, 0, 0};
    zl_status st = zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(50)), ZL_FX_INT(W) / (zl_fixed)H,
                                       ZL_FX_ONE / 2, ZL_FX_INT(20));
    if (st == ZL_OK)
        st = zl_mat4_look_at(&view, eye, target, up);
    if (st != ZL_OK)
        return st;
    zl_mat4_rotate_x(&rx, zl_angle_from_deg(ZL_FX_INT(25)));
    zl_mat4_rotate_y(&ry, zl_angle_from_deg(ZL_FX_INT(35)));
    zl_mat4_translate(&t, at);
    zl_mat4_mul(&m, &rx, &ry);
    zl_mat4_mul(&vm, &t, &m);
    zl_mat4_mul(&m, &view, &vm);
    zl_mat4_mul(mvp, &proj, &m);
    return ZL_OK;
}

static zl_status add_cubes(zl_frame *f, uint8_t *lit)
{
    static zl_style textured;
    zl_mat4 left, right;
    zl_state state;
    zl_lighting lt;
    zl_mesh lit_cube = cube_mesh;
    zl_status st = cube_matrix(&left, -ZL_FX_INT(3) / 2);
    if (st == ZL_OK)
        st = cube_matrix(&right, ZL_FX_INT(3) / 2);
    if (st != ZL_OK)
        return st;
    zl_state_default(&state);
    zl_style_default(&textured);
    textured.texture = &crate_texture;
    textured.texcoords = cube_texcoords;
    textured.tex_mapping = ZL_TEX_PERSPECTIVE;
    st = zl_frame_add_mesh_styled(f, &cube_mesh, &left, &state, &textured);
    if (st != ZL_OK)
        return st;
    zl_lighting_default(&lt);
    lt.light_count = 1;
    lt.lights[0].dir.x = ZL_FX_ONE;
    lt.lights[0].dir.y = ZL_FX_INT(2);
    lt.lights[0].dir.z = ZL_FX_INT(3);
    st = zl_light_vertices(&lt, NULL, &cube_mesh, cube_normals, lit);
    if (st != ZL_OK)
        return st;
    lit_cube.vertex_colors = lit;
    state.shading = ZL_SHADE_GOURAUD;
    return zl_frame_add_mesh(f, &lit_cube, &right, &state);
}

static int render(wire *w)
{
    static uint64_t work[4096]; /* 32 KB, 8-byte aligned */
    static uint8_t lit[3u * CUBE_VERTEX_COUNT];
    const zl_rgb clear = {0, 0, 96};
    zl_panel_bus bus = {0};
    zl_panel_config pc = zl_panel_config_st7789_240x240();
    zl_frame_config cfg = {0};
    zl_panel panel;
    zl_frame frame;

    bus.user = w;
    bus.select = bus_select;
    bus.set_dc = bus_set_dc;
    bus.write = bus_write;
    bus.delay_ms = bus_delay;
    cfg.width = W;
    cfg.height = H;
    cfg.band_rows = 1;
    cfg.format = ZL_FORMAT_RGB565_BE;
    cfg.color_buffers = 1;
    cfg.gouraud = 1;
    cfg.styled = 1;
    cfg.textured = 1;
    cfg.max_meshes = 2;
    cfg.max_vertices = 2u * CUBE_VERTEX_COUNT;
    cfg.max_triangles = 2u * CUBE_TRIANGLE_COUNT;
    cfg.max_active = 2u * CUBE_TRIANGLE_COUNT; /* a row crosses far fewer */
    if (zl_frame_bytes(&cfg) == 0 || zl_frame_bytes(&cfg) > sizeof work) {
        printf("assets: the frame needs %lu bytes of work memory\n", (unsigned long)zl_frame_bytes(&cfg));
        return 1;
    }
    if (zl_panel_init(&panel, &pc, &bus) != ZL_OK || zl_panel_window(&panel, 0, 0, W, H) != ZL_OK ||
        zl_frame_begin(&frame, &cfg, work, sizeof work, clear, 65535) != ZL_OK || add_cubes(&frame, lit) != ZL_OK ||
        zl_frame_render(&frame, zl_panel_send_band, &panel) != 0 || zl_panel_finish(&panel) != ZL_OK) {
        printf("assets: zline or the panel driver refused the scene\n");
        return 1;
    }
    return 0;
}

static uint16_t pixel_at(const wire *w, uint32_t x, uint32_t y)
{
    const uint8_t *p = &w->pixels[2u * (y * W + x)];
    return (uint16_t)((unsigned)p[0] << 8 | p[1]); /* RGB565, high byte first */
}

/* What the program can check alone; returns the failure count. */
static int plausible(const wire *w)
{
    const uint16_t clear565 = 96u >> 3, white = 0xFFFFu;
    uint32_t x, y, drawn = 0;
    int failures = 0, has_white = 0;
    if (w->pixel_bytes != W * H * 2u) {
        printf("assets: %lu pixel bytes on the wire, expected %lu\n", (unsigned long)w->pixel_bytes,
               (unsigned long)(W * H * 2u));
        return 1;
    }
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            uint16_t c = pixel_at(w, x, y);
            drawn += c != clear565;
            has_white |= x < W / 2 && c == white; /* the texture's diagonal, unlit */
        }
    if (pixel_at(w, 0, 0) != clear565 || pixel_at(w, W - 1, H - 1) != clear565) {
        printf("assets: the corners are not the clear colour\n");
        failures++;
    }
    if (drawn < W * H / 8u || drawn > W * H * 3u / 4u) {
        printf("assets: %lu pixels drawn, not the two cubes\n", (unsigned long)drawn);
        failures++;
    }
    if (!has_white) {
        printf("assets: no texel of the crate's white diagonal on the left cube\n");
        failures++;
    }
    return failures;
}

int main(void)
{
    static wire w;
    uint32_t x, y;
    int failures;
    memset(&w, 0, sizeof w);
    if (render(&w) != 0)
        return 1;
    failures = plausible(&w);
    for (y = 0; y < H && w.pixel_bytes == W * H * 2u; y++) {
        printf("assets: row %02lu ", (unsigned long)y);
        for (x = 0; x < 2u * W; x++)
            printf("%02x", (unsigned)w.pixels[2u * W * y + x]);
        printf("\n");
    }
    printf("assets: %lu commands, %lu pixel bytes, crate %ux%u, cube %u vertices %u triangles, %d failures\n",
           (unsigned long)w.command_count, (unsigned long)w.pixel_bytes, (unsigned)CRATE_WIDTH,
           (unsigned)CRATE_HEIGHT, (unsigned)CUBE_VERTEX_COUNT, (unsigned)CUBE_TRIANGLE_COUNT, failures);
    return failures;
}

/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: the OBJ loader (port/host zl_obj_load_mem) on arbitrary
 * bytes, then the loaded mesh rendered by the core.
 *
 * The first byte picks the options (normalise or not), the loader (plain or
 * keeping texture coordinates) and the size of the message buffer (0..62
 * bytes, guarded); the rest is the file. The text is
 * copied into a buffer of exactly its size without a terminating NUL, so a
 * read past the end is an AddressSanitizer finding. Checked:
 *   - success: counts within the zl_mesh limits, every index < vertex_count,
 *     triangle_count >= face_count, the message untouched (empty);
 *   - failure: a known status, *obj left empty, the message NUL-terminated
 *     inside its buffer and, when there is room, starting with the name;
 *   - a loaded mesh draws (ZL_OK, or ZL_ERR_RANGE for coordinates beyond
 *     +-16384 when not normalised) into a guarded target without a write
 *     outside it.
 */
#include "fz_common.h"
#include "zl_obj.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void draw_obj(const zl_obj *obj)
{
    enum { W = 24, H = 16 };
    fz_buf color, depth;
    zl_target t;
    zl_context ctx;
    zl_mat4 proj, view, mvp;
    zl_vec3 eye = {0, 0, ZL_FX_INT(3)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_mesh mesh = zl_obj_mesh(obj);
    zl_status st;
    fz_buf_alloc(&color, (size_t)W * H * 2);
    fz_buf_alloc(&depth, (size_t)W * H * 2);
    t.color = color.data;
    t.color_stride = W * 2;
    t.depth = (uint16_t *)(void *)depth.data;
    t.depth_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB565;
    FZ_REQUIRE(zl_init(&ctx, &t) == ZL_OK, "zl_init");
    FZ_REQUIRE(zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_ONE * 3 / 2, ZL_FX_ONE / 10,
                                   ZL_FX_INT(100)) == ZL_OK,
               "perspective");
    FZ_REQUIRE(zl_mat4_look_at(&view, eye, target, up) == ZL_OK, "look_at");
    zl_mat4_mul(&mvp, &proj, &view);
    FZ_REQUIRE(zl_clear(&ctx, (zl_rgb){0, 0, 0}, 65535) == ZL_OK, "zl_clear");
    st = zl_draw_mesh(&ctx, &mesh, &mvp);
    FZ_REQUIRE(st == ZL_OK || st == ZL_ERR_RANGE, "zl_draw_mesh of a loaded OBJ: %d", st);
    /* the pixel-space path takes any Q16.16 position */
    st = zl_draw_mesh(&ctx, &mesh, NULL);
    FZ_REQUIRE(st == ZL_OK, "zl_draw_mesh of a loaded OBJ in pixel space: %d", st);
    fz_buf_check(&color, "colour");
    fz_buf_check(&depth, "depth");
    fz_buf_free(&color);
    fz_buf_free(&depth);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    zl_obj obj;
    zl_obj_options opt;
    fz_buf msg;
    char *text;
    size_t msg_size, i;
    zl_obj_status st;
    uint8_t sel = size > 0 ? data[0] : 0;
    if (size > 0) {
        data++;
        size--;
    }
    zl_obj_options_default(&opt);
    opt.normalize = sel & 1u;
    msg_size = (sel >> 1) % 63;
    fz_buf_alloc(&msg, msg_size);
    text = (char *)malloc(size ? size : 1);
    if (text == NULL)
        abort();
    if (size > 0)
        memcpy(text, data, size);
    /* bit 7 of the selector: the loader that keeps texture coordinates
     * (vertices split at vt seams) */
    if (sel & 128u)
        st = zl_obj_load_mem_tex(&obj, size ? text : NULL, size, "fuzz.obj", &opt,
                                 msg_size ? (char *)msg.data : NULL, msg_size);
    else
        st = zl_obj_load_mem(&obj, size ? text : NULL, size, "fuzz.obj", &opt, msg_size ? (char *)msg.data : NULL,
                             msg_size);
    fz_buf_check(&msg, "message");
    if (msg_size > 0)
        FZ_REQUIRE(memchr(msg.data, '\0', msg_size) != NULL, "message not NUL-terminated in %zu bytes", msg_size);
    if (st == ZL_OBJ_OK) {
        FZ_REQUIRE(obj.vertex_count <= ZL_OBJ_MAX_VERTICES && obj.triangle_count <= ZL_OBJ_MAX_TRIANGLES,
                   "counts %u %u", obj.vertex_count, obj.triangle_count);
        FZ_REQUIRE(obj.triangle_count >= obj.face_count && obj.triangle_count > 0, "triangles %u faces %u",
                   obj.triangle_count, obj.face_count);
        FZ_REQUIRE(msg_size == 0 || msg.data[0] == '\0', "message on success: %s", (char *)msg.data);
        /* normalised positions are in -1 .. 1 for every valid file (issue 16:
         * denormal boxes and boxes near DBL_MAX once gave NaN here) */
        for (i = 0; opt.normalize && i < (size_t)obj.vertex_count * 3; i++)
            FZ_REQUIRE(obj.positions[i] >= -65536 && obj.positions[i] <= 65536, "normalised coordinate %ld",
                       (long)obj.positions[i]);
        for (i = 0; i < (size_t)obj.triangle_count * 3; i++)
            FZ_REQUIRE(obj.indices[i] < obj.vertex_count, "index %u of %u vertices", obj.indices[i],
                       obj.vertex_count);
        if (!(sel & 128u))
            FZ_REQUIRE(obj.texcoords == NULL, "texture coordinates from the plain loader");
        draw_obj(&obj);
        zl_obj_free(&obj);
    } else {
        FZ_REQUIRE(st == ZL_OBJ_ERR_PARSE || st == ZL_OBJ_ERR_LIMIT || st == ZL_OBJ_ERR_MEMORY,
                   "status %d", (int)st);
        FZ_REQUIRE(obj.positions == NULL && obj.indices == NULL && obj.vertex_colors == NULL && obj.texcoords == NULL &&
                       obj.vertex_count == 0 && obj.triangle_count == 0,
                   "a failed load left data in *obj");
        if (msg_size > 10)
            FZ_REQUIRE(strncmp((const char *)msg.data, "fuzz.obj", msg_size - 1 < 8 ? msg_size - 1 : 8) == 0,
                       "message without the name: %s", (const char *)msg.data);
        zl_obj_free(&obj);
    }
    free(text);
    fz_buf_free(&msg);
    return 0;
}

/* SPDX-License-Identifier: MIT */
/*
 * Fuzzed scenes for fuzz_draw and fuzz_frame: a mesh, a render state and a
 * matrix read from the fuzzer's bytes, with the validity zline.h promises
 * for each computed independently of the library (the oracle for the status
 * codes).
 */
#ifndef FZ_SCENE_H
#define FZ_SCENE_H

#include "fz_common.h"

#define FZ_MAX_VERTICES 48u
#define FZ_MAX_TRIANGLES 48u

typedef struct {
    zl_fixed positions[FZ_MAX_VERTICES * 3];
    uint16_t indices[FZ_MAX_TRIANGLES * 3];
    uint8_t vertex_colors[FZ_MAX_VERTICES * 3];
    uint8_t face_colors[FZ_MAX_TRIANGLES * 3];
    zl_mesh mesh;
    int indices_ok;     /* every index < vertex_count */
} fz_mesh;

/* Model coordinates and matrix entries must lie within +-16384.0. */
#define FZ_COORD_LIMIT ((zl_fixed)1 << 30)

static inline int fz_in_range(zl_fixed v)
{
    return v >= -FZ_COORD_LIMIT && v <= FZ_COORD_LIMIT;
}

/* Read a mesh. `w`, `h`: the target size, so that pixel-space vertices
 * often land near it. */
static inline void fz_read_mesh(fz_in *in, fz_mesh *m, unsigned w, unsigned h)
{
    uint32_t flags = fz_u8(in);
    unsigned nv = fz_u8(in) % (FZ_MAX_VERTICES + 1), nt = fz_u8(in) % (FZ_MAX_TRIANGLES + 1), i;
    memset(m, 0, sizeof *m);
    for (i = 0; i < nv; i++) {
        if (flags & 1u) {
            /* near the target, 1/256 pixel resolution, up to 4x outside */
            m->positions[i * 3] = (zl_fixed)((int32_t)(fz_u16(in) % (9u * w * 256u + 1u)) - (int32_t)(4u * w * 256u)) * 256;
            m->positions[i * 3 + 1] = (zl_fixed)((int32_t)(fz_u16(in) % (9u * h * 256u + 1u)) - (int32_t)(4u * h * 256u)) * 256;
            m->positions[i * 3 + 2] = (zl_fixed)(fz_u16(in) + (fz_u8(in) & 1u) * 65536u) - 1024;
        } else {
            m->positions[i * 3] = fz_fixed(in);
            m->positions[i * 3 + 1] = fz_fixed(in);
            m->positions[i * 3 + 2] = fz_fixed(in);
        }
        m->vertex_colors[i * 3] = (uint8_t)fz_u8(in);
        m->vertex_colors[i * 3 + 1] = (uint8_t)fz_u8(in);
        m->vertex_colors[i * 3 + 2] = (uint8_t)fz_u8(in);
    }
    m->indices_ok = 1;
    for (i = 0; i < nt * 3; i++) {
        /* one more than the vertex count now and then: an unknown vertex */
        unsigned range = nv + ((flags & 2u) ? 1u : 0u);
        m->indices[i] = (uint16_t)(range ? fz_u8(in) % range : fz_u8(in));
        if (m->indices[i] >= nv)
            m->indices_ok = 0;
    }
    for (i = 0; i < nt * 3; i++)
        m->face_colors[i] = (uint8_t)fz_u8(in);
    m->mesh.positions = (nv || (flags & 4u)) ? m->positions : NULL;
    m->mesh.indices = (nt || (flags & 4u)) ? m->indices : NULL;
    m->mesh.vertex_colors = (flags & 8u) ? m->vertex_colors : NULL;
    m->mesh.face_colors = (flags & 16u) ? m->face_colors : NULL;
    m->mesh.vertex_count = (uint16_t)nv;
    m->mesh.triangle_count = (uint16_t)nt;
}

/* A field that is usually valid (0..n-1) and sometimes not. */
static inline uint8_t fz_enum(fz_in *in, unsigned n)
{
    uint32_t b = fz_u8(in);
    return (uint8_t)(b < 240 ? b % n : b);
}

static inline void fz_read_state(fz_in *in, zl_state *s, int *ok)
{
    zl_state_default(s);
    s->depth_test = fz_enum(in, 2);
    s->depth_write = fz_enum(in, 2);
    s->depth_func = fz_enum(in, 8);
    s->color_mask = fz_enum(in, 8);
    s->cull = fz_enum(in, 3);
    s->front_face = fz_enum(in, 2);
    s->shading = fz_enum(in, 2);
    s->light_on = fz_enum(in, 2);
    s->ambient = (uint8_t)fz_u8(in);
    s->color.r = (uint8_t)fz_u8(in);
    s->color.g = (uint8_t)fz_u8(in);
    s->color.b = (uint8_t)fz_u8(in);
    if (fz_u8(in) & 1u) {
        s->light_dir.x = fz_fixed(in);
        s->light_dir.y = fz_fixed(in);
        s->light_dir.z = fz_fixed(in);
    }
    *ok = s->depth_test <= 1 && s->depth_write <= 1 && s->depth_func <= 7 && s->color_mask <= 7 &&
          s->cull <= 2 && s->front_face <= 1 && s->shading <= 1 && s->light_on <= 1 &&
          (!s->light_on || (s->light_dir.x >= -ZL_FX_ONE && s->light_dir.x <= ZL_FX_ONE &&
                            s->light_dir.y >= -ZL_FX_ONE && s->light_dir.y <= ZL_FX_ONE &&
                            s->light_dir.z >= -ZL_FX_ONE && s->light_dir.z <= ZL_FX_ONE));
}

/*
 * A matrix: NULL (pixel space), 16 raw entries, or a camera built with the
 * library's own builders (perspective or ortho, look_at, a rotation, a
 * scale), which gives realistic clipping: w near zero, near-plane crossings,
 * vertices behind the eye. Returns NULL for pixel space.
 */
static inline const zl_mat4 *fz_read_matrix(fz_in *in, zl_mat4 *out)
{
    uint32_t kind = fz_u8(in) % 4;
    if (kind == 0)
        return NULL;
    if (kind == 1) {
        unsigned i;
        for (i = 0; i < 16; i++)
            out->m[i] = fz_fixed(in);
        return out;
    } else {
        zl_mat4 proj, view, model, rot, tmp;
        zl_vec3 eye, target, up, scale;
        zl_status st;
        if (kind == 2)
            st = zl_mat4_perspective(&proj, (zl_angle)fz_u16(in), fz_fixed(in), fz_fixed(in), fz_fixed(in));
        else
            st = zl_mat4_ortho(&proj, fz_fixed(in), fz_fixed(in), fz_fixed(in), fz_fixed(in), fz_fixed(in),
                               fz_fixed(in));
        if (st != ZL_OK)
            zl_mat4_identity(&proj);
        eye.x = fz_fixed(in);
        eye.y = fz_fixed(in);
        eye.z = fz_fixed(in);
        target.x = fz_fixed(in);
        target.y = fz_fixed(in);
        target.z = fz_fixed(in);
        up.x = 0;
        up.y = ZL_FX_ONE;
        up.z = fz_fixed(in);
        if (zl_mat4_look_at(&view, eye, target, up) != ZL_OK)
            zl_mat4_identity(&view);
        scale.x = fz_fixed(in);
        scale.y = fz_fixed(in);
        scale.z = fz_fixed(in);
        zl_mat4_scale(&model, scale);
        zl_mat4_rotate_x(&rot, (zl_angle)fz_u16(in));
        zl_mat4_mul(&tmp, &rot, &model);
        zl_mat4_rotate_y(&rot, (zl_angle)fz_u16(in));
        zl_mat4_mul(&model, &rot, &tmp);
        zl_mat4_mul(&tmp, &view, &model);
        zl_mat4_mul(out, &proj, &tmp);
        return out;
    }
}

#endif /* FZ_SCENE_H */

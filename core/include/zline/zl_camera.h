/* SPDX-License-Identifier: MIT */
/*
 * A camera object: the view and the projection of a scene, described once,
 * and a model matrix per draw (issue 25). The camera keeps the perspective's
 * near and far planes, so a draw through it takes the exact depth mapping
 * (zline.h, Pseudodepth: state.near_z, far_z) without the caller repeating
 * them; lights stay in world space (zl_lighting with zl_light_faces or
 * zl_light_vertices, given the same model matrix).
 *
 *   zl_camera cam;
 *   zl_camera_init(&cam);
 *   zl_camera_perspective(&cam, fovy, aspect, near_z, far_z);
 *   zl_camera_look_at(&cam, eye, target, up);
 *   every frame, every mesh:
 *       zl_draw_mesh_camera(&ctx, &mesh, &cam, &model);           (frame mode)
 *       zl_frame_add_mesh_camera(&frame, &mesh, &cam, &model, &state);  (bands)
 *
 * The matrix of a draw is proj x (view x model), each product by zl_mat4_mul
 * (64-bit sums, rounded once per entry, saturating), in that order: the
 * same matrix a caller gets from zl_mat4_mul(&vm, &view, &model) then
 * zl_mat4_mul(&mvp, &proj, &vm). Integer only, like the rest of the core.
 */
#ifndef ZL_CAMERA_H
#define ZL_CAMERA_H

#include "zline.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    zl_mat4 view;           /* world to eye */
    zl_mat4 proj;           /* eye to clip */
    zl_fixed near_z, far_z; /* the perspective's planes; 0, 0 for an orthographic projection */
} zl_camera;

/* View and projection the identity, near_z = far_z = 0 (no exact depth
 * mapping until a perspective is set). */
void zl_camera_init(zl_camera *cam);
/* The projection of zl_mat4_perspective, and its near and far for the exact
 * depth mapping. On an error (ZL_ERR_ARG for NULL, ZL_ERR_RANGE as
 * zl_mat4_perspective) the camera is unchanged. */
zl_status zl_camera_perspective(zl_camera *cam, zl_angle fovy, zl_fixed aspect, zl_fixed near_z,
                                zl_fixed far_z);
/* The projection of zl_mat4_ortho; near_z = far_z = 0 (its depth is already
 * linear and exact to the matrix). Unchanged on an error. */
zl_status zl_camera_ortho(zl_camera *cam, zl_fixed l, zl_fixed r, zl_fixed b, zl_fixed t, zl_fixed near_z,
                          zl_fixed far_z);
/* The view of zl_mat4_look_at. Unchanged on an error. */
zl_status zl_camera_look_at(zl_camera *cam, zl_vec3 eye, zl_vec3 target, zl_vec3 up);

/* mvp = proj x (view x model); model NULL is the identity. ZL_ERR_ARG for a
 * NULL cam or mvp. */
zl_status zl_camera_mvp(const zl_camera *cam, const zl_mat4 *model, zl_mat4 *mvp);
/* st->near_z, far_z from the camera (the exact depth mapping of a
 * perspective camera; 0, 0 for an orthographic one). Without
 * ZL_FEATURE_DEPTH_MAP (zl_config.h) st is left as it is: the depth is the
 * matrix's z / w. */
void zl_camera_apply_depth(const zl_camera *cam, zl_state *st);

/* zl_draw_mesh with the camera's matrix for this model (computed into
 * ctx->camera_mvp, which stays readable after the draw) and ctx->state's
 * near_z, far_z taken from the camera for this draw (ctx->state is left as
 * it was). Errors as zl_draw_mesh, and ZL_ERR_ARG for a NULL cam. */
zl_status zl_draw_mesh_camera(zl_context *ctx, const zl_mesh *mesh, const zl_camera *cam, const zl_mat4 *model);
/* zl_frame_add_mesh with the camera's matrix for this model and a copy of
 * state whose near_z, far_z come from the camera. */
zl_status zl_frame_add_mesh_camera(zl_frame *f, const zl_mesh *mesh, const zl_camera *cam, const zl_mat4 *model,
                                   const zl_state *state);

#ifdef __cplusplus
}
#endif

#endif /* ZL_CAMERA_H */

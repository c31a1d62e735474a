/* SPDX-License-Identifier: MIT */
/*
 * The camera object (zline/zl_camera.h): view and projection kept together
 * with the perspective's near and far, so a draw gets both its matrix and
 * the exact depth mapping from one description.
 */
#include "zline/zl_camera.h"

#include <stddef.h>

#include "../1_base/zl_internal.h"

void zl_camera_init(zl_camera *cam)
{
    if (cam == NULL)
        return;
    zl_mat4_identity(&cam->view);
    zl_mat4_identity(&cam->proj);
    cam->near_z = 0;
    cam->far_z = 0;
}

zl_status zl_camera_perspective(zl_camera *cam, zl_angle fovy, zl_fixed aspect, zl_fixed near_z,
                                zl_fixed far_z)
{
    zl_mat4 proj;
    zl_status st;
    if (cam == NULL)
        return ZL_ERR_ARG;
    st = zl_mat4_perspective(&proj, fovy, aspect, near_z, far_z);
    if (st != ZL_OK)
        return st;
    cam->proj = proj;
    cam->near_z = near_z;
    cam->far_z = far_z;
    return ZL_OK;
}

zl_status zl_camera_ortho(zl_camera *cam, zl_fixed l, zl_fixed r, zl_fixed b, zl_fixed t, zl_fixed near_z,
                          zl_fixed far_z)
{
    zl_mat4 proj;
    zl_status st;
    if (cam == NULL)
        return ZL_ERR_ARG;
    st = zl_mat4_ortho(&proj, l, r, b, t, near_z, far_z);
    if (st != ZL_OK)
        return st;
    cam->proj = proj;
    cam->near_z = 0; /* an orthographic depth is linear in eye z: no mapping to make exact */
    cam->far_z = 0;
    return ZL_OK;
}

zl_status zl_camera_look_at(zl_camera *cam, zl_vec3 eye, zl_vec3 target, zl_vec3 up)
{
    zl_mat4 view;
    zl_status st;
    if (cam == NULL)
        return ZL_ERR_ARG;
    st = zl_mat4_look_at(&view, eye, target, up);
    if (st == ZL_OK)
        cam->view = view;
    return st;
}

/* Out of line: its temporary must not sit in zl_draw_mesh_camera's frame
 * under the whole draw (the 2048-byte stack bound, CTest stack_bound_*). */
ZL_NOINLINE zl_status zl_camera_mvp(const zl_camera *cam, const zl_mat4 *model, zl_mat4 *mvp)
{
    zl_mat4 view_model;
    if (cam == NULL || mvp == NULL)
        return ZL_ERR_ARG;
    if (model == NULL) {
        zl_mat4_mul(mvp, &cam->proj, &cam->view);
        return ZL_OK;
    }
    zl_mat4_mul(&view_model, &cam->view, model);
    zl_mat4_mul(mvp, &cam->proj, &view_model);
    return ZL_OK;
}

void zl_camera_apply_depth(const zl_camera *cam, zl_state *st)
{
    if (cam == NULL || st == NULL || !ZL_FEATURE_DEPTH_MAP) /* off: the matrix's z / w (zl_config.h) */
        return;
    st->near_z = cam->near_z;
    st->far_z = cam->far_z;
}

zl_status zl_draw_mesh_camera(zl_context *ctx, const zl_mesh *mesh, const zl_camera *cam, const zl_mat4 *model)
{
    zl_fixed near_z, far_z;
    zl_status st;
    if (ctx == NULL)
        return ZL_ERR_ARG;
    /* The matrix goes to the context's scratch: on the stack it would sit
     * under the whole draw (the 2048-byte bound of CTest stack_bound_*). */
    st = zl_camera_mvp(cam, model, &ctx->camera_mvp);
    if (st != ZL_OK)
        return st;
    /* The caller's state is borrowed for this draw only. */
    near_z = ctx->state.near_z;
    far_z = ctx->state.far_z;
    zl_camera_apply_depth(cam, &ctx->state);
    st = zl_draw_mesh(ctx, mesh, &ctx->camera_mvp);
    ctx->state.near_z = near_z;
    ctx->state.far_z = far_z;
    return st;
}

zl_status zl_frame_add_mesh_camera(zl_frame *f, const zl_mesh *mesh, const zl_camera *cam, const zl_mat4 *model,
                                   const zl_state *state)
{
    zl_mat4 mvp;
    zl_state with_depth;
    zl_status st;
    if (state == NULL)
        return ZL_ERR_ARG;
    st = zl_camera_mvp(cam, model, &mvp);
    if (st != ZL_OK)
        return st;
    with_depth = *state;
    zl_camera_apply_depth(cam, &with_depth);
    return zl_frame_add_mesh(f, mesh, &mvp, &with_depth);
}

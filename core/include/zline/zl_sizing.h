/* SPDX-License-Identifier: MIT */
/*
 * Sizing without a dry run: capacities for zl_frame that hold a mesh in
 * every orientation, computed from the mesh and the viewport alone.
 *
 * The poses: the mesh turned by any rotation about its own origin (scale 1,
 * no translation), seen by a perspective camera at `distance` from that
 * origin looking at it (any direction, any roll), with the projection of
 * zl_mat4_perspective(fovy, aspect = width / height, near_z, far_z).
 *
 * The bound, and why it holds. A row of the viewport is a plane through the
 * eye; a triangle is active on a row only if it comes within about a pixel
 * of that plane (snapping and the row rule: 2 pixels are allowed, i.e. a
 * distance m = 2 (distance + R) / f in model units, f = height / 2 /
 * tan(fovy / 2) the focal length in pixels, R the mesh's radius about its
 * origin). So the triangles on one row are at most the triangles whose
 * vertices' projections onto the plane's normal n span an interval that
 * meets [s - m, s + m] for some s: the most intervals one point can stab,
 * over every normal n. Every unit n lies within sqrt(2) / g (in the
 * max-norm face coordinates) of a direction q of a grid of g + 1 by g + 1
 * points on three cube faces (n and -n give the same planes), and moving
 * from q to n moves each projection by at most sqrt(2) R / g: so for each q
 * of the grid each interval is widened by that and by m (|q| + sqrt(2) / g),
 * the widened intervals are counted in 128 bins (a bin count is at least
 * the stabbing number of any point in it), and the largest count over all
 * q and bins bounds max_active. Nothing here depends on culling, so culled
 * meshes need no more either.
 *
 * This holds when no triangle is ever clipped (a clipped triangle may count
 * up to 8 pieces): when distance - R > near_z, distance + R < far_z and the
 * mesh's projection stays inside zline's 16-bit window range. Otherwise the
 * always-sufficient 8 x triangle_count (at most 65534) is given.
 *
 * Cost: 3 (g + 1)^2 x triangle_count triangle projections, integer only, no
 * heap, 256 bytes of bins on the stack: for tools and start-up, not per frame.
 */
#ifndef ZL_SIZING_H
#define ZL_SIZING_H

#include "zline.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    zl_angle fovy;     /* vertical field of view, as zl_mat4_perspective */
    zl_fixed near_z;   /* near and far planes, as zl_mat4_perspective */
    zl_fixed far_z;
    zl_fixed distance; /* from the eye to the mesh's origin */
} zl_orbit_camera;

/* Directions per axis of the sweep's grid: more is tighter and slower. */
#define ZL_SIZING_PRECISION_DEFAULT 16u
#define ZL_SIZING_PRECISION_MAX 64u

/*
 * Set cfg->max_meshes = 1, max_vertices = mesh->vertex_count,
 * max_triangles = mesh->triangle_count and max_active to the bound above
 * (the rest of cfg - size, bands, format, features - as the caller set it),
 * and return zl_frame_bytes(cfg): a work buffer of that size renders the
 * mesh alone in every pose without ZL_ERR_CAPACITY. Returns 0 (cfg
 * unchanged) for a NULL or invalid argument: an invalid mesh, a vertex
 * beyond +-16384.0, fovy outside (0, half a turn), near_z <= 0,
 * far_z <= near_z, distance <= 0, precision outside 1 .. 64, or a cfg that
 * zl_frame_bytes refuses.
 */
size_t zl_frame_bound(zl_frame_config *cfg, const zl_mesh *mesh, const zl_orbit_camera *camera,
                      unsigned precision);

#ifdef __cplusplus
}
#endif

#endif /* ZL_SIZING_H */

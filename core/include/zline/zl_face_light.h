/* SPDX-License-Identifier: MIT */
/*
 * One lighting description for flat and smooth shading: zl_lighting (zline.h:
 * ambient, up to 4 directional lights with diffuse and specular colours, a
 * viewer, shininess), with lights given once in world (or eye) space and a
 * model matrix per draw. Smooth shading: zl_light_vertices (vertex colours,
 * then a Gouraud draw). Flat shading: zl_light_faces below (face colours,
 * then a flat draw with state.light_on = 0).
 *
 * FLAT LIGHTING. Per triangle, with m its material colour (the mesh's face
 * colour, else lighting.material), n its face normal in model space (front
 * side by the winding front_face names, computed as the flat rule of
 * zl_state computes it: the normal scaled to 14 bits) and each channel:
 *
 *   c = min(255, round(m L / 255) + sum_i ((S_i s_i + 2^13) >> 14))
 *   L = A + sum_i ((D_i d_i + 2^13) >> 14)
 *   d_i = min(2^14, trunc(n . l_i / |n|)) when positive, else 0 (Q14)
 *   s_i = d_i > 0 ? (n . h_i / |n|)^e in Q14 (each product rounded), else 0
 *
 * where l_i = the light's direction brought into model space (M^-1 l, from
 * the adjugate of the model matrix's 3x3; NULL: identity), as a Q16 unit
 * vector - used as it is when it is already unit within 1/8192, which a
 * rounded unit vector is, else normalised - and then in Q14 as the flat
 * rule takes light_dir (truncated to a quarter); h_i the same for the half
 * vector unit(unit(l) + unit(viewer)). A = ambient, D_i, S_i the light's
 * diffuse and specular colours, e = shininess.
 *
 * A point light (zl_light.point, at q_i in the lights' space, no
 * attenuation) instead has l_i = P_i - c per triangle, with P_i = M^-1 (q_i
 * - t) its position in model space (t: the model matrix's translation;
 * computed once per call) and c the triangle's centroid (l_i from 3 P_i -
 * (p0 + p1 + p2), exact), made a Q16 unit vector and taken in Q14 as
 * above; h_i = unit(unit(l_i) + V) with V = unit(M^-1 viewer). A centroid at
 * the light gets nothing from it.
 *
 * Equivalence: one light along the unit vector l with diffuse (255 - a) in
 * every channel, ambient (a, a, a), no specular and no model matrix (or one
 * that maps l exactly, such as quarter turns) gives exactly the colours of
 * state.light_on with light_dir = l and ambient = a (tests/test_face_light.c).
 * light_dir stays, for compatibility; it is not deprecated. Several lights
 * with specular stay within 3.5 of the equation evaluated exactly (the
 * test's bound: each light's Q14 terms round separately).
 */
#ifndef ZL_FACE_LIGHT_H
#define ZL_FACE_LIGHT_H

#include "zline.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The lit colour of every triangle into colors (3 bytes per triangle), by
 * FLAT LIGHTING. front_face: zl_front_face of the draw. ZL_ERR_ARG for a
 * NULL pointer, an unknown front_face or an index out of range;
 * ZL_ERR_RANGE for more than ZL_MAX_LIGHTS lights, shininess above
 * ZL_MAX_SHININESS, a zero light direction (or viewer, with specular), a
 * singular matrix or a position beyond +-16384.0. Nothing is written on an
 * error. */
zl_status zl_light_faces(const zl_lighting *lt, const zl_mat4 *model, const zl_mesh *mesh, uint8_t front_face,
                         uint8_t *colors);

#ifdef __cplusplus
}
#endif

#endif /* ZL_FACE_LIGHT_H */

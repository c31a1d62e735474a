/* SPDX-License-Identifier: MIT */
/*
 * zline: an integer-only 3D rasteriser for microcontrollers.
 *
 * ===========================================================================
 * RASTER CONTRACT (tests/ check every clause exactly)
 * ===========================================================================
 * Window coordinates: x grows right, y grows down, origin at the top-left
 *   corner of the top-left pixel. Pixel (i, j) has its centre at
 *   (i + 0.5, j + 0.5). Row 0 is the top row.
 *
 * Viewport: clip-space (x, y, w) maps to window x = (x/w + 1) * width / 2 and
 *   y = (1 - y/w) * height / 2 (OpenGL's mapping, rows counted downwards);
 *   with a NULL matrix positions are window coordinates already.
 *
 * Snapping: vertex x and y snap to 1/16 pixel (2^ZL_SUBPIXEL_BITS), rounded
 *   to nearest; a value exactly half-way rounds towards +infinity (right or
 *   down).
 *
 * Coverage: a pixel is covered when its centre is inside the triangle. A
 *   centre exactly on an edge is covered only if that edge is a top edge
 *   (horizontal, with the interior below it) or a left edge (interior to its
 *   right): the top-left rule. So two triangles sharing an edge never both
 *   cover a pixel, and a mesh without holes leaves none. Zero-area triangles
 *   cover nothing.
 *
 * Depth: window depth z_w is 0 at the near plane and 1 at the far plane. It
 *   is sampled at the pixel centre and stored as round(z_w * 65535). With
 *   the exact mapping (state.near_z, far_z set: see Pseudodepth) it is
 *   within +-1 of the exact depth at that centre of the triangle itself: the
 *   plane through its vertices at their unsnapped window positions (kept to
 *   2^-16 pixel from the transform's unrounded sums), not through the
 *   snapped ones coverage uses, so snapping moves no depth. Without it
 *   (near_z = far_z = 0, or pixel space), whose per-vertex depth is biased
 *   by the Q16.16 matrix anyway, the plane goes through the snapped
 *   vertices and the stored value is within +-1 of it. Measured per
 *   pixel against a long double reference by tests/host/test_depth_exact.c
 *   on the bunny from the benchmark camera and from close-ups (eye within
 *   1 unit of the model): every covered pixel within +-1, at most 0.53 step
 *   from exact, mean error below 0.002 step. (Nearly edge-on triangles whose
 *   depth changes by more than 2^20 steps per pixel get depths clamped to
 *   their vertices' range instead, and a triangle with an edge of 8192
 *   pixels or more, or whose depth the snapping could push out of 0 ..
 *   65535 by a quarter step, takes the plane through its snapped vertices.)
 *   A triangle that clipping cuts (see Clipping) takes the depth (and colour
 *   and texture coordinates) of the original triangle, not of its snapped
 *   pieces. Texture planes (and 1/w) of an unclipped triangle go through
 *   the unsnapped vertices too (see TEXTURES); its colour planes are still
 *   solved through the snapped vertices.
 *
 * Pseudodepth: for the perspective projection, with eye distance z (> 0),
 *   near n and far f,
 *       z_w = A + B / z,   A = f / (f - n),   B = -f n / (f - n).
 *   Why this is linear in screen space: the projection's z row gives
 *   z_clip = A z + B and w_clip = z, so z_w = z_clip / w_clip. Both z_clip and
 *   w_clip are affine in eye space; a plane in eye space a x + b y + c z = d
 *   divided through by z gives a (x/z) + b (y/z) + c = d / z, so 1/z, and
 *   with it A + B/z, is an affine function of the screen position
 *   (x/z, y/z). Hence z_w is stepped across a triangle by pure addition.
 *   z = n gives 0, z = f gives 1, and dz_w/dz = -B/z^2 > 0: monotonic.
 *   Per vertex, the window depth (kept to 1/65536 step) is z_clip / w_clip
 *   of the matrix by default. The matrix holds A and B rounded to Q16.16
 *   and z_clip, w_clip are rounded too, so that is biased: on the benchmark
 *   scene (the bunny, zline-render's default camera) by +0.26 step on
 *   average, 0.42 at most, and by several steps close to the near plane.
 *   With state.near_z and state.far_z set to the n and f given to
 *   zl_mat4_perspective it is instead 65535 (A + B/z) for the exact A and B
 *   of those Q16.16 n and f and the exact eye distance z = w_clip of the
 *   Q16.16 vertex and matrix (the transform's 64-bit sum, before any
 *   rounding), clamped to 0 .. 65535: within 1/1000 step of it when
 *   f >= 2n, so each vertex's stored depth is within 0.5 step (plus that
 *   1/1000) of the exact value and the mean error vanishes (measured
 *   against a long double reference by tests/host/test_depth_exact.c:
 *   at most 0.00006 step, mean +0.00001 on the benchmark scene). A clipped
 *   triangle takes the same mapping through its Q16.16 clip w (Clipping).
 *
 * Clipping: triangles are clipped in homogeneous clip space against
 *   w > 0, near (z >= 0), far (z <= w), and four x/y planes ZL_GUARD_PX
 *   pixels outside the viewport (the guard band). Pixels outside the target
 *   are never written (spans are clamped), so a triangle that stays inside
 *   the guard band covers exactly the in-viewport pixels of the unclipped
 *   triangle. A triangle through the eye point is clipped at the near plane
 *   like any other: no wrap-around, no division by zero.
 *   Clipping decides coverage only (the snapped clipped polygon, split into
 *   a fan, by the rules above). Depth, Gouraud colour and texture
 *   coordinates come from the original triangle, as if it had not been
 *   cut (each piece's span loop runs with the original triangle's planes,
 *   set up once per piece): at every pixel a
 *   clipped triangle covers, the stored depth is within +-1 of
 *   clamp(round(65535 z_w), 0, 65535) with z_w the exact depth at the pixel
 *   centre of the triangle through its three clip-space vertices as the
 *   transform gives them (Q16.16, NOT snapped: homogeneous 2D
 *   interpolation, Olano and Greer 1997, which needs no division by a w
 *   that may be zero or negative): z_clip / w_clip, or with state.near_z
 *   and far_z set 65535 (A + B / w) with w the clip w of that point. A
 *   pixel the snapped polygon covers just beyond the near or far plane
 *   gets 0 or 65535. When every vertex has w > 0, the Gouraud colour is
 *   within the Gouraud bound (below: +-1 in RGB888) of the exact
 *   screen-linear interpolation of the vertex colours at the unsnapped
 *   projected vertices (times the light intensity / 255).
 *   Perspective-correct Gouraud colour and texture
 *   coordinates come from the same original planes: a / w and 1 / w are
 *   affine in the window position, and the span loops divide them per
 *   pixel as for an unclipped triangle, so perspective-correct colour is
 *   within +-1 of sum c_i b_i / sum b_i (b = M^-1 n as above, times the
 *   light / 255), and a texture coordinate c (texels) of
 *   sum c_i b_i / sum b_i, or for an affine texture of the screen-linear
 *   sum c_i w_i b_i / sum w_j b_j; the texel sampled is the one containing
 *   that value except within 1/32 texel + |c| / 2^14 of a texel boundary,
 *   plus the drift of the stepped planes: half a plane unit for each of
 *   the up to 1 + width + height pixel steps from the anchor, a unit being
 *   2^-16 texel (affine) or 2^12 / Q texel, Q = 2^28 w_min / w (the
 *   pixel's w against the least w of the clipped polygon), as for an
 *   unclipped triangle. A triangle with a vertex at w <= 0 (across the
 *   eye plane) has no screen-linear interpolation: its affine texture is
 *   perspective-correct (as OpenGL interpolates), and its screen-linear
 *   Gouraud colour is, on each fan piece, linear between the colours the
 *   clipper gives the piece's vertices (perspective-correct there).
 *   Exception: pixels where the depth changes by more than 65536 steps per
 *   pixel. zl_visibility's AET and ray caster compare the same original
 *   planes (its painter and BSP store no depth). Checked against exact
 *   references by tests/host/test_clip_planes.c (depth, screen-linear
 *   colour), test_clip_attrs.c (perspective colour, textures) and
 *   test_clip_coverage.c (coverage: watertight, and pinned).
 *   Built with ZL_FEATURE_EXACT_CLIP 0 (zl_config.h; the minimal
 *   configuration), the coverage is the same but each fan piece is set up
 *   as an unclipped triangle through its snapped vertices, with the depth,
 *   colour and texture coordinates the clipper interpolates there
 *   (perspective-correct at those vertices); the AET and the ray caster
 *   compare those planes. At a pixel whose exact depth changes by g steps
 *   a pixel (|d/dx| + |d/dy|) the stored depth is then within +-1 of
 *   clamp(round(65535 z'), 0, 65535) for a z' within g (1/32 + e) + d
 *   steps of the exact value above: 1/32 pixel is the snapping, e and d
 *   the move of a vertex the clipper makes by one Q16.16 unit of its clip
 *   x, y, w and z, in pixels ((max(W, H) / 2) (1 + R) / w) and in steps
 *   (65535 * 2 / w, times f / (f - n) with the exact mapping), w the least
 *   clip w and R the largest |x / w|, |y / w| of the vertices the clipper
 *   makes (in pixel space 2^-16 pixel and 1 step). A steep piece can so be
 *   off by hundreds of steps where the original planes keep +-1 (the test
 *   below measures both); a scene whose geometry stays in front of the
 *   near plane and behind the far one is never cut. The Gouraud colour
 *   stays within the vertex colours (+-1). test_clip_planes_exact_clip_off
 *   checks both bounds against the same reference.
 *
 * Gouraud colour (screen-linear, state.shading ZL_SHADE_GOURAUD): at a
 *   covered pixel each channel is the exact mix e (8-bit units, a real
 *   number) of the vertex colours at the pixel centre, interpolated over the
 *   snapped triangle (times the light intensity / 255 when light_on). RGB888
 *   stores a value within +-1 of e. RGB565 and RGB565_BE store the top 5, 6,
 *   5 bits of a value within -0.6 .. +1.6 of e, so each RGB565 channel is
 *   within 1 of the exact floor(e / 8) (red, blue) or floor(e / 4) (green):
 *   spans step the colour in 8.8 fixed point two pixels per 32-bit word
 *   ("lane colour", zl_span.h), for speed. Checked against the exact
 *   rational mix by tests/test_paths_match_reference.c and
 *   tests/test_gouraud_bound.c (spans up to 1040 pixels).
 *
 * Order: triangles are drawn in submission order; the depth test decides
 *   per pixel. Frame mode and the scanline/band modes of zl_frame produce
 *   byte-identical colour and depth.
 * ===========================================================================
 *
 * LIMITS (enforced: an input beyond one returns an error before any byte
 * is written; inputs at a limit render by the contract above. Tested at
 * each edge in tests/test_limits.c; docs/CONTRACT.md's "What bad input gets"
 * lists every error.)
 *
 *   target width, height     1 .. ZL_MAX_DIM (4096)            ZL_ERR_SIZE
 *   colour stride (bytes)    >= width * bytes per pixel        ZL_ERR_SIZE
 *   depth stride (bytes)     >= width * 2, even                ZL_ERR_SIZE
 *   native RGB565 colour,    2-byte aligned address, even      ZL_ERR_ARG
 *   depth                    colour stride (RGB565_BE and
 *                            RGB888 are bytes: any alignment)
 *   zl_frame work buffer     >= zl_frame_bytes(cfg) bytes      ZL_ERR_SIZE
 *                            8-byte aligned                    ZL_ERR_ARG
 *   vertices, triangles      0 .. 65535 per mesh (uint16), every ZL_ERR_RANGE
 *                            index < vertex_count
 *   with a matrix (mvp):     every matrix entry and every      ZL_ERR_RANGE
 *                            model coordinate of the mesh within
 *                            +-16384.0 (raw +-2^30), and every
 *                            vertex's clip-space position
 *                            mvp * (p, 1) inside Q16.16
 *                            (checked for all vertices of the mesh by
 *                            zl_draw_mesh and zl_frame_add_mesh, whether
 *                            a triangle uses them or not)
 *   without a matrix         any Q16.16 position: x, y up to +-32768
 *                            pixels, z is clipped to 0 .. 1
 *   window coordinates       exact (the contract) within the guard band,
 *                            ZL_GUARD_PX (131072) pixels beyond each edge
 *                            of the target; geometry reaching further, or
 *                            behind the eye, is clipped, never dropped
 *   smallest triangle        none: a triangle one subpixel (1/16 pixel)
 *                            wide covers the pixel whose centre it holds
 *                            by the top-left rule; zero area covers nothing
 *   triangles per frame      sum of triangle_count over the    ZL_ERR_CAPACITY
 *                            meshes of a zl_frame <= 65535
 *   render state             enum fields in range              ZL_ERR_ARG
 *                            light_dir within +-1.0 per        ZL_ERR_RANGE
 *                            component (when light_on)
 *   NULL pointers            context, target, mesh, arrays     ZL_ERR_ARG
 *                            with a non-zero count
 *
 * Memory: the library never allocates. The caller owns the context, every
 * buffer (with strides in bytes) and, in scanline mode, one work buffer
 * whose exact size zl_frame_bytes() returns. There is no global state: two
 * contexts render independently. All numbers are integers or Q16.16
 * (zl_fixed.h); core/ uses no floating point.
 */
#ifndef ZLINE_H
#define ZLINE_H

#include <stddef.h>
#include <stdint.h>

#include "zl_config.h"
#include "zl_fixed.h"
#include "zl_version.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- vectors */

typedef struct {
    zl_fixed x, y, z;
} zl_vec3;

/* 4x4 matrix, row-major: m[row * 4 + col]; vectors are columns (v' = M v). */
typedef struct {
    zl_fixed m[16];
} zl_mat4;

void zl_mat4_identity(zl_mat4 *out);
/* out = a * b (apply b first). Entries saturate instead of wrapping. */
void zl_mat4_mul(zl_mat4 *out, const zl_mat4 *a, const zl_mat4 *b);
void zl_mat4_translate(zl_mat4 *out, zl_vec3 t);
void zl_mat4_scale(zl_mat4 *out, zl_vec3 s);
/* Rotation about the x, y or z axis, counter-clockwise looking down the axis. */
void zl_mat4_rotate_x(zl_mat4 *out, zl_angle a);
void zl_mat4_rotate_y(zl_mat4 *out, zl_angle a);
void zl_mat4_rotate_z(zl_mat4 *out, zl_angle a);
/*
 * View matrix looking from eye towards target (right-handed, camera looks
 * down its -z); up need not be unit length. ZL_ERR_RANGE when eye ==
 * target, up is zero or parallel to the view direction, target - eye leaves
 * Q16.16, or the eye is so far from the origin that the translation does not
 * fit Q16.16.
 */
zl_status zl_mat4_look_at(zl_mat4 *out, zl_vec3 eye, zl_vec3 target, zl_vec3 up);
/*
 * Perspective projection with the pseudodepth of the contract above.
 * fovy: vertical field of view, 0 < fovy < half a turn. aspect = width/height
 * in Q16.16, 1/64 .. 64. 0 < near < far <= 32767. ZL_ERR_RANGE otherwise, or
 * when the depth constants A = f/(f-n), B = -fn/(f-n) do not fit Q16.16.
 */
zl_status zl_mat4_perspective(zl_mat4 *out, zl_angle fovy, zl_fixed aspect, zl_fixed near_z,
                              zl_fixed far_z);
/* Orthographic projection of the box [l,r]x[b,t]x[-near,-far] in eye space. */
zl_status zl_mat4_ortho(zl_mat4 *out, zl_fixed l, zl_fixed r, zl_fixed b, zl_fixed t, zl_fixed near_z,
                        zl_fixed far_z);

/* Homogeneous clip-space position, Q16.16. */
typedef struct {
    zl_fixed x, y, z, w;
} zl_vec4;

/*
 * M * (v, 1) with 64-bit accumulation, rounded once. Matrix entries and
 * positions must lie within +-16384.0 (raw +-2^30) so the sum of products
 * fits 64 bits; ZL_ERR_RANGE if an input is outside or a component of the
 * result leaves Q16.16. zl_draw_mesh and zl_frame_add_mesh refuse a mesh
 * with such a vertex (ZL_ERR_RANGE, see LIMITS) before drawing anything.
 */
zl_status zl_transform_point(const zl_mat4 *m, zl_vec3 v, zl_vec4 *out);

/* ------------------------------------------------------------- pseudodepth */

/*
 * Window depth (0..65535) of eye distance z for the perspective mapping with
 * the given near and far planes (Q16.16), computed from A + B/z in 64-bit
 * integers and rounded. z outside [near, far] is clamped.
 */
uint16_t zl_depth_of_distance(zl_fixed near_z, zl_fixed far_z, zl_fixed z);
/*
 * The precision question: the smallest increase dz of eye distance z that
 * changes the stored depth by one step, for depth of `bits` bits (1..16):
 *     dz = k z^2 / (1 - k z),   k = (f - n) / ((2^bits - 1) f n).
 * Q16.16, rounded up; ZL_FX_MAX when no step is left beyond z.
 */
zl_fixed zl_depth_resolution(zl_fixed near_z, zl_fixed far_z, zl_fixed z, unsigned bits);

/* ----------------------------------------------------------------- pixels */

typedef enum {
    ZL_FORMAT_RGB565 = 0,    /* uint16 per pixel in native byte order */
    ZL_FORMAT_RGB565_BE = 1, /* RGB565, high byte first: what SPI panels take */
    ZL_FORMAT_RGB888 = 2     /* 3 bytes per pixel: R, G, B */
} zl_format;

/* Bytes per pixel of a format, 0 for an unknown one. */
unsigned zl_format_bytes(zl_format f);

typedef struct {
    uint8_t r, g, b;
} zl_rgb;

/* --------------------------------------------------------------- geometry */

/*
 * A triangle mesh in caller memory; every array may be const in flash.
 * positions: 3 Q16.16 per vertex, in model space (or, with a NULL matrix,
 *   in pixel space: x, y in pixels, y down, z = window depth 0..1).
 * indices: 3 per triangle, each < vertex_count.
 * vertex_colors (optional): 3 bytes (r, g, b) per vertex, for Gouraud.
 * face_colors (optional): 3 bytes per triangle, for flat shading;
 *   without them the state's colour is used.
 */
typedef struct {
    const zl_fixed *positions;
    const uint16_t *indices;
    const uint8_t *vertex_colors;
    const uint8_t *face_colors;
    uint16_t vertex_count;
    uint16_t triangle_count;
} zl_mesh;

/* --------------------------------------------------------------- state */

typedef enum {
    ZL_NEVER = 0,
    ZL_LESS = 1,
    ZL_EQUAL = 2,
    ZL_LEQUAL = 3,
    ZL_GREATER = 4,
    ZL_NOTEQUAL = 5,
    ZL_GEQUAL = 6,
    ZL_ALWAYS = 7
} zl_depth_func;

typedef enum { ZL_CULL_NONE = 0, ZL_CULL_BACK = 1, ZL_CULL_FRONT = 2 } zl_cull;
/* Winding of front faces as seen on screen (y down, as the viewer sees it). */
typedef enum { ZL_FRONT_CCW = 0, ZL_FRONT_CW = 1 } zl_front_face;
typedef enum { ZL_SHADE_FLAT = 0, ZL_SHADE_GOURAUD = 1 } zl_shading;

#define ZL_MASK_R 1u
#define ZL_MASK_G 2u
#define ZL_MASK_B 4u
#define ZL_MASK_RGB 7u

/*
 * Per-draw render state, as OpenGL's depth and polygon state. Lighting:
 * when light_on is set, each triangle's colour (flat) or vertex colours
 * (Gouraud) are scaled by ambient + (255 - ambient) * max(0, n . l) / 255,
 * n the face normal in model space (front side), l = light_dir, a unit
 * vector in model space pointing towards the light.
 */
typedef struct {
    uint8_t depth_test;  /* 0: every fragment passes and depth is not written */
    uint8_t depth_write; /* depth write mask */
    uint8_t depth_func;  /* zl_depth_func */
    uint8_t color_mask;  /* ZL_MASK_* bits of the channels written */
    uint8_t cull;        /* zl_cull */
    uint8_t front_face;  /* zl_front_face */
    uint8_t shading;     /* zl_shading */
    uint8_t light_on;
    uint8_t ambient;     /* 0..255 */
    zl_rgb color;        /* flat colour when the mesh has no face colours */
    zl_vec3 light_dir;
    /* Exact depth mapping (see Pseudodepth): the near and far planes given
     * to zl_mat4_perspective for the matrix (Q16.16, 0 < near_z < far_z),
     * or both 0 (the default: window depth is z_clip / w_clip). Ignored in
     * pixel space. Leave them 0 for an orthographic or any other matrix.
     * Without ZL_FEATURE_DEPTH_MAP (zl_config.h) they must stay 0. */
    zl_fixed near_z, far_z;
} zl_state;

/* Defaults: depth test on, LESS, depth write on, all channels, no culling,
 * CCW front, flat white, no lighting, depth z_clip / w_clip (near_z = far_z
 * = 0). */
void zl_state_default(zl_state *s);
/* ZL_ERR_ARG when an enum field is out of range; ZL_ERR_RANGE when light_on
 * is set and a light_dir component is outside +-1.0, or when near_z and
 * far_z are not both 0 and not 0 < near_z < far_z; ZL_ERR_UNSUPPORTED for
 * light_on set without ZL_FEATURE_LIGHTING, near_z or far_z set without
 * ZL_FEATURE_DEPTH_MAP, or (depth_test set) a
 * depth_func other than LESS, LEQUAL and ALWAYS without
 * ZL_FEATURE_DEPTH_FUNCS (zl_config.h). */
zl_status zl_state_check(const zl_state *s);

/* --------------------------------------------- smooth (per-vertex) lighting */

/*
 * SMOOTH LIGHTING (tests/test_smooth_light.c checks it against a
 * high-precision model of this equation). The OpenGL 1.x fixed-function
 * model with GL_COLOR_MATERIAL (ambient and diffuse), an infinite viewer and
 * directional or point lights (point lights without attenuation: OpenGL's
 * default constant 1), evaluated once per vertex by zl_light_vertices into a
 * caller array of lit colours, which a Gouraud draw then interpolates
 * (state.shading = ZL_SHADE_GOURAUD, state.light_on = 0, mesh.vertex_colors
 * = that array). Per vertex, with n its normal (model space, any non-zero
 * length), m its material colour (the mesh's vertex colour, else
 * lighting.material) and each channel separately:
 *
 *   c = min(255, round( m (A + sum_i D_i d_i) / 255 + sum_i S_i s_i ))
 *   d_i = max(0, n^ . L_i)
 *   s_i = d_i > 0 ? max(0, n^ . H_i)^e : 0          (0^0 = 1)
 *   L_i = unit(M^-1 l_i),  H_i = unit(M^-1 unit(unit(l_i) + unit(v)))
 *   point light: L_i = unit(M^-1 (q_i - t) - p),  H_i = unit(L_i + unit(M^-1 v))
 *
 * n^ = n / |n| (a zero normal gets the ambient term only), A = ambient,
 * D_i, S_i the light's diffuse and specular colours (0..255, already
 * multiplied by the material's), e = shininess (Blinn-Phong), l_i the light
 * direction and v the direction towards the viewer, both in the lights'
 * space (world or eye space), and M the upper-left 3x3 of the matrix from
 * model space to that space (NULL: identity, the lights are in model
 * space). The lights are brought into model space once per call (M^-1 from
 * the adjugate, no per-vertex matrix); when M is a rotation times a uniform
 * scale this is exactly OpenGL's eye-space evaluation with GL_NORMALIZE.
 * With any other M the normals are not re-normalised after the transform
 * (a non-uniform scale then bends the lighting slightly; OpenGL's
 * difference). A half vector of zero (light straight behind the viewer)
 * gives no specular.
 * A point light (zl_light.point) is at q_i in the lights' space: M^-1 (q_i -
 * t), with t the model matrix's translation, is its position in model space
 * (computed once per call), p the vertex position (so the mesh's positions
 * are read); a vertex at the light gets no diffuse or specular from it.
 *
 * Bound: every channel is within 1 of the exact real value of c before
 * its rounding (the test measures the worst case); integer arithmetic only
 * (Q30 unit vectors, 64-bit dot products), so every target computes the
 * same bytes.
 */
#define ZL_MAX_LIGHTS 4
#define ZL_MAX_SHININESS 128

typedef struct {
    zl_vec3 dir;      /* towards the light, lights' space; non-zero, any length (directional) */
    zl_rgb diffuse;   /* light diffuse x material diffuse, 0..255 each */
    zl_rgb specular;  /* light specular x material specular; 0,0,0: none */
    uint8_t point;    /* 1: a point light at `position` (dir unused); 0: directional */
    zl_vec3 position; /* a point light's position in the lights' space, Q16.16 */
} zl_light;

typedef struct {
    zl_rgb ambient;       /* scene (and lights') ambient x material ambient */
    zl_rgb material;      /* material colour when the mesh has no vertex colours */
    uint8_t light_count;  /* 0 .. ZL_MAX_LIGHTS */
    uint8_t shininess;    /* Blinn-Phong exponent e, 0 .. ZL_MAX_SHININESS */
    zl_vec3 viewer;       /* towards the viewer in the lights' space, non-zero
                             when a light has specular: (0, 0, 1) in eye space */
    zl_light lights[ZL_MAX_LIGHTS];
} zl_lighting;

/* Defaults: ambient 51 (0.2, OpenGL's), white material, no lights, shininess
 * 0, viewer (0, 0, 1); each light white diffuse, no specular, along +z. */
void zl_lighting_default(zl_lighting *lt);

/*
 * Lit colour of every vertex of mesh into colors (3 bytes r, g, b per
 * vertex, vertex_count of them) by the SMOOTH LIGHTING equation. normals:
 * 3 int16 per vertex (model space; unit length as Q14, 16384 = 1.0, is the
 * convention, any non-zero length gives the same result). model: the
 * matrix from model space to the lights' space (its upper-left 3x3 is
 * used), NULL for the identity. Only vertex_count and vertex_colors of the
 * mesh are read, and its positions when a light is a point light.
 * ZL_ERR_ARG for a NULL pointer (positions, with a point light); ZL_ERR_RANGE
 * for more than ZL_MAX_LIGHTS lights, shininess above ZL_MAX_SHININESS, a zero light
 * direction (or viewer, with specular), or a singular matrix. Nothing is
 * written on an error.
 */
zl_status zl_light_vertices(const zl_lighting *lt, const zl_mat4 *model, const zl_mesh *mesh,
                            const int16_t *normals, uint8_t *colors);

/* ------------------------------------------------- lines, points, style */

/*
 * LINE RULE (tests/test_lines.c checks it pixel for pixel)
 *
 * Endpoints: a vertex at window position (x, y), after the 1/16 pixel
 *   snapping, is in pixel (X, Y) = (floor(x), floor(y)): the pixel that
 *   contains it, a position on a pixel border belonging to the pixel right
 *   of / below it.
 * Pixels: a segment from (X0, Y0) to (X1, Y1), DX = X1 - X0, DY = Y1 - Y0,
 *   covers exactly max(|DX|, |DY|) + 1 pixels, both endpoints included:
 *     x-major (|DX| >= |DY|, diagonals included): one pixel per column X
 *       between X0 and X1, in the row nearest to Y0 + (X - X0) DY / DX;
 *     y-major (|DY| > |DX|): one pixel per row Y between Y0 and Y1, in the
 *       column nearest to X0 + (Y - Y0) DX / DY;
 *   an exact half rounds down (to the smaller row or column). The set
 *   depends only on the two endpoints, not on their order: A to B covers
 *   the same pixels as B to A.
 * Algorithms: ZL_LINE_BRESENHAM computes exactly this with a decision
 *   variable (an integer error term: no multiplication or division per
 *   pixel). ZL_LINE_DDA steps the minor coordinate as a 16.16 fixed-point
 *   value, s = DY/DX rounded to 1/65536, from the endpoint with the smaller
 *   major coordinate, and takes floor(value + 1/2). It differs from the rule
 *   (1) at exact halves, which it rounds up, and (2) where the slope's
 *   rounding, at most u / 2^17 pixel after u steps, carries the value across
 *   a half: possible only when u * (major length) >= 2^16, so never for
 *   lines shorter than 256 pixels, and for its far endpoint only when the
 *   major length is 2^16 or more. It is symmetric as well.
 * Strips and loops (ZL_PRIM_LINE_STRIP, ZL_PRIM_LINE_LOOP) plot each shared
 *   vertex once: every segment after the first leaves out the pixel of its
 *   first vertex (unless clipping moved that vertex), and a loop's closing
 *   segment also the pixel of its last one. ZL_PRIM_LINES segments are
 *   independent and keep both endpoints.
 * Depth: window depth is linear in screen space (see Pseudodepth), so it is
 *   interpolated linearly along the major axis between the endpoint depths
 *   (plus the style's offset units) and rounded; it is within +-1 of the
 *   exact value, and depth-tested and written as for triangles.
 * Clipping: as triangles (near, far, the guard band); a segment inside the
 *   guard band covers exactly the in-viewport pixels of the whole segment.
 *
 * POINTS: a point of size N (1 .. ZL_MAX_POINT_SIZE) at (x, y) covers the
 *   N x N pixels whose centres lie in (x - N/2, x + N/2] x (y - N/2, y + N/2];
 *   for N = 1 that is the pixel containing the vertex, as for a line
 *   endpoint. A point whose vertex is outside a clip plane is not drawn (as
 *   OpenGL). Its depth is the vertex depth (plus the offset units).
 *
 * POLYGON MODES (as glPolygonMode): after culling, a triangle facing the
 *   viewer is drawn as style.polygon_front says, one facing away as
 *   style.polygon_back: ZL_POLY_FILL (the raster contract above),
 *   ZL_POLY_LINE (its three edges v0-v1, v1-v2, v2-v0 as independent
 *   depth-tested segments, each clipped on its own; edges made by clipping
 *   are not drawn) or ZL_POLY_POINT (its vertices as points). Facing comes
 *   from the winding of the projected (clipped) triangle; zero-area
 *   triangles draw nothing in any mode.
 *
 * POLYGON OFFSET: every fragment of a triangle, in all three modes, has its
 *   depth moved by
 *       offset = factor * max(|dz/dx|, |dz/dy|) + units * r
 *   where the slopes are the triangle's depth plane in stored depth steps
 *   per pixel and r = 1 stored step (1/65535 of the depth range); factor and
 *   units are Q16.16 and the sum is computed in integers (Q20 steps). Lines
 *   and points drawn with zl_draw_lines have no slope: they move by
 *   units * r only. The result is clamped to the depth range.
 */
/*
 * ANTIALIASED LINES (style.line_aa): between the same endpoint pixels as the
 *   LINE RULE, every column (x-major) or row (y-major) u lights the two
 *   pixels nearest to the ideal line n(u) = N0 + u DN / DM: floor(n) with
 *   weight 1 - f and floor(n) + 1 with weight f, f = n - floor(n), as
 *   round(255 * weight). Each is blended into the colour buffer,
 *   new = (old (255 - w) + colour w) / 255 rounded, per channel (RGB565 is
 *   widened to 8 bits first), after the depth test; antialiased lines never
 *   write depth. A weight of 0 leaves the pixel alone. Strips and loops leave
 *   out the shared column as above, so a shared vertex is blended once.
 */
#define ZL_MAX_POINT_SIZE 64

/*
 * TEXTURES. A texture is RGB565 or RGBA4444 texels (native byte order; see
 * TEXEL FORMATS AND SIZES) in caller memory, const allowed (flash), width and
 * height 1 .. 4096, row r at texels + r * stride (zline-img2c makes one from
 * an image). Texture coordinates (style.texcoords) are 2 Q16.16
 * per vertex, (s, t), 1.0 = the texture's width or height; they are carried
 * through clipping with the vertex. A pixel takes the texel containing its
 * coordinate (nearest sampling: texel floor(s * width), floor(t * height)),
 * wrapped (ZL_WRAP_REPEAT: modulo the size) or clamped to the edge texels
 * (ZL_WRAP_CLAMP), per axis (wrap_s, wrap_t), times the lighting intensity
 * when the state's light is on.
 *
 * Texels exact (issue 22): with the exact depth mapping (state.near_z,
 * far_z set) and ZL_FEATURE_EXACT_DEPTH (the default), the texture planes
 * go through the vertices at their unsnapped window positions (2^-16
 * pixel; the set-up solves them with one reciprocal per triangle, the
 * vertex values of u/w and 1/w kept to the plane unit), so the
 * coordinate at a pixel centre is the exact one of the triangle there
 * (perspective or affine as below; clipped triangles: see Clipping) but
 * for the stepped planes' drift: half a plane unit for each of the up to
 * 1 + width + height pixel steps from the anchor, a unit being 2^-16
 * texel (affine) or 2^-16 w / w_min texel (perspective; w_min the
 * triangle's least clip w, w the pixel's): at most 1/234 texel on a
 * 320x240 target where w / w_min <= 1. The texel sampled (nearest) is
 * the one containing that exact coordinate except within 1/64 texel plus
 * that drift of a texel boundary, and bilinear weights are within 1/16
 * (plus the drift) of exact. Measured per pixel against a long double
 * reference by tests/host/test_texel_exact.c (perspective floors from
 * above, at a grazing angle and across the near plane; 64x64 and 48x40
 * random textures, RGB565 and RGBA4444, affine and perspective, frame and
 * scanline mode): every pixel beyond 1/64 texel of a boundary takes the
 * exact texel (none needs the drift; with the 12 fraction bits the planes
 * had before, 0.1 to 0.5 % took a neighbour); pixels where the coordinate
 * changes by more than 16 texels per pixel (a floor's horizon) are not
 * covered by the bound. Without the exact mapping, or with ZL_FEATURE_EXACT_DEPTH 0,
 * the planes go through the snapped vertices (1/16 pixel): the coordinate
 * is then that of the snapped triangle, which is off by up to 1/32 pixel
 * times its gradient (measured on the same floors before this change:
 * 1.4 to 1.8 % of the pixels took a neighbouring texel).
 *
 * Mapping: ZL_TEX_AFFINE interpolates (s, t) linearly in screen space, as
 * Gouraud colour (cheap, wrong under perspective). ZL_TEX_PERSPECTIVE
 * interpolates s/w, t/w and 1/w linearly in screen space (w the clip w of
 * each vertex, scaled per triangle so the nearest vertex has 1/w = 2^24) and
 * divides per pixel: one integer reciprocal R = 2^44 / (1/w) and two
 * multiplications. The texel coordinate is then within |c| / 2^16 + 1/128
 * texel of the exact perspective value c (coordinates are kept in 1/256
 * texel, |c| < 32768 texels). style.tex_every = N (2, 4, .. 64) computes the
 * exact value only every N pixels of a span (from its first pixel) and steps
 * linearly between: the error grows by at most N^2/8 times the second
 * derivative of the coordinate along the row, plus N/256 texel from the
 * truncated step (measured on the floor of tests/test_texture.c).
 *
 * style.persp_gouraud interpolates Gouraud colours the same perspective-
 * correct way (colour/w and 1/w) instead of linearly in screen space.
 * Textures and perspective Gouraud need cfg.textured in scanline mode.
 */
/*
 * TOON: with style.toon_bands = N > 0, a filled triangle's flat colour is
 * toon_colors[b], b = min(N - 1, floor(i * N / 256)) where i is its Lambert
 * intensity 0..255 of the lighting rule (zl_state; 255 with the light off).
 * Its face colour is not used; Gouraud shading keeps its vertex colours.
 */
/*
 * TEXEL FORMATS AND SIZES (texture.format): ZL_TEXEL_RGB565 (the default,
 * 0 after memset) or ZL_TEXEL_RGBA4444: one uint16 per texel in native
 * byte order, red in bits 15..12, green 11..8, blue 7..4, alpha 3..0
 * (OpenGL's GL_UNSIGNED_SHORT_4_4_4_4). A 4-bit channel v widens to 8 bits
 * as v * 17 (0 -> 0, 15 -> 255), an RGB565 one by bit replication. RGBA4444
 * rather than RGB565 plus a 1-bit key: the same 2 bytes per texel, and 16
 * levels of alpha give soft edges, glass and fades, which a key cannot; a
 * colour key is simply alpha 0 or 15. Width and height may be any size
 * 1 .. 4096: repeat takes the index modulo the size (a mask for powers of
 * two, which alone take the fast RGB565 span loop; other sizes divide per
 * texel). Without blending the alpha of RGBA4444 texels is ignored.
 *
 * BLENDING (style.blend, per draw, filled triangles only): after the depth
 *   test, with a = style.alpha (0..255) for RGB565 texels or no texture, and
 *   a = round(style.alpha * texel_alpha / 255) for RGBA4444 texels,
 *     ZL_BLEND_OFF    the fragment's colour is written (the default)
 *     ZL_BLEND_ALPHA  new = round((src a + old (255 - a)) / 255)
 *     ZL_BLEND_ADD    new = min(255, old + round(src a / 255))
 *   per 8-bit channel; old is the pixel in the colour buffer (RGB565 widened
 *   by bit replication), new is packed as any colour is (RGB565 keeps the
 *   top bits), and the colour mask applies. A fragment with a = 0 is
 *   discarded (neither colour nor depth written), so cut-out texels leave
 *   holes even with depth writes on. Depth is written as the state says.
 *   Lines and points are not blended. Frame and scanline/band modes give the
 *   same bytes (triangles blend in submission order in both); in scanline
 *   mode blending needs cfg.styled and cfg.textured (it uses the styled rows).
 *   Transparent geometry: draw the opaque meshes first (depth test and
 *   writes on), then the transparent ones with depth_write = 0 and their
 *   triangles in back-to-front order by the painter's key of
 *   zl_visibility.h (the farthest vertex's window depth, far first;
 *   zl_painter_order writes a mesh's indices in that order), so each blends
 *   over what is behind it and none hides another (ALPHA is order
 *   dependent; ADD is not).
 */
typedef enum { ZL_WRAP_REPEAT = 0, ZL_WRAP_CLAMP = 1 } zl_wrap;
typedef enum { ZL_TEX_AFFINE = 0, ZL_TEX_PERSPECTIVE = 1 } zl_tex_mapping;
typedef enum { ZL_TEXEL_RGB565 = 0, ZL_TEXEL_RGBA4444 = 1 } zl_texel_format;
typedef enum { ZL_BLEND_OFF = 0, ZL_BLEND_ALPHA = 1, ZL_BLEND_ADD = 2 } zl_blend;
/*
 * TEXTURE FILTERING (style.tex_filter): ZL_FILTER_NEAREST (the default) takes
 *   the texel containing the coordinate. ZL_FILTER_BILINEAR blends the four
 *   texels around it: per axis, with c the texel coordinate in 1/256 texel
 *   (as above), p = c - 128 (the texel centres), i = floor(p / 256) and
 *   f = p - 256 i (0..255), the texels i and i + 1, each wrapped or clamped
 *   by the axis' rule; per 8-bit channel (alpha too)
 *     top = t(i, j) (256 - fs) + t(i + 1, j) fs, bottom likewise at j + 1,
 *     value = (top (256 - ft) + bottom ft + 2^15) >> 16.
 *   Integer only (products below 2^24); it takes the general span loop.
 */
typedef enum { ZL_FILTER_NEAREST = 0, ZL_FILTER_BILINEAR = 1 } zl_tex_filter;

typedef struct {
    const uint16_t *texels; /* zl_texel_format, native byte order */
    uint16_t width, height; /* 1 .. 4096 (powers of two are faster) */
    uint16_t stride;        /* texels from one row to the next, >= width */
    uint8_t wrap_s, wrap_t; /* zl_wrap */
    uint8_t format;         /* zl_texel_format (0: RGB565) */
} zl_texture;

typedef enum {
    ZL_PRIM_LINES = 0,      /* independent segments: indices 2k, 2k + 1 */
    ZL_PRIM_LINE_STRIP = 1, /* a polyline through every index */
    ZL_PRIM_LINE_LOOP = 2,  /* a closed polyline */
    ZL_PRIM_POINTS = 3      /* one point per index */
} zl_prim;

typedef enum { ZL_LINE_BRESENHAM = 0, ZL_LINE_DDA = 1 } zl_line_algo;
typedef enum { ZL_POLY_FILL = 0, ZL_POLY_LINE = 1, ZL_POLY_POINT = 2 } zl_polygon_mode;

/*
 * Lines or points in caller memory (every array may be const in flash).
 * positions: 3 Q16.16 per vertex, as zl_mesh (model space, or pixel space
 *   with a NULL matrix). indices: `count` of them, each < vertex_count, or
 *   NULL for the vertices in order. colors (optional): 3 bytes (r, g, b) per
 *   primitive (segment or point, in order); without them the state's colour.
 */
typedef struct {
    const zl_fixed *positions;
    const uint16_t *indices;
    const uint8_t *colors;
    uint16_t vertex_count;
    uint16_t count;
    uint8_t prim; /* zl_prim */
} zl_lines;

/* Number of segments or points a zl_lines describes (0 if prim is unknown). */
uint32_t zl_lines_primitives(const zl_lines *l);

/*
 * How primitives are drawn, beside zl_state: polygon modes, offset, lines
 * and points. Kept apart from zl_state so that scenes that do not use these
 * features pay nothing for them in scanline mode.
 */
typedef struct {
    uint8_t polygon_front;  /* zl_polygon_mode of front faces */
    uint8_t polygon_back;   /* zl_polygon_mode of back faces */
    uint8_t point_size;     /* 1 .. ZL_MAX_POINT_SIZE pixels */
    uint8_t line_algo;      /* zl_line_algo */
    zl_fixed offset_factor; /* polygon offset, Q16.16, -256.0 .. 256.0 */
    zl_fixed offset_units;  /* polygon offset, Q16.16 depth steps (any value) */
    const zl_texture *texture;  /* NULL: no texture */
    const zl_fixed *texcoords;  /* 2 Q16.16 per vertex of the mesh (with a texture) */
    uint8_t tex_mapping;        /* zl_tex_mapping */
    uint8_t tex_every;          /* perspective: exact every N pixels, N = 2..64 a power of two; 0 or 1: every pixel */
    uint8_t persp_gouraud;      /* 1: perspective-correct Gouraud colours */
    uint8_t toon_bands;         /* toon shading: 0 off, else 1 .. 255 bands (see TOON) */
    const zl_rgb *toon_colors;  /* toon_bands colours, darkest band first */
    uint8_t line_aa;            /* 1: antialiased lines (see ANTIALIASED LINES) */
    uint8_t blend;              /* zl_blend of filled triangles (see BLENDING) */
    uint8_t alpha;              /* constant alpha 0..255 of blending (default 255) */
    uint8_t tex_filter;         /* zl_tex_filter (see TEXTURE FILTERING) */
} zl_style;

/*
 * OUTLINES. zl_mesh_edges lists every edge of a mesh once with the two
 * triangles sharing it (the adjacency; a tool can run it offline and keep the
 * list as a const array). An outline draws the selected edges as lines (the
 * LINE RULE, depth-tested with the state, moved by style.offset_units so the
 * faces they border do not hide them; about -1/16 of the depth range per
 * pixel of a steep face is typical, see docs/FEATURES.md):
 *   silhouettes  an edge between a front-facing and a back-facing triangle
 *                (facing from the homogeneous winding of the clip-space
 *                vertices, the rasteriser's own rule for visible triangles)
 *   creases      an edge whose two face normals (model space) have a cosine
 *                below crease_cos (Q16.16), i.e. a dihedral angle above the
 *                threshold, drawn when one of its faces is front-facing
 *   borders      an edge with one triangle
 */
#define ZL_NO_TRIANGLE 0xFFFFu

typedef struct {
    uint16_t v0, v1; /* vertex indices, v0 < v1 */
    uint16_t t0, t1; /* the triangles sharing the edge; t1 = ZL_NO_TRIANGLE at a border */
} zl_mesh_edge;

/* Fill `edges` (capacity >= 3 * triangle_count entries) with the mesh's edge
 * list, sorted by vertices; returns the number of edges (0 on an invalid
 * mesh or too small a capacity). No memory beyond the list (in-place heap
 * sort). An edge of three or more triangles gives one entry per pair. */
uint32_t zl_mesh_edges(const zl_mesh *mesh, zl_mesh_edge *edges, uint32_t capacity);

typedef struct {
    const zl_mesh_edge *edges; /* from zl_mesh_edges, for the mesh drawn */
    uint32_t edge_count;
    zl_fixed crease_cos;       /* creases where cos(angle between normals) < this */
    uint8_t silhouettes, creases, borders;
    zl_rgb color;
} zl_outline;

/* Defaults: fill both faces, points of 1 pixel, Bresenham, no offset, no
 * texture, screen-linear Gouraud, no blending (alpha 255). */
void zl_style_default(zl_style *s);
/* ZL_ERR_ARG for an unknown enum value, ZL_ERR_RANGE for a number outside its
 * range, ZL_ERR_UNSUPPORTED for a field asking for a feature compiled out
 * (zl_config.h: textures, blending, polygon modes, offset). */
zl_status zl_style_check(const zl_style *s);

/* ------------------------------------------------------- frame mode */

/* A full-frame render target: colour and depth in caller memory. */
typedef struct {
    void *color;           /* width x height pixels of `format`, or NULL for none;
                              RGB565 needs 2-byte alignment (ZL_ERR_ARG otherwise),
                              RGB565_BE and RGB888 are byte streams: any alignment */
    int32_t color_stride;  /* bytes from one row to the next, >= width * bpp
                              (even for RGB565) */
    uint16_t *depth;       /* width x height depth values (2-byte aligned), or NULL */
    int32_t depth_stride;  /* bytes, >= width * 2 and even */
    uint16_t width, height; /* 1 .. ZL_MAX_DIM */
    uint8_t format;         /* zl_format */
} zl_target;

typedef struct {
    zl_target target;
    zl_state state;
    zl_style style; /* polygon modes, offset, lines and points */
    /* Optional vertex cache for zl_draw_mesh (NULL after zl_init): with at
     * least ZL_VERTEX_CACHE_BYTES(mesh->vertex_count) bytes, 4-byte aligned,
     * each vertex is transformed once per draw instead of once per triangle
     * that uses it (the same pixels either way). A smaller cache is not used.
     * The cache is scratch: a draw that fails (ZL_ERR_RANGE) may have written
     * it, never the target. */
    void *vertex_cache;
    size_t vertex_cache_bytes;
    /* Optional draw cache for zl_draw_mesh (NULL after zl_init): without
     * the vertex cache above, a plain flat or Gouraud draw keeps the window
     * vertices of recent triangles here, a direct-mapped cache of
     * ZL_DRAW_CACHE_SLOTS entries (zl_config.h) after the draw's transform
     * set-up. It needs zl_draw_cache_bytes() bytes (14,480 with the default
     * 1024 slots), 8-byte aligned (declare it as uint64_t[]; where uint64_t
     * is aligned to less, as on AVR, add __attribute__((aligned(8)))). NULL,
     * a smaller or a misaligned cache is not used: each triangle then
     * transforms and clips its own three vertices (the general path:
     * slower, the same pixels). Library scratch, rewritten by every draw. */
    void *draw_cache;
    size_t draw_cache_bytes;
    /* Scratch of zl_draw_mesh_camera (zl_camera.h): the matrix of its last
     * draw, here rather than on the stack under the whole draw. */
    zl_mat4 camera_mvp;
} zl_context;

/* Bytes of vertex cache for n vertices (scanline mode uses the same entries). */
/* One cached vertex: 12 bytes (8 without ZL_FEATURE_EXACT_DEPTH, zl_config.h). */
#define ZL_VERTEX_CACHE_ENTRY (ZL_FEATURE_EXACT_DEPTH ? 12u : 8u)
#define ZL_VERTEX_CACHE_BYTES(n) ((size_t)(n) * ZL_VERTEX_CACHE_ENTRY)
/* Bytes of draw cache for a library built with ZL_DRAW_CACHE_SLOTS = slots:
 * the transform set-up (144 bytes), then a cached window vertex
 * (ZL_VERTEX_CACHE_ENTRY bytes) and a 2-byte tag a slot; 0 for 0 slots (no draw cache). */
#define ZL_DRAW_CACHE_SETUP_BYTES 144u
#define ZL_DRAW_CACHE_BYTES(slots) \
    ((slots) > 0 ? ZL_DRAW_CACHE_SETUP_BYTES + (size_t)(slots) * (ZL_VERTEX_CACHE_ENTRY + 2u) : (size_t)0)
/* The draw cache this library uses: ZL_DRAW_CACHE_BYTES of the
 * ZL_DRAW_CACHE_SLOTS it was built with (0: it has none). */
size_t zl_draw_cache_bytes(void);

/* Check the target and set the default state and style (ZL_ERR_UNSUPPORTED
 * for RGB888 without ZL_FEATURE_FORMATS, zl_config.h). */
zl_status zl_init(zl_context *ctx, const zl_target *target);
/* Clear colour (respecting the colour mask) and depth (respecting the
 * depth write mask), as glClear does. */
zl_status zl_clear(zl_context *ctx, zl_rgb color, uint16_t depth);
/*
 * Draw a mesh transformed by mvp (model-view-projection, to clip space), or,
 * when mvp is NULL, a mesh whose positions are in pixel space. Nothing is
 * drawn if any argument is invalid (checked before the first pixel).
 */
zl_status zl_draw_mesh(zl_context *ctx, const zl_mesh *mesh, const zl_mat4 *mvp);
/* Draw lines or points with ctx->state (depth, masks, colour) and ctx->style
 * (point size, line algorithm, offset units), by the LINE RULE above. */
zl_status zl_draw_lines(zl_context *ctx, const zl_lines *lines, const zl_mat4 *mvp);
/* Draw the outline of a mesh (see OUTLINES) with ctx->state and ctx->style,
 * usually right after the mesh itself. */
zl_status zl_draw_outlines(zl_context *ctx, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_outline *outline);

/* -------------------------------------------------- scanline and band mode */

/*
 * zl_frame renders a whole frame a band of rows at a time: band_rows = 1 is
 * scanline mode (one row of depth, reused for every row), band_rows = height
 * is a full frame. Geometry is submitted first; then each band is cleared,
 * every triangle crossing it is filled, and the band is handed to the
 * caller. Output is byte-identical to zl_draw_mesh into a full target.
 *
 * Sizing: every byte lives in the caller's work buffer, whose exact size
 * zl_frame_bytes() gives for a configuration. Capacities:
 *   max_meshes     zl_frame_add_mesh calls per frame
 *   max_vertices   sum of vertex_count over the meshes
 *   max_triangles  triangles kept after culling and off-screen rejection
 *                  (the sum of triangle_count always suffices); <= 65535
 *   max_active     triangles crossing one row at once, 1 .. 65534; a
 *                  clipped triangle counts once per piece (up to 8), so
 *                  8 x the sum of triangle_count always suffices when
 *                  that is below the cap; zl_frame_needs() gives the exact
 *                  figure of a scene
 * Over capacity (issue 25): when the submitted scene needs more triangles
 * or active records than the buffer holds, zl_frame_next_band does not fail:
 * the frame still comes out complete and byte-identical to frame mode. The
 * rows are then planned a window at a time (the longest run of whole bands
 * whose primitives fit one plan, rendered band after band from it); a band
 * where not even that fits is rendered in passes over consecutive ranges of
 * primitives in submission order, into the same band colour and depth, so
 * every pixel still sees the primitives in submission order (depth ties and
 * blending as in frame mode). A plan's primitives that start above its
 * first row are first walked there without writing. zl_frame_needs() still
 * reports the true needs, and `replans` the plans made after the whole
 * frame's (0 when the scene fitted: check it to know that it happened).
 * Cost: every window or band classifies every primitive again, twice for a
 * window (count, place) and up to three times for a band in passes (find
 * the window, count, place), so a frame over capacity is much
 * slower: the bunny on the host (callgrind, tools/bench/zline-bench-modes
 * MODEL --only MODE --over K) 2.17 M instructions in scanline mode within
 * capacity, 191 M at half its capacities, 234 M at a tenth; in bands of 16
 * rows 2.14 M, 21.7 M, 21.9 M. Size for the needs (zl_frame_bound), and
 * treat replans as a warning. Frames that fit take the same path as before
 * (without the fast paths, zl_config.h's ZL_FAST_PATHS=0, every frame is
 * planned this way: one window when it fits, with replans 0).
 * ZL_ERR_CAPACITY remains, before any band, only when one primitive alone
 * does not fit (max_triangles 0, or fewer active records than its pieces:
 * up to 8 for a clipped triangle, 3 for the lines or points of a polygon
 * mode), and for the parts of a split frame (zl_frame_split), which are not
 * planned again. max_meshes and max_vertices do not depend on the pose:
 * over them zl_frame_add_mesh fails with ZL_ERR_CAPACITY as before.
 *
 * Order and faults: zl_frame_begin first (a zeroed zl_frame is refused with
 * ZL_ERR_ARG by every other call); meshes, lines and outlines before the
 * first band (after it: ZL_ERR_ARG, the frame goes on); then bands until
 * ZL_DONE, which every later call returns again. A frame may be abandoned at
 * any point, a band callback may stop it at any band: zl_frame_begin on the
 * same zl_frame and work buffer starts the next frame as from new (nothing
 * of the stopped frame remains, tests/test_frame_faults.c).
 */
typedef struct {
    uint16_t width, height;
    uint16_t band_rows;     /* 1 .. height */
    uint8_t format;         /* zl_format of the colour band */
    uint8_t color_buffers;  /* 1, or 2 to alternate bands for DMA double buffering */
    uint8_t gouraud;        /* reserve room for Gouraud gradients (else only flat shading) */
    uint16_t max_meshes;
    uint32_t max_vertices;
    uint32_t max_triangles;
    uint32_t max_active;
    /* Features beyond the flat/Gouraud mesh; 0 leaves the layout as it was. */
    uint8_t styled;         /* reserve a zl_style per mesh: needed by zl_frame_add_lines
                               and by zl_frame_add_mesh_styled with a non-default style */
    uint8_t textured;       /* reserve texture / perspective planes per active record
                               (textures, perspective-correct Gouraud) */
    uint8_t parts;          /* 2: the frame will be split across two cores (zl_frame_split):
                               the submission leaves the vertex transform to the
                               parts' zl_frame_prepare, which share it; 0 or 1: one */
} zl_frame_config;

/* A finished band: rows first_row .. first_row + rows - 1. */
typedef struct {
    uint16_t first_row, rows, width;
    uint8_t format;
    void *color;            /* rows x width pixels: the caller's to draw on
                               (zl_overlay.h) until the next band */
    int32_t color_stride;   /* bytes */
    const uint16_t *depth;  /* rows x width depth values */
    int32_t depth_stride;   /* bytes */
} zl_band;

/* What a submitted scene needs (after zl_frame_next_band has planned it). */
typedef struct {
    uint32_t triangles;   /* visible triangles kept for the frame */
    uint32_t active;      /* bound on triangles crossing one row at once */
    uint32_t replans;     /* plans after the whole frame's: 0 when the scene
                             fitted the buffer; over capacity one per window
                             of bands and per pass of a band (see Sizing
                             above); zl_vis_needs: always 0 */
} zl_frame_needs_t;

/* Private bookkeeping; the caller allocates it but never touches it. */
typedef struct zl_frame_mesh zl_frame_mesh;
typedef struct zl_active zl_active;

typedef struct {
    zl_frame_config cfg;
    zl_rgb clear_color;
    uint16_t clear_depth;
    uint16_t next_row;       /* first row of the next band */
    uint16_t end_row;        /* rows end here: height, or the split row (zl_frame_split) */
    uint8_t planned;
    uint8_t band_index;
    uint8_t part;            /* 0: a whole frame; 1, 2: the first, second part of a split one */
    uint8_t prepared;        /* a part: zl_frame_prepare done */
    uint16_t split_row;      /* a part: the row asked of zl_frame_split (0: balanced) */
    uint8_t over;            /* over capacity: planned by windows of bands, `planned` stays 0 */
    uint16_t over_end;       /* over capacity: the rows the current window's plan covers end here */
    uint16_t mesh_count;
    uint32_t vertex_count;
    uint32_t triangle_total;
    zl_frame_needs_t needs;
    /* carved from the work buffer by zl_frame_begin */
    zl_frame_mesh *meshes;
    uint8_t *vcache;         /* packed cached window vertices */
    uint16_t *row_start;     /* height + 1 offsets into visible[] */
    uint16_t *visible;       /* visible triangle ids sorted by first row */
    zl_active *pool;         /* max_active active-triangle records */
    uint8_t *gouraud;        /* max_active Gouraud gradient records or NULL */
    uint8_t *ext;            /* max_meshes style records (cfg.styled) or NULL */
    uint8_t *tex;            /* max_active texture plane records (cfg.textured) or NULL */
    uint16_t active_head;    /* first active record, sorted by triangle id */
    uint16_t free_head;
    uint16_t *depth_band;
    uint8_t *color_band[2];
} zl_frame;

/* Exact number of work-buffer bytes for a configuration; 0 if it is invalid. */
size_t zl_frame_bytes(const zl_frame_config *cfg);

/* Start a frame in `work`: at least zl_frame_bytes(cfg) bytes, 8-byte aligned
 * (declare it as uint64_t work[(bytes + 7) / 8]; where uint64_t is aligned
 * to less, as on AVR, add __attribute__((aligned(8)))); ZL_ERR_ARG if
 * misaligned; ZL_ERR_UNSUPPORTED for RGB888 without ZL_FEATURE_FORMATS, or two parts without ZL_FEATURE_SPLIT (zl_config.h). */
zl_status zl_frame_begin(zl_frame *f, const zl_frame_config *cfg, void *work, size_t work_bytes,
                         zl_rgb clear_color, uint16_t clear_depth);
/* Submit a mesh with its transform (NULL: pixel space) and state (copied).
 * With a matrix the vertex positions are transformed here, into the work
 * buffer's vertex cache; the mesh's arrays (indices, colours, and positions
 * for lighting) are still read while the bands are rendered, so they must
 * stay valid and unchanged until the frame is done. */
zl_status zl_frame_add_mesh(zl_frame *f, const zl_mesh *mesh, const zl_mat4 *mvp,
                            const zl_state *state);
/* The same with a style (polygon modes, offset, points); NULL means the
 * default style. Needs cfg.styled unless the style is the default. Lines and
 * points of polygon modes count in max_active as up to 3 records per
 * triangle. */
zl_status zl_frame_add_mesh_styled(zl_frame *f, const zl_mesh *mesh, const zl_mat4 *mvp,
                                   const zl_state *state, const zl_style *style);
/* Submit lines or points (needs cfg.styled). Each segment or point is one
 * primitive in submission order with the triangles (it counts in the 65535
 * primitives of a frame, in max_triangles and in max_active). */
zl_status zl_frame_add_lines(zl_frame *f, const zl_lines *lines, const zl_mat4 *mvp,
                             const zl_state *state, const zl_style *style);
/* Submit the outline of a mesh (needs cfg.styled): one primitive per edge of
 * the list, as lines. */
zl_status zl_frame_add_outlines(zl_frame *f, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state,
                                const zl_style *style, const zl_outline *outline);
/*
 * Pull form: render the next band and describe it in *band. Returns ZL_OK
 * with a band, ZL_DONE when all rows are out, or an error. With two colour
 * buffers the band returned last time stays untouched until the next call
 * after this one: the display may still be sending it.
 */
zl_status zl_frame_next_band(zl_frame *f, zl_band *band);
/* Push form: call fn for every band in order. Returns 0 when all rows are
 * out, a negative zl_status on an error of the library, or the first
 * non-zero value fn returned (which stops the frame). */
typedef int (*zl_band_fn)(void *user, const zl_band *band);
int zl_frame_render(zl_frame *f, zl_band_fn fn, void *user);
/* What the submitted scene needs; valid after the first zl_frame_next_band. */
zl_frame_needs_t zl_frame_needs(const zl_frame *f);

/* ------------------------------------------------------------- ABI check */

/* A short English description of a status, for logs ("unknown status" for
 * a value that is none). */
const char *zl_status_string(zl_status s);

/*
 * ZL_ABI_KEY: a 32-bit fingerprint (FNV-1a) of the sizes of the public
 * structs and of the zl_config.h values, as this compilation sees them.
 * zl_init and zl_frame_begin are macros that pass the application's key to
 * the library, which compares it with its own: ZL_ERR_ABI when they differ
 * (the library built with other configuration macros, another compiler or
 * other ABI flags than the application), before anything is written. The
 * functions themselves stay callable, unchecked, as (zl_init)(ctx, target).
 */
#define ZL_ABI_MIX(h, v) ((uint32_t)((uint32_t)((uint32_t)(h) ^ (uint32_t)(v)) * UINT32_C(16777619)))
/* one struct size or configuration value at a time */
#define ZL_ABI_S1 ZL_ABI_MIX(UINT32_C(2166136261), sizeof(zl_context))
#define ZL_ABI_S2 ZL_ABI_MIX(ZL_ABI_S1, sizeof(zl_target))
#define ZL_ABI_S3 ZL_ABI_MIX(ZL_ABI_S2, sizeof(zl_state))
#define ZL_ABI_S4 ZL_ABI_MIX(ZL_ABI_S3, sizeof(zl_style))
#define ZL_ABI_S5 ZL_ABI_MIX(ZL_ABI_S4, sizeof(zl_mesh))
#define ZL_ABI_S6 ZL_ABI_MIX(ZL_ABI_S5, sizeof(zl_texture))
#define ZL_ABI_S7 ZL_ABI_MIX(ZL_ABI_S6, sizeof(zl_lines))
#define ZL_ABI_S8 ZL_ABI_MIX(ZL_ABI_S7, sizeof(zl_outline))
#define ZL_ABI_S9 ZL_ABI_MIX(ZL_ABI_S8, sizeof(zl_lighting))
#define ZL_ABI_S10 ZL_ABI_MIX(ZL_ABI_S9, sizeof(zl_frame))
#define ZL_ABI_S11 ZL_ABI_MIX(ZL_ABI_S10, sizeof(zl_frame_config))
#define ZL_ABI_S12 ZL_ABI_MIX(ZL_ABI_S11, sizeof(zl_band))
#define ZL_ABI_S13 ZL_ABI_MIX(ZL_ABI_S12, sizeof(zl_frame_needs_t))
#define ZL_ABI_SIZES ZL_ABI_S13
#define ZL_ABI_C1 ZL_ABI_MIX(ZL_ABI_SIZES, ZL_SUBPIXEL_BITS)
#define ZL_ABI_C2 ZL_ABI_MIX(ZL_ABI_C1, ZL_GUARD_PX)
#define ZL_ABI_C3 ZL_ABI_MIX(ZL_ABI_C2, ZL_MAX_DIM)
#define ZL_ABI_C4 ZL_ABI_MIX(ZL_ABI_C3, ZL_DRAW_CACHE_SLOTS)
#define ZL_ABI_C5 ZL_ABI_MIX(ZL_ABI_C4, ZL_SMALL_TRIANGLE_SETUP)
#define ZL_ABI_C6 ZL_ABI_MIX(ZL_ABI_C5, ZL_FEATURES)
#define ZL_ABI_KEY ZL_ABI_C6

/* The library's own ZL_ABI_KEY. */
uint32_t zl_abi_key(void);
/* zl_init and zl_frame_begin after the key check (ZL_ERR_ABI on a mismatch).
 * The macros are variadic so that an argument with commas of its own (a
 * compound literal such as (zl_rgb){0, 0, 0}) passes through unchanged. */
zl_status zl_init_abi(uint32_t abi_key, zl_context *ctx, const zl_target *target);
zl_status zl_frame_begin_abi(uint32_t abi_key, zl_frame *f, const zl_frame_config *cfg, void *work,
                             size_t work_bytes, zl_rgb clear_color, uint16_t clear_depth);
#define zl_init(...) zl_init_abi(ZL_ABI_KEY, __VA_ARGS__)
#define zl_frame_begin(...) zl_frame_begin_abi(ZL_ABI_KEY, __VA_ARGS__)
/* ------------------------------------------------- two cores, one frame */

/*
 * A frame split across two cores (or threads) by halves: the first core
 * renders rows 0 .. split - 1 through the zl_frame it submitted to, the
 * second rows split .. height - 1 through a second zl_frame that
 * zl_frame_split makes from it. Halves rather than interleaved bands: a
 * core planning only its rows drops the other half's triangles before any
 * setup, and only triangles crossing the split row are set up on both cores
 * (interleaved bands would set up every triangle that crosses a band edge
 * twice: every triangle taller than one row in scanline mode).
 *
 * Per frame:
 *   first core                          second core
 *   zl_frame_begin (cfg.parts = 2)
 *   zl_frame_add_* (the submission)
 *   zl_frame_split(f, &second, ...)
 *   signal the second core  ----------> wait for the signal
 *   zl_frame_prepare(f)                 zl_frame_prepare(&second)
 *   ---------------------- the barrier: both prepared ----------------------
 *   zl_frame_next_band / zl_frame_render on f, and on &second, as usual
 *   wait for the second's "done" <----- signal "done"
 * zl_frame_prepare transforms the part's half of the vertices into the
 * shared vertex cache (with cfg.parts = 2; without it the submission did
 * them all, serially). After the barrier each part's first band classifies
 * the triangles of its rows into its own edge table (both parts read the
 * whole vertex cache: hence the barrier), the second part also walking, into
 * a scratch row it does not hand out, the rows above the split of the
 * triangles crossing it, so that its records reach the split row exactly as
 * one core's would. The split row, unless given, is the one with half the
 * cached vertices above it (both parts compute the same), rounded down to a
 * multiple of band_rows. A part hands out its own rows' bands, in order,
 * each with its first_row (zl_band): a display with a row window takes them
 * as they come; one that takes rows only in order must keep the second
 * part's bands (or let it wait) until the first part is done. Pixels are
 * byte-identical to one core's (tests/host/test_frame_dual.c,
 * port/cortex-m/bench/dual.c).
 *
 * Memory. The first core's work buffer (zl_frame_bytes) holds the shared
 * part: the mesh records and style records (written by the submission
 * only) and the vertex cache (each part writes its half in
 * zl_frame_prepare, both read all of it after the barrier), and the first
 * part's own regions. The second core's work buffer (zl_frame_part_bytes)
 * holds what each part has its own of: edge table (height + 1 row starts,
 * max_triangles ids), active records (and their Gouraud and texture
 * records), depth band and colour band(s). Each core writes only its own
 * zl_frame, its own regions and its half of the vertex cache; the meshes,
 * matrices, states, textures and colour arrays are read by both and must
 * not change until both are done. Both parts must be prepared and rendered
 * (or both abandoned) before zl_frame_begin reuses either work buffer.
 *
 * Synchronisation (no locks and no OS calls in the library): the caller
 *   1. after zl_frame_split, on the first core: a memory barrier (DMB on
 *      Cortex-M, `fence rw,w` on RISC-V, a release store or pthread_create
 *      on a host), then starts or signals the second core (a flag it polls);
 *      the second core, after seeing it: a barrier (DMB; `fence r,rw`; an
 *      acquire load) before touching the frame;
 *   2. the barrier after zl_frame_prepare: each core, a memory barrier, then
 *      its "prepared" flag, then it waits for the other's, then a memory
 *      barrier (or pthread_barrier_wait);
 *   3. on the second core, when its last band is out: a barrier, then its
 *      "done" flag; the first core waits for it (and a barrier) before
 *      zl_frame_begin reuses either work buffer.
 * Uncached or write-through shared RAM is assumed (as on RP2040, RP2350 and
 * the SSE-200); a part with data caches also needs its cache maintenance.
 */
/* Bytes of the second core's work buffer: zl_frame_bytes minus the mesh
 * records and the vertex cache (with cfg.styled the style records' room is
 * kept, unused); 0 if cfg is invalid. */
size_t zl_frame_part_bytes(const zl_frame_config *cfg);
/* Split f (begun, submitted, not yet planned) at row `split_row` (0: the
 * balanced row, see above; else rounded down to a multiple of band_rows, at
 * most height) and make `second`, in `work` (8-byte aligned, >=
 * zl_frame_part_bytes), the frame of the rows below it. ZL_ERR_ARG if f is
 * not in that state or an argument is NULL or misaligned, ZL_ERR_SIZE if
 * work_bytes is short. */
zl_status zl_frame_split(zl_frame *f, zl_frame *second, void *work, size_t work_bytes, uint16_t split_row);
/* A part's share of the vertex transform, once, before the barrier; its
 * first zl_frame_next_band without it is ZL_ERR_ARG. ZL_ERR_ARG if f is not
 * a part of a split frame or is prepared already. */
zl_status zl_frame_prepare(zl_frame *part);

#ifdef __cplusplus
}
#endif

/* 2D overlays over the 3D, in every mode: rectangles, lines, text, images. */
#include "zl_overlay.h"
/* Work-buffer capacities for a mesh in every pose, without a dry run. */
#include "zl_sizing.h"
/* Flat shading from the zl_lighting of smooth shading (lights in world space). */
#include "zl_face_light.h"

#endif /* ZLINE_H */

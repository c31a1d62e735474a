/* SPDX-License-Identifier: MIT */
/*
 * The scenes of the Cortex-M benchmarks and of the host-equals-target test.
 * Portable: compiled for the target and for the host (bench/host).
 *
 *   bunny        the benchmark scene (../../../tools/bench/bench_scene.h):
 *                bunny.obj normalised, 320x240, camera at (0, 0, 3.5), 60
 *                degree vertical field of view, near 0.1, far 100, back faces
 *                culled, one lit flat colour per triangle, 16-bit depth
 *   fill         fill rate: 4 triangles, each covering the whole 320x240
 *                screen, drawn far to near (every fragment passes the depth
 *                test: 4 x 76800 pixels written), flat colours
 *   fill_gouraud the same with a colour per vertex, Gouraud shaded
 *   tris         triangle rate: a 64 x 64 grid, 8192 triangles of about 9
 *                pixels, covering the screen once, flat colour
 *   bunny_gouraud (issue 21) the benchmark scene with a colour per vertex
 *                (made from the vertex's position in scene_make), Gouraud
 *                shaded, no lighting
 *   bunny_smooth (issue 21, SCENE_BUNNY_LIT) the benchmark scene lit per
 *                vertex by zl_light_vertices: the flat bunny's ambient,
 *                material and one directional light (eye space, no
 *                specular), the vertex normals of zline-obj2c, Gouraud
 *   bunny_specular (SCENE_BUNNY_SMOOTH; golden test and bench_smooth.c,
 *                whose intervals keep the name bunny_smooth) the bunny's camera with
 *                smooth lighting (zl_light_vertices, issue 15): area-weighted
 *                normals from zline-obj2c, a key light with white Blinn-Phong
 *                specular (exponent 24) and a blue fill light, both in eye
 *                space (brought to model space by the view matrix), the lit
 *                vertex colours Gouraud-interpolated
 *   bunny_exact  the benchmark scene with zl_state near_z = 0.1, far_z = 100:
 *                the exact depth mapping (zline.h, Pseudodepth), its cost
 *   bunny_clip   the benchmark scene with the near plane at 3.45, just in
 *                front of the bunny's centre and no culling: the near
 *                plane cuts the model through the middle (198 of its 3674
 *                triangles cross it; their pieces take the original
 *                triangles' planes) and its inside shows
 *   tetra        (golden test only) a vertex-coloured model close to the
 *                camera: near-plane clipping and Gouraud shading
 *   textured     (golden test only, issue 15) floor.obj (texture coordinates
 *                kept by zline-obj2c) with checker.ppm (zline-img2c, RGB565,
 *                64x64), perspective-correct; over it two blended copies of
 *                the floor (depth writes off): a "glass" plane 0.5 above it
 *                with rgba5x3.ppm + alpha as RGBA4444 (5x3: not a power of
 *                two), alpha blended at constant alpha 200, and a narrow
 *                additive band (flat colour, constant alpha 120)
 * The meshes are const (flash): bunny, grid and tetra are generated from OBJ
 * files by zline-obj2c at build time.
 */
#ifndef ZLINE_BENCH_SCENES_H
#define ZLINE_BENCH_SCENES_H

#include "zline/zline.h"

#define SCENE_W 320
#define SCENE_H 240

enum {
    SCENE_BUNNY, SCENE_FILL, SCENE_FILL_GOURAUD, SCENE_TRIS, SCENE_BUNNY_EXACT, SCENE_TETRA, SCENE_BUNNY_SMOOTH,
    SCENE_TEXTURED, SCENE_BUNNY_CLIP, SCENE_BUNNY_GOURAUD, SCENE_BUNNY_LIT, SCENE_COUNT
};

/* The most meshes drawn after the first one (styled scenes). */
#define SCENE_MAX_EXTRA 2

typedef struct {
    const char *name;
    zl_mesh mesh;
    zl_mat4 mvp;
    zl_state state;
    uint8_t gouraud; /* the scanline frame must reserve Gouraud records */
    /* SCENE_BUNNY_SMOOTH: mesh.vertex_colors = lit, made by
     * zl_light_vertices(&lighting, &modelview, mesh without vertex colours,
     * normals, lit) in scene_make (lit is a static array of scenes.c) */
    zl_lighting lighting;
    zl_mat4 modelview;
    const int16_t *normals;
    uint8_t *lit;
    /* Styled scenes (textures, blending): the first mesh's style, then
     * extra_count more meshes drawn in order after it. Zero for the others. */
    uint8_t styled;
    zl_style style;
    uint8_t extra_count;
    zl_mesh extra_mesh[SCENE_MAX_EXTRA];
    zl_mat4 extra_mvp[SCENE_MAX_EXTRA];
    zl_state extra_state[SCENE_MAX_EXTRA];
    zl_style extra_style[SCENE_MAX_EXTRA];
} scene;

/* Build scene `which` (SCENE_*). Returns 0, or -1 if the camera cannot be built. */
int scene_make(scene *s, int which);

#endif

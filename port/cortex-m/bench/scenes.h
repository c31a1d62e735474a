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
 *   bunny_exact  the benchmark scene with zl_state near_z = 0.1, far_z = 100:
 *                the exact depth mapping (zline.h, Pseudodepth), its cost
 *   tetra        (golden test only) a vertex-coloured model close to the
 *                camera: near-plane clipping and Gouraud shading
 * The meshes are const (flash): bunny, grid and tetra are generated from OBJ
 * files by zline-obj2c at build time.
 */
#ifndef ZLINE_BENCH_SCENES_H
#define ZLINE_BENCH_SCENES_H

#include "zline/zline.h"

#define SCENE_W 320
#define SCENE_H 240

enum { SCENE_BUNNY, SCENE_FILL, SCENE_FILL_GOURAUD, SCENE_TRIS, SCENE_BUNNY_EXACT, SCENE_TETRA, SCENE_COUNT };

typedef struct {
    const char *name;
    zl_mesh mesh;
    zl_mat4 mvp;
    zl_state state;
    uint8_t gouraud; /* the scanline frame must reserve Gouraud records */
} scene;

/* Build scene `which` (SCENE_*). Returns 0, or -1 if the camera cannot be built. */
int scene_make(scene *s, int which);

#endif

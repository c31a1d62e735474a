/* SPDX-License-Identifier: MIT */
/*
 * zline-size: how large zline's work buffer must be for a model seen from
 * every angle, in bytes, two ways:
 *
 *   worst case  the model rendered (planned: zl_frame_needs) in a sweep of
 *               STEPS yaw x STEPS pitch x STEPS roll orientations: exact for
 *               those orientations, not a guarantee between them;
 *   bound       zl_frame_bound (zl_sizing.h): proven for every orientation,
 *               from the mesh and the viewport alone, no rendering.
 *
 *   zline-size MODEL.obj [--size WxH] [--bands N] [--format rgb565|rgb565be|rgb888]
 *              [--gouraud] [--fov DEG] [--distance D] [--near N] [--far F]
 *              [--cull back|front|none] [--steps N] [--precision G] [--raw]
 *
 * The camera stands at DISTANCE from the model's origin looking at it
 * (zl_orbit_camera); the model turns about its origin. The model is
 * normalised as zline-obj2c --normalize does (centred, largest extent 2)
 * unless --raw. Defaults: 240x240, bands of 8 rows, rgb565, flat, fov 45,
 * distance 3, near 0.1, far 100, culling back faces, 12 steps, precision 64.
 * Prints the capacities and bytes of both; exit 0, 1 on a bad model or a
 * failed render, 2 on usage.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zl_obj.h"
#include "zline/zline.h"

typedef struct {
    const char *model;
    unsigned width, height, bands, steps, precision;
    int format, gouraud, cull, raw;
    double fov, distance, near_z, far_z;
} options;

static void usage(void)
{
    fprintf(stderr, "usage: zline-size MODEL.obj [--size WxH] [--bands N] [--format rgb565|rgb565be|rgb888] "
                    "[--gouraud] [--fov DEG] [--distance D] [--near N] [--far F] [--cull back|front|none] "
                    "[--steps N] [--precision G] [--raw]\n");
    exit(2);
}

static double number(const char *s, double lo, double hi)
{
    char *end;
    double v = strtod(s, &end);
    if (*s == '\0' || *end != '\0' || !(v >= lo && v <= hi))
        usage();
    return v;
}

static int choice(const char *s, const char *const names[], int count)
{
    int i;
    for (i = 0; i < count; i++)
        if (strcmp(s, names[i]) == 0)
            return i;
    usage();
    return 0;
}

static void parse(int argc, char **argv, options *o)
{
    static const char *const formats[] = {"rgb565", "rgb565be", "rgb888"};
    static const char *const culls[] = {"none", "back", "front"};
    int i;
    memset(o, 0, sizeof *o);
    o->width = o->height = 240;
    o->bands = 8;
    o->steps = 12;
    o->precision = ZL_SIZING_PRECISION_MAX; /* the tightest: a fraction of a second here */
    o->fov = 45;
    o->distance = 3;
    o->near_z = 0.1;
    o->far_z = 100;
    o->cull = ZL_CULL_BACK;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--gouraud") == 0) {
            o->gouraud = 1;
            continue;
        }
        if (strcmp(a, "--raw") == 0) {
            o->raw = 1;
            continue;
        }
        if (a[0] != '-') {
            if (o->model != NULL)
                usage();
            o->model = a;
            continue;
        }
        if (v == NULL)
            usage();
        i++;
        if (strcmp(a, "--size") == 0) {
            if (sscanf(v, "%ux%u", &o->width, &o->height) != 2 || o->width < 1 || o->height < 1 ||
                o->width > ZL_MAX_DIM || o->height > ZL_MAX_DIM)
                usage();
        } else if (strcmp(a, "--bands") == 0) {
            o->bands = (unsigned)number(v, 1, ZL_MAX_DIM);
        } else if (strcmp(a, "--format") == 0) {
            o->format = choice(v, formats, 3);
        } else if (strcmp(a, "--cull") == 0) {
            o->cull = choice(v, culls, 3);
        } else if (strcmp(a, "--fov") == 0) {
            o->fov = number(v, 1, 179);
        } else if (strcmp(a, "--distance") == 0) {
            o->distance = number(v, 0.001, 16000);
        } else if (strcmp(a, "--near") == 0) {
            o->near_z = number(v, 0.001, 32000);
        } else if (strcmp(a, "--far") == 0) {
            o->far_z = number(v, 0.001, 32767);
        } else if (strcmp(a, "--steps") == 0) {
            o->steps = (unsigned)number(v, 1, 64);
        } else if (strcmp(a, "--precision") == 0) {
            o->precision = (unsigned)number(v, 1, ZL_SIZING_PRECISION_MAX);
        } else {
            usage();
        }
    }
    if (o->model == NULL || o->bands > o->height || o->near_z >= o->far_z)
        usage();
}

static zl_fixed fx(double v)
{
    return (zl_fixed)(v * 65536.0 + (v < 0 ? -0.5 : 0.5));
}

static zl_orbit_camera camera_of(const options *o)
{
    zl_orbit_camera c;
    c.fovy = zl_angle_from_deg(fx(o->fov));
    c.near_z = fx(o->near_z);
    c.far_z = fx(o->far_z);
    c.distance = fx(o->distance);
    return c;
}

static void config_of(const options *o, zl_frame_config *c)
{
    memset(c, 0, sizeof *c);
    c->width = (uint16_t)o->width;
    c->height = (uint16_t)o->height;
    c->band_rows = (uint16_t)o->bands;
    c->format = (uint8_t)o->format;
    c->color_buffers = 1;
    c->gouraud = (uint8_t)o->gouraud;
}

/* The sweep's view-projection: camera on +z at the distance, looking at the origin. */
static int view_projection(const options *o, zl_mat4 *vp)
{
    zl_mat4 proj, view;
    zl_vec3 eye = {0, 0, 0}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_orbit_camera c = camera_of(o);
    eye.z = c.distance;
    if (zl_mat4_perspective(&proj, c.fovy, fx((double)o->width / o->height), c.near_z, c.far_z) != ZL_OK ||
        zl_mat4_look_at(&view, eye, target, up) != ZL_OK)
        return -1;
    zl_mat4_mul(vp, &proj, &view);
    return 0;
}

typedef struct {
    uint32_t triangles, active;
} worst;

/* Plan the model in one orientation and fold its needs into *w. */
static int plan_pose(const options *o, const zl_mesh *mesh, const zl_mat4 *vp, zl_angle yaw, zl_angle pitch,
                     zl_angle roll, void *work, size_t bytes, worst *w)
{
    zl_frame_config cfg;
    zl_frame frame;
    zl_state st;
    zl_mat4 ry, rx, rz, m, mvp;
    zl_band band;
    zl_rgb black = {0, 0, 0};
    zl_frame_needs_t n;
    zl_status s;
    config_of(o, &cfg);
    cfg.max_meshes = 1;
    cfg.max_vertices = mesh->vertex_count;
    cfg.max_triangles = 65535;
    cfg.max_active = 65534;
    zl_mat4_rotate_y(&ry, yaw);
    zl_mat4_rotate_x(&rx, pitch);
    zl_mat4_rotate_z(&rz, roll);
    zl_mat4_mul(&m, &rx, &ry);
    zl_mat4_mul(&m, &rz, &m);
    zl_mat4_mul(&mvp, vp, &m);
    zl_state_default(&st);
    st.cull = (uint8_t)o->cull;
    st.shading = o->gouraud ? ZL_SHADE_GOURAUD : ZL_SHADE_FLAT;
    s = zl_frame_begin(&frame, &cfg, work, bytes, black, 65535);
    if (s == ZL_OK)
        s = zl_frame_add_mesh(&frame, mesh, &mvp, &st);
    if (s == ZL_OK) {
        s = zl_frame_next_band(&frame, &band);
        s = s == ZL_DONE ? ZL_OK : s;
    }
    if (s != ZL_OK)
        return s;
    n = zl_frame_needs(&frame);
    w->triangles = n.triangles > w->triangles ? n.triangles : w->triangles;
    w->active = n.active > w->active ? n.active : w->active;
    return 0;
}

static int sweep(const options *o, const zl_mesh *mesh, worst *w)
{
    zl_frame_config cfg;
    zl_mat4 vp;
    void *work;
    size_t bytes;
    unsigned i, j, k;
    int r = 0;
    config_of(o, &cfg);
    cfg.max_meshes = 1;
    cfg.max_vertices = mesh->vertex_count;
    cfg.max_triangles = 65535;
    cfg.max_active = 65534;
    bytes = zl_frame_bytes(&cfg);
    work = bytes != 0 ? malloc(bytes) : NULL; /* malloc aligns for any type */
    if (work == NULL || view_projection(o, &vp) != 0) {
        free(work);
        return -1;
    }
    w->triangles = w->active = 0;
    for (i = 0; i < o->steps && r == 0; i++)
        for (j = 0; j < o->steps && r == 0; j++)
            for (k = 0; k < o->steps && r == 0; k++)
                r = plan_pose(o, mesh, &vp, (zl_angle)(ZL_ANGLE_TURN * i / o->steps),
                              (zl_angle)(ZL_ANGLE_TURN * j / o->steps), (zl_angle)(ZL_ANGLE_TURN * k / o->steps),
                              work, bytes, w);
    free(work);
    return r;
}

int main(int argc, char **argv)
{
    options o;
    zl_obj obj;
    zl_obj_options lo;
    zl_mesh mesh;
    zl_frame_config exact, bound;
    zl_orbit_camera cam;
    worst w;
    char msg[512];
    size_t bound_bytes;
    parse(argc, argv, &o);
    zl_obj_options_default(&lo);
    lo.normalize = !o.raw;
    if (zl_obj_load_file(&obj, o.model, &lo, msg, sizeof msg) != ZL_OBJ_OK) {
        fprintf(stderr, "zline-size: %s\n", msg);
        return 1;
    }
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = obj.positions;
    mesh.indices = obj.indices;
    mesh.vertex_count = (uint16_t)obj.vertex_count;
    mesh.triangle_count = (uint16_t)obj.triangle_count;
    printf("model: %s, %u vertices, %u triangles%s\n", o.model, (unsigned)mesh.vertex_count,
           (unsigned)mesh.triangle_count, o.raw ? "" : " (normalised: centred, largest extent 2)");
    printf("frame: %ux%u, bands of %u rows, %s%s; camera at %g looking at the model's origin, fov %g, "
           "near %g, far %g\n",
           o.width, o.height, o.bands, o.format == 0 ? "rgb565" : o.format == 1 ? "rgb565be" : "rgb888",
           o.gouraud ? ", Gouraud" : "", o.distance, o.fov, o.near_z, o.far_z);
    if (sweep(&o, &mesh, &w) != 0) {
        fprintf(stderr, "zline-size: the sweep failed to render (camera inside the model, or out of range?)\n");
        zl_obj_free(&obj);
        return 1;
    }
    config_of(&o, &exact);
    exact.max_meshes = 1;
    exact.max_vertices = mesh.vertex_count;
    exact.max_triangles = w.triangles > 0 ? w.triangles : 1;
    exact.max_active = w.active > 0 ? w.active : 1;
    printf("worst case over %u orientations (%u yaw x %u pitch x %u roll, culling %s; zl_frame_needs):\n"
           "  max_triangles %u, max_active %u: %lu bytes\n",
           o.steps * o.steps * o.steps, o.steps, o.steps, o.steps,
           o.cull == ZL_CULL_BACK ? "back faces" : o.cull == ZL_CULL_FRONT ? "front faces" : "none",
           (unsigned)exact.max_triangles, (unsigned)exact.max_active, (unsigned long)zl_frame_bytes(&exact));
    config_of(&o, &bound);
    cam = camera_of(&o);
    bound_bytes = zl_frame_bound(&bound, &mesh, &cam, o.precision);
    if (bound_bytes == 0) {
        fprintf(stderr, "zline-size: zl_frame_bound refused the model or camera\n");
        zl_obj_free(&obj);
        return 1;
    }
    printf("bound for every orientation (zl_frame_bound, precision %u):\n"
           "  max_triangles %u, max_active %u: %lu bytes\n",
           o.precision, (unsigned)bound.max_triangles, (unsigned)bound.max_active, (unsigned long)bound_bytes);
    zl_obj_free(&obj);
    return 0;
}

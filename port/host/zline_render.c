/* SPDX-License-Identifier: MIT */
/*
 * zline-render: render an OBJ model to a PPM image with the zline core.
 *
 * Floating point appears only where text is parsed (options, the OBJ file);
 * every number is converted to Q16.16 before it reaches the core, and the
 * matrices are built with the core's own zl_mat4_* functions, so the image
 * is what a microcontroller running zline would draw.
 */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zl_image.h"
#include "zl_obj.h"
#include "zl_output.h"
#include "zl_pnm.h"
#include "zline/zline.h"
#include "zline/zl_visibility.h"
#include "bsp_build.h"

#define EXIT_USAGE 2
#define CLEAR_DEPTH 65535u
/* Returned by the band callback when writing a row failed. */
#define BAND_WRITE_FAILED 100

/* zl_draw_mesh's draw cache (zl_context.draw_cache) at the library's size. */
static uint64_t draw_cache_buf[ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) / 8 + 1];

/* Help of --visibility (issue #6), printed after usage_text (C99 caps a string at 4095). */
static const char vis_usage_text[] =
    "\nVisibility (docs/VISIBILITY.md)\n"
    "  --visibility V       hidden surfaces by zbuffer (default, with --mode), aet\n"
    "                       (scan-line, no depth memory), painter (depth sort), bsp\n"
    "                       (tree built here, drawn back to front) or raycast (the\n"
    "                       reference); all but zbuffer draw flat colours and take\n"
    "                       no --depth, --shade depth/vertex, --pixel-space, --mode\n";

/* Help of the issue #5 features, printed after usage_text too. */
static const char features_usage_text[] =
    "\nLines, points, toon, outlines (docs/FEATURES.md; with the z-buffer only)\n"
    "  --wireframe          draw the triangles' edges (polygon mode line for\n"
    "                       front and back faces), depth-tested, by the line rule\n"
    "  --points             draw the triangles' vertices (polygon mode point)\n"
    "  --toon N             toon shading: the light quantised to N bands (1..16)\n"
    "  --outline            silhouette and crease (> 60 degrees) edges in black\n"
    "                       over the model, with a small depth offset\n"
    "  --aa-lines           antialiased lines for --wireframe and --outline\n"
    "  --texture FILE       texture the model with a PPM, PGM or PNG image (any\n"
    "                       size up to 4096) by its vt coordinates, repeated,\n"
    "                       perspective-correct; lit with the light. Converted as\n"
    "                       zline-img2c converts it: RGB565, or RGBA4444 when the\n"
    "                       image has alpha\n"
    "  --affine             with --texture: affine (screen-linear) mapping\n"
    "  --tex-filter F       with --texture: nearest (default) or bilinear\n"
    "  --tex-wrap W[,T]     with --texture: repeat (default) or clamp (to the\n"
    "                       edge texels); W,T sets the s and t axes apart\n"
    "  --blend MODE[,A]     blend the model over the background: alpha or add,\n"
    "                       with constant alpha A (0..255, default 255) times the\n"
    "                       texture's alpha\n";

/* Help of smooth lighting (issue #15), printed after usage_text too. */
static const char smooth_usage_text[] =
    "\nSmooth lighting (zl_light_vertices: OpenGL 1.x per-vertex lighting)\n"
    "  --shade smooth       lit per vertex from vertex normals, Gouraud-\n"
    "                       interpolated: ambient (--ambient, grey) plus\n"
    "                       --light with diffuse 255 - ambient, plus fill lights;\n"
    "                       the model's vertex colours or --color as material;\n"
    "                       lights in world space (= model space here)\n"
    "  --normals MODE       file: the OBJ's vn (an error without them); area or\n"
    "                       angle: computed, weighted by triangle area or corner\n"
    "                       angle; auto (default): vn when the OBJ has them, else\n"
    "                       area\n"
    "  --fill-light X,Y,Z,R,G,B  one more directional light with its diffuse\n"
    "                       colour (up to 3 of them)\n"
    "  --specular R,G,B     Blinn-Phong specular colour of every light (default\n"
    "                       0,0,0: none), the viewer towards the camera\n"
    "  --shininess N        specular exponent 0..128 (default 32)\n";

static const char usage_text[] =
    "Usage: zline-render [options] model.obj out.ppm\n"
    "\n"
    "Render a Wavefront OBJ model with the zline integer rasteriser and write\n"
    "the image as a binary PPM (P6). With no options this is the benchmark\n"
    "scene: the model normalised (bounding box centred on the origin, largest\n"
    "extent 2), camera at (0,0,3.5) looking at the origin, 60 degree vertical\n"
    "field of view, near 0.1, far 100, back faces culled, 320x240, flat shading.\n"
    "On any error nothing is written and the exit status is non-zero (2 for\n"
    "a bad command line). An option's value follows it or an '=' sign.\n"
    "\n"
    "Image\n"
    "  --size WxH           image size in pixels, 1..4096 each (default 320x240)\n"
    "  --format F           colour buffer format: rgb888 (default), rgb565 or\n"
    "                       rgb565be; the PPM shows what that format keeps\n"
    "  --bg R,G,B           background colour, 0..255 each (default 0,0,0)\n"
    "  --depth out.pgm      also write the 16-bit depth buffer as a PGM (P5,\n"
    "                       maxval 65535; 65535 where nothing was drawn)\n"
    "\n"
    "Camera (model space = world space; angles in degrees)\n"
    "  --eye X,Y,Z          camera position (default 0,0,3.5)\n"
    "  --target X,Y,Z       point looked at (default 0,0,0)\n"
    "  --orbit YAW,PITCH,D  camera on a sphere of radius D around the target:\n"
    "                       yaw about +y from +z, pitch up from the xz plane;\n"
    "                       0,0,3.5 is the default camera (not with --eye)\n"
    "  --fov DEG            vertical field of view, 0 < DEG < 180 (default 60)\n"
    "  --near N --far F     clip planes, 0 < N < F <= 32767, N >= F/65536\n"
    "                       (default 0.1 and 100)\n"
    "  The up direction is +y (-z when looking straight up or down). Eye to\n"
    "  target must be at most 180 units.\n"
    "\n"
    "Geometry\n"
    "  --no-normalize       use the file's coordinates as they are (they must\n"
    "                       fit Q16.16: -32768 .. 32767.99998)\n"
    "  --pixel-space        positions are already window coordinates: x, y in\n"
    "                       pixels (y down), z window depth 0..1; no camera, no\n"
    "                       normalisation (the core is given no matrix); no\n"
    "                       lighting unless --light is given\n"
    "  --cull none|back|front  faces to discard (default back)\n"
    "  --front ccw|cw       winding of front faces as seen on screen (default ccw,\n"
    "                       the OBJ convention)\n"
    "\n"
    "Shading\n"
    "  --shade flat         one colour per triangle, lit by a directional light\n"
    "                       (default)\n"
    "  --shade vertex       Gouraud: the model's per-vertex colours (v x y z r g b),\n"
    "                       or --color on every vertex when it has none; lit too\n"
    "  --shade depth        the depth buffer as grey: nearest vertex of the model\n"
    "                       white, farthest dark grey (64), linear in stored depth;\n"
    "                       the background colour where nothing was drawn\n"
    "  --color R,G,B        model colour, 0..255 each (default 255,255,255)\n"
    "  --light X,Y,Z        direction towards the light, model space (normalised;\n"
    "                       default -1,2,2)\n"
    "  --ambient A          light reaching faces turned away, 0..255 (default 48)\n"
    "  --no-light           no lighting: flat colour or vertex colours as they are\n"
    "\n"
    "Renderer\n"
    "  --mode frame         zl_draw_mesh into a full-frame colour and depth buffer\n"
    "                       (default)\n"
    "  --mode scanline      zl_frame, one row per band: the frame is never held;\n"
    "                       rows go to the files as the bands come out\n"
    "  --mode band=N        zl_frame with bands of N rows (clamped to the height)\n"
    "                       The three modes give byte-identical files.\n"
    "  --stats              print the model size, memory used (in scanline and\n"
    "                       band mode the exact zl_frame_bytes work buffer) and\n"
    "                       what the scene needed (zl_frame_needs)\n"
    "  --help               this text\n"
    "\n"
    "Limits: a model has at most 65535 vertices and 65535 triangles (after\n"
    "splitting polygons into triangles).\n"
    "\n"
    "Example:\n"
    "  zline-render port/host/models/bunny.obj bunny.ppm\n"
    "  zline-render --orbit 30,20,3.5 --depth bunny.pgm --mode scanline --stats \\\n"
    "      port/host/models/bunny.obj bunny.ppm\n";

enum { SHADE_FLAT, SHADE_VERTEX, SHADE_DEPTH, SHADE_SMOOTH };

typedef struct {
    const char *model, *out, *depth_out;
    unsigned width, height;
    int have_eye, have_target, have_orbit;
    double eye[3], target[3], orbit[3];
    double fov, near_z, far_z;
    int have_near, have_far, have_fov;
    int cull, front, shade, light_on, have_light;
    double light[3];
    int ambient;
    zl_rgb color, bg;
    int pixel_space, normalize;
    unsigned band_rows; /* 0: frame mode */
    int visibility;     /* 0: z-buffer, else a zl_visibility.h method (VIS_*) */
    zl_format format;
    int stats;
    /* issue #5 features */
    int wireframe, points, toon, outline, aa_lines;
    zl_rgb toon_table[16];
    zl_mesh_edge *edges; /* --outline: the model's edge list */
    uint32_t edge_count;
    const char *texture_path; /* --texture */
    int affine;               /* --affine */
    int tex_filter;           /* --tex-filter: zl_tex_filter */
    int wrap_s, wrap_t;       /* --tex-wrap: zl_wrap per axis */
    int have_tex_options;     /* --tex-filter or --tex-wrap given */
    int blend, alpha;         /* --blend MODE[,A]: zl_blend, constant alpha */
    zl_texture texture;
    const zl_fixed *texcoords;
    /* issue #15: smooth lighting */
    const char *normals_mode; /* file, area, angle or auto */
    int fill_count;
    double fill[3][6];        /* direction, colour */
    zl_rgb specular;
    int shininess;
    /* render state options (issue #14) */
    int have_state;           /* any of them given */
    uint8_t depth_func, depth_write, color_mask;
    uint16_t clear_depth;     /* stored depth the buffer is cleared to */
    int have_ortho;
    double ortho_height;
    int have_offset;
    zl_fixed offset_factor, offset_units;
    int have_poly_mode;
    uint8_t poly_front, poly_back;
    int persp_color;
} options;

/* ------------------------------------------------------------------ errors */

static void error(const char *fmt, ...)
{
    va_list ap;
    fputs("zline-render: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

static int usage_error(const char *fmt, ...)
{
    va_list ap;
    fputs("zline-render: ", stderr);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputs("\nTry 'zline-render --help'.\n", stderr);
    return EXIT_USAGE;
}

/* ------------------------------------------------------ output paths */

/* The output rule of every tool (zl_output.h): neither output may be the
 * model, the texture or the other output, nor a FIFO, device, folder or
 * read-only file. Checked before anything is read or written. */
static int check_output_paths(const options *o)
{
    const char *outs[2], *ins[2];
    char msg[512];
    outs[0] = o->out;
    outs[1] = o->depth_out;
    ins[0] = o->model;
    ins[1] = o->texture_path;
    if (zl_output_check(outs, 2, ins, 2, msg, sizeof msg) != 0)
        return usage_error("%s", msg);
    return 0;
}

static const char *status_name(zl_status s)
{
    switch (s) {
    case ZL_OK:
        return "ok";
    case ZL_DONE:
        return "done";
    case ZL_ERR_ARG:
        return "ZL_ERR_ARG (bad argument)";
    case ZL_ERR_RANGE:
        return "ZL_ERR_RANGE (a number out of range)";
    case ZL_ERR_SIZE:
        return "ZL_ERR_SIZE (bad buffer or dimension)";
    case ZL_ERR_CAPACITY:
        return "ZL_ERR_CAPACITY (the scene needs more than the frame was sized for)";
    case ZL_ERR_IO:
        return "ZL_ERR_IO (a display bus transfer failed)";
    case ZL_ERR_ABI:
        return "ZL_ERR_ABI (the tool and the library were built with different configuration)";
    case ZL_ERR_UNSUPPORTED:
        return "ZL_ERR_UNSUPPORTED (a feature this library build leaves out)";
    }
    return "unknown status";
}

/* ------------------------------------------------------------ option values */

static int parse_real(const char *s, double *out)
{
    char *end;
    double v;
    if (*s == '\0')
        return 0;
    v = strtod(s, &end);
    if (*end != '\0' || !isfinite(v))
        return 0;
    *out = v;
    return 1;
}

/* n comma-separated reals. */
/* The largest |component| of a direction; 0 for the zero vector or a
 * component that is not finite (no direction). */
static double direction_scale(const double *l)
{
    double m = 0;
    int k;
    for (k = 0; k < 3; k++) {
        double a = fabs(l[k]);
        if (!(a <= DBL_MAX))
            return 0;
        if (a > m)
            m = a;
    }
    return m;
}

static int parse_reals(const char *s, double *out, int n)
{
    char buf[256];
    char *p = buf;
    int i;
    if (strlen(s) >= sizeof buf)
        return 0;
    strcpy(buf, s);
    for (i = 0; i < n; i++) {
        char *comma = strchr(p, ',');
        if ((comma == NULL) != (i == n - 1))
            return 0;
        if (comma != NULL)
            *comma = '\0';
        if (!parse_real(p, &out[i]))
            return 0;
        p = comma != NULL ? comma + 1 : p;
    }
    return 1;
}

static int parse_uint(const char *s, unsigned long max, unsigned long *out)
{
    unsigned long v = 0;
    if (*s == '\0')
        return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9')
            return 0;
        v = v * 10 + (unsigned long)(*s - '0');
        if (v > max)
            return 0;
    }
    *out = v;
    return 1;
}

/* One wrap mode by name: repeat or clamp (zl_wrap), n characters of s. */
static int parse_wrap(const char *s, size_t n, int *out)
{
    if (n == 6 && strncmp(s, "repeat", 6) == 0)
        *out = ZL_WRAP_REPEAT;
    else if (n == 5 && strncmp(s, "clamp", 5) == 0)
        *out = ZL_WRAP_CLAMP;
    else
        return 0;
    return 1;
}

/* --tex-wrap: one mode for both axes, or S,T (zl_texture's wrap_s, wrap_t). */
static int parse_wrap_pair(const char *s, int *wrap_s, int *wrap_t)
{
    const char *comma = strchr(s, ',');
    if (comma == NULL) {
        if (!parse_wrap(s, strlen(s), wrap_s))
            return 0;
        *wrap_t = *wrap_s;
        return 1;
    }
    return parse_wrap(s, (size_t)(comma - s), wrap_s) && parse_wrap(comma + 1, strlen(comma + 1), wrap_t);
}

static int parse_rgb(const char *s, zl_rgb *out)
{
    double v[3];
    int i;
    if (!parse_reals(s, v, 3))
        return 0;
    for (i = 0; i < 3; i++)
        if (v[i] < 0.0 || v[i] > 255.0 || v[i] != floor(v[i]))
            return 0;
    out->r = (uint8_t)v[0];
    out->g = (uint8_t)v[1];
    out->b = (uint8_t)v[2];
    return 1;
}

/* A real to Q16.16, rounded to nearest; 0 when out of range. */
static int to_fixed(double v, zl_fixed *out)
{
    double r = floor(v * 65536.0 + 0.5);
    if (!(r >= (double)INT32_MIN && r <= (double)INT32_MAX))
        return 0;
    *out = (zl_fixed)r;
    return 1;
}

static int to_vec3(const double *v, zl_vec3 *out)
{
    return to_fixed(v[0], &out->x) && to_fixed(v[1], &out->y) && to_fixed(v[2], &out->z);
}

/* ------------------------------------------- render state options (#14) */

/* Help of the render state options, printed after usage_text too. */
static const char state_usage_text[] =
    "\nRender state (zl_state and zl_style; with the z-buffer only)\n"
    "  --depth-func F       depth test: never, less (default), equal, lequal,\n"
    "                       greater, notequal, gequal or always\n"
    "  --depth-write on|off depth write mask (default on)\n"
    "  --color-mask M       colour channels written: a set of the letters r, g\n"
    "                       and b (rgb default, e.g. rg) or none\n"
    "  --clear-depth D      depth the buffer is cleared to, 0..1 as glClearDepth\n"
    "                       (stored round(65535 D); default 1); --shade depth\n"
    "                       shows the background where the depth is still that\n"
    "  --ortho H            orthographic camera seeing a box H units high (width\n"
    "                       H times the aspect ratio) between --near and --far;\n"
    "                       depth linear in eye distance (not with --fov)\n"
    "  --polygon-offset F,U polygon offset (glPolygonOffset): depth moved by\n"
    "                       F x the depth slope + U steps; -256 <= F <= 256\n"
    "  --polygon-mode M     fill (default), line or point for every face, or\n"
    "                       FRONT,BACK for the two sides (glPolygonMode; not\n"
    "                       with --wireframe or --points)\n"
    "  --persp-color        perspective-correct Gouraud colours (colour/w and\n"
    "                       1/w interpolated, as OpenGL); the default is linear\n"
    "                       in screen space, the library's default: no divide\n"
    "                       per pixel, and what a microcontroller draws unless\n"
    "                       it asks for more\n"
    "  With a perspective camera the core gets its near and far (zl_state\n"
    "  near_z, far_z): each vertex's depth is the exact pseudodepth of its eye\n"
    "  distance, unbiased.\n";

static int parse_poly_mode(const char *s, size_t n, uint8_t *out)
{
    static const char *const names[] = {"fill", "line", "point"};
    uint8_t k;
    for (k = 0; k < 3; k++)
        if (strlen(names[k]) == n && strncmp(s, names[k], n) == 0) {
            *out = k; /* ZL_POLY_FILL, ZL_POLY_LINE, ZL_POLY_POINT */
            return 1;
        }
    return 0;
}

/*
 * The render state options. Returns 1 when `name` is one of them and its
 * value is good, 0 when it is not one of them, or usage_error's status (> 1)
 * for a bad value. *val is the value (NULL: none given yet), taken from
 * argv[*i + 1] when the option needs one.
 */
static int parse_state_option(const char *name, const char *val, int argc, char **argv, int *i,
                              options *o)
{
    static const char *const funcs[] = {"never",    "less",   "equal",  "lequal",
                                        "greater",  "notequal", "gequal", "always"};
    int takes_value = strcmp(name, "--persp-color") != 0;
    if (strcmp(name, "--depth-func") != 0 && strcmp(name, "--depth-write") != 0 &&
        strcmp(name, "--color-mask") != 0 && strcmp(name, "--colour-mask") != 0 &&
        strcmp(name, "--clear-depth") != 0 && strcmp(name, "--ortho") != 0 &&
        strcmp(name, "--polygon-offset") != 0 && strcmp(name, "--polygon-mode") != 0 &&
        strcmp(name, "--persp-color") != 0)
        return 0;
    if (!takes_value) {
        if (val != NULL)
            return usage_error("%s takes no value", name);
        o->persp_color = 1;
        return 1;
    }
    if (val == NULL) {
        if (*i + 1 >= argc || argv[*i + 1] == NULL)
            return usage_error("%s needs a value", name);
        val = argv[++*i];
    }
    if (strcmp(name, "--depth-func") == 0) {
        int k;
        for (k = 0; k < 8 && strcmp(val, funcs[k]) != 0; k++)
            ;
        if (k == 8)
            return usage_error("--depth-func: expected never, less, equal, lequal, greater, "
                               "notequal, gequal or always, got '%s'",
                               val);
        o->depth_func = (uint8_t)k; /* zl_depth_func: ZL_NEVER .. ZL_ALWAYS in this order */
    } else if (strcmp(name, "--depth-write") == 0) {
        if (strcmp(val, "on") == 0)
            o->depth_write = 1;
        else if (strcmp(val, "off") == 0)
            o->depth_write = 0;
        else
            return usage_error("--depth-write: expected on or off, got '%s'", val);
    } else if (strcmp(name, "--color-mask") == 0 || strcmp(name, "--colour-mask") == 0) {
        const char *p;
        unsigned m = 0;
        if (strcmp(val, "none") != 0) {
            for (p = val; *p; p++) {
                unsigned bit = *p == 'r' ? ZL_MASK_R : *p == 'g' ? ZL_MASK_G : *p == 'b' ? ZL_MASK_B : 0u;
                if (bit == 0 || (m & bit))
                    break;
                m |= bit;
            }
            if (*p != '\0' || m == 0)
                return usage_error("--color-mask: expected some of the letters r, g, b (each "
                                   "once) or none, got '%s'",
                                   val);
        }
        o->color_mask = (uint8_t)m;
    } else if (strcmp(name, "--clear-depth") == 0) {
        double d;
        if (!parse_real(val, &d) || d < 0.0 || d > 1.0)
            return usage_error("--clear-depth: expected a depth 0..1, got '%s'", val);
        o->clear_depth = (uint16_t)floor(d * 65535.0 + 0.5);
    } else if (strcmp(name, "--ortho") == 0) {
        if (!parse_real(val, &o->ortho_height) || !(o->ortho_height > 0.0 && o->ortho_height <= 32767.0))
            return usage_error("--ortho: expected a height in (0, 32767], got '%s'", val);
        o->have_ortho = 1;
    } else if (strcmp(name, "--polygon-offset") == 0) {
        double v[2];
        if (!parse_reals(val, v, 2) || v[0] < -256.0 || v[0] > 256.0 || !to_fixed(v[0], &o->offset_factor) ||
            !to_fixed(v[1], &o->offset_units))
            return usage_error("--polygon-offset: expected FACTOR,UNITS with -256 <= FACTOR <= 256 "
                               "and UNITS in -32768 .. 32767, got '%s'",
                               val);
        o->have_offset = o->offset_factor != 0 || o->offset_units != 0;
    } else if (strcmp(name, "--polygon-mode") == 0) {
        const char *comma = strchr(val, ',');
        size_t n = comma != NULL ? (size_t)(comma - val) : strlen(val);
        if (!parse_poly_mode(val, n, &o->poly_front) ||
            !parse_poly_mode(comma != NULL ? comma + 1 : val, comma != NULL ? strlen(comma + 1) : n,
                             &o->poly_back))
            return usage_error("--polygon-mode: expected fill, line or point, or FRONT,BACK of "
                               "those, got '%s'",
                               val);
        o->have_poly_mode = 1;
    } else {
        o->persp_color = 1;
    }
    return 1;
}

/* Checks between the state options and the others, after all are parsed. */
static int check_state_options(const options *o)
{
    if (o->have_poly_mode && (o->wireframe || o->points))
        return usage_error("--polygon-mode and --wireframe or --points both set the polygon mode: "
                           "give one");
    if (o->have_ortho && o->have_fov)
        return usage_error("--ortho and --fov: an orthographic camera has no field of view");
    if (o->have_ortho && o->pixel_space)
        return usage_error("--pixel-space takes no camera options (--ortho)");
    if (o->have_state && o->visibility != 0)
        return usage_error("--visibility other than zbuffer takes no render state options (--depth-func, "
                           "--depth-write, --color-mask, --clear-depth, --ortho, --polygon-offset, "
                           "--polygon-mode, --persp-color)");
    return 0;
}

/* --ortho: the box H high, H x aspect wide, centred on the view axis. */
static zl_status ortho_projection(const options *o, zl_fixed aspect, zl_fixed near_z, zl_fixed far_z,
                                  zl_mat4 *proj)
{
    zl_fixed half_h, half_w;
    double hw = o->ortho_height * 0.5 * (aspect / 65536.0);
    if (!to_fixed(o->ortho_height * 0.5, &half_h) || !to_fixed(hw, &half_w) || half_h <= 0 || half_w <= 0 ||
        hw > 16383.0)
        return ZL_ERR_RANGE;
    return zl_mat4_ortho(proj, -half_w, half_w, -half_h, half_h, near_z, far_z);
}

/* The state options into the core's state and style. */
static void apply_state_options(const options *o, zl_state *state, zl_style *sty)
{
    if (state != NULL) {
        zl_fixed n, f;
        state->depth_func = o->depth_func;
        state->depth_write = o->depth_write;
        state->color_mask = o->color_mask;
        /* The perspective camera's near and far: the core maps each vertex's
         * eye distance to depth exactly (unbiased), not through the matrix's
         * Q16.16 constants, as zl_mat4_perspective got them in build_mvp. */
        if (!o->pixel_space && !o->have_ortho && to_fixed(o->near_z, &n) && to_fixed(o->far_z, &f) && n > 0 &&
            f > n) {
            state->near_z = n;
            state->far_z = f;
        }
    }
    if (sty != NULL) {
        if (o->have_poly_mode) {
            sty->polygon_front = o->poly_front;
            sty->polygon_back = o->poly_back;
        }
        sty->offset_factor = o->offset_factor;
        sty->offset_units = o->offset_units;
        sty->persp_gouraud = (uint8_t)o->persp_color;
    }
}

/* Whether the state options need a styled frame (cfg.styled, cfg.textured). */
static int state_styled(const options *o)
{
    return o->have_poly_mode || o->have_offset || o->persp_color;
}

static int parse_options(int argc, char **argv, options *o)
{
    int i, positional = 0;
    memset(o, 0, sizeof *o);
    o->width = 320;
    o->height = 240;
    o->eye[2] = 3.5;
    o->fov = 60.0;
    o->near_z = 0.1;
    o->far_z = 100.0;
    o->cull = ZL_CULL_BACK;
    o->front = ZL_FRONT_CCW;
    o->shade = SHADE_FLAT;
    o->light_on = 1;
    o->light[0] = -1.0;
    o->light[1] = 2.0;
    o->light[2] = 2.0;
    o->ambient = 48;
    o->shininess = 32;
    o->color.r = o->color.g = o->color.b = 255;
    o->normalize = 1;
    o->format = ZL_FORMAT_RGB888;
    o->depth_func = ZL_LESS;
    o->depth_write = 1;
    o->color_mask = ZL_MASK_RGB;
    o->clear_depth = CLEAR_DEPTH;

    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = NULL;
        char name[32];
        if (positional || a[0] != '-' || a[1] == '\0') {
            if (o->model == NULL)
                o->model = a;
            else if (o->out == NULL)
                o->out = a;
            else
                return usage_error("unexpected argument '%s'", a);
            continue;
        }
        if (strcmp(a, "--") == 0) {
            positional = 1;
            continue;
        }
        /* --name=value or --name value */
        {
            const char *eq = strchr(a, '=');
            size_t n = eq ? (size_t)(eq - a) : strlen(a);
            if (n >= sizeof name)
                return usage_error("unknown option '%s'", a);
            memcpy(name, a, n);
            name[n] = '\0';
            if (eq)
                val = eq + 1;
        }
#define FLAG(s) (strcmp(name, s) == 0)
#define NEEDS_VALUE                                                                                \
    do {                                                                                           \
        if (val == NULL) {                                                                         \
            if (i + 1 >= argc)                                                                     \
                return usage_error("%s needs a value", name);                                      \
            val = argv[++i];                                                                       \
        }                                                                                          \
    } while (0)
#define NO_VALUE                                                                                   \
    do {                                                                                           \
        if (val != NULL)                                                                           \
            return usage_error("%s takes no value", name);                                         \
    } while (0)
        if (FLAG("--help") || FLAG("-h")) {
            fputs(usage_text, stdout);
            fputs(vis_usage_text, stdout);
            fputs(features_usage_text, stdout);
            fputs(smooth_usage_text, stdout);
            fputs(state_usage_text, stdout);
            return -1;
        } else if (FLAG("--size")) {
            unsigned long w, h;
            char buf[32];
            char *x;
            NEEDS_VALUE;
            if (strlen(val) >= sizeof buf)
                return usage_error("--size: expected WxH, got '%s'", val);
            strcpy(buf, val);
            x = strchr(buf, 'x');
            if (x == NULL)
                return usage_error("--size: expected WxH, got '%s'", val);
            *x = '\0';
            if (!parse_uint(buf, ZL_MAX_DIM, &w) || !parse_uint(x + 1, ZL_MAX_DIM, &h) || w < 1 ||
                h < 1)
                return usage_error("--size: expected WxH with 1..%d each, got '%s'", ZL_MAX_DIM,
                                   val);
            o->width = (unsigned)w;
            o->height = (unsigned)h;
        } else if (FLAG("--format")) {
            NEEDS_VALUE;
            if (strcmp(val, "rgb888") == 0)
                o->format = ZL_FORMAT_RGB888;
            else if (strcmp(val, "rgb565") == 0)
                o->format = ZL_FORMAT_RGB565;
            else if (strcmp(val, "rgb565be") == 0)
                o->format = ZL_FORMAT_RGB565_BE;
            else
                return usage_error("--format: expected rgb888, rgb565 or rgb565be, got '%s'", val);
        } else if (FLAG("--eye")) {
            NEEDS_VALUE;
            if (!parse_reals(val, o->eye, 3))
                return usage_error("--eye: expected X,Y,Z, got '%s'", val);
            o->have_eye = 1;
        } else if (FLAG("--target")) {
            NEEDS_VALUE;
            if (!parse_reals(val, o->target, 3))
                return usage_error("--target: expected X,Y,Z, got '%s'", val);
            o->have_target = 1;
        } else if (FLAG("--orbit")) {
            NEEDS_VALUE;
            if (!parse_reals(val, o->orbit, 3) || o->orbit[2] <= 0.0)
                return usage_error("--orbit: expected YAW,PITCH,DISTANCE with DISTANCE > 0, got "
                                   "'%s'",
                                   val);
            o->have_orbit = 1;
        } else if (FLAG("--fov")) {
            NEEDS_VALUE;
            if (!parse_real(val, &o->fov) || !(o->fov > 0.0 && o->fov < 180.0))
                return usage_error("--fov: expected degrees, 0 < DEG < 180, got '%s'", val);
            o->have_fov = 1;
        } else if (FLAG("--near")) {
            NEEDS_VALUE;
            if (!parse_real(val, &o->near_z) || !(o->near_z > 0.0))
                return usage_error("--near: expected a number > 0, got '%s'", val);
            o->have_near = 1;
        } else if (FLAG("--far")) {
            NEEDS_VALUE;
            if (!parse_real(val, &o->far_z) || !(o->far_z > 0.0 && o->far_z <= 32767.0))
                return usage_error("--far: expected a number in (0, 32767], got '%s'", val);
            o->have_far = 1;
        } else if (FLAG("--cull")) {
            NEEDS_VALUE;
            if (strcmp(val, "none") == 0)
                o->cull = ZL_CULL_NONE;
            else if (strcmp(val, "back") == 0)
                o->cull = ZL_CULL_BACK;
            else if (strcmp(val, "front") == 0)
                o->cull = ZL_CULL_FRONT;
            else
                return usage_error("--cull: expected none, back or front, got '%s'", val);
        } else if (FLAG("--front")) {
            NEEDS_VALUE;
            if (strcmp(val, "ccw") == 0)
                o->front = ZL_FRONT_CCW;
            else if (strcmp(val, "cw") == 0)
                o->front = ZL_FRONT_CW;
            else
                return usage_error("--front: expected ccw or cw, got '%s'", val);
        } else if (FLAG("--shade")) {
            NEEDS_VALUE;
            if (strcmp(val, "flat") == 0)
                o->shade = SHADE_FLAT;
            else if (strcmp(val, "vertex") == 0)
                o->shade = SHADE_VERTEX;
            else if (strcmp(val, "depth") == 0)
                o->shade = SHADE_DEPTH;
            else if (strcmp(val, "smooth") == 0)
                o->shade = SHADE_SMOOTH;
            else
                return usage_error("--shade: expected flat, vertex, smooth or depth, got '%s'", val);
        } else if (FLAG("--normals")) {
            NEEDS_VALUE;
            if (strcmp(val, "file") != 0 && strcmp(val, "area") != 0 && strcmp(val, "angle") != 0 &&
                strcmp(val, "auto") != 0)
                return usage_error("--normals: expected file, area, angle or auto, got '%s'", val);
            o->normals_mode = val;
        } else if (FLAG("--fill-light")) {
            double *f;
            NEEDS_VALUE;
            if (o->fill_count >= 3)
                return usage_error("--fill-light: at most 3 (4 lights with --light)");
            f = o->fill[o->fill_count];
            if (!parse_reals(val, f, 6) || direction_scale(f) == 0 || f[3] < 0 ||
                f[3] > 255 || f[4] < 0 || f[4] > 255 || f[5] < 0 || f[5] > 255)
                return usage_error("--fill-light: expected X,Y,Z,R,G,B with a non-zero direction and "
                                   "colours 0..255, got '%s'", val);
            o->fill_count++;
        } else if (FLAG("--specular")) {
            NEEDS_VALUE;
            if (!parse_rgb(val, &o->specular))
                return usage_error("--specular: expected R,G,B with integers 0..255, got '%s'", val);
        } else if (FLAG("--shininess")) {
            unsigned long v;
            NEEDS_VALUE;
            if (!parse_uint(val, ZL_MAX_SHININESS, &v))
                return usage_error("--shininess: expected 0..%d, got '%s'", ZL_MAX_SHININESS, val);
            o->shininess = (int)v;
        } else if (FLAG("--color") || FLAG("--colour")) {
            NEEDS_VALUE;
            if (!parse_rgb(val, &o->color))
                return usage_error("--color: expected R,G,B with integers 0..255, got '%s'", val);
        } else if (FLAG("--bg")) {
            NEEDS_VALUE;
            if (!parse_rgb(val, &o->bg))
                return usage_error("--bg: expected R,G,B with integers 0..255, got '%s'", val);
        } else if (FLAG("--light")) {
            NEEDS_VALUE;
            o->have_light = 1;
            if (!parse_reals(val, o->light, 3) || direction_scale(o->light) == 0)
                return usage_error("--light: expected a non-zero direction X,Y,Z, got '%s'", val);
        } else if (FLAG("--ambient")) {
            unsigned long v;
            NEEDS_VALUE;
            if (!parse_uint(val, 255, &v))
                return usage_error("--ambient: expected 0..255, got '%s'", val);
            o->ambient = (int)v;
        } else if (FLAG("--no-light")) {
            NO_VALUE;
            o->light_on = 0;
        } else if (FLAG("--depth")) {
            NEEDS_VALUE;
            if (*val == '\0')
                return usage_error("--depth needs a file name");
            o->depth_out = val;
        } else if (FLAG("--pixel-space")) {
            NO_VALUE;
            o->pixel_space = 1;
        } else if (FLAG("--no-normalize") || FLAG("--no-normalise")) {
            NO_VALUE;
            o->normalize = 0;
        } else if (FLAG("--mode")) {
            NEEDS_VALUE;
            if (strcmp(val, "frame") == 0) {
                o->band_rows = 0;
            } else if (strcmp(val, "scanline") == 0) {
                o->band_rows = 1;
            } else if (strncmp(val, "band=", 5) == 0) {
                unsigned long n;
                if (!parse_uint(val + 5, 65535, &n) || n < 1)
                    return usage_error("--mode band=N: N must be 1..65535, got '%s'", val + 5);
                o->band_rows = (unsigned)n;
            } else {
                return usage_error("--mode: expected frame, scanline or band=N, got '%s'", val);
            }
        } else if (FLAG("--wireframe")) {
            NO_VALUE;
            o->wireframe = 1;
        } else if (FLAG("--points")) {
            NO_VALUE;
            o->points = 1;
        } else if (FLAG("--outline")) {
            NO_VALUE;
            o->outline = 1;
        } else if (FLAG("--aa-lines")) {
            NO_VALUE;
            o->aa_lines = 1;
        } else if (FLAG("--texture")) {
            NEEDS_VALUE;
            o->texture_path = val;
        } else if (FLAG("--affine")) {
            NO_VALUE;
            o->affine = 1;
        } else if (FLAG("--tex-filter")) {
            NEEDS_VALUE;
            if (strcmp(val, "nearest") == 0)
                o->tex_filter = ZL_FILTER_NEAREST;
            else if (strcmp(val, "bilinear") == 0)
                o->tex_filter = ZL_FILTER_BILINEAR;
            else
                return usage_error("--tex-filter: expected nearest or bilinear, got '%s'", val);
            o->have_tex_options = 1;
        } else if (FLAG("--tex-wrap")) {
            NEEDS_VALUE;
            if (!parse_wrap_pair(val, &o->wrap_s, &o->wrap_t))
                return usage_error("--tex-wrap: expected repeat or clamp, or two of them as S,T, got '%s'", val);
            o->have_tex_options = 1;
        } else if (FLAG("--blend")) {
            unsigned long alpha = 255;
            const char *comma;
            size_t len;
            NEEDS_VALUE;
            comma = strchr(val, ',');
            len = comma != NULL ? (size_t)(comma - val) : strlen(val);
            if (comma != NULL && !parse_uint(comma + 1, 255, &alpha))
                return usage_error("--blend: expected an alpha 0..255 after the comma, got '%s'", comma + 1);
            if (len == 5 && strncmp(val, "alpha", 5) == 0)
                o->blend = ZL_BLEND_ALPHA;
            else if (len == 3 && strncmp(val, "add", 3) == 0)
                o->blend = ZL_BLEND_ADD;
            else
                return usage_error("--blend: expected alpha or add, got '%s'", val);
            o->alpha = (int)alpha;
        } else if (FLAG("--toon")) {
            unsigned long n;
            NEEDS_VALUE;
            if (!parse_uint(val, 16, &n) || n < 1)
                return usage_error("--toon: expected a number of bands 1..16, got '%s'", val);
            o->toon = (int)n;
        } else if (FLAG("--visibility")) {
            static const char *const vis_names[] = {"zbuffer", "aet", "painter", "bsp", "raycast"};
            int k;
            NEEDS_VALUE;
            for (k = 0; k < 5 && strcmp(val, vis_names[k]) != 0; k++)
                ;
            if (k == 5)
                return usage_error("--visibility: expected zbuffer, aet, painter, bsp or raycast, got '%s'",
                                   val);
            o->visibility = k;
        } else if (FLAG("--stats")) {
            NO_VALUE;
            o->stats = 1;
        } else {
            int r = parse_state_option(name, val, argc, argv, &i, o);
            if (r == 0)
                return usage_error("unknown option '%s'", a);
            if (r > 1)
                return r;
            o->have_state = 1;
        }
#undef FLAG
#undef NEEDS_VALUE
#undef NO_VALUE
    }
    if (o->model == NULL || o->out == NULL)
        return usage_error("expected a model and an output file: zline-render [options] "
                           "model.obj out.ppm");
    {
        int rc = check_output_paths(o);
        if (rc != 0)
            return rc;
    }
    if (o->have_eye && o->have_orbit)
        return usage_error("--eye and --orbit both place the camera: give one");
    if (o->pixel_space) {
        if (o->have_eye || o->have_target || o->have_orbit || o->have_fov || o->have_near ||
            o->have_far)
            return usage_error("--pixel-space takes no camera options (--eye, --target, "
                               "--orbit, --fov, --near, --far)");
        o->normalize = 0;
        if (!o->have_light)
            o->light_on = 0; /* a light in window space only if asked for */
    }
    if (o->band_rows > o->height)
        o->band_rows = o->height;
    if (o->have_tex_options && o->texture_path == NULL)
        return usage_error("--tex-filter and --tex-wrap need --texture");
    if (check_state_options(o) != 0)
        return EXIT_USAGE;
    if (o->visibility != 0 && (o->depth_out != NULL || o->shade != SHADE_FLAT || o->pixel_space ||
                               o->band_rows != 0))
        return usage_error("--visibility other than zbuffer draws flat colours from a camera: it takes no "
                           "--depth, --shade depth/vertex, --pixel-space or --mode");
    return 0;
}

/* ------------------------------------------------------------------ camera */

static int build_mvp(const options *o, zl_mat4 *mvp)
{
    zl_vec3 eye, target, up;
    zl_mat4 view, proj;
    zl_fixed fov_deg, near_z, far_z, aspect;
    zl_status st;
    int64_t dx, dy, dz;

    if (!to_vec3(o->target, &target)) {
        error("--target is outside the Q16.16 range");
        return 0;
    }
    if (o->have_orbit) {
        zl_fixed yaw_deg, pitch_deg, dist;
        zl_angle yaw, pitch;
        zl_fixed cp, sp, cy, sy;
        int64_t ex, ey, ez;
        if (!to_fixed(o->orbit[0], &yaw_deg) || !to_fixed(o->orbit[1], &pitch_deg) ||
            !to_fixed(o->orbit[2], &dist) || dist <= 0) {
            error("--orbit: a value is outside the Q16.16 range");
            return 0;
        }
        yaw = zl_angle_from_deg(yaw_deg);
        pitch = zl_angle_from_deg(pitch_deg);
        cp = zl_cos(pitch);
        sp = zl_sin(pitch);
        cy = zl_cos(yaw);
        sy = zl_sin(yaw);
        /* target + dist * (cos p sin y, sin p, cos p cos y); |dist| < 32768 and
         * |sin|, |cos| <= 1 keep every product in range. */
        ex = (int64_t)target.x + zl_fx_mul(dist, zl_fx_mul(cp, sy));
        ey = (int64_t)target.y + zl_fx_mul(dist, sp);
        ez = (int64_t)target.z + zl_fx_mul(dist, zl_fx_mul(cp, cy));
        if (ex != zl_fx_sat(ex) || ey != zl_fx_sat(ey) || ez != zl_fx_sat(ez)) {
            error("--orbit: the camera position leaves the Q16.16 range");
            return 0;
        }
        eye.x = (zl_fixed)ex;
        eye.y = (zl_fixed)ey;
        eye.z = (zl_fixed)ez;
    } else if (!to_vec3(o->eye, &eye)) {
        error("--eye is outside the Q16.16 range");
        return 0;
    }
    /* +y up, unless the view is (nearly) vertical: then -z. */
    dx = (int64_t)target.x - eye.x;
    dy = (int64_t)target.y - eye.y;
    dz = (int64_t)target.z - eye.z;
    up.x = 0;
    up.y = ZL_FX_ONE;
    up.z = 0;
    if (((dx < 0 ? -dx : dx) + (dz < 0 ? -dz : dz)) * 64 < (dy < 0 ? -dy : dy)) {
        up.y = 0;
        up.z = -ZL_FX_ONE;
    }
    st = zl_mat4_look_at(&view, eye, target, up);
    if (st != ZL_OK) {
        error("camera: zl_mat4_look_at failed with %s: the eye must differ from the target and "
              "be at most 180 units from it",
              status_name(st));
        return 0;
    }
    if (!to_fixed(o->fov, &fov_deg) || !to_fixed(o->near_z, &near_z) ||
        !to_fixed(o->far_z, &far_z) || near_z <= 0) {
        error("--fov, --near or --far is outside the Q16.16 range (or --near rounds to 0)");
        return 0;
    }
    aspect = (zl_fixed)(((int64_t)o->width * 65536 + o->height / 2) / o->height);
    if (o->have_ortho) {
        st = ortho_projection(o, aspect, near_z, far_z, &proj);
        if (st != ZL_OK) {
            error("projection: zl_mat4_ortho failed with %s: need --ortho H with H x aspect / 2 "
                  "below 16384 and 0 < near < far",
                  status_name(st));
            return 0;
        }
    } else {
        st = zl_mat4_perspective(&proj, zl_angle_from_deg(fov_deg), aspect, near_z, far_z);
    }
    if (st != ZL_OK) {
        error("projection: zl_mat4_perspective failed with %s: need 0 < fov < 180, "
              "0 < near < far <= 32767, near >= far / 65536, aspect 1/64 .. 64",
              status_name(st));
        return 0;
    }
    zl_mat4_mul(mvp, &proj, &view);
    return 1;
}

/* ----------------------------------------------------------------- output */

typedef struct {
    const options *opt;
    zl_pnm_writer image, depth;
    uint16_t dmin, dmax; /* window depth of the model's nearest and farthest vertex */
    uint8_t *grey_row;   /* --shade depth: one RGB888 row */
    uint32_t rows_out;
} output;

/*
 * The depth range the grey scale spans: the window depths of the model's
 * vertices. Computed from the geometry (not the pixels), so it is known
 * before the first band and identical in every mode.
 */
static void depth_range(output *out, const zl_obj *obj, const zl_mat4 *mvp, const options *o)
{
    uint32_t i;
    uint16_t lo = 65535, hi = 0;
    zl_fixed near_z = 0, far_z = 0;
    if (mvp != NULL) {
        to_fixed(o->near_z, &near_z);
        to_fixed(o->far_z, &far_z);
    }
    for (i = 0; i < obj->vertex_count; i++) {
        zl_vec3 p;
        uint16_t d;
        p.x = obj->positions[3 * i];
        p.y = obj->positions[3 * i + 1];
        p.z = obj->positions[3 * i + 2];
        if (mvp == NULL) {
            /* pixel space: z is window depth 0..1 */
            int64_t z = ((int64_t)p.z * 65535 + 32768) >> 16;
            d = (uint16_t)(z < 0 ? 0 : (z > 65535 ? 65535 : z));
        } else {
            zl_vec4 c;
            if (zl_transform_point(mvp, p, &c) != ZL_OK)
                continue;
            if (o->have_ortho) {
                /* orthographic: w_clip = 1 and z_clip is the window depth */
                int64_t z = ((int64_t)c.z * 65535 + 32768) >> 16;
                d = (uint16_t)(z < 0 ? 0 : (z > 65535 ? 65535 : z));
            } else {
                /* w_clip is the eye distance; zl_depth_of_distance clamps to [near, far] */
                d = zl_depth_of_distance(near_z, far_z, c.w);
            }
        }
        if (d < lo)
            lo = d;
        if (d > hi)
            hi = d;
    }
    if (lo > hi)
        lo = hi = 0;
    out->dmin = lo;
    out->dmax = hi;
}

static uint8_t depth_grey(const output *out, uint16_t d)
{
    uint32_t span = (uint32_t)out->dmax - out->dmin;
    uint32_t t;
    if (span == 0)
        span = 1;
    if (d <= out->dmin)
        return 255;
    if (d >= out->dmax)
        return 64;
    t = ((uint32_t)(d - out->dmin) * 191u + span / 2) / span;
    return (uint8_t)(255u - t);
}

/* Write `rows` rows of colour and depth to the open files. */
static int write_rows(output *out, const void *color, int32_t cstride, const uint16_t *depth,
                      int32_t dstride, unsigned rows)
{
    const options *o = out->opt;
    unsigned y, x;
    for (y = 0; y < rows; y++) {
        const uint16_t *drow =
            (const uint16_t *)(const void *)((const uint8_t *)depth + (size_t)y * (size_t)dstride);
        /* dstride 0: the no-depth rows of --visibility, which option parsing
         * never pairs with --shade depth (said here for static analysis) */
        if (o->shade == SHADE_DEPTH && dstride != 0) {
            for (x = 0; x < o->width; x++) {
                uint8_t *px = out->grey_row + 3 * (size_t)x;
                if (drow[x] == o->clear_depth) {
                    px[0] = o->bg.r;
                    px[1] = o->bg.g;
                    px[2] = o->bg.b;
                } else {
                    px[0] = px[1] = px[2] = depth_grey(out, drow[x]);
                }
            }
            if (zl_pnm_write_row_rgb(&out->image, out->grey_row, ZL_FORMAT_RGB888) != ZL_PNM_OK)
                return 0;
        } else if (zl_pnm_write_row_rgb(&out->image,
                                        (const uint8_t *)color + (size_t)y * (size_t)cstride,
                                        o->format) != ZL_PNM_OK) {
            return 0;
        }
        if (o->depth_out != NULL && zl_pnm_write_row_gray16(&out->depth, drow) != ZL_PNM_OK)
            return 0;
        out->rows_out++;
    }
    return 1;
}

static int band_out(void *user, const zl_band *band)
{
    output *out = (output *)user;
    if (band->first_row != out->rows_out) {
        error("internal: band starts at row %u, expected %lu", (unsigned)band->first_row,
              (unsigned long)out->rows_out);
        return BAND_WRITE_FAILED;
    }
    if (!write_rows(out, band->color, band->color_stride, band->depth, band->depth_stride,
                    band->rows))
        return BAND_WRITE_FAILED;
    return 0;
}

/* ----------------------------------------------------------------- render */

/* The style of the options (polygon modes, toon, antialiased lines). */
static void style_of(const options *o, zl_style *sty)
{
    zl_style_default(sty);
    if (o->wireframe) {
        sty->polygon_front = ZL_POLY_LINE;
        sty->polygon_back = ZL_POLY_LINE;
    } else if (o->points) {
        sty->polygon_front = ZL_POLY_POINT;
        sty->polygon_back = ZL_POLY_POINT;
    }
    if (o->toon > 0) {
        sty->toon_bands = (uint8_t)o->toon;
        sty->toon_colors = o->toon_table;
    }
    sty->line_aa = (uint8_t)o->aa_lines;
    if (o->texture_path != NULL) {
        sty->texture = &o->texture;
        sty->texcoords = o->texcoords;
        sty->tex_mapping = (uint8_t)(o->affine ? ZL_TEX_AFFINE : ZL_TEX_PERSPECTIVE);
        sty->tex_filter = (uint8_t)o->tex_filter;
    }
    sty->blend = (uint8_t)o->blend;
    sty->alpha = (uint8_t)(o->blend ? o->alpha : 255);
    apply_state_options(o, NULL, sty);
}

static int styled(const options *o)
{
    return o->wireframe || o->points || o->toon || o->outline || o->aa_lines || o->texture_path != NULL || o->blend ||
           state_styled(o);
}

/* Outline: silhouettes and creases over 60 degrees, black, drawn with LEQUAL
 * and pulled towards the eye by 64 depth steps. */
static void outline_of(const options *o, zl_outline *ol, zl_state *st, zl_style *sty)
{
    memset(ol, 0, sizeof *ol);
    ol->edges = o->edges;
    ol->edge_count = o->edge_count;
    ol->silhouettes = 1;
    ol->creases = 1;
    ol->crease_cos = ZL_FX_ONE / 2;
    st->depth_func = ZL_LEQUAL;
    st->light_on = 0;
    sty->polygon_front = ZL_POLY_FILL;
    sty->polygon_back = ZL_POLY_FILL;
    sty->offset_units = -ZL_FX_INT(64);
}

static int render_frame(const options *o, const zl_mesh *mesh, const zl_mat4 *mvp,
                        const zl_state *state, output *out)
{
    unsigned bpp = zl_format_bytes(o->format);
    size_t cbytes = (size_t)o->width * o->height * bpp;
    size_t dbytes = (size_t)o->width * o->height * sizeof(uint16_t);
    void *color = malloc(cbytes);
    uint16_t *depth = (uint16_t *)malloc(dbytes);
    zl_target target;
    zl_context ctx;
    zl_status st;
    int ok = 0;
    if (color == NULL || depth == NULL) {
        error("out of memory for a %ux%u frame", o->width, o->height);
        goto done;
    }
    memset(&target, 0, sizeof target);
    target.color = color;
    target.color_stride = (int32_t)(o->width * bpp);
    target.depth = depth;
    target.depth_stride = (int32_t)(o->width * sizeof(uint16_t));
    target.width = (uint16_t)o->width;
    target.height = (uint16_t)o->height;
    target.format = (uint8_t)o->format;
    st = zl_init(&ctx, &target);
    /* Clear with zl_init's state: zl_clear honours the colour and depth
     * write masks (as glClear), and the whole frame must start cleared, as
     * every band of zl_frame does. */
    if (st == ZL_OK)
        st = zl_clear(&ctx, o->bg, o->clear_depth);
    if (st == ZL_OK) {
        ctx.state = *state;
        style_of(o, &ctx.style);
        ctx.draw_cache = draw_cache_buf;
        ctx.draw_cache_bytes = sizeof draw_cache_buf;
        st = zl_draw_mesh(&ctx, mesh, mvp);
    }
    if (st == ZL_OK && o->outline) {
        zl_outline ol;
        outline_of(o, &ol, &ctx.state, &ctx.style);
        st = zl_draw_outlines(&ctx, mesh, mvp, &ol);
    }
    if (st != ZL_OK) {
        error("render failed: %s", status_name(st));
        goto done;
    }
    if (o->stats)
        printf("frame buffers: %lu bytes (colour %lu + depth %lu)\n",
               (unsigned long)(cbytes + dbytes), (unsigned long)cbytes, (unsigned long)dbytes);
    ok = write_rows(out, color, target.color_stride, depth, target.depth_stride, o->height);
done:
    free(color);
    free(depth);
    return ok;
}

static void frame_config(zl_frame_config *cfg, const options *o, const zl_mesh *mesh,
                         uint32_t triangles, uint32_t active)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->width = (uint16_t)o->width;
    cfg->height = (uint16_t)o->height;
    cfg->band_rows = (uint16_t)o->band_rows;
    cfg->format = (uint8_t)o->format;
    cfg->color_buffers = 1;
    cfg->gouraud = o->shade == SHADE_VERTEX || o->shade == SHADE_SMOOTH;
    cfg->max_meshes = 1;
    cfg->max_vertices = mesh->vertex_count;
    cfg->max_triangles = triangles;
    cfg->max_active = active;
    if (styled(o)) {
        /* line and point pieces: 3 a triangle; outline edges: 1 each */
        cfg->styled = 1;
        cfg->textured = o->texture_path != NULL || o->blend || o->persp_color; /* blending uses the styled rows */
        cfg->max_meshes = 2;
        cfg->max_triangles = triangles + o->edge_count;
        cfg->max_active = active * 3u + o->edge_count;
    }
}

/*
 * Begin a frame in a fresh work buffer of exactly zl_frame_bytes(cfg) bytes
 * and submit the scene (the mesh, then its outline). *work is the buffer to
 * free, also on failure (NULL when none was allocated).
 */
static zl_status frame_submit(const options *o, const zl_mesh *mesh, const zl_mat4 *mvp,
                              const zl_state *state, const zl_frame_config *cfg, zl_frame *frame,
                              void **work, size_t *bytes)
{
    zl_status st;
    zl_style sty;
    *work = NULL;
    *bytes = zl_frame_bytes(cfg);
    if (*bytes == 0) {
        error("zl_frame_bytes rejects the frame configuration (%ux%u, %u rows a band, "
              "max_triangles %lu, max_active %lu)",
              o->width, o->height, o->band_rows, (unsigned long)cfg->max_triangles,
              (unsigned long)cfg->max_active);
        return ZL_ERR_SIZE;
    }
    *work = malloc(*bytes); /* exactly what zl_frame_bytes asks, nothing more */
    if (*work == NULL) {
        error("out of memory for a %lu-byte work buffer", (unsigned long)*bytes);
        return ZL_ERR_SIZE;
    }
    st = zl_frame_begin(frame, cfg, *work, *bytes, o->bg, o->clear_depth);
    if (st == ZL_OK) {
        style_of(o, &sty);
        st = zl_frame_add_mesh_styled(frame, mesh, mvp, state, &sty);
    }
    if (st == ZL_OK && o->outline) {
        zl_outline ol;
        zl_state ost = *state;
        outline_of(o, &ol, &ost, &sty);
        st = zl_frame_add_outlines(frame, mesh, mvp, &ost, &sty, &ol);
    }
    if (st != ZL_OK)
        error("zl_frame setup failed: %s", status_name(st));
    return st;
}

/*
 * Scanline and band mode. The first try sizes the frame for one record per
 * triangle, enough for most scenes. A clipped triangle can be several pieces
 * in a row (up to 8), so a scene can need more: the frame then comes out
 * over capacity, the same bytes, planned again by the library (slower,
 * zline.h). Only when one triangle alone does not fit (a model of fewer
 * than 8 triangles, one of them clipped into more pieces) does the first
 * band fail with ZL_ERR_CAPACITY before any row is drawn or written: the
 * frame is then sized again from what zl_frame_needs reports and rendered
 * once more. So these modes render whatever frame mode renders
 * (below the library's caps of 65535 primitives and 65534 records a row).
 */
static int render_bands(const options *o, const zl_mesh *mesh, const zl_mat4 *mvp,
                        const zl_state *state, output *out)
{
    zl_frame_config cfg;
    zl_frame frame;
    size_t bytes = 0;
    void *work = NULL;
    int r = 0, attempt;
    frame_config(&cfg, o, mesh, mesh->triangle_count, mesh->triangle_count);
    for (attempt = 0; attempt < 2; attempt++) {
        zl_frame_needs_t needs;
        free(work);
        if (frame_submit(o, mesh, mvp, state, &cfg, &frame, &work, &bytes) != ZL_OK) {
            free(work);
            return 0;
        }
        r = zl_frame_render(&frame, band_out, out);
        if (r != ZL_ERR_CAPACITY || attempt == 1)
            break;
        needs = zl_frame_needs(&frame);
        if (needs.active > 65534u || needs.triangles > 65535u) {
            error("the scene needs %lu primitives and %lu records a row; zl_frame takes at most "
                  "65535 and 65534 (--mode frame has no such limit)",
                  (unsigned long)needs.triangles, (unsigned long)needs.active);
            free(work);
            return 0;
        }
        if (needs.triangles > cfg.max_triangles)
            cfg.max_triangles = needs.triangles;
        if (needs.active > cfg.max_active)
            cfg.max_active = needs.active;
    }
    if (r != 0) {
        if (r != BAND_WRITE_FAILED)
            error("render failed: %s", status_name((zl_status)r));
        free(work);
        return 0;
    }
    if (o->stats) {
        zl_frame_needs_t needs = zl_frame_needs(&frame);
        zl_frame_config tight = cfg;
        printf("work buffer: %lu bytes (zl_frame_bytes: %ux%u, %u row%s a band, max_triangles = "
               "%lu, max_active = %lu)\n",
               (unsigned long)bytes, o->width, o->height, o->band_rows,
               o->band_rows == 1 ? "" : "s", (unsigned long)cfg.max_triangles,
               (unsigned long)cfg.max_active);
        tight.max_triangles = needs.triangles;
        tight.max_active = needs.active ? needs.active : 1;
        printf("needs: %lu visible primitives, at most %lu active in a row; sized to that the "
               "work buffer would be %lu bytes\n",
               (unsigned long)needs.triangles, (unsigned long)needs.active,
               (unsigned long)zl_frame_bytes(&tight));
    }
    free(work);
    return 1;
}

/* ------------------------------------------------- --visibility (issue #6) */

static int vis_row_out(void *user, const zl_vis_row *row)
{
    output *out = (output *)user;
    static const uint16_t no_depth[1] = {0};
    return write_rows(out, row->color, 0, no_depth, 0, 1) ? 0 : BAND_WRITE_FAILED;
}

/* The eye in model space: the point the projection maps to x = y = w = 0. */
static zl_vec3 eye_of(const zl_mat4 *m)
{
    double a[3][4], p[3];
    int r, c, k;
    const int rows[3] = {0, 1, 3};
    zl_vec3 e;
    for (r = 0; r < 3; r++)
        for (c = 0; c < 4; c++)
            a[r][c] = m->m[rows[r] * 4 + c] / 65536.0;
    for (c = 0; c < 3; c++) { /* Gauss-Jordan with partial pivoting on [A | -b] */
        int piv = c;
        for (r = c + 1; r < 3; r++)
            if (fabs(a[r][c]) > fabs(a[piv][c]))
                piv = r;
        for (k = 0; k < 4; k++) {
            double t = a[c][k];
            a[c][k] = a[piv][k];
            a[piv][k] = t;
        }
        for (r = 0; r < 3; r++)
            if (r != c && a[c][c] != 0) {
                double f = a[r][c] / a[c][c];
                for (k = 0; k < 4; k++)
                    a[r][k] -= f * a[c][k];
            }
    }
    for (r = 0; r < 3; r++)
        p[r] = a[r][r] != 0 ? -a[r][3] / a[r][r] : 0;
    e.x = (zl_fixed)floor(p[0] * 65536.0 + 0.5);
    e.y = (zl_fixed)floor(p[1] * 65536.0 + 0.5);
    e.z = (zl_fixed)floor(p[2] * 65536.0 + 0.5);
    return e;
}

static int render_vis(const options *o, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state,
                      output *out)
{
    unsigned bpp = zl_format_bytes(o->format);
    void *work = NULL, *frame = NULL;
    zl_vis_target tg;
    zl_status st = ZL_OK;
    int ok = 0, r;
    memset(&tg, 0, sizeof tg);
    tg.color_stride = (int32_t)(o->width * bpp);
    tg.width = (uint16_t)o->width;
    tg.height = (uint16_t)o->height;
    tg.format = (uint8_t)o->format;
    if (o->visibility == 3) {
        bsp_tree tree;
        zl_bsp bsp;
        if (bsp_build(&tree, mesh->positions, mesh->vertex_count, mesh->indices, mesh->triangle_count, NULL) != 0)
            return 0;
        bsp = bsp_view(&tree);
        frame = malloc((size_t)tg.color_stride * o->height);
        tg.color = frame;
        if (frame != NULL)
            st = zl_bsp_draw(&bsp, mvp, eye_of(mvp), state, &tg, o->bg, ZL_BSP_BACK_TO_FRONT, NULL, 0);
        if (o->stats)
            printf("BSP tree: %u -> %u triangles, %u nodes, depth %u; RAM: the colour frame, %lu bytes\n",
                   (unsigned)mesh->triangle_count, tree.triangle_count, tree.node_count, tree.depth,
                   (unsigned long)tg.color_stride * o->height);
        bsp_free(&tree);
    } else {
        zl_vis_config cfg;
        zl_vis v;
        size_t bytes;
        memset(&cfg, 0, sizeof cfg);
        cfg.width = (uint16_t)o->width;
        cfg.height = (uint16_t)o->height;
        cfg.algorithm = (uint8_t)(o->visibility == 1 ? ZL_VIS_AET : o->visibility == 2 ? ZL_VIS_PAINTER : ZL_VIS_RAYCAST);
        cfg.format = (uint8_t)o->format;
        cfg.max_meshes = 1;
        cfg.max_vertices = mesh->vertex_count;
        cfg.max_triangles = mesh->triangle_count;
        cfg.max_active = (uint32_t)mesh->triangle_count * 7u + 1u; /* always enough */
        bytes = zl_vis_bytes(&cfg);
        work = bytes ? malloc(bytes) : NULL;
        if (work == NULL) {
            error("out of memory for a %lu-byte work buffer", (unsigned long)bytes);
            return 0;
        }
        st = zl_vis_begin(&v, &cfg, work, bytes);
        if (st == ZL_OK)
            st = zl_vis_add_mesh(&v, mesh, mvp, state);
        if (st == ZL_OK && cfg.algorithm == ZL_VIS_PAINTER) {
            frame = malloc((size_t)tg.color_stride * o->height);
            tg.color = frame;
            st = frame ? zl_painter_draw(&v, &tg, o->bg) : ZL_ERR_SIZE;
        } else if (st == ZL_OK) {
            r = zl_vis_render_rows(&v, o->bg, vis_row_out, out);
            if (r == BAND_WRITE_FAILED)
                goto done;
            st = (zl_status)r;
        }
        if (o->stats)
            printf("work buffer: %lu bytes (zl_vis_bytes)%s\n", (unsigned long)bytes,
                   frame ? " plus the colour frame" : "");
    }
    if (st != ZL_OK || (frame == NULL && tg.color == NULL && o->visibility != 1 && o->visibility != 4)) {
        error("render failed: %s", status_name(st));
        goto done;
    }
    ok = 1;
    if (frame != NULL) {
        static const uint16_t no_depth[1] = {0};
        unsigned y;
        for (y = 0; y < o->height && ok; y++)
            ok = write_rows(out, (const uint8_t *)frame + (size_t)y * (size_t)tg.color_stride, 0, no_depth, 0, 1);
    }
done:
    free(work);
    free(frame);
    return ok;
}

/* ------------------------------------------------------------------- main */

/* --texture: the image as texels (*texels, to free), converted by
 * zl_image.h exactly as zline-img2c converts it for firmware: RGB565, or
 * RGBA4444 when the image has alpha. */
static int load_texture(options *o, const zl_obj *obj, uint16_t **texels)
{
    zl_image img;
    char msg[1024];
    zl_texel_format fmt;
    if (obj->texcoords == NULL) {
        error("--texture: %s has no texture coordinates (vt) on its faces", o->model);
        return 0;
    }
    if (zl_image_load(&img, o->texture_path, NULL, msg, sizeof msg) != 0) {
        error("--texture: %s", msg);
        return 0;
    }
    fmt = img.has_alpha ? ZL_TEXEL_RGBA4444 : ZL_TEXEL_RGB565;
    *texels = (uint16_t *)malloc((size_t)img.width * img.height * sizeof(uint16_t));
    if (*texels == NULL) {
        error("out of memory");
        zl_image_free(&img);
        return 0;
    }
    zl_image_texels(&img, fmt, *texels);
    o->texture.texels = *texels;
    o->texture.width = (uint16_t)img.width;
    o->texture.height = (uint16_t)img.height;
    o->texture.stride = (uint16_t)img.width;
    o->texture.wrap_s = (uint8_t)o->wrap_s;
    o->texture.wrap_t = (uint8_t)o->wrap_t;
    o->texture.format = (uint8_t)fmt;
    o->texcoords = obj->texcoords;
    zl_image_free(&img);
    return 1;
}

/*
 * --shade smooth: the model's normals (vn or computed, by --normals), then
 * zl_light_vertices into *lit, which the Gouraud draw interpolates. The
 * lights are in world space, which is model space in this tool (no model
 * matrix); the viewer direction is from the target towards the eye.
 */
static int normalize_light(const double *l, zl_vec3 *out);

static int smooth_colors(const options *o, zl_obj *obj, zl_mesh *mesh, const zl_mat4 *mvp, uint8_t **lit)
{
    const char *mode = o->normals_mode != NULL ? o->normals_mode : "auto";
    zl_lighting lt;
    zl_status st;
    int k;
    if (strcmp(mode, "file") == 0 && obj->normals == NULL) {
        error("--normals file: %s has no normals (vn) on its faces", o->model);
        return 0;
    }
    if (strcmp(mode, "area") == 0 || strcmp(mode, "angle") == 0 || obj->normals == NULL) {
        int angle = strcmp(mode, "angle") == 0;
        if (zl_obj_compute_normals(obj, angle ? ZL_OBJ_NORMALS_ANGLE : ZL_OBJ_NORMALS_AREA) != ZL_OBJ_OK) {
            error("out of memory computing normals");
            return 0;
        }
        if (o->stats)
            printf("normals: computed, %s-weighted\n", angle ? "angle" : "area");
    } else if (o->stats) {
        printf("normals: the OBJ's vn\n");
    }
    zl_lighting_default(&lt);
    lt.ambient.r = lt.ambient.g = lt.ambient.b = (uint8_t)o->ambient;
    lt.material = o->color;
    lt.shininess = (uint8_t)o->shininess;
    if (o->light_on) {
        lt.light_count = 1;
        if (!normalize_light(o->light, &lt.lights[0].dir)) {
            error("--light: bad direction");
            return 0;
        }
        lt.lights[0].diffuse.r = lt.lights[0].diffuse.g = lt.lights[0].diffuse.b = (uint8_t)(255 - o->ambient);
        lt.lights[0].specular = o->specular;
        for (k = 0; k < o->fill_count; k++) {
            zl_light *L = &lt.lights[lt.light_count++];
            if (!normalize_light(o->fill[k], &L->dir)) {
                error("--fill-light: bad direction");
                return 0;
            }
            L->diffuse.r = (uint8_t)(o->fill[k][3] + 0.5);
            L->diffuse.g = (uint8_t)(o->fill[k][4] + 0.5);
            L->diffuse.b = (uint8_t)(o->fill[k][5] + 0.5);
            L->specular = o->specular;
        }
    }
    if (mvp != NULL) {
        zl_vec3 eye = eye_of(mvp), target;
        double v[3];
        if (!to_vec3(o->target, &target))
            return 0;
        v[0] = (eye.x - (double)target.x) / 65536.0;
        v[1] = (eye.y - (double)target.y) / 65536.0;
        v[2] = (eye.z - (double)target.z) / 65536.0;
        if (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] > 0 && !normalize_light(v, &lt.viewer))
            return 0;
    } else {
        lt.viewer.z = -ZL_FX_ONE; /* pixel space: the viewer looks down +z */
    }
    *lit = (uint8_t *)malloc((size_t)mesh->vertex_count * 3 + 1);
    if (*lit == NULL) {
        error("out of memory");
        return 0;
    }
    st = zl_light_vertices(&lt, NULL, mesh, obj->normals, *lit);
    if (st != ZL_OK) {
        error("zl_light_vertices failed with %s", status_name(st));
        return 0;
    }
    mesh->vertex_colors = *lit;
    return 1;
}

/* The unit vector of l: scaled by its largest component first, so that any
 * finite non-zero direction works (1e300,0,0 squared would overflow). */
static int normalize_light(const double *l, zl_vec3 *out)
{
    double m = direction_scale(l), n, u[3];
    int k;
    if (m == 0)
        return 0;
    for (k = 0; k < 3; k++)
        u[k] = l[k] / m;
    n = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    for (k = 0; k < 3; k++)
        u[k] /= n;
    return to_vec3(u, out);
}

int main(int argc, char **argv)
{
    options o;
    zl_obj obj;
    zl_obj_options lopt;
    zl_mesh mesh;
    zl_mat4 mvp;
    const zl_mat4 *mvp_ptr = NULL;
    zl_state state;
    output out;
    uint8_t *colors = NULL;
    uint16_t *texels = NULL;
    char msg[512];
    int r, ok = 0;

    r = parse_options(argc, argv, &o);
    if (r < 0)
        return 0; /* --help */
    if (r > 0)
        return r;

    zl_obj_options_default(&lopt);
    lopt.normalize = o.normalize;
    if ((o.texture_path != NULL ? zl_obj_load_file_tex(&obj, o.model, &lopt, msg, sizeof msg)
                                : zl_obj_load_file(&obj, o.model, &lopt, msg, sizeof msg)) != ZL_OBJ_OK) {
        error("%s", msg);
        return EXIT_FAILURE;
    }
    mesh = zl_obj_mesh(&obj);

    memset(&out, 0, sizeof out);
    out.opt = &o;

    if (!o.pixel_space) {
        if (!build_mvp(&o, &mvp))
            goto done;
        mvp_ptr = &mvp;
    }

    zl_state_default(&state);
    state.cull = (uint8_t)o.cull;
    state.front_face = (uint8_t)o.front;
    state.color = o.color;
    state.light_on = (uint8_t)(o.light_on && o.shade != SHADE_DEPTH);
    state.ambient = (uint8_t)o.ambient;
    apply_state_options(&o, &state, NULL);
    if (!normalize_light(o.light, &state.light_dir)) {
        error("--light: bad direction");
        goto done;
    }
    if (o.shade == SHADE_SMOOTH) {
        state.shading = ZL_SHADE_GOURAUD;
        state.light_on = 0; /* the light is in the vertex colours */
        if (!smooth_colors(&o, &obj, &mesh, mvp_ptr, &colors))
            goto done;
    } else if (o.shade == SHADE_VERTEX) {
        state.shading = ZL_SHADE_GOURAUD;
        if (mesh.vertex_colors == NULL) {
            uint32_t i;
            colors = (uint8_t *)malloc((size_t)mesh.vertex_count * 3 + 1);
            if (colors == NULL) {
                error("out of memory");
                goto done;
            }
            for (i = 0; i < mesh.vertex_count; i++) {
                colors[3 * i] = o.color.r;
                colors[3 * i + 1] = o.color.g;
                colors[3 * i + 2] = o.color.b;
            }
            mesh.vertex_colors = colors;
        }
    } else {
        state.shading = ZL_SHADE_FLAT;
        mesh.vertex_colors = NULL;
    }
    if (zl_state_check(&state) != ZL_OK) {
        error("internal: invalid render state");
        goto done;
    }
    if (o.visibility != 0 && styled(&o)) {
        error("--wireframe, --points, --toon, --outline, --aa-lines, --texture and --blend need the z-buffer (no "
              "--visibility)");
        goto done;
    }
    if (o.texture_path != NULL && !load_texture(&o, &obj, &texels))
        goto done;
    if (o.toon > 0) {
        /* band k of N: the model colour at (k + 1) / N, the darkest at 1/(2N) */
        int k;
        for (k = 0; k < o.toon; k++) {
            unsigned f = (unsigned)(k == 0 ? 128 / o.toon : 256 * (k + 1) / o.toon);
            o.toon_table[k].r = (uint8_t)(o.color.r * (f > 255 ? 255 : f) / 255);
            o.toon_table[k].g = (uint8_t)(o.color.g * (f > 255 ? 255 : f) / 255);
            o.toon_table[k].b = (uint8_t)(o.color.b * (f > 255 ? 255 : f) / 255);
        }
    }
    if (o.outline) {
        o.edges = (zl_mesh_edge *)malloc((size_t)mesh.triangle_count * 3 * sizeof(zl_mesh_edge) + 1);
        if (o.edges == NULL) {
            error("out of memory");
            goto done;
        }
        o.edge_count = zl_mesh_edges(&mesh, o.edges, (uint32_t)mesh.triangle_count * 3u);
    }

    if (o.shade == SHADE_DEPTH) {
        depth_range(&out, &obj, mvp_ptr, &o);
        out.grey_row = (uint8_t *)malloc((size_t)o.width * 3);
        if (out.grey_row == NULL) {
            error("out of memory");
            goto done;
        }
    }

    if (o.stats) {
        printf("model: %s: %lu vertices, %lu triangles (%lu faces)%s\n", o.model,
               (unsigned long)obj.vertex_count, (unsigned long)obj.triangle_count,
               (unsigned long)obj.face_count, mesh.vertex_colors ? ", vertex colours" : "");
        printf("mode: %s, %ux%u %s\n",
               o.band_rows == 0 ? "frame" : (o.band_rows == 1 ? "scanline" : "band"), o.width,
               o.height,
               o.format == ZL_FORMAT_RGB888
                   ? "RGB888"
                   : (o.format == ZL_FORMAT_RGB565 ? "RGB565" : "RGB565_BE"));
    }

    /* Open the files first: in band mode the rows go out as they are drawn. */
    if (zl_pnm_open(&out.image, o.out, ZL_PNM_PPM, o.width, o.height, msg, sizeof msg) !=
        ZL_PNM_OK) {
        error("%s", msg);
        goto done;
    }
    if (o.depth_out != NULL && zl_pnm_open(&out.depth, o.depth_out, ZL_PNM_PGM16, o.width, o.height,
                                           msg, sizeof msg) != ZL_PNM_OK) {
        error("%s", msg);
        goto done;
    }
    /* Writer errors land in msg; the renderer reports its own. */
    msg[0] = '\0';
    if (o.visibility != 0)
        ok = render_vis(&o, &mesh, mvp_ptr, &state, &out);
    else if (o.band_rows == 0)
        ok = render_frame(&o, &mesh, mvp_ptr, &state, &out);
    else
        ok = render_bands(&o, &mesh, mvp_ptr, &state, &out);
    /* All files complete before any takes its name: all or nothing. */
    if (ok && zl_pnm_finish(&out.image) != ZL_PNM_OK)
        ok = 0;
    if (ok && o.depth_out != NULL && zl_pnm_finish(&out.depth) != ZL_PNM_OK)
        ok = 0;
    if (ok && zl_pnm_commit(&out.image) != ZL_PNM_OK)
        ok = 0;
    if (ok && o.depth_out != NULL && zl_pnm_commit(&out.depth) != ZL_PNM_OK) {
        /* The image has its name already: say so rather than delete it. */
        fprintf(stderr, "zline-render: %s was written, the depth image was not\n", o.out);
        ok = 0;
    }
    if (!ok && msg[0] != '\0')
        error("%s", msg);

done:
    zl_pnm_abort(&out.image);
    zl_pnm_abort(&out.depth);
    free(out.grey_row);
    free(colors);
    free(o.edges);
    free(texels);
    zl_obj_free(&obj);
    return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}

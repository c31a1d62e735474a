/* SPDX-License-Identifier: MIT */
/* Work-buffer capacities for a mesh in every pose, without rendering (see
 * zl_sizing.h for the bound and its proof). */
#include "zline/zl_sizing.h"

#define BINS 256
#define POSITION_LIMIT (INT32_C(1) << 30) /* +-16384.0: zl_transform_point's range */
#define WINDOW_LIMIT 32000                /* pixels: inside the cache's int16 window range */
#define ACTIVE_CAP 65534u

/* ceil(sqrt(2) * v) for v >= 0, from above (1.41422 > sqrt(2)). */
static int64_t times_sqrt2_up(int64_t v)
{
    return (v * 141422 + 99999) / 100000;
}

static int64_t ceil_div(int64_t a, int64_t b) /* a >= 0, b > 0 */
{
    return (a + b - 1) / b;
}

/* The mesh's radius about its origin, raw Q16.16, rounded up; -1 when a
 * vertex is out of range or an index out of bounds. */
static int64_t mesh_radius(const zl_mesh *m)
{
    uint64_t most = 0;
    uint32_t i;
    for (i = 0; i < (uint32_t)m->triangle_count * 3u; i++)
        if (m->indices[i] >= m->vertex_count)
            return -1;
    for (i = 0; i < m->vertex_count; i++) {
        const zl_fixed *p = m->positions + (size_t)i * 3u;
        uint64_t sq = 0;
        int k;
        for (k = 0; k < 3; k++) {
            if (p[k] > POSITION_LIMIT || p[k] < -POSITION_LIMIT)
                return -1;
            sq += (uint64_t)((int64_t)p[k] * p[k]);
        }
        if (sq > most)
            most = sq;
    }
    return (int64_t)zl_isqrt64(most) + 1;
}

/* Focal length in pixels, raw Q16.16, rounded down (a shorter focal length
 * only widens the margin). */
static int64_t focal_length(zl_angle fovy, uint16_t height)
{
    zl_fixed s = zl_sin(fovy / 2), c = zl_cos(fovy / 2);
    if (s <= 0 || c <= 0)
        return 0;
    return (int64_t)height * c * 65536 / (2 * (int64_t)s);
}

/* Whether no vertex of any pose is clipped: the mesh's sphere is between
 * the near and far planes and projects inside the window range. */
static int never_clipped(const zl_orbit_camera *cam, int64_t radius, int64_t focal, const zl_frame_config *cfg)
{
    int64_t closest = (int64_t)cam->distance - radius, half = cfg->width > cfg->height ? cfg->width : cfg->height;
    if (closest <= cam->near_z || (int64_t)cam->distance + radius >= cam->far_z)
        return 0;
    /* |X - centre| <= f R / (distance - R) pixels */
    return focal / 65536 * radius / closest + 1 + half / 2 + 1 < WINDOW_LIMIT;
}

static int64_t dot3(const int32_t q[3], const zl_fixed *p)
{
    return (int64_t)q[0] * p[0] + (int64_t)q[1] * p[1] + (int64_t)q[2] * p[2];
}

/* The most widened triangle intervals one bin holds, for grid direction q
 * (integer components in -g .. g, g times the face point): each interval
 * [min q.v, max q.v] widened by `widen`, all inside [-reach, reach]. */
static uint32_t busiest_bin(const zl_mesh *m, const int32_t q[3], int64_t widen, int64_t reach)
{
    uint16_t diff[BINS + 1]; /* counts modulo 2^16: each running sum is <= 65535 */
    int64_t bin_width = ceil_div(2 * reach + 1, BINS);
    uint32_t t, best = 0;
    uint16_t running = 0;
    int b;
    for (b = 0; b <= BINS; b++)
        diff[b] = 0;
    for (t = 0; t < m->triangle_count; t++) {
        const uint16_t *idx = m->indices + (size_t)t * 3u;
        int64_t a = dot3(q, m->positions + (size_t)idx[0] * 3u), lo = a, hi = a;
        int k;
        for (k = 1; k < 3; k++) {
            a = dot3(q, m->positions + (size_t)idx[k] * 3u);
            lo = a < lo ? a : lo;
            hi = a > hi ? a : hi;
        }
        diff[(lo - widen + reach) / bin_width]++;
        diff[(hi + widen + reach) / bin_width + 1]--;
    }
    for (b = 0; b < BINS; b++) {
        running = (uint16_t)(running + diff[b]);
        if (running > best)
            best = running;
    }
    return best;
}

/* The bound over the whole grid of directions (see zl_sizing.h). */
static uint32_t stabbing_bound(const zl_mesh *m, int64_t radius, int64_t margin, int32_t g)
{
    uint32_t best = 0;
    int axis;
    int32_t i, j;
    for (axis = 0; axis < 3; axis++)
        for (i = -g; i <= g; i += 2)
            for (j = -g; j <= g; j += 2) {
                int32_t q[3];
                int64_t norm, widen, reach;
                uint32_t n;
                q[axis] = g;
                q[(axis + 1) % 3] = i;
                q[(axis + 2) % 3] = j;
                norm = (int64_t)zl_isqrt64((uint64_t)((int64_t)g * g + (int64_t)i * i + (int64_t)j * j)) + 1;
                /* sqrt(2) R for the step from q to n, m (|q| + sqrt(2)) for the margin */
                widen = times_sqrt2_up(radius) + margin * (norm + 2);
                reach = norm * radius + widen;
                n = busiest_bin(m, q, widen, reach);
                best = n > best ? n : best;
            }
    return best;
}

static int camera_ok(const zl_orbit_camera *c)
{
    return c->fovy > 0 && c->fovy < ZL_ANGLE_TURN / 2 && c->near_z > 0 && c->far_z > c->near_z && c->distance > 0;
}

size_t zl_frame_bound(zl_frame_config *cfg, const zl_mesh *mesh, const zl_orbit_camera *camera,
                      unsigned precision)
{
    zl_frame_config c;
    int64_t radius, focal;
    uint32_t active, all = 0;
    size_t bytes;
    if (cfg == NULL || mesh == NULL || camera == NULL || !camera_ok(camera) || precision < 1u ||
        precision > ZL_SIZING_PRECISION_MAX || mesh->positions == NULL ||
        (mesh->triangle_count > 0 && mesh->indices == NULL))
        return 0;
    radius = mesh_radius(mesh);
    focal = focal_length(camera->fovy, cfg->height);
    if (radius < 0 || focal <= 0)
        return 0;
    c = *cfg;
    if (never_clipped(camera, radius, focal, &c)) {
        /* m = 1 pixel at the farthest depth, in raw model units, rounded up */
        int64_t margin = ceil_div(((int64_t)camera->distance + radius) * 65536, focal);
        active = stabbing_bound(mesh, radius, margin, (int32_t)precision);
        all = mesh->triangle_count;
    } else {
        active = 8u * mesh->triangle_count;
        all = active;
    }
    c.max_meshes = 1;
    c.max_vertices = mesh->vertex_count;
    c.max_triangles = mesh->triangle_count > 0 ? mesh->triangle_count : 1u;
    if (active > all)
        active = all;
    c.max_active = active < 1u ? 1u : (active > ACTIVE_CAP ? ACTIVE_CAP : active);
    bytes = zl_frame_bytes(&c);
    if (bytes != 0)
        *cfg = c;
    return bytes;
}

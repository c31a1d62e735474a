/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: zl_light_vertices (zline.h, SMOOTH LIGHTING) with arbitrary
 * lighting structs (light counts and shininess beyond their limits, zero and
 * huge directions and viewers), meshes with and without vertex colours,
 * normals of any length (zero too) and matrices (NULL, raw entries,
 * singular ones). Every array is allocated with exactly the size the call is
 * promised (positions, normals, vertex colours: vertex_count entries), so a
 * read past one is an AddressSanitizer finding; the output is a guarded
 * buffer of exactly 3 * vertex_count bytes. Checked, against expectations
 * computed here from zline.h:
 *   - the status is ZL_OK, ZL_ERR_ARG (exactly for a NULL pointer) or
 *     ZL_ERR_RANGE; ZL_ERR_RANGE whenever a documented range error holds
 *     (too many lights, shininess above ZL_MAX_SHININESS, a zero light
 *     direction, a zero viewer with a specular light);
 *   - on an error nothing is written (the payload keeps its pattern);
 *   - on success no byte outside the payload changed and every channel is
 *     at least the ambient term m * A / 255 less 1 (every other term is
 *     non-negative); a vertex with a zero normal, or any vertex when no
 *     light is on, is the ambient term within 1.
 */
#include "fz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define FZ_LIGHT_MAX_VERTICES 64u

static zl_vec3 read_vec(fz_in *in)
{
    zl_vec3 v;
    uint32_t kind = fz_u8(in) % 4;
    if (kind == 0) { /* an axis, one of whose components may be zero */
        v.x = (zl_fixed)((int32_t)(int8_t)fz_u8(in) * 256);
        v.y = (zl_fixed)((int32_t)(int8_t)fz_u8(in) * 256);
        v.z = (zl_fixed)((int32_t)(int8_t)fz_u8(in) * 256);
    } else {
        v.x = fz_fixed(in);
        v.y = fz_fixed(in);
        v.z = fz_fixed(in);
    }
    return v;
}

static int is_zero(zl_vec3 v)
{
    return v.x == 0 && v.y == 0 && v.z == 0;
}

static void read_rgb(fz_in *in, zl_rgb *c)
{
    c->r = (uint8_t)fz_u8(in);
    c->g = (uint8_t)fz_u8(in);
    c->b = (uint8_t)fz_u8(in);
}

static void read_lighting(fz_in *in, zl_lighting *lt)
{
    unsigned i;
    uint32_t f = fz_u8(in);
    zl_lighting_default(lt);
    read_rgb(in, &lt->ambient);
    read_rgb(in, &lt->material);
    lt->light_count = (uint8_t)((f & 1u) ? fz_u8(in) : fz_u8(in) % (ZL_MAX_LIGHTS + 1));
    lt->shininess = (uint8_t)((f & 2u) ? fz_u8(in) : fz_u8(in) % (ZL_MAX_SHININESS + 1));
    if (f & 4u)
        lt->viewer = read_vec(in);
    for (i = 0; i < ZL_MAX_LIGHTS; i++) {
        lt->lights[i].dir = read_vec(in);
        read_rgb(in, &lt->lights[i].diffuse);
        if (f & (8u << i))
            read_rgb(in, &lt->lights[i].specular);
    }
}

/* The documented ZL_ERR_RANGE cases that need no arithmetic. */
static int plain_range_error(const zl_lighting *lt)
{
    unsigned i;
    int specular = 0;
    if (lt->light_count > ZL_MAX_LIGHTS || lt->shininess > ZL_MAX_SHININESS)
        return 1;
    for (i = 0; i < lt->light_count; i++) {
        const zl_rgb *s = &lt->lights[i].specular;
        if (is_zero(lt->lights[i].dir))
            return 1;
        specular |= s->r != 0 || s->g != 0 || s->b != 0;
    }
    return specular && is_zero(lt->viewer);
}

static void check_colours(const zl_lighting *lt, const uint8_t *material, const int16_t *normals,
                          const uint8_t *out, unsigned n)
{
    const uint8_t amb[3] = {lt->ambient.r, lt->ambient.g, lt->ambient.b};
    const uint8_t mat[3] = {lt->material.r, lt->material.g, lt->material.b};
    unsigned v, k;
    for (v = 0; v < n; v++) {
        int ambient_only = lt->light_count == 0 ||
                           (normals[v * 3] == 0 && normals[v * 3 + 1] == 0 && normals[v * 3 + 2] == 0);
        for (k = 0; k < 3; k++) {
            uint32_t m = material != NULL ? material[v * 3 + k] : mat[k];
            uint32_t a255 = m * amb[k];           /* 255 x the ambient term */
            uint32_t got255 = 255u * out[v * 3 + k];
            FZ_REQUIRE(got255 + 255u >= a255, "vertex %u channel %u: %u below the ambient term %u/255", v, k,
                       out[v * 3 + k], a255);
            if (ambient_only)
                FZ_REQUIRE(got255 <= a255 + 255u, "vertex %u channel %u: %u, ambient only %u/255", v, k,
                           out[v * 3 + k], a255);
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    zl_lighting lt;
    zl_mat4 mat;
    zl_mesh mesh;
    zl_fixed *positions;
    int16_t *normals;
    uint8_t *material = NULL;
    fz_buf out;
    unsigned n, i;
    zl_status st;
    uint32_t f = fz_u8(&in), kind;
    const zl_mat4 *model = NULL;
    int null_arg;
    read_lighting(&in, &lt);
    kind = fz_u8(&in) % 4;
    if (kind == 1 || kind == 2) {
        for (i = 0; i < 16; i++)
            mat.m[i] = fz_fixed(&in);
        if (kind == 2) /* a singular upper-left 3x3: a zero row or repeated column */
            mat.m[(fz_u8(&in) % 3) * 4] = mat.m[(fz_u8(&in) % 3) * 4 + 1] = mat.m[2] = 0;
        model = &mat;
    } else if (kind == 3) {
        zl_mat4_rotate_y(&mat, (zl_angle)fz_u16(&in));
        model = &mat;
    }
    n = fz_u8(&in) % (FZ_LIGHT_MAX_VERTICES + 1);
    positions = (zl_fixed *)malloc((n ? n : 1) * 3 * sizeof(zl_fixed));
    normals = (int16_t *)malloc((n ? n : 1) * 3 * sizeof(int16_t));
    if (positions == NULL || normals == NULL)
        abort();
    for (i = 0; i < n * 3; i++) {
        positions[i] = (zl_fixed)i;
        normals[i] = (f & 1u) ? (int16_t)(int32_t)(fz_u16(&in) - 32768u) : (int16_t)((int8_t)fz_u8(&in) * 128);
    }
    if (f & 2u) {
        material = (uint8_t *)malloc((size_t)n * 3 + 1);
        if (material == NULL)
            abort();
        for (i = 0; i < n * 3; i++)
            material[i] = (uint8_t)fz_u8(&in);
    }
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = positions;
    mesh.vertex_colors = material;
    mesh.vertex_count = (uint16_t)n;
    fz_buf_alloc(&out, (size_t)n * 3);
    /* bits 2..4: a NULL lighting, mesh or normals */
    null_arg = (f & 28u) != 0;
    st = zl_light_vertices((f & 4u) ? NULL : &lt, model, (f & 8u) ? NULL : &mesh, (f & 16u) ? NULL : normals,
                           (uint8_t *)out.data);
    fz_buf_check(&out, "colours");
    FZ_REQUIRE(st == ZL_OK || st == ZL_ERR_ARG || st == ZL_ERR_RANGE, "status %d", (int)st);
    /* A NULL lighting or mesh is ZL_ERR_ARG; NULL normals are an error only
     * when there are vertices to read them for, and zline.h does not say
     * which of ZL_ERR_ARG and ZL_ERR_RANGE comes first then. */
    if (f & 12u)
        FZ_REQUIRE(st == ZL_ERR_ARG, "status %d for a NULL lighting or mesh", (int)st);
    else if ((f & 16u) && n > 0)
        FZ_REQUIRE(st != ZL_OK, "NULL normals accepted for %u vertices", n);
    else
        FZ_REQUIRE(st != ZL_ERR_ARG, "status ZL_ERR_ARG without a NULL pointer");
    if (!null_arg && plain_range_error(&lt))
        FZ_REQUIRE(st == ZL_ERR_RANGE, "status %d for a documented range error", (int)st);
    if (st != ZL_OK) {
        for (i = 0; i < n * 3; i++)
            FZ_REQUIRE(out.data[i] == fz_pattern(FZ_GUARD + i), "byte %u written on error %d", i, (int)st);
    } else {
        check_colours(&lt, material, normals, out.data, n);
    }
    fz_buf_free(&out);
    free(positions);
    free(normals);
    free(material);
    return 0;
}

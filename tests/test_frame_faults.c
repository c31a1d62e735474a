/* SPDX-License-Identifier: MIT */
/*
 * Faults in the middle of a frame (issue 26): a band callback that fails at
 * any band, a pull loop abandoned part-way, and zl_frame_* calls out of
 * order. Each gives its documented status (zline.h, "scanline and band
 * mode"), writes nothing outside the work buffer (guard bytes on every
 * target, ASan on the host), and leaves the zl_frame and its work buffer
 * usable: the next frame begun in them is byte for byte the frame a fresh
 * zl_frame and work buffer render. That fresh frame is itself checked
 * against the scene drawn pixel by pixel from its exact, axis-aligned
 * rectangles (written out here, independent of the library).
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_guard.h"

#define W 40
#define H 30
#define BAND 4
#define BANDS ((H + BAND - 1) / BAND)
#define CALLBACK_ERROR 7

/* Two rectangles (two triangles each), flat colours, the red one nearer:
 * red covers x 4..23, y 3..20; blue x 12..35, y 10..27, behind red. Corners
 * on pixel edges, so coverage is exactly the integer rectangle. */
static const zl_fixed positions[8 * 3] = {
    ZL_FX_INT(4),  ZL_FX_INT(3),  ZL_FX_ONE / 4,     ZL_FX_INT(24), ZL_FX_INT(3),  ZL_FX_ONE / 4,
    ZL_FX_INT(24), ZL_FX_INT(21), ZL_FX_ONE / 4,     ZL_FX_INT(4),  ZL_FX_INT(21), ZL_FX_ONE / 4,
    ZL_FX_INT(12), ZL_FX_INT(10), ZL_FX_ONE / 2,     ZL_FX_INT(36), ZL_FX_INT(10), ZL_FX_ONE / 2,
    ZL_FX_INT(36), ZL_FX_INT(28), ZL_FX_ONE / 2,     ZL_FX_INT(12), ZL_FX_INT(28), ZL_FX_ONE / 2,
};
static const uint16_t indices[4 * 3] = {0, 2, 1, 0, 3, 2, 4, 6, 5, 4, 7, 6};
static const uint8_t face_colors[4 * 3] = {255, 0, 0, 255, 0, 0, 0, 0, 255, 0, 0, 255};
#define RED 0xF800u
#define BLUE 0x001Fu
#define BG 0x0000u

static zl_frame_config cfg;
static uint16_t fresh[W * H], got[W * H];

static void scene_config(void)
{
    zt_frame_config_of(&cfg, W, H, BAND, ZL_FORMAT_RGB565);
    zt_frame_capacity(&cfg, 2, 16, 8, 8);
}

static zl_status submit(zl_frame *f)
{
    zl_mesh mesh;
    zl_state st;
    zl_state_default(&st);
    st.light_on = 0;
    st.cull = ZL_CULL_NONE;
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.face_colors = face_colors;
    mesh.vertex_count = 8;
    mesh.triangle_count = 4;
    return zl_frame_add_mesh(f, &mesh, NULL, &st);
}

/* A frame begun in work (a guarded block of exactly zl_frame_bytes). */
static void begin(zl_frame *f, void *work)
{
    zl_rgb bg = {0, 0, 0};
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(f, &cfg, work, zl_frame_bytes(&cfg), bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, submit(f));
}

typedef struct {
    zt_frame_copy copy;
    int calls, fail_at;
} band_sink;

/* Copies every band; returns CALLBACK_ERROR at band fail_at. */
static int sink_fn(void *user, const zl_band *b)
{
    band_sink *s = (band_sink *)user;
    if (s->calls++ == s->fail_at)
        return CALLBACK_ERROR;
    zt_band_copy(&s->copy, b);
    return 0;
}

static void render_whole(zl_frame *f, uint16_t *out)
{
    band_sink s;
    memset(&s, 0, sizeof s);
    s.copy.color = out;
    s.fail_at = -1;
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(f, sink_fn, &s));
    TEST_ASSERT_EQUAL_INT(BANDS, s.calls);
}

static void assert_guards(void)
{
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, zt_guard_check(), zt_guard_report());
}

/* The reference frame: a fresh zl_frame and work buffer, checked against the
 * rectangles pixel by pixel. */
static void setUp_fresh(void)
{
    zl_frame f;
    void *work;
    int x, y;
    zt_guard_reset();
    scene_config();
    work = zt_guard_alloc(zl_frame_bytes(&cfg));
    TEST_ASSERT_NOT_NULL(work);
    begin(&f, work);
    render_whole(&f, fresh);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            int red = x >= 4 && x < 24 && y >= 3 && y < 21;
            int blue = x >= 12 && x < 36 && y >= 10 && y < 28;
            uint16_t want = red ? RED : blue ? BLUE : BG;
            TEST_ASSERT_EQUAL_HEX16(want, fresh[y * W + x]);
        }
    }
    assert_guards();
    zt_guard_reset();
}

/* The next frame begun in the same zl_frame and work buffer is the fresh
 * frame, and no guard byte moved; the arena is then free for the next case. */
static void assert_next_frame_fresh(zl_frame *f, void *work)
{
    memset(got, 0xA5, sizeof got);
    begin(f, work);
    render_whole(f, got);
    TEST_ASSERT_EQUAL_MEMORY(fresh, got, sizeof got);
    assert_guards();
    zt_guard_reset();
}

static void test_callback_error_at_every_band(void)
{
    int k;
    setUp_fresh();
    for (k = 0; k < BANDS; k++) {
        zl_frame f;
        band_sink s;
        void *work = zt_guard_alloc(zl_frame_bytes(&cfg));
        TEST_ASSERT_NOT_NULL(work);
        begin(&f, work);
        memset(&s, 0, sizeof s);
        s.copy.color = got;
        s.fail_at = k;
        /* The callback's own value comes back and stops the frame. */
        TEST_ASSERT_EQUAL_INT(CALLBACK_ERROR, zl_frame_render(&f, sink_fn, &s));
        TEST_ASSERT_EQUAL_INT(k + 1, s.calls);
        assert_next_frame_fresh(&f, work);
    }
}

static void test_pull_loop_abandoned_at_every_band(void)
{
    int k;
    setUp_fresh();
    for (k = 0; k <= BANDS; k++) {
        zl_frame f;
        zl_band band;
        int i;
        void *work = zt_guard_alloc(zl_frame_bytes(&cfg));
        TEST_ASSERT_NOT_NULL(work);
        begin(&f, work);
        for (i = 0; i < k; i++)
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &band));
        assert_next_frame_fresh(&f, work);
    }
}

static void test_calls_out_of_order(void)
{
    zl_frame f;
    zl_band band;
    zl_state st;
    void *work;
    setUp_fresh();
    zl_state_default(&st);
    /* Before zl_frame_begin: a zeroed zl_frame is refused, not read. */
    memset(&f, 0, sizeof f);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_next_band(&f, &band));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, submit(&f));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_render(&f, sink_fn, NULL));
    work = zt_guard_alloc(zl_frame_bytes(&cfg));
    TEST_ASSERT_NOT_NULL(work);
    begin(&f, work);
    /* A mesh after the first band: ZL_ERR_ARG, and the frame goes on. */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&f, &band));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, submit(&f));
    /* The rest of the frame, then ZL_DONE for every later call. */
    while (zl_frame_next_band(&f, &band) == ZL_OK)
        ;
    TEST_ASSERT_EQUAL_INT(ZL_DONE, zl_frame_next_band(&f, &band));
    TEST_ASSERT_EQUAL_INT(ZL_DONE, zl_frame_next_band(&f, &band));
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, sink_fn, NULL)); /* nothing left: no call */
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, submit(&f));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_next_band(&f, NULL));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_render(&f, NULL, NULL));
    /* And the same zl_frame renders the next frame as a fresh one does. */
    assert_next_frame_fresh(&f, work);
}

void setUp(void) {}
void tearDown(void) {}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_callback_error_at_every_band);
    RUN_TEST(test_pull_loop_abandoned_at_every_band);
    RUN_TEST(test_calls_out_of_order);
    return UNITY_END();
}

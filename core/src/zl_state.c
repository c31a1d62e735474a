/* Render state defaults and validation; pixel format sizes. */
#include "zline/zline.h"

void zl_state_default(zl_state *s)
{
    s->depth_test = 1;
    s->depth_write = 1;
    s->depth_func = ZL_LESS;
    s->color_mask = ZL_MASK_RGB;
    s->cull = ZL_CULL_NONE;
    s->front_face = ZL_FRONT_CCW;
    s->shading = ZL_SHADE_FLAT;
    s->light_on = 0;
    s->ambient = 0;
    s->color.r = 255;
    s->color.g = 255;
    s->color.b = 255;
    s->light_dir.x = 0;
    s->light_dir.y = 0;
    s->light_dir.z = ZL_FX_ONE;
}

zl_status zl_state_check(const zl_state *s)
{
    if (s == NULL)
        return ZL_ERR_ARG;
    if (s->depth_func > ZL_ALWAYS || s->cull > ZL_CULL_FRONT || s->front_face > ZL_FRONT_CW ||
        s->shading > ZL_SHADE_GOURAUD || s->color_mask > ZL_MASK_RGB || s->depth_test > 1 ||
        s->depth_write > 1 || s->light_on > 1)
        return ZL_ERR_ARG;
    /* A unit vector: components within +-1.0 keep the lighting dot product
     * (normal below 2^31 times light) far inside 64 bits. */
    if (s->light_on && (s->light_dir.x < -ZL_FX_ONE || s->light_dir.x > ZL_FX_ONE ||
                        s->light_dir.y < -ZL_FX_ONE || s->light_dir.y > ZL_FX_ONE ||
                        s->light_dir.z < -ZL_FX_ONE || s->light_dir.z > ZL_FX_ONE))
        return ZL_ERR_RANGE;
    return ZL_OK;
}

unsigned zl_format_bytes(zl_format f)
{
    switch (f) {
    case ZL_FORMAT_RGB565:
    case ZL_FORMAT_RGB565_BE:
        return 2;
    case ZL_FORMAT_RGB888:
        return 3;
    }
    return 0;
}

/* SPDX-License-Identifier: MIT */
/* Stage 5, render: the ABI check of zl_init and zl_frame_begin (issue 23)
 * and the status strings. zline.h turns each call of zl_init and
 * zl_frame_begin into its _abi form with the application's ZL_ABI_KEY; a
 * key other than the library's means the two were compiled with different
 * struct sizes or configuration, and every later call would read the
 * caller's structs at the wrong offsets: refused before anything is
 * written. */
#include "../1_base/zl_internal.h"

uint32_t zl_abi_key(void)
{
    return ZL_ABI_KEY;
}

zl_status zl_init_abi(uint32_t abi_key, zl_context *ctx, const zl_target *target)
{
    if (abi_key != ZL_ABI_KEY)
        return ZL_ERR_ABI;
    return (zl_init)(ctx, target);
}

zl_status zl_frame_begin_abi(uint32_t abi_key, zl_frame *f, const zl_frame_config *cfg, void *work,
                             size_t work_bytes, zl_rgb clear_color, uint16_t clear_depth)
{
    if (abi_key != ZL_ABI_KEY)
        return ZL_ERR_ABI;
    return (zl_frame_begin)(f, cfg, work, work_bytes, clear_color, clear_depth);
}

const char *zl_status_string(zl_status s)
{
    switch (s) {
    case ZL_OK:
        return "ok";
    case ZL_DONE:
        return "done: every row of the frame has been produced";
    case ZL_ERR_ARG:
        return "invalid argument: a NULL pointer, an unknown enum value or a call out of order";
    case ZL_ERR_RANGE:
        return "a number outside its documented range";
    case ZL_ERR_SIZE:
        return "a buffer or dimension too small or too large";
    case ZL_ERR_CAPACITY:
        return "the scene needs more than the frame was sized for";
    case ZL_ERR_IO:
        return "the display bus reported a failed or timed-out transfer";
    case ZL_ERR_ABI:
        return "application and zline library disagree on struct sizes or configuration "
               "(zl_config.h macros, compiler or ABI flags): build both with the same";
    case ZL_ERR_UNSUPPORTED:
        return "a feature this build of the zline library leaves out (zl_config.h)";
    }
    return "unknown status";
}

/* SPDX-License-Identifier: MIT */
/*
 * zline compile-time options.
 *
 * Every option is an #ifndef block: set it with -D on the compiler command
 * line (or in a header named by ZL_CONFIG_HEADER), never by editing this file.
 */
#ifndef ZLINE_CONFIG_H
#define ZLINE_CONFIG_H

#ifdef ZL_CONFIG_HEADER
#include ZL_CONFIG_HEADER
#endif

/*
 * ZL_SUBPIXEL_BITS: fractional bits of window x and y. Vertices snap to
 * 1/2^bits pixel. Default 4 (1/16 pixel). Range 0..6: more bits shrink the
 * coordinate range the edge steppers can hold in 32 bits.
 */
#ifndef ZL_SUBPIXEL_BITS
#define ZL_SUBPIXEL_BITS 4
#endif
#if ZL_SUBPIXEL_BITS < 0 || ZL_SUBPIXEL_BITS > 6
#error "ZL_SUBPIXEL_BITS must be in 0..6"
#endif

/*
 * ZL_GUARD_PX: the guard band, in pixels, on each side of the viewport.
 * Geometry is clipped against x/y planes only this far outside the viewport,
 * so triangles reaching less far than this are rasterised unclipped and
 * cover exactly the in-viewport pixels of the whole triangle. With the
 * window limit ZL_MAX_DIM the largest window coordinate is
 * (ZL_MAX_DIM + ZL_GUARD_PX) * 2^ZL_SUBPIXEL_BITS, which must stay below
 * 2^23 so edge setup products fit in 64 bits and steppers in 32 bits.
 */
#ifndef ZL_GUARD_PX
#define ZL_GUARD_PX 131072
#endif

/* ZL_MAX_DIM: largest width or height of a render target, in pixels. */
#ifndef ZL_MAX_DIM
#define ZL_MAX_DIM 4096
#endif

#if ((ZL_MAX_DIM + ZL_GUARD_PX) << ZL_SUBPIXEL_BITS) > (1L << 23)
#error "ZL_GUARD_PX + ZL_MAX_DIM too large for ZL_SUBPIXEL_BITS"
#endif

/*
 * ZL_DRAW_CACHE_SLOTS: entries of zl_draw_mesh's own post-transform vertex
 * cache, used when the caller gives no vertex cache (zl_context.vertex_cache
 * NULL or too small). Direct-mapped by vertex index; each entry costs 14
 * bytes of zl_context (a 12-byte window vertex and a 2-byte tag), plus 144
 * bytes for the draw's transform set-up: the default 1024 is 14480 bytes
 * (zl_context is frame mode's, next to a full colour and depth target). A
 * power of two from 2 to 32768, or 0 for no cache (then each triangle
 * transforms and clips its own three vertices: slower, the same pixels). Measured on the bunny (docs/MEASUREMENTS.md, Cortex-M4):
 * smaller caches miss more often, each miss is one vertex transform.
 * zl_context's layout depends on it: the library and its callers must be
 * built with the same value.
 */
#ifndef ZL_DRAW_CACHE_SLOTS
#define ZL_DRAW_CACHE_SLOTS 1024
#endif
#if ZL_DRAW_CACHE_SLOTS != 0 && \
    (ZL_DRAW_CACHE_SLOTS < 2 || ZL_DRAW_CACHE_SLOTS > 32768 || (ZL_DRAW_CACHE_SLOTS & (ZL_DRAW_CACHE_SLOTS - 1)) != 0)
#error "ZL_DRAW_CACHE_SLOTS must be 0 or a power of two from 2 to 32768"
#endif

/*
 * ZL_ASSERT(x): internal consistency checks. Off by default (the library
 * validates every argument itself and returns an error); define it to your
 * platform's assert to catch bugs in zline during development.
 */
#ifndef ZL_ASSERT
#define ZL_ASSERT(x) ((void)0)
#endif

#endif /* ZLINE_CONFIG_H */

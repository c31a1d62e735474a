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
/* The configuration a CMake build of the library recorded (ZLINE_CONFIG):
 * the CMake package and zline.pc define ZL_BUILD_CONFIG for every consumer. */
#ifdef ZL_BUILD_CONFIG
#include "zline/zl_build_config.h"
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
 * ZL_DRAW_CACHE_SLOTS: entries of zl_draw_mesh's post-transform vertex
 * cache, used when the caller gives no vertex cache (zl_context.vertex_cache
 * NULL or too small) but a draw cache (zl_context.draw_cache, caller memory
 * of zl_draw_cache_bytes() bytes). Direct-mapped by vertex index; each entry
 * costs 14 bytes (a 12-byte window vertex and a 2-byte tag), plus 144 bytes
 * for the draw's transform set-up: the default 1024 is 14480 bytes. A power
 * of two from 2 to 32768, or 0 for no cache (then each triangle transforms
 * and clips its own three vertices: slower, the same pixels; so does a draw
 * given no draw cache). Measured on the bunny (docs/MEASUREMENTS.md,
 * Cortex-M4): smaller caches miss more often, each miss is one vertex
 * transform. It does not change zl_context (issue 23): a caller compiled
 * with another value gets zl_draw_cache_bytes() from the library, and a
 * draw cache smaller than that is not used.
 */
#ifndef ZL_DRAW_CACHE_SLOTS
#define ZL_DRAW_CACHE_SLOTS 1024
#endif
#if ZL_DRAW_CACHE_SLOTS != 0 && \
    (ZL_DRAW_CACHE_SLOTS < 2 || ZL_DRAW_CACHE_SLOTS > 32768 || (ZL_DRAW_CACHE_SLOTS & (ZL_DRAW_CACHE_SLOTS - 1)) != 0)
#error "ZL_DRAW_CACHE_SLOTS must be 0 or a power of two from 2 to 32768"
#endif

/*
 * ZL_SMALL_TRIANGLE_SETUP: 1 lets small triangles take the compact 32-bit
 * set-up of zl_setup_fast.c (zl_tiny_*), 0 sends them to the general one
 * (the same pixels). Default 1 where int has 32 bits or more, 0 where it has
 * 16 (AVR, MSP430): there the set-up's 32-bit products are library calls, it
 * costs about 54 KB of ATmega2560 code at -Os, and before issue 23 a 16-bit
 * shift in its range check (1u << 25) kept it unreachable there anyway.
 */
#ifndef ZL_SMALL_TRIANGLE_SETUP
#include <limits.h>
#if INT_MAX > 32767
#define ZL_SMALL_TRIANGLE_SETUP 1
#else
#define ZL_SMALL_TRIANGLE_SETUP 0
#endif
#endif

/*
 * ZL_FAST_SPANS: 1 gives the common textured and blended RGB565 spans their
 * own loops (zl_span_tex.c and the texture loops of zl_rows_styled.c), 0
 * sends them to the general loop: the same pixels (the texture, blending
 * and path tests run in both configurations: tests/CMakeLists.txt's
 * *_small_code), less code, slower. Default 1 where int has 32 bits or
 * more, 0 where it has 16 (AVR: the ATmega2560 firmware of CTest
 * arduino_qemu_mega2560 went from 104 bytes over its 256 KB of flash to
 * 220,376 bytes with them left out).
 */
#ifndef ZL_FAST_SPANS
#include <limits.h>
#if INT_MAX > 32767
#define ZL_FAST_SPANS 1
#else
#define ZL_FAST_SPANS 0
#endif
#endif

/*
 * ZL_FAST_PATHS: 1 (the default) keeps the copies of the common paths that
 * buy speed with flash:
 * - vertices: the 32-bit transform (vx_fast) and the prepared one
 *   (vx_cache) beside the definition (cache_vertex_generic), the bound
 *   that spares zl_check_positions a transform a vertex, the 32-bit face
 *   normal beside the 64-bit one, a copy of the clip-plane distance in
 *   each file that clips (one compact copy without), a second copy of the
 *   face shading, the depth division in short digits (depth_q16);
 * - arithmetic: ARMv6-M's 32-bit forms of 64-bit products (ZL_MUL32_ONLY
 *   defaults to 0 without), the sine table (without: its nodes from a
 *   polynomial, the same values, zl_fixed.c), small 64-bit helpers copied
 *   into their callers (without: out of line, ZL_SMALL_NOINLINE);
 * - set-up: cached flat triangles in 32 bits (setup_flat_32), attribute
 *   planes of small triangles in 32 bits (plane_fast) and their divisions
 *   by 64-by-32 reciprocals (muldiv_pow2);
 * - clears: zl_fill16's block stores, zl_clear's one fill of a target
 *   whose rows have no gaps;
 * - frame mode: the loops over the vertex cache for plain flat and Gouraud
 *   draws (draw_plain, draw_plain_gouraud), the all-rows loop of flat
 *   triangles (zl_tri_rows_flat);
 * - spans: the RGB565 LESS / LEQUAL loops of flat rows and spans
 *   (rows_flat_565, span_flat_565 / _exact) and the packed Gouraud lanes
 *   (lanes_fast, lanes_generic);
 * - scanline mode: the planning of a whole frame (zl_frame_plan: the
 *   edge table's first rows kept in idle regions, the bit array of visible
 *   triangles, the inlined classification on the vertex cache) beside
 *   over capacity's windows and their classification on the vertex cache
 *   (zl_frame_rows_cached), the band loop of a planned frame, the set-up
 *   of cached flat triangles (activate_cached), the row walks for LESS,
 *   LEQUAL and unstyled meshes (render_row_less, _lequal, _plain,
 *   activate_plain).
 * 0 sends those vertices, triangles, spans and rows to the general code,
 * and plans every scanline frame as over capacity's are (zl_frame_over.c:
 * a frame that fits is one window, with the same needs and no replan):
 * the same pixels (the *_fast_paths_off tests), slower. With the other
 * knobs of README's minimal-small configuration, Cortex-M0 -O2
 * (ZLINE_CONFIG="..." sh port/cortex-m/bench/measure-m0.sh, with and without
 * ZL_FAST_PATHS=0): the fill scene takes 5.7 times the instructions in
 * frame mode and 6.2 times in scanline mode, the bunny 2.5 times with the
 * vertex cache and 3.0 times in scanline mode, a clear of the target 21.7
 * times. (The bunny's scanline ratio was 1.3 when 0 kept the inlined
 * classification and the unstyled row walk, 2.1 when it kept
 * zl_frame_plan and activate_cached, 2.6 when it kept over capacity's
 * cached classification: dropping them took the minimal-small-frame and
 * minimal-small-scanline rows of README's flash table within 16 KB and the
 * minimal-small row from 32,431 to its figure now.)
 */
#ifndef ZL_FAST_PATHS
#define ZL_FAST_PATHS 1
#endif
#if ZL_FAST_PATHS != 0 && ZL_FAST_PATHS != 1
#error "ZL_FAST_PATHS must be 0 or 1"
#endif

/*
 * Feature switches (issue 23): pay only for what you draw. Each is 1 (the
 * default: compiled in) or 0 (compiled out: the code that draws it is
 * unreachable, so the compiler and the linker's section garbage collection
 * drop it; the API that would use it returns ZL_ERR_UNSUPPORTED).
 *
 *   ZL_FEATURE_TEXTURES  textured triangles and perspective-correct Gouraud
 *                        (zl_style.texture, .persp_gouraud)
 *   ZL_FEATURE_BLEND     alpha and additive blending (zl_style.blend)
 *   ZL_FEATURE_LINES     lines and points (zl_draw_lines, zl_frame_add_lines),
 *                        polygon modes LINE and POINT, antialiased lines
 *   ZL_FEATURE_OUTLINES  outlines (zl_draw_outlines, zl_frame_add_outlines;
 *                        zl_mesh_edges finds no edge)
 *   ZL_FEATURE_DEPTH_MAP the exact depth mapping (zl_state near_z, far_z:
 *                        each vertex's depth from its w, zline.h
 *                        Pseudodepth): off, a state with near_z or far_z
 *                        set is refused (zl_state_check), a camera's depth
 *                        planes are not applied (zl_camera.h), and the
 *                        depth is the matrix's z / w. Needs to be on for
 *                        ZL_FEATURE_EXACT_DEPTH.
 *   ZL_FEATURE_EXACT_DEPTH  with the exact depth mapping (zl_state near_z,
 *                        far_z), the depth plane through the unsnapped
 *                        vertices (issue 22: within +-1 of exact at every
 *                        pixel). It keeps 4 bytes more a cached vertex
 *                        (ZL_VERTEX_CACHE_BYTES: 12 instead of 8; the
 *                        scanline bunny's work buffer 35,464 bytes instead
 *                        of 28,104). Off, the plane goes through the
 *                        snapped vertices whatever the mapping (zline.h,
 *                        Pseudodepth); nothing returns ZL_ERR_UNSUPPORTED.
 *   ZL_FEATURE_EXACT_CLIP  a triangle that clipping cuts keeps the depth,
 *                        colour and texture planes of the original triangle
 *                        (zline.h, Clipping: 256-bit homogeneous solves,
 *                        zl_clip_planes.c; README's flash table has its
 *                        cost: rows minimal-small, -exact-clip).
 *                        Off, each fan piece is set up as an unclipped
 *                        triangle through its snapped vertices, with the
 *                        depth and colour the clipper gives them (zline.h,
 *                        Clipping, for the bound); nothing returns
 *                        ZL_ERR_UNSUPPORTED.
 *   ZL_FEATURE_LIGHTING  the state's light (zl_state.light_on, ambient,
 *                        light_dir): off, a state with light_on set is
 *                        refused (zl_state_check)
 *   ZL_FEATURE_OFFSET    polygon offset (zl_style.offset_factor,
 *                        .offset_units; outlines are then drawn unmoved)
 *   ZL_FEATURE_DEPTH_FUNCS  the depth functions beyond ZL_LESS and ZL_LEQUAL:
 *                        off, zl_state.depth_func must be one of those two
 *                        or ZL_ALWAYS (which costs nothing: the loops of
 *                        depth_test 0 take it) when depth_test is set
 *   ZL_FEATURE_FORMATS   the colour formats beyond RGB565 (ZL_FORMAT_RGB565
 *                        and _RGB565_BE, what panels take, stay): off, an
 *                        RGB888 target or frame is refused (zl_init,
 *                        zl_frame_begin; the
 *                        visibility methods and the overlay, with pixel
 *                        code of their own, keep every format)
 *   ZL_FEATURE_SPLIT     a scanline frame split across two cores
 *                        (zl_frame_split, zl_frame_prepare,
 *                        zl_frame_config.parts = 2: refused when off)
 *
 * Off, a style (a state, a format) that asks for the feature makes every
 * draw and submission with it return ZL_ERR_UNSUPPORTED (zl_style_check,
 * zl_state_check). Flat and Gouraud triangles, frame, band and scanline
 * modes and the visibility methods (their own API, linked only when
 * called) stay.
 */
#ifndef ZL_FEATURE_TEXTURES
#define ZL_FEATURE_TEXTURES 1
#endif
#ifndef ZL_FEATURE_BLEND
#define ZL_FEATURE_BLEND 1
#endif
#ifndef ZL_FEATURE_LINES
#define ZL_FEATURE_LINES 1
#endif
#ifndef ZL_FEATURE_OUTLINES
#define ZL_FEATURE_OUTLINES 1
#endif
#ifndef ZL_FEATURE_DEPTH_MAP
#define ZL_FEATURE_DEPTH_MAP 1
#endif
#ifndef ZL_FEATURE_EXACT_DEPTH
#define ZL_FEATURE_EXACT_DEPTH ZL_FEATURE_DEPTH_MAP
#endif
#ifndef ZL_FEATURE_EXACT_CLIP
#define ZL_FEATURE_EXACT_CLIP 1
#endif
#ifndef ZL_FEATURE_LIGHTING
#define ZL_FEATURE_LIGHTING 1
#endif
#ifndef ZL_FEATURE_OFFSET
#define ZL_FEATURE_OFFSET 1
#endif
#ifndef ZL_FEATURE_DEPTH_FUNCS
#define ZL_FEATURE_DEPTH_FUNCS 1
#endif
#ifndef ZL_FEATURE_FORMATS
#define ZL_FEATURE_FORMATS 1
#endif
#ifndef ZL_FEATURE_SPLIT
#define ZL_FEATURE_SPLIT 1
#endif
#if (ZL_FEATURE_TEXTURES != 0 && ZL_FEATURE_TEXTURES != 1) || (ZL_FEATURE_BLEND != 0 && ZL_FEATURE_BLEND != 1) || \
    (ZL_FEATURE_LINES != 0 && ZL_FEATURE_LINES != 1) || (ZL_FEATURE_OUTLINES != 0 && ZL_FEATURE_OUTLINES != 1) || \
    (ZL_FEATURE_EXACT_DEPTH != 0 && ZL_FEATURE_EXACT_DEPTH != 1) ||                                              \
    (ZL_FEATURE_LIGHTING != 0 && ZL_FEATURE_LIGHTING != 1) || (ZL_FEATURE_OFFSET != 0 && ZL_FEATURE_OFFSET != 1) || \
    (ZL_FEATURE_DEPTH_FUNCS != 0 && ZL_FEATURE_DEPTH_FUNCS != 1) ||                                              \
    (ZL_FEATURE_FORMATS != 0 && ZL_FEATURE_FORMATS != 1) || (ZL_FEATURE_SPLIT != 0 && ZL_FEATURE_SPLIT != 1) || \
    (ZL_FEATURE_DEPTH_MAP != 0 && ZL_FEATURE_DEPTH_MAP != 1) ||                                                  \
    (ZL_FEATURE_EXACT_CLIP != 0 && ZL_FEATURE_EXACT_CLIP != 1)
#error "each ZL_FEATURE_* must be 0 or 1"
#endif
#if ZL_FEATURE_EXACT_DEPTH && !ZL_FEATURE_DEPTH_MAP
#error "ZL_FEATURE_EXACT_DEPTH needs ZL_FEATURE_DEPTH_MAP (the exact plane is the mapping's)"
#endif

/*
 * ZL_FEATURES: the feature set compiled in, one bit a switch above. Part of
 * ZL_ABI_KEY (zline.h), so an application and a library built with
 * different feature sets fail zl_init with ZL_ERR_ABI.
 */
#define ZL_FEATURES                                                                                       \
    ((unsigned)ZL_FEATURE_TEXTURES | ((unsigned)ZL_FEATURE_BLEND << 1) | ((unsigned)ZL_FEATURE_LINES << 2) | \
     ((unsigned)ZL_FEATURE_OUTLINES << 3) | ((unsigned)ZL_FEATURE_EXACT_DEPTH << 4) |                      \
     ((unsigned)ZL_FEATURE_LIGHTING << 5) | ((unsigned)ZL_FEATURE_OFFSET << 6) |                           \
     ((unsigned)ZL_FEATURE_DEPTH_FUNCS << 7) | ((unsigned)ZL_FEATURE_FORMATS << 8) |                      \
     ((unsigned)ZL_FEATURE_SPLIT << 9) | ((unsigned)ZL_FEATURE_DEPTH_MAP << 10) |                        \
     ((unsigned)ZL_FEATURE_EXACT_CLIP << 11))

/*
 * ZL_MESH_READ_FIXED(p), ZL_MESH_READ_U16(p), ZL_MESH_READ_U8(p): how the
 * triangle pipeline reads one element of a zl_mesh's arrays; p is a
 * const zl_fixed * into positions, a const uint16_t * into indices, a
 * const uint8_t * into vertex_colors or face_colors. Default: a plain read,
 * *(p), the same object code as before the hook (issue 23). For a target
 * whose data pointers cannot reach where its meshes are kept: the 8 KB
 * ATmega2560 keeps its mesh in flash (PROGMEM) and reads it with
 * pgm_read_dword, _word and _byte (port/avr/zl_avr_flash.h, named by
 * ZL_CONFIG_HEADER). Define all three or none. With them defined, every
 * mesh given to the covered calls must be where they read:
 *   covered      zl_frame_add_mesh, zl_frame_add_mesh_styled,
 *                zl_frame_add_mesh_camera and the bands of zl_frame_render /
 *                zl_frame_next_band (scanline and band mode, over capacity
 *                too); zl_draw_mesh and zl_draw_mesh_camera (CTest
 *                mesh_read_hook checks these with a hook that decodes
 *                scrambled meshes);
 *   not covered  the calls of zl_visibility.h, zl_sizing.h and
 *                zl_face_light.h, and zl_mesh_edges: they read the arrays
 *                directly, so do not call them in such a build; nor the
 *                arrays of zl_style (texture coordinates) and textures;
 *   compiled out lines and outlines share the vertex stage's reads with
 *                their own arrays, so a build that defines the hook must set
 *                ZL_FEATURE_LINES and ZL_FEATURE_OUTLINES to 0 (#error).
 * Only the library's sources expand it: what matters is how the library
 * was built, and the application keeps its meshes where that build reads.
 */
#if defined(ZL_MESH_READ_FIXED) || defined(ZL_MESH_READ_U16) || defined(ZL_MESH_READ_U8)
#if !defined(ZL_MESH_READ_FIXED) || !defined(ZL_MESH_READ_U16) || !defined(ZL_MESH_READ_U8)
#error "define all three of ZL_MESH_READ_FIXED, ZL_MESH_READ_U16 and ZL_MESH_READ_U8, or none"
#endif
#if ZL_FEATURE_LINES || ZL_FEATURE_OUTLINES
#error "ZL_MESH_READ_* needs ZL_FEATURE_LINES 0 and ZL_FEATURE_OUTLINES 0"
#endif
#else
#define ZL_MESH_READ_FIXED(p) (*(p))
#define ZL_MESH_READ_U16(p) (*(p))
#define ZL_MESH_READ_U8(p) (*(p))
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

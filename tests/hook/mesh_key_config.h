/* SPDX-License-Identifier: MIT */
/*
 * zline configuration of tests/hook/mesh_read_hook.c (ZL_CONFIG_HEADER):
 * zl_config.h's mesh read hook decodes meshes stored scrambled. With
 * zt_mesh_key 0 it reads them as they are; with a key, positions are stored
 * XORed with a mask of low bits, indices mirrored (i as vertices - 1 - i)
 * and colours XORed: a read that bypasses the hook gets another position,
 * vertex or colour, so the pixels change.
 */
#ifndef ZT_MESH_KEY_CONFIG_H
#define ZT_MESH_KEY_CONFIG_H

#include <stdint.h>

extern uint32_t zt_mesh_key;      /* 0: plain reads */
extern uint16_t zt_mesh_vertices; /* vertex_count of the mesh being drawn */

#define ZT_POSITION_MASK UINT32_C(0x00015555)
#define ZL_MESH_READ_FIXED(p) ((int32_t)((uint32_t) * (p) ^ (zt_mesh_key != 0 ? ZT_POSITION_MASK : 0u)))
#define ZL_MESH_READ_U16(p) ((uint16_t)(zt_mesh_key != 0 ? zt_mesh_vertices - 1u - *(p) : *(p)))
#define ZL_MESH_READ_U8(p) ((uint8_t)(*(p) ^ (uint8_t)zt_mesh_key))

#endif

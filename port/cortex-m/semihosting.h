/* SPDX-License-Identifier: MIT */
/*
 * ARM semihosting for the Cortex-M port: the debugger (here QEMU with
 * -semihosting-config enable=on) services a "bkpt 0xab" with r0 = operation
 * and r1 = a pointer to the arguments. Calls only work under a debugger or
 * QEMU with semihosting enabled; on a bare board they stop the core.
 *
 * Operations and numbers: "Semihosting for AArch32 and AArch64", ARM, v2.0.
 */
#ifndef ZL_SEMIHOSTING_H
#define ZL_SEMIHOSTING_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* SYS_OPEN modes: the index of the fopen() mode string in
 * {"r","rb","r+","r+b","w","wb","w+","w+b","a","ab","a+","a+b"}. */
enum {
    ZL_SEMI_MODE_R = 0,
    ZL_SEMI_MODE_RB = 1,
    ZL_SEMI_MODE_W = 4,
    ZL_SEMI_MODE_WB = 5,
    ZL_SEMI_MODE_A = 8,
    ZL_SEMI_MODE_AB = 9
};

/* The raw call: returns r0 after the bkpt. */
int zl_semi_call(int op, void *arg);

/* Print a NUL-terminated string on the host console (SYS_WRITE0). */
void zl_semi_puts(const char *s);

/* Print len bytes on the host console (no NUL needed). */
void zl_semi_write_console(const void *buf, size_t len);

/* Open a host file, path relative to QEMU's working directory (CTest runs
 * tests in their build directory). Returns a handle >= 0 or -1. */
int zl_semi_open(const char *path, int mode);
/* Write len bytes; returns 0 when all were written, -1 otherwise. */
int zl_semi_write(int handle, const void *buf, size_t len);
/* Read up to len bytes; returns the number read (0 at end of file), -1 on error. */
long zl_semi_read(int handle, void *buf, size_t len);
/* Seek to an absolute position; 0 or -1. */
int zl_semi_seek(int handle, long pos);
/* Length of an open file in bytes, or -1. */
long zl_semi_flen(int handle);
/* 1 when the handle is the host console. */
int zl_semi_istty(int handle);
int zl_semi_close(int handle);

/* Write a whole host file in one go (create or truncate, binary).
 * Returns 0 on success, -1 on any failure. For sending images out. */
int zl_semi_write_file(const char *path, const void *data, size_t len);

/* Stop the program: QEMU exits with code & 0xff (SYS_EXIT_EXTENDED). */
void zl_semi_exit(int code) __attribute__((noreturn));

#ifdef __cplusplus
}
#endif

#endif

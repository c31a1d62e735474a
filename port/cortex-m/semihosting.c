/* SPDX-License-Identifier: MIT */
/* ARM semihosting calls; see semihosting.h. */
#include "semihosting.h"

#include <stdint.h>
#include <string.h>

enum {
    SYS_OPEN = 0x01,
    SYS_CLOSE = 0x02,
    SYS_WRITE0 = 0x04,
    SYS_WRITE = 0x05,
    SYS_READ = 0x06,
    SYS_ISTTY = 0x09,
    SYS_SEEK = 0x0a,
    SYS_FLEN = 0x0c,
    SYS_EXIT = 0x18,
    SYS_EXIT_EXTENDED = 0x20
};

/* ADP_Stopped_ApplicationExit: the reason code of a normal exit. */
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u

int zl_semi_call(int op, void *arg)
{
    register int r0 __asm__("r0") = op;
    register void *r1 __asm__("r1") = arg;
    /* "memory": the host reads and writes the argument block and buffers. */
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void zl_semi_puts(const char *s)
{
    zl_semi_call(SYS_WRITE0, (void *)(uintptr_t)s);
}

void zl_semi_write_console(const void *buf, size_t len)
{
    /* SYS_WRITE0 needs a NUL: copy through a small buffer. */
    const char *p = buf;
    char chunk[65];
    while (len > 0) {
        size_t n = len < sizeof chunk - 1 ? len : sizeof chunk - 1;
        size_t i, k = 0;
        for (i = 0; i < n; i++) {
            if (p[i] != '\0')
                chunk[k++] = p[i];
        }
        chunk[k] = '\0';
        zl_semi_puts(chunk);
        p += n;
        len -= n;
    }
}

int zl_semi_open(const char *path, int mode)
{
    uintptr_t args[3];
    args[0] = (uintptr_t)path;
    args[1] = (uintptr_t)mode;
    args[2] = strlen(path);
    return zl_semi_call(SYS_OPEN, args);
}

int zl_semi_write(int handle, const void *buf, size_t len)
{
    uintptr_t args[3];
    args[0] = (uintptr_t)handle;
    args[1] = (uintptr_t)buf;
    args[2] = len;
    /* Returns the number of bytes NOT written. */
    return zl_semi_call(SYS_WRITE, args) == 0 ? 0 : -1;
}

long zl_semi_read(int handle, void *buf, size_t len)
{
    uintptr_t args[3];
    int left;
    args[0] = (uintptr_t)handle;
    args[1] = (uintptr_t)buf;
    args[2] = len;
    /* Returns the number of bytes NOT read; -1 is an error. */
    left = zl_semi_call(SYS_READ, args);
    if (left < 0 || (size_t)left > len)
        return -1;
    return (long)(len - (size_t)left);
}

int zl_semi_seek(int handle, long pos)
{
    uintptr_t args[2];
    args[0] = (uintptr_t)handle;
    args[1] = (uintptr_t)pos;
    return zl_semi_call(SYS_SEEK, args) == 0 ? 0 : -1;
}

long zl_semi_flen(int handle)
{
    uintptr_t args[1];
    args[0] = (uintptr_t)handle;
    return zl_semi_call(SYS_FLEN, args);
}

int zl_semi_istty(int handle)
{
    uintptr_t args[1];
    args[0] = (uintptr_t)handle;
    return zl_semi_call(SYS_ISTTY, args) == 1;
}

int zl_semi_close(int handle)
{
    uintptr_t args[1];
    args[0] = (uintptr_t)handle;
    return zl_semi_call(SYS_CLOSE, args) == 0 ? 0 : -1;
}

int zl_semi_write_file(const char *path, const void *data, size_t len)
{
    int h = zl_semi_open(path, ZL_SEMI_MODE_WB);
    int rc;
    if (h < 0)
        return -1;
    rc = zl_semi_write(h, data, len);
    if (zl_semi_close(h) != 0)
        rc = -1;
    return rc;
}

void zl_semi_exit(int code)
{
    /* SYS_EXIT_EXTENDED carries the code; plain SYS_EXIT on M-profile only
     * tells "success" from "failure". Both words are read by the host. */
    uintptr_t block[2];
    block[0] = ADP_STOPPED_APPLICATION_EXIT;
    block[1] = (uintptr_t)code;
    zl_semi_call(SYS_EXIT_EXTENDED, block);
    /* A host without SYS_EXIT_EXTENDED: fall back to the plain exit. */
    zl_semi_call(SYS_EXIT, (void *)(uintptr_t)(code == 0 ? ADP_STOPPED_APPLICATION_EXIT : 0x20023u));
    for (;;)
        ;
}

/* SPDX-License-Identifier: MIT */
/*
 * newlib system calls over semihosting: stdout and stderr go to the host
 * console, fopen/fread/fwrite/fseek reach host files (paths relative to
 * QEMU's working directory), malloc gets the RAM between .bss and the stack
 * guard, exit() stops QEMU with its status as the exit code. Anything else
 * comes from libnosys (--specs=nosys.specs) and fails with ENOSYS.
 */
#include <errno.h>
#include <fcntl.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "semihosting.h"

#undef errno
extern int errno;

int _open(const char *path, int flags, ...);
int _close(int fd);
ssize_t _read(int fd, void *buf, size_t len);
ssize_t _write(int fd, const void *buf, size_t len);
off_t _lseek(int fd, off_t offset, int whence);
int _fstat(int fd, struct stat *st);
int _isatty(int fd);
void *_sbrk(ptrdiff_t incr);
int _getpid(void);
int _kill(int pid, int sig);

/* ------------------------------------------------------------------ files */

/* newlib descriptors 0..2 are the console; 3.. index this table of host
 * handles. The position is kept here because SYS_SEEK only seeks to an
 * absolute offset and there is no "tell". */
#define ZL_PORT_MAX_FILES 8
static struct {
    int handle; /* semihosting handle; -1: free */
    long pos;
} files[ZL_PORT_MAX_FILES];
static int files_ready;

static void files_init(void)
{
    int i;
    if (files_ready)
        return;
    for (i = 0; i < ZL_PORT_MAX_FILES; i++)
        files[i].handle = -1;
    files_ready = 1;
}

static int file_slot(int fd)
{
    files_init();
    if (fd < 3 || fd >= 3 + ZL_PORT_MAX_FILES || files[fd - 3].handle < 0) {
        errno = EBADF;
        return -1;
    }
    return fd - 3;
}

int _open(const char *path, int flags, ...)
{
    int mode, i, h;
    files_init();
    /* O_* to the semihosting fopen-style mode, always binary. */
    switch (flags & O_ACCMODE) {
    case O_RDONLY: mode = 1; break;                                   /* rb */
    case O_WRONLY: mode = (flags & O_APPEND) ? 9 : 5; break;          /* ab, wb */
    default: mode = (flags & O_APPEND) ? 11 : (flags & O_TRUNC) ? 7 : 3; break; /* a+b w+b r+b */
    }
    for (i = 0; i < ZL_PORT_MAX_FILES && files[i].handle >= 0; i++)
        ;
    if (i == ZL_PORT_MAX_FILES) {
        errno = EMFILE;
        return -1;
    }
    h = zl_semi_open(path, mode);
    if (h < 0) {
        errno = ENOENT;
        return -1;
    }
    files[i].handle = h;
    files[i].pos = 0;
    if (flags & O_APPEND) {
        long len = zl_semi_flen(h);
        files[i].pos = len > 0 ? len : 0;
    }
    return 3 + i;
}

int _close(int fd)
{
    int s;
    if (fd >= 0 && fd < 3)
        return 0;
    s = file_slot(fd);
    if (s < 0)
        return -1;
    zl_semi_close(files[s].handle);
    files[s].handle = -1;
    return 0;
}

ssize_t _read(int fd, void *buf, size_t len)
{
    long n;
    int s;
    if (fd >= 0 && fd < 3)
        return 0; /* no console input: end of file */
    s = file_slot(fd);
    if (s < 0)
        return -1;
    n = zl_semi_read(files[s].handle, buf, len);
    if (n < 0) {
        errno = EIO;
        return -1;
    }
    files[s].pos += n;
    return (ssize_t)n;
}

ssize_t _write(int fd, const void *buf, size_t len)
{
    int s;
    if (fd == 1 || fd == 2) {
        zl_semi_write_console(buf, len);
        return (ssize_t)len;
    }
    s = file_slot(fd);
    if (s < 0)
        return -1;
    if (zl_semi_write(files[s].handle, buf, len) != 0) {
        errno = EIO;
        return -1;
    }
    files[s].pos += (long)len;
    return (ssize_t)len;
}

off_t _lseek(int fd, off_t offset, int whence)
{
    long base, to;
    int s = file_slot(fd);
    if (s < 0)
        return -1;
    if (whence == SEEK_SET)
        base = 0;
    else if (whence == SEEK_CUR)
        base = files[s].pos;
    else if (whence == SEEK_END)
        base = zl_semi_flen(files[s].handle);
    else
        base = -1;
    to = base + (long)offset;
    if (base < 0 || to < 0 || zl_semi_seek(files[s].handle, to) != 0) {
        errno = EINVAL;
        return -1;
    }
    files[s].pos = to;
    return (off_t)to;
}

int _fstat(int fd, struct stat *st)
{
    /* The console is a character device, so stdout is line buffered. */
    st->st_mode = (fd >= 0 && fd < 3) ? S_IFCHR : S_IFREG;
    st->st_blksize = 0;
    return 0;
}

int _isatty(int fd)
{
    return fd >= 0 && fd < 3;
}

/* ------------------------------------------------------------ heap, exit */

extern char __heap_start[], __heap_end[];

void *_sbrk(ptrdiff_t incr)
{
    static char *brk;
    char *prev;
    if (brk == NULL)
        brk = __heap_start;
    if (incr > __heap_end - brk || incr < __heap_start - brk) {
        errno = ENOMEM;
        return (void *)-1;
    }
    prev = brk;
    brk += incr;
    return prev;
}

void _exit(int status)
{
    /* The host sees status & 0xff: keep a failure a failure. */
    if (status != 0 && (status & 0xff) == 0)
        status = 255;
    zl_semi_exit(status);
}

int _getpid(void)
{
    return 1;
}

int _kill(int pid, int sig)
{
    /* abort() raises SIGABRT on itself: stop like a crash would. */
    if (pid == 1) {
        zl_semi_puts("\n*** killed by signal ");
        {
            char d[4];
            d[0] = (char)('0' + (sig / 10) % 10);
            d[1] = (char)('0' + sig % 10);
            d[2] = '\n';
            d[3] = '\0';
            zl_semi_puts(d);
        }
        _exit(128 + sig);
    }
    errno = EINVAL;
    return -1;
}

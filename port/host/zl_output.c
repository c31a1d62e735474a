/* SPDX-License-Identifier: MIT */
/* The host tools' output rule. See zl_output.h. */
#if !defined(_WIN32) && !defined(_POSIX_C_SOURCE)
#define _POSIX_C_SOURCE 200809L /* lstat, readlink, fchmod, fdopen, getpid */
#endif

#include "zl_output.h"

#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#ifndef _WIN32
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

/* Symbolic links followed before a chain is called a loop (Linux's limit). */
#define MAX_LINK_HOPS 40
#define PATH_BYTES 4096

static void set_msg(char *msg, size_t msg_size, const char *fmt, ...)
{
    va_list ap;
    if (msg == NULL || msg_size == 0)
        return;
    va_start(ap, fmt);
    vsnprintf(msg, msg_size, fmt, ap);
    va_end(ap);
}

static char *dup_string(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = (char *)malloc(n);
    if (d != NULL)
        memcpy(d, s, n);
    return d;
}

/* The folder part of path ("." when it has none) and its last component. */
static int split_path(const char *path, char *dir, size_t dir_size, const char **base)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash != NULL ? (size_t)(slash - path) : 0;
    *base = slash != NULL ? slash + 1 : path;
    if (n + 2 > dir_size)
        return -1;
    if (slash == NULL)
        strcpy(dir, ".");
    else if (n == 0)
        strcpy(dir, "/");
    else {
        memcpy(dir, path, n);
        dir[n] = '\0';
    }
    return 0;
}

/*
 * The file a write to path lands in: path itself, or the final target of the
 * symbolic links it is (relative targets are relative to the link's folder).
 * NULL for a loop or a path too long (errno says which).
 */
static char *link_target(const char *path)
{
    char *cur = dup_string(path);
#ifndef _WIN32
    unsigned hops;
    for (hops = 0; cur != NULL && hops < MAX_LINK_HOPS; hops++) {
        struct stat st;
        char link[PATH_BYTES], dir[PATH_BYTES];
        const char *base;
        ssize_t n;
        size_t size;
        char *next;
        if (lstat(cur, &st) != 0 || !S_ISLNK(st.st_mode))
            return cur;
        n = readlink(cur, link, sizeof link - 1);
        if (n < 0 || (size_t)n >= sizeof link - 1 || split_path(cur, dir, sizeof dir, &base) != 0) {
            free(cur);
            errno = ENAMETOOLONG;
            return NULL;
        }
        link[n] = '\0';
        size = strlen(dir) + (size_t)n + 2;
        next = (char *)malloc(size);
        if (next != NULL && link[0] == '/') {
            memcpy(next, link, (size_t)n + 1);
        } else if (next != NULL) { /* relative to the link's folder */
            size_t d = strlen(dir);
            memcpy(next, dir, d);
            next[d] = '/';
            memcpy(next + d + 1, link, (size_t)n + 1);
        }
        free(cur);
        cur = next;
    }
    if (cur != NULL) {
        free(cur);
        errno = ELOOP;
        return NULL;
    }
#endif
    return cur;
}

/*
 * Which file a path names: an existing file by its device and inode; a path
 * that does not exist yet by its folder's device and inode and its name.
 */
typedef struct {
    int known;    /* 0: the path could not be resolved (a link loop) */
    int exists;
    int regular;
    int writable;
    unsigned mode;
    unsigned long long dev, ino;
    char base[PATH_BYTES];
} file_id;

static void identify(const char *path, file_id *id)
{
    char *target;
    memset(id, 0, sizeof *id);
    target = link_target(path);
    if (target == NULL)
        return;
    id->known = 1;
#ifndef _WIN32
    {
        struct stat st;
        char dir[PATH_BYTES];
        const char *base;
        if (stat(target, &st) == 0) {
            id->exists = 1;
            id->regular = S_ISREG(st.st_mode);
            /* root may write anything: the permission bits still say read-only */
            id->writable = (st.st_mode & 0222) != 0 && access(target, W_OK) == 0;
            id->mode = (unsigned)(st.st_mode & 07777);
            id->dev = (unsigned long long)st.st_dev;
            id->ino = (unsigned long long)st.st_ino;
        } else if (split_path(target, dir, sizeof dir, &base) == 0 && stat(dir, &st) == 0) {
            id->dev = (unsigned long long)st.st_dev;
            id->ino = (unsigned long long)st.st_ino;
            snprintf(id->base, sizeof id->base, "%s", base);
        } else {
            snprintf(id->base, sizeof id->base, "%s", target); /* no folder: compare spellings */
        }
    }
#else
    snprintf(id->base, sizeof id->base, "%s", target);
    {
        FILE *f = fopen(target, "rb");
        id->exists = f != NULL;
        id->regular = id->writable = f != NULL;
        if (f != NULL)
            fclose(f);
    }
#endif
    free(target);
}

static int same_id(const file_id *x, const file_id *y)
{
    if (!x->known || !y->known || x->exists != y->exists)
        return 0;
    if (x->exists)
        return x->dev == y->dev && x->ino == y->ino;
    return x->dev == y->dev && x->ino == y->ino && strcmp(x->base, y->base) == 0;
}

int zl_output_same_file(const char *a, const char *b)
{
    file_id x, y;
    identify(a, &x);
    identify(b, &y);
    return same_id(&x, &y);
}

/* Rules 2 and 4 for one output. */
static int check_replaceable(const char *path, const file_id *id, char *msg, size_t msg_size)
{
    if (!id->known) {
        set_msg(msg, msg_size, "%s: cannot resolve the output path: %s", path, strerror(errno));
        return -1;
    }
    if (id->exists && !id->regular) {
        set_msg(msg, msg_size,
                "%s is not a regular file (a FIFO, device or folder): refusing to replace it; write to a "
                "file and copy it there",
                path);
        return -1;
    }
    if (id->exists && !id->writable) {
        set_msg(msg, msg_size, "%s is read-only: refusing to replace it", path);
        return -1;
    }
    return 0;
}

int zl_output_check(const char *const *outs, size_t n_outs, const char *const *ins, size_t n_ins, char *msg,
                    size_t msg_size)
{
    size_t i, j;
    for (i = 0; i < n_outs; i++) {
        file_id out;
        if (outs[i] == NULL)
            continue;
        identify(outs[i], &out);
        if (check_replaceable(outs[i], &out, msg, msg_size) != 0)
            return -1;
        for (j = 0; j < n_ins; j++) {
            if (ins[j] != NULL && zl_output_same_file(ins[j], outs[i])) {
                set_msg(msg, msg_size, "refusing to write over the input %s (the output %s is that file)",
                        ins[j], outs[i]);
                return -1;
            }
        }
        for (j = 0; j < i; j++) {
            if (outs[j] != NULL && zl_output_same_file(outs[j], outs[i])) {
                set_msg(msg, msg_size, "the outputs %s and %s are one file", outs[j], outs[i]);
                return -1;
            }
        }
    }
    return 0;
}

void zl_output_discard(zl_output *o)
{
    if (o == NULL)
        return;
    if (o->file != NULL)
        fclose(o->file);
    if (o->tmp_path != NULL)
        remove(o->tmp_path);
    free(o->target);
    free(o->tmp_path);
    memset(o, 0, sizeof *o);
}

/* A new file beside o->target, never an existing one (O_EXCL). */
static FILE *create_temp(zl_output *o, int binary)
{
    size_t n = strlen(o->target) + 48;
    unsigned attempt;
    o->tmp_path = (char *)malloc(n);
    if (o->tmp_path == NULL)
        return NULL;
    for (attempt = 0; attempt < 100; attempt++) {
#ifdef _WIN32
        FILE *f;
        snprintf(o->tmp_path, n, "%s.tmp%u", o->target, attempt);
        f = fopen(o->tmp_path, "rb");
        if (f != NULL) { /* taken: try the next name */
            fclose(f);
            continue;
        }
        return fopen(o->tmp_path, binary ? "wb" : "w");
#else
        int fd;
        FILE *f;
        snprintf(o->tmp_path, n, "%s.tmp%ld-%u", o->target, (long)getpid(), attempt);
        /* 0666 and the umask give the permissions of a file made by fopen;
         * a replaced file's own bits are kept instead. */
        fd = open(o->tmp_path, O_WRONLY | O_CREAT | O_EXCL, 0666);
        if (fd < 0) {
            if (errno == EEXIST)
                continue;
            break;
        }
        if (o->mode != 0)
            (void)fchmod(fd, (mode_t)o->mode);
        f = fdopen(fd, binary ? "wb" : "w");
        if (f == NULL) {
            close(fd);
            remove(o->tmp_path);
        }
        return f;
#endif
    }
    free(o->tmp_path);
    o->tmp_path = NULL;
    return NULL;
}

int zl_output_open(zl_output *o, const char *path, int binary, char *msg, size_t msg_size)
{
    file_id id;
    if (o == NULL || path == NULL) {
        set_msg(msg, msg_size, "zl_output_open: NULL argument");
        return -1;
    }
    memset(o, 0, sizeof *o);
    identify(path, &id);
    if (check_replaceable(path, &id, msg, msg_size) != 0)
        return -1;
    o->target = link_target(path);
    if (o->target == NULL) {
        set_msg(msg, msg_size, "%s: out of memory", path);
        return -1;
    }
    o->mode = id.exists ? id.mode : 0u;
    o->file = create_temp(o, binary);
    if (o->file == NULL) {
        set_msg(msg, msg_size, "%s: cannot create a temporary file beside it: %s", path, strerror(errno));
        zl_output_discard(o);
        return -1;
    }
    return 0;
}

/* Close o's stream; -1 (o released, temporary removed) on a write error. */
static int close_stream(zl_output *o, char *msg, size_t msg_size)
{
    int bad;
    if (o->file == NULL)
        return 0;
    bad = fflush(o->file) != 0 || ferror(o->file);
    bad = fclose(o->file) != 0 || bad;
    o->file = NULL;
    if (bad) {
        set_msg(msg, msg_size, "%s: write error: %s", o->target, strerror(errno));
        zl_output_discard(o);
        return -1;
    }
    return 0;
}

int zl_output_commit_all(zl_output *outs, size_t n, char *msg, size_t msg_size)
{
    size_t k;
    int status = 0;
    for (k = 0; k < n && status == 0; k++)
        status = close_stream(&outs[k], msg, msg_size);
    for (k = 0; k < n && status == 0; k++)
        status = zl_output_commit(&outs[k], msg, msg_size);
    for (k = 0; k < n; k++)
        zl_output_discard(&outs[k]); /* the rest, after a failure */
    return status;
}

int zl_output_commit(zl_output *o, char *msg, size_t msg_size)
{
    if (o == NULL || o->tmp_path == NULL) {
        set_msg(msg, msg_size, "zl_output_commit: no output open");
        return -1;
    }
    if (close_stream(o, msg, msg_size) != 0)
        return -1;
#ifdef _WIN32
    remove(o->target); /* rename does not replace there */
#endif
    if (rename(o->tmp_path, o->target) != 0) {
        set_msg(msg, msg_size, "%s: cannot rename %s to it: %s", o->target, o->tmp_path, strerror(errno));
        zl_output_discard(o);
        return -1;
    }
    free(o->tmp_path);
    o->tmp_path = NULL;
    zl_output_discard(o);
    return 0;
}

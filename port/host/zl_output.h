/* SPDX-License-Identifier: MIT */
/*
 * The output rule of every host tool (zline-render, zline-img2c, zline-obj2c,
 * zline-bsp and any tool added later), in one place (issue 26):
 *
 *  1. An output is never the same file as an input or another output,
 *     compared by device and inode: through symbolic and hard links and
 *     "..", and for a path that does not exist yet by its resolved folder
 *     and name (zl_output_check).
 *  2. Nothing is deleted or replaced that is not a regular file: an output
 *     that exists and is a FIFO, a device or a folder is refused before
 *     anything is written.
 *  3. A symbolic link as an output is followed: its final target is the
 *     file written, and the link stays a link.
 *  4. A read-only output (no write permission bit, or not writable by the
 *     caller) is an error, even for root, who could replace it.
 *  5. The data goes to a new temporary file in the target's folder, which
 *     is renamed over the target only after everything was written
 *     (zl_output_commit). On any failure the previous file is intact and no
 *     temporary is left (zl_output_discard). A replaced file keeps its
 *     permission bits.
 *
 * Host only (POSIX; on Windows files are compared by their spelling).
 */
#ifndef ZL_OUTPUT_H
#define ZL_OUTPUT_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One output being written. Zero-initialise, or let zl_output_open do it. */
typedef struct {
    char *target;   /* the file replaced on commit: the path, or its link's target */
    char *tmp_path; /* the temporary file beside the target */
    FILE *file;     /* open on tmp_path while writing */
    unsigned mode;  /* the permission bits to give the result */
} zl_output;

/*
 * Rules 1, 2 and 4 for a whole command before it writes anything: n_outs
 * output paths (NULL entries skipped) against each other and against n_ins
 * input paths (NULL entries skipped). Returns 0, or -1 with a message that
 * names the paths in msg.
 */
int zl_output_check(const char *const *outs, size_t n_outs, const char *const *ins, size_t n_ins, char *msg,
                    size_t msg_size);

/* Whether two paths name one file (rule 1's comparison; a or b may not exist). */
int zl_output_same_file(const char *a, const char *b);

/*
 * Rules 2 to 5: check the path again and open a new temporary file beside its
 * target, binary when binary != 0. Returns 0 with o->file open, or -1 with
 * the reason in msg (nothing created).
 */
int zl_output_open(zl_output *o, const char *path, int binary, char *msg, size_t msg_size);

/*
 * Close the temporary file and rename it over the target. A write error seen
 * on the stream fails the commit. Returns 0, or -1 with the reason in msg;
 * either way o is released, and on failure the temporary is removed.
 */
int zl_output_commit(zl_output *o, char *msg, size_t msg_size);

/*
 * zl_output_commit for n outputs that belong together (a .c and its .h):
 * every stream is closed and checked before any is renamed, so a write
 * error leaves every previous file intact. Returns 0, or -1 with the reason
 * in msg; every output is released either way.
 */
int zl_output_commit_all(zl_output *outs, size_t n, char *msg, size_t msg_size);

/* Close and remove the temporary file; the target is untouched. Safe on a
 * zeroed or already released output. */
void zl_output_discard(zl_output *o);

#ifdef __cplusplus
}
#endif

#endif

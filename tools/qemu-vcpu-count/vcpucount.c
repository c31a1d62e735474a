/* SPDX-License-Identifier: MIT */
/*
 * vcpucount: QEMU TCG plugin counting the instructions each vCPU executes
 * (issue 27: each core's share of a frame split across the two Cortex-M33
 * of mps2-an521). Every time a vCPU enters the function at `mark` (the
 * firmware's mark(), port/cortex-m/bench/dual.c) the plugin notes that
 * vCPU's count so far; at exit it writes one line per mark,
 *   MARK vcpu k count
 * (k numbers the vCPU's own marks from 0) to `out`. An interval between two
 * marks of a vCPU is the difference of their counts: the instructions that
 * core ran from one call of mark() to the next, mark()'s own included.
 *
 *   qemu-system-arm -M mps2-an521 ... -plugin path/vcpucount.so,mark=0x1234,out=marks.txt
 */
#include <inttypes.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- from QEMU 7.2 include/qemu/qemu-plugin.h (QEMU_PLUGIN_VERSION 1) ---- */
typedef uint64_t qemu_plugin_id_t;
typedef struct qemu_info_t {
    const char *target_name;
    struct {
        int min;
        int cur;
    } version;
    bool system_emulation;
    union {
        struct {
            int smp_vcpus;
            int max_vcpus;
        } system;
    };
} qemu_info_t;
struct qemu_plugin_tb;
enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_CB_R_REGS, QEMU_PLUGIN_CB_RW_REGS };
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_cb(struct qemu_plugin_tb *tb, qemu_plugin_vcpu_udata_cb_t cb,
                                          enum qemu_plugin_cb_flags flags, void *userdata);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
uint64_t qemu_plugin_tb_vaddr(const struct qemu_plugin_tb *tb);
void qemu_plugin_outs(const char *string);
#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))
QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc,
                                           char **argv);
/* ---------------------------------------------------------------------------- */

QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

#define MAX_VCPUS 8
#define MAX_MARKS 4096

/* A translated block: what its execution adds, and whether it is mark().
 * Blocks are never freed: QEMU may execute one until the end. */
typedef struct {
    uint32_t insns;
    bool is_mark;
} block;

/* Per vCPU (each touched only by its own vCPU's thread). */
static uint64_t count[MAX_VCPUS];
static uint64_t marks[MAX_VCPUS][MAX_MARKS];
static unsigned mark_count[MAX_VCPUS];
static uint64_t mark_addr = UINT64_MAX;
static const char *out_path;

static void block_exec(unsigned int vcpu, void *udata)
{
    const block *b = udata;
    if (vcpu >= MAX_VCPUS)
        return;
    if (b->is_mark && mark_count[vcpu] < MAX_MARKS)
        marks[vcpu][mark_count[vcpu]++] = count[vcpu];
    count[vcpu] += b->insns;
}

static void block_trans(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    block *b = malloc(sizeof *b);
    (void)id;
    if (b == NULL)
        return;
    b->insns = (uint32_t)qemu_plugin_tb_n_insns(tb);
    b->is_mark = qemu_plugin_tb_vaddr(tb) == mark_addr;
    qemu_plugin_register_vcpu_tb_exec_cb(tb, block_exec, QEMU_PLUGIN_CB_NO_REGS, b);
}

static void at_exit(qemu_plugin_id_t id, void *userdata)
{
    FILE *f;
    unsigned v, k;
    (void)id;
    (void)userdata;
    if (out_path == NULL || (f = fopen(out_path, "w")) == NULL) {
        qemu_plugin_outs("vcpucount: cannot write the marks (out=FILE)\n");
        return;
    }
    for (v = 0; v < MAX_VCPUS; v++) {
        for (k = 0; k < mark_count[v]; k++)
            fprintf(f, "MARK %u %u %" PRIu64 "\n", v, k, marks[v][k]);
        if (count[v] != 0)
            fprintf(f, "TOTAL %u %" PRIu64 "\n", v, count[v]);
    }
    fclose(f);
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv)
{
    int i;
    if (info->version.cur < 1 || strcmp(info->target_name, "arm") != 0) {
        qemu_plugin_outs("vcpucount: needs qemu-system-arm with plugin API version 1 (QEMU 7.2)\n");
        return -1;
    }
    for (i = 0; i < argc; i++) {
        if (strncmp(argv[i], "mark=", 5) == 0)
            mark_addr = strtoull(argv[i] + 5, NULL, 0) & ~(uint64_t)1; /* Thumb bit off */
        else if (strncmp(argv[i], "out=", 4) == 0)
            out_path = argv[i] + 4;
        else {
            qemu_plugin_outs("vcpucount: arguments: mark=ADDR out=FILE\n");
            return -1;
        }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, block_trans);
    qemu_plugin_register_atexit_cb(id, at_exit, NULL);
    return 0;
}

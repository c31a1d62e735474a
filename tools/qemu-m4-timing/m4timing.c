/* SPDX-License-Identifier: MIT */
/*
 * m4timing: a QEMU TCG plugin that ESTIMATES Cortex-M4 cycles by applying the
 * instruction timing table of the Cortex-M4 Technical Reference Manual
 * (ARM DDI 0439, section 3.3) to every executed Thumb instruction. It is a
 * model, not a measurement: no wait states, no bus contention, and the
 * choices below where the table gives a range.
 *
 *   qemu-system-arm ... -plugin path/m4timing.so,mark=0x1234,out=marks.txt[,p=2][,div=12]
 *       [,profile=FILE[,from=I,to=J]][,any=1]
 *
 * any=1 lets it load into another QEMU (qemu-system-avr for port/avr): its
 * instruction counts hold for any CPU, its cycle estimates for none but the
 * Cortex-M4.
 *
 * Cost model (cycles):
 *   data processing, moves, compares, shifts, extends, IT, hints     1
 *   MUL 1; MLA, MLS 2; SMULL, UMULL, SMLAL, UMLAL and the DSP multiplies 1
 *   SDIV, UDIV: div (default 12, the table's worst case; the table says
 *     2..12 by operand values, which a plugin of QEMU 7.2 cannot read; the
 *     count of divisions is printed, so other values can be applied)
 *   LDR and the other single loads: 2, or 1 when the previous executed
 *     instruction was a single load or store (the TRM's pipelining note)
 *   STR and the other single stores: 1
 *   LDM, STM, PUSH, POP: 1 + N registers; LDRD, STRD: 3; TBB, TBH: 2 + P
 *   branches (B, BL, BX, BLX, CBZ/CBNZ, writes to PC by POP, LDM, LDR,
 *     MOV, ADD): + P when taken, P = p (default 2; the table gives 1..3);
 *     a conditional branch (or one in an IT block) costs 1 when not taken
 * Instructions skipped by a failed IT condition are charged as executed.
 *
 * Counting: per translated block the static cost is summed at translation
 * time; a callback at the start of every executed block adds it, and adds P
 * when the previous block ended in a conditional branch that was taken (the
 * block does not start at its fall-through address). Every time a block
 * starts at `mark` (the benchmark's mark() function, bench.c) the running
 * totals are recorded; at exit they are written to `out` as
 *   MARK index instructions cycles
 * and a final TOTAL line. The instruction counts let a reader check the
 * plugin against QEMU's -icount timer counts of the same intervals.
 *
 * Profile (profile=FILE): executions of every translated block are counted
 * and, at exit, FILE gets one line "PC COUNT" (hex address, decimal count)
 * per guest instruction that ran: COUNT is how many times it executed (an
 * address translated more than once appears once per translation; sum them).
 * With from=I,to=J only blocks executed from the entry of mark number I up to
 * (not including) the entry of mark number J are counted: exactly the
 * instructions that the MARK lines count between those two marks, i.e. the
 * interval with mark()'s own instructions included. A "# total" line gives
 * the sum. port/cortex-m/bench/profile.sh maps the addresses to functions.
 *
 * QEMU 7.2 ships plugin support but Debian installs no qemu-plugin.h: the
 * few declarations used here are copied from QEMU 7.2's API (version 1).
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
struct qemu_plugin_insn;
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
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb, size_t idx);
const void *qemu_plugin_insn_data(const struct qemu_plugin_insn *insn);
size_t qemu_plugin_insn_size(const struct qemu_plugin_insn *insn);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
void qemu_plugin_outs(const char *string);
#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))
QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc,
                                           char **argv);
/* ---------------------------------------------------------------------------- */

QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

enum { END_PLAIN, END_COND, END_ALWAYS };
enum { K_OTHER, K_LOAD, K_STORE };

typedef struct {
    uint64_t vaddr, fallthrough;
    uint64_t cycles;     /* static cost, pipelining inside the block included */
    uint32_t insns, divs;
    uint8_t end;         /* END_*: how the last instruction leaves the block */
    uint8_t first_kind;  /* K_* of the first instruction */
    uint8_t last_kind;   /* K_* of the last one */
    uint64_t execs;      /* executions while profiling */
    uint32_t *pcs;       /* instruction addresses, for the profile */
} block;

static unsigned penalty = 2, div_cycles = 12;
static uint64_t mark_addr = UINT64_MAX;
static const char *out_path = "m4timing.txt";
static const char *profile_path;
static long prof_from = -1, prof_to = -1; /* mark numbers; -1: whole run */
static int profiling = 1;
static block **blocks;
static size_t block_count, block_cap;

static uint64_t insns, cycles, divs, taken;
static const block *prev;
typedef struct {
    uint64_t insns, cycles;
} stamp;
static stamp *marks;
static size_t mark_count, mark_cap;

static unsigned popcount16(unsigned v)
{
    unsigned n = 0;
    for (v &= 0xFFFFu; v; v &= v - 1)
        n++;
    return n;
}

typedef struct {
    unsigned cost; /* without branch penalties */
    int kind;      /* K_* */
    int branch;    /* 0, END_COND (taken or not), END_ALWAYS */
    int div;
    unsigned it;   /* instructions in the IT block this one opens */
} insn_class;

/* Classify one Thumb instruction (hw1, and hw2 for a 32-bit one). */
static insn_class classify(unsigned hw1, unsigned hw2, int wide)
{
    insn_class c = {1, K_OTHER, 0, 0, 0};
    if (!wide) {
        unsigned op6 = hw1 >> 10;
        if ((hw1 & 0xFFC0) == 0x4340) {                  /* MULS */
            c.cost = 1;
        } else if ((hw1 & 0xFF00) == 0x4700) {           /* BX, BLX register */
            c.branch = END_ALWAYS;
        } else if ((hw1 & 0xFD00) == 0x4400) {           /* ADD, MOV high registers */
            if (((hw1 >> 4) & 8u) + (hw1 & 7u) == 15)
                c.branch = END_ALWAYS;                   /* to PC */
        } else if (op6 == 0x12 || op6 == 0x13) {         /* LDR literal */
            c.kind = K_LOAD;
        } else if ((hw1 >> 12) == 0x5) {                 /* load/store register offset */
            unsigned opb = (hw1 >> 9) & 7u;
            c.kind = opb < 3 ? K_STORE : K_LOAD;
        } else if ((hw1 >> 13) == 0x3 || (hw1 >> 12) == 0x8 || (hw1 >> 12) == 0x9) {
            c.kind = (hw1 & 0x0800) ? K_LOAD : K_STORE;  /* immediate offset, SP-relative */
        } else if ((hw1 & 0xF500) == 0xB100) {           /* CBZ, CBNZ */
            c.branch = END_COND;
        } else if ((hw1 & 0xFE00) == 0xB400) {           /* PUSH */
            c.cost = 1 + popcount16(hw1 & 0x1FF);
        } else if ((hw1 & 0xFE00) == 0xBC00) {           /* POP */
            c.cost = 1 + popcount16(hw1 & 0x1FF);
            if (hw1 & 0x100)
                c.branch = END_ALWAYS;
        } else if ((hw1 & 0xFF00) == 0xBF00 && (hw1 & 0xF)) { /* IT */
            unsigned mask = hw1 & 0xF;
            c.it = mask & 1 ? 4 : mask & 2 ? 3 : mask & 4 ? 2 : 1;
        } else if ((hw1 >> 12) == 0xC) {                 /* LDM, STM */
            c.cost = 1 + popcount16(hw1 & 0xFF);
        } else if ((hw1 >> 12) == 0xD && ((hw1 >> 9) & 7u) != 7) { /* B<cond> */
            c.branch = END_COND;
        } else if ((hw1 >> 11) == 0x1C) {                /* B */
            c.branch = END_ALWAYS;
        }
        return c;
    }
    if ((hw1 & 0xFE40) == 0xE800) {                      /* LDM, STM (T2) */
        c.cost = 1 + popcount16(hw2);
        if ((hw1 & 0x0010) && (hw2 & 0x8000))
            c.branch = END_ALWAYS;
    } else if ((hw1 & 0xFE40) == 0xE840) {               /* dual, exclusive, table branch */
        if ((hw1 & 0xFFF0) == 0xE8D0 && (hw2 & 0xFFE0) == 0xF000) {
            c.cost = 2;                                  /* TBB, TBH */
            c.branch = END_ALWAYS;
        } else if (hw1 & 0x0120) {
            c.cost = 3;                                  /* LDRD, STRD */
        } else {
            c.cost = 2;                                  /* LDREX, STREX */
        }
    } else if ((hw1 >> 11) == 0x1E && (hw2 & 0x8000)) {  /* branches, misc control */
        if ((hw2 & 0xD000) == 0x8000) {
            if (((hw1 >> 7) & 7u) != 7)
                c.branch = END_COND;                     /* B<cond> T3 */
        } else if ((hw2 & 0xD000) == 0x9000 || (hw2 & 0xD000) == 0xD000) {
            c.branch = END_ALWAYS;                       /* B T4, BL */
        }
    } else if ((hw1 & 0xFE10) == 0xF800) {               /* STR, STRB, STRH */
        c.kind = K_STORE;
    } else if ((hw1 & 0xFE10) == 0xF810) {               /* single loads (0xF8x1, 0xF9x1) */
        c.kind = K_LOAD;
        if ((hw2 >> 12) == 15 && ((hw1 >> 5) & 3u) == 2)
            c.branch = END_ALWAYS;                       /* LDR PC */
    } else if ((hw1 & 0xFF80) == 0xFB00) {               /* multiply, multiply-accumulate */
        unsigned op1 = (hw1 >> 4) & 7u, op2 = (hw2 >> 4) & 3u;
        if (op1 == 0 && (op2 == 1 || (op2 == 0 && (hw2 >> 12) != 15)))
            c.cost = 2;                                  /* MLS, MLA */
    } else if ((hw1 & 0xFF80) == 0xFB80) {               /* long multiply, divide */
        unsigned op1 = (hw1 >> 4) & 7u;
        if (op1 == 1 || op1 == 3) {
            c.cost = div_cycles;
            c.div = 1;
        }
    }
    /* everything else (data processing, shifts, extends, moves): 1 */
    return c;
}

static void block_exec(unsigned int vcpu, void *udata)
{
    block *b = (block *)udata;
    (void)vcpu;
    if (prev != NULL) {
        if (prev->end == END_COND && b->vaddr != prev->fallthrough) {
            cycles += penalty;
            taken++;
        }
        if (prev->last_kind != K_OTHER && b->first_kind == K_LOAD)
            cycles -= 1; /* a load right after a load/store, across blocks */
    }
    if (b->vaddr == mark_addr) {
        if (mark_count == mark_cap) {
            mark_cap = mark_cap ? 2 * mark_cap : 1024;
            marks = realloc(marks, mark_cap * sizeof *marks);
            if (marks == NULL)
                abort();
        }
        marks[mark_count].insns = insns;
        marks[mark_count].cycles = cycles;
        if (prof_from >= 0)
            profiling = (long)mark_count >= prof_from && (long)mark_count < prof_to;
        mark_count++;
    }
    if (profiling)
        b->execs++;
    insns += b->insns;
    cycles += b->cycles;
    divs += b->divs;
    prev = b;
}

static void block_trans(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    size_t i, n = qemu_plugin_tb_n_insns(tb);
    block *b = calloc(1, sizeof *b);
    int prev_kind = K_OTHER;
    unsigned it_left = 0;
    (void)id;
    if (b == NULL)
        abort();
    b->vaddr = qemu_plugin_tb_vaddr(tb);
    if (profile_path != NULL) {
        b->pcs = calloc(n ? n : 1, sizeof *b->pcs);
        if (block_count == block_cap) {
            block_cap = block_cap ? 2 * block_cap : 4096;
            blocks = realloc(blocks, block_cap * sizeof *blocks);
        }
        if (b->pcs == NULL || blocks == NULL)
            abort();
        blocks[block_count++] = b;
    }
    for (i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        const uint8_t *d = (const uint8_t *)qemu_plugin_insn_data(insn);
        size_t size = qemu_plugin_insn_size(insn);
        unsigned hw1 = (unsigned)d[0] | (unsigned)d[1] << 8;
        unsigned hw2 = size >= 4 ? ((unsigned)d[2] | (unsigned)d[3] << 8) : 0;
        insn_class c = classify(hw1, hw2, size >= 4);
        unsigned cost = c.cost;
        int in_it = it_left > 0;
        if (it_left > 0)
            it_left--;
        if (c.it)
            it_left = c.it;
        if (c.kind == K_LOAD)
            cost = prev_kind != K_OTHER ? 1 : 2; /* pipelined behind a load/store: 1 */
        if (c.branch == END_ALWAYS && !in_it)
            cost += penalty;
        b->cycles += cost;
        b->divs += (uint32_t)c.div;
        b->insns++;
        if (i == 0)
            b->first_kind = (uint8_t)c.kind;
        b->last_kind = (uint8_t)c.kind;
        b->end = c.branch == 0 ? END_PLAIN : (c.branch == END_ALWAYS && !in_it) ? END_ALWAYS : END_COND;
        b->fallthrough = qemu_plugin_insn_vaddr(insn) + size;
        if (b->pcs != NULL)
            b->pcs[i] = (uint32_t)qemu_plugin_insn_vaddr(insn);
        prev_kind = c.kind;
    }
    /* the first instruction's load cost assumed not pipelined (2); the
     * exec callback takes 1 off when the previous block ended in a load/store */
    qemu_plugin_register_vcpu_tb_exec_cb(tb, block_exec, QEMU_PLUGIN_CB_NO_REGS, b);
}

static void write_profile(void)
{
    FILE *f = fopen(profile_path, "w");
    uint64_t total = 0;
    size_t i, k;
    char msg[256];
    if (f == NULL) {
        snprintf(msg, sizeof msg, "m4timing: cannot write %s\n", profile_path);
        qemu_plugin_outs(msg);
        return;
    }
    fprintf(f, "# m4timing profile: PC executions; marks %ld..%ld (-1: whole run)\n", prof_from, prof_to);
    for (i = 0; i < block_count; i++) {
        const block *b = blocks[i];
        if (b->execs == 0)
            continue;
        for (k = 0; k < b->insns; k++)
            fprintf(f, "%08" PRIx32 " %" PRIu64 "\n", b->pcs[k], b->execs);
        total += b->execs * b->insns;
    }
    fprintf(f, "# total %" PRIu64 "\n", total);
    fclose(f);
}

static void at_exit(qemu_plugin_id_t id, void *udata)
{
    FILE *f = fopen(out_path, "w");
    size_t i;
    char msg[256];
    (void)id;
    (void)udata;
    if (f == NULL) {
        snprintf(msg, sizeof msg, "m4timing: cannot write %s\n", out_path);
        qemu_plugin_outs(msg);
        return;
    }
    fprintf(f, "# m4timing ESTIMATE: Cortex-M4 TRM timing table, P=%u, SDIV/UDIV=%u cycles\n", penalty,
            div_cycles);
    for (i = 0; i < mark_count; i++)
        fprintf(f, "MARK %zu %" PRIu64 " %" PRIu64 "\n", i, marks[i].insns, marks[i].cycles);
    fprintf(f, "TOTAL insns %" PRIu64 " cycles %" PRIu64 " divisions %" PRIu64 " taken_cond_branches %" PRIu64 "\n",
            insns, cycles, divs, taken);
    fclose(f);
    if (profile_path != NULL)
        write_profile();
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info, int argc, char **argv)
{
    int i, any_cpu = 0;
    for (i = 0; i < argc; i++)
        if (strcmp(argv[i], "any=1") == 0)
            any_cpu = 1;
    /* any=1: another CPU (port/avr counts AVR instructions so); the
     * instruction counts hold for it, the cycle columns do not */
    if (info->version.cur < 1 || (!any_cpu && strcmp(info->target_name, "arm") != 0)) {
        qemu_plugin_outs("m4timing: needs qemu-system-arm with plugin API version 1 (QEMU 7.2)\n");
        return -1;
    }
    for (i = 0; i < argc; i++) {
        if (strncmp(argv[i], "mark=", 5) == 0)
            mark_addr = strtoull(argv[i] + 5, NULL, 0) & ~(uint64_t)1; /* Thumb bit off */
        else if (strncmp(argv[i], "out=", 4) == 0)
            out_path = argv[i] + 4;
        else if (strncmp(argv[i], "p=", 2) == 0)
            penalty = (unsigned)strtoul(argv[i] + 2, NULL, 0);
        else if (strncmp(argv[i], "div=", 4) == 0)
            div_cycles = (unsigned)strtoul(argv[i] + 4, NULL, 0);
        else if (strncmp(argv[i], "profile=", 8) == 0)
            profile_path = argv[i] + 8;
        else if (strncmp(argv[i], "from=", 5) == 0)
            prof_from = strtol(argv[i] + 5, NULL, 0);
        else if (strncmp(argv[i], "to=", 3) == 0)
            prof_to = strtol(argv[i] + 3, NULL, 0);
        else if (strcmp(argv[i], "any=1") == 0)
            continue; /* taken above */
        else {
            qemu_plugin_outs("m4timing: arguments: mark=ADDR out=FILE p=CYCLES div=CYCLES profile=FILE from=I to=J any=1\n");
            return -1;
        }
    }
    if ((prof_from >= 0) != (prof_to >= 0) || prof_to < prof_from) {
        qemu_plugin_outs("m4timing: profile interval needs both from=I and to=J, I <= J\n");
        return -1;
    }
    if (prof_from >= 0)
        profiling = 0;
    qemu_plugin_register_vcpu_tb_trans_cb(id, block_trans);
    qemu_plugin_register_atexit_cb(id, at_exit, NULL);
    return 0;
}

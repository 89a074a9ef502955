/*
 * insn_count.c - QEMU TCG plugin counting executed guest instructions (plugin API v1, QEMU 7.2).
 *
 * Debian's QEMU loads plugins but ships no qemu-plugin.h, so the few API entry points used
 * are declared below exactly as in QEMU 7.2's include/qemu/qemu-plugin.h.
 *
 * Arguments (-plugin insn_count.so,arg=value,...):
 *   out=PATH          write the result there at exit (default: QEMU's log, i.e. stderr)
 *   lo=ADDR,hi=ADDR   count only instructions with lo <= address < hi (hex or decimal)
 *   start=ADDR,stop=ADDR  count only between executing `start` and executing `stop`
 *                     (start counted, stop not; windows add up, nesting is not tracked)
 * Output: "insns TOTAL\nrange RANGE\nwindow WINDOW\nwindows N\n".
 *
 * Counting: one inline 64-bit add per translated block (n instructions at block entry), so
 * the cost is small.  Instructions inside IT blocks whose condition fails are counted (they
 * occupy issue slots on hardware too).  A block left early by a synchronous fault would be
 * over-counted; semihosting BKPT and SVC end their block, so they are not.
 * Markers: a callback on the marker instruction computes how many instructions ran before
 * it as total - (instructions of its block not yet executed).
 */
#include <inttypes.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- declarations from qemu-plugin.h (QEMU 7.2, QEMU_PLUGIN_VERSION 1) ---- */
typedef uint64_t qemu_plugin_id_t;
typedef struct qemu_info_t qemu_info_t;   /* opaque here: only its pointer is passed */
struct qemu_plugin_tb;
struct qemu_plugin_insn;
enum qemu_plugin_cb_flags { QEMU_PLUGIN_CB_NO_REGS, QEMU_PLUGIN_CB_R_REGS, QEMU_PLUGIN_CB_RW_REGS };
enum qemu_plugin_op { QEMU_PLUGIN_INLINE_ADD_U64 };
typedef void (*qemu_plugin_udata_cb_t)(qemu_plugin_id_t id, void *userdata);
typedef void (*qemu_plugin_vcpu_udata_cb_t)(unsigned int vcpu_index, void *userdata);
typedef void (*qemu_plugin_vcpu_tb_trans_cb_t)(qemu_plugin_id_t id, struct qemu_plugin_tb *tb);

void qemu_plugin_register_vcpu_tb_trans_cb(qemu_plugin_id_t id, qemu_plugin_vcpu_tb_trans_cb_t cb);
void qemu_plugin_register_vcpu_tb_exec_inline(struct qemu_plugin_tb *tb, enum qemu_plugin_op op,
                                              void *ptr, uint64_t imm);
void qemu_plugin_register_vcpu_insn_exec_inline(struct qemu_plugin_insn *insn,
                                                enum qemu_plugin_op op, void *ptr, uint64_t imm);
void qemu_plugin_register_vcpu_insn_exec_cb(struct qemu_plugin_insn *insn,
                                            qemu_plugin_vcpu_udata_cb_t cb,
                                            enum qemu_plugin_cb_flags flags, void *userdata);
void qemu_plugin_register_atexit_cb(qemu_plugin_id_t id, qemu_plugin_udata_cb_t cb, void *userdata);
size_t qemu_plugin_tb_n_insns(const struct qemu_plugin_tb *tb);
struct qemu_plugin_insn *qemu_plugin_tb_get_insn(const struct qemu_plugin_tb *tb, size_t idx);
uint64_t qemu_plugin_insn_vaddr(const struct qemu_plugin_insn *insn);
void qemu_plugin_outs(const char *string);

#define QEMU_PLUGIN_EXPORT __attribute__((visibility("default")))
QEMU_PLUGIN_EXPORT int qemu_plugin_version = 1;

/* ---- plugin state (one emulated CPU on MPS2; QEMU runs TCG single-threaded for it) ---- */
static uint64_t g_total;        /* every executed instruction */
static uint64_t g_range;        /* executed instructions with lo <= pc < hi */
static uint64_t g_lo, g_hi;
static int g_have_range;
static uint64_t g_start_addr, g_stop_addr;
static int g_have_markers;
static int g_inside;            /* between a start and a stop marker */
static uint64_t g_window_begin; /* g_total-based count when the window opened */
static uint64_t g_window;       /* instructions inside closed windows */
static uint64_t g_windows;
static char g_out[4096];

/* userdata = instructions of the block from this one to its end (this one included) */
static void on_start(unsigned int vcpu, void *userdata)
{
    (void)vcpu;
    if (!g_inside) {
        g_inside = 1;
        g_window_begin = g_total - (uint64_t)(uintptr_t)userdata;
    }
}

static void on_stop(unsigned int vcpu, void *userdata)
{
    (void)vcpu;
    if (g_inside) {
        g_inside = 0;
        g_window += (g_total - (uint64_t)(uintptr_t)userdata) - g_window_begin;
        g_windows++;
    }
}

static void on_tb_trans(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    size_t n = qemu_plugin_tb_n_insns(tb);
    qemu_plugin_register_vcpu_tb_exec_inline(tb, QEMU_PLUGIN_INLINE_ADD_U64, &g_total, n);
    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        uint64_t pc = qemu_plugin_insn_vaddr(insn);
        if (g_have_range && pc >= g_lo && pc < g_hi) {
            qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &g_range, 1);
        }
        if (g_have_markers) {
            void *pending = (void *)(uintptr_t)(n - i);
            if (pc == g_start_addr) {
                qemu_plugin_register_vcpu_insn_exec_cb(insn, on_start, QEMU_PLUGIN_CB_NO_REGS, pending);
            }
            if (pc == g_stop_addr) {
                qemu_plugin_register_vcpu_insn_exec_cb(insn, on_stop, QEMU_PLUGIN_CB_NO_REGS, pending);
            }
        }
    }
}

static void at_exit(qemu_plugin_id_t id, void *userdata)
{
    (void)id;
    (void)userdata;
    char text[256];
    snprintf(text, sizeof text, "insns %" PRIu64 "\nrange %" PRIu64 "\nwindow %" PRIu64
             "\nwindows %" PRIu64 "\n", g_total, g_range, g_window, g_windows);
    if (g_out[0] != '\0') {
        FILE *f = fopen(g_out, "w");
        if (f != NULL) {
            fputs(text, f);
            fclose(f);
            return;
        }
    }
    qemu_plugin_outs(text);
}

static int parse_addr(const char *text, uint64_t *value)
{
    char *end = NULL;
    unsigned long long v = strtoull(text, &end, 0);
    if (end == text || *end != '\0') {
        return -1;
    }
    *value = (uint64_t)v;
    return 0;
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                                           int argc, char **argv)
{
    (void)info;
    int have_lo = 0, have_hi = 0, have_start = 0, have_stop = 0;
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        int bad = 0;
        if (strncmp(a, "out=", 4) == 0) {
            snprintf(g_out, sizeof g_out, "%s", a + 4);
        } else if (strncmp(a, "lo=", 3) == 0) {
            bad = parse_addr(a + 3, &g_lo);
            have_lo = 1;
        } else if (strncmp(a, "hi=", 3) == 0) {
            bad = parse_addr(a + 3, &g_hi);
            have_hi = 1;
        } else if (strncmp(a, "start=", 6) == 0) {
            bad = parse_addr(a + 6, &g_start_addr);
            have_start = 1;
        } else if (strncmp(a, "stop=", 5) == 0) {
            bad = parse_addr(a + 5, &g_stop_addr);
            have_stop = 1;
        } else {
            bad = 1;
        }
        if (bad) {
            fprintf(stderr, "insn_count: bad argument '%s'\n", a);
            return -1;
        }
    }
    if (have_lo != have_hi || have_start != have_stop) {
        fprintf(stderr, "insn_count: give lo with hi and start with stop\n");
        return -1;
    }
    g_have_range = have_lo;
    g_have_markers = have_start;
    qemu_plugin_register_vcpu_tb_trans_cb(id, on_tb_trans);
    qemu_plugin_register_atexit_cb(id, at_exit, NULL);
    return 0;
}
